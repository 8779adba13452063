"""Scene builders shared by the path-following tests (test_continuation_lee, _euler, _subcritical,
test_restart_continuation): Lee's frame, the perfect Euler column and a clamped cosine arch (sources in
those tests)."""
import numpy as np

import beamtools as bt

LEE_L, LEE_E, LEE_N = 120.0, 720.0, 20


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
