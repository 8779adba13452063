"""Scene builders shared by the path-following tests (test_continuation_lee, _euler, _subcritical,
test_restart_continuation, test_continuation_stop_reason): Lee's frame, the perfect Euler column, a
clamped cosine arch and the von Mises truss (sources in those tests)."""
import math

import numpy as np

import beamtools as bt

LEE_L, LEE_E, LEE_N = 120.0, 720.0, 20
# von Mises truss: half span, rise, bar diameter (A = 1e-3 with E = 1e7: EA = 1e4)
TRUSS_A, TRUSS_H, TRUSS_D = 1.0, 0.1, math.sqrt(4 * 1e-3 / math.pi)


def von_mises_truss(cont):
    """Two pinned bars (axial mode only) meeting at the apex node 2, a unit load down on it; `cont`:
    the opt.continuation block. Scene text."""
    a, H = TRUSS_A, TRUSS_H
    return bt.yaml_text({"title": "von Mises truss", "nodes": [[-a, 0, 0], [0, H, 0], [a, 0, 0]], "elements": [[1, 2], [3, 2]],
            "nprops": {"1": {"fix": True}, "3": {"fix": True},
                       "2": {"fix_z": True, "fix_orien": True, "force": [0, -1, 0]}},
            "eprops": [{"elems": [1, 2], "flex": [1], "emod": 1e7, "smod": 4e6, "cshape": "circ", "dim": [TRUSS_D]}],
            "opt": {"rls": {"1": [2, 3, 4, 5, 6], "2": [2, 3, 4, 5, 6]}, "calccompl": False, "continuation": cont}})


def lee_frame(max_steps=38):
    """Lee's frame, 20 beam elements per member, in-plane; (scene text, load node)."""
    L, E, n = LEE_L, LEE_E, LEE_N
    nodes = [[0.0, L * i / n, 0.0] for i in range(n + 1)] + [[L * i / n, L, 0.0] for i in range(1, n + 1)]
    elems = [[i + 1, i + 2] for i in range(len(nodes) - 1)]
    load = n + 1 + n // 5  # x = 24
    nprops = {i + 1: {"fix_z": True} for i in range(len(nodes))}
    nprops[1] = {"fix_pos": True}
    nprops[len(nodes)] = {"fix_pos": True}
    nprops[load] = {"fix_z": True, "force": [0, -1, 0]}
    return bt.yaml_text({"title": "Lee's frame", "nodes": nodes, "elements": elems, "nprops": nprops,
                         "eprops": [{"elems": list(range(1, len(elems) + 1)), "flex": [1, 2, 3, 4, 5, 6], "emod": E,
                                     "smod": E / 2.6, "cshape": "rect", "dim": [3.0, 2.0], "orien": [0, 0, 1]}],
                         "opt": {"calccompl": False,
                                 "continuation": {"method": "arclength", "ds": 10.0, "ds_max": 20.0, "node": load,
                                                  "direction": "y", "max_steps": max_steps}}}), load


def euler_column(n=20, max_steps=20, L=1.0, d=0.01, E=210e9):
    """Perfect fixed-free Euler column (circ d) under its Euler load P_cr at the top; (text, P_cr)."""
    Pcr = np.pi ** 2 * E * np.pi * d ** 4 / 64 / (4 * L ** 2)
    nprops = {i + 1: {"fix_z": True} for i in range(n + 1)}
    nprops[1] = {"fix": True}
    nprops[n + 1] = {"fix_z": True, "force": [0, -Pcr, 0]}
    return bt.yaml_text({"title": "perfect Euler column", "nodes": [[0.0, L * i / n, 0.0] for i in range(n + 1)],
                         "elements": [[i + 1, i + 2] for i in range(n)], "nprops": nprops,
                         "eprops": [{"elems": list(range(1, n + 1)), "flex": [1, 2, 3, 4, 5, 6], "emod": E, "smod": E / 2.6,
                                     "cshape": "circ", "dim": [d]}],
                         "opt": {"calccompl": False,
                                 "continuation": {"method": "arclength", "constraint": "spherical", "psi": float(1 / Pcr),
                                                  "ds": 0.1, "ds_max": 0.3, "node": n + 1, "direction": "x",
                                                  "max_steps": max_steps}}}), Pcr


def clamped_arch(h, imperfection=0.0, n=40, ds=0.008, max_steps=10, L=0.1, t=0.5e-3, wd=5e-3, E=210e9):
    """Clamped cosine arch w0 = h/2 (1 - cos 2 pi x/L) plus an antisymmetric imperfection
    imperfection * h * sin(2 pi x/L) (1 - cos 2 pi x/L), rect wd x t, a unit downward force at mid-span
    (the load factor is the force in N); (scene text, mid-span node)."""
    x = np.linspace(0, L, n + 1)
    y = h / 2 * (1 - np.cos(2 * np.pi * x / L)) + imperfection * h * np.sin(2 * np.pi * x / L) * (1 - np.cos(2 * np.pi * x / L))
    c = n // 2 + 1
    nprops = {i + 1: {"fix_z": True} for i in range(n + 1)}
    nprops[1] = {"fix": True}
    nprops[n + 1] = {"fix": True}
    nprops[c] = {"fix_z": True, "force": [0, -1, 0]}
    return bt.yaml_text({"title": "clamped cosine arch", "nodes": [[float(a), float(b), 0.0] for a, b in zip(x, y)],
                         "elements": [[i + 1, i + 2] for i in range(n)], "nprops": nprops,
                         "eprops": [{"elems": list(range(1, n + 1)), "flex": [1, 2, 3, 4, 5, 6], "emod": E, "smod": E / 2.6,
                                     "cshape": "rect", "dim": [wd, t], "orien": [0, 0, 1]}],
                         "opt": {"calccompl": False,
                                 "continuation": {"method": "arclength", "ds": ds, "ds_max": ds, "node": c,
                                                  "direction": "y", "max_steps": max_steps}}}), c


def pinned_shallow_arch(cont, n=40, L=1.0, h=0.01, wd=0.02, t=0.004, E=210e9, P=100.0):
    """Issue 24's shallow pinned arch: circular, span L, rise h, rect wd x t (bending about the weak axis
    in the arch plane), steel, both ends pinned (fix_pos), a downward force P at mid-span (load factor
    1 = P); `cont`: the opt.continuation block (node and direction are set here). (scene text, mid node)."""
    R = (L ** 2 / 4 + h ** 2) / (2 * h)
    x = np.linspace(0, L, n + 1)
    y = np.sqrt(R ** 2 - (x - L / 2) ** 2) - (R - h)
    c = n // 2 + 1
    nprops = {i + 1: {"fix_z": True} for i in range(n + 1)}
    nprops[1] = {"fix_pos": True}
    nprops[n + 1] = {"fix_pos": True}
    nprops[c] = {"fix_z": True, "force": [0, -P, 0]}
    return bt.yaml_text({"title": "shallow pinned arch", "nodes": [[float(a), float(b), 0.0] for a, b in zip(x, y)],
                         "elements": [[i + 1, i + 2] for i in range(n)], "nprops": nprops,
                         "eprops": [{"elems": list(range(1, n + 1)), "flex": [1, 2, 3, 4, 5, 6], "emod": E, "smod": E / 2.6,
                                     "cshape": "rect", "dim": [wd, t], "orien": [0, 0, 1]}],
                         "opt": {"calccompl": False, "continuation": dict(cont, node=c, direction="y")}}), c


def deep_arch(cont, n=40, R=100.0, angle=215.0, EI=1e6, EA=1e8, P=1000.0):
    """The deep circular arch of DaDeppo & Schmidt (1975): radius R, opening angle `angle` (degrees),
    clamped at the left end, pinned at the right, a downward force P at the apex (load factor 1 = P;
    P R^2/EI = 10 with the defaults), EI and EA of a square section; `cont`: the opt.continuation
    block (node and direction are set here). (scene text, apex node)."""
    d = math.sqrt(12 * EI / EA)  # square d x d: I/A = d^2/12
    Em = EA / d ** 2
    half = math.radians(angle) / 2
    phi = np.linspace(-half, half, n + 1)
    c = n // 2 + 1
    nodes = [[float(R * math.sin(p)), float(R * math.cos(p)), 0.0] for p in phi]
    nprops = {i + 1: {"fix_z": True} for i in range(n + 1)}
    nprops[1] = {"fix": True}
    nprops[n + 1] = {"fix_pos": True}
    nprops[c] = {"fix_z": True, "force": [0, -P, 0]}
    return bt.yaml_text({"title": "deep circular arch", "nodes": nodes, "elements": [[i + 1, i + 2] for i in range(n)],
                         "nprops": nprops,
                         "eprops": [{"elems": list(range(1, n + 1)), "flex": [1, 2, 3, 4, 5, 6], "emod": Em, "smod": Em / 2.6,
                                     "cshape": "rect", "dim": [d, d], "orien": [0, 0, 1]}],
                         "opt": {"calccompl": False, "continuation": dict(cont, node=c, direction="y")}}), c
