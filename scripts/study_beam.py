#!/usr/bin/python3
"""Accuracy study of the 3D beam (docs/accuracy_beam.md, docs/accuracy_beam.png).

Two problems, one scene element split into nbeams = 1, 2, 4, ..., 64 elements, Newton tolerance
-snes_rtol 1e-4 ... 1e-10, one rank:
1. Roll-up (reference B1): an end moment M = 2 pi EI / L closes the cantilever into a full circle;
   exact tip at the root. Error = |tip| / L after the last of 20 load steps.
2. Tip-loaded large-deflection cantilever (Bisshopp & Drucker 1945): a tip force P perpendicular to
   the undeformed axis, alpha = P L^2 / EI = 10, load not following the tip. The elastica reference
   comes from the elliptic-integral solution (scipy.special), cross-checked by a shooting ODE
   integration. The axial mode is rigid (flex 2..6: inextensible); the shear flexibility of the
   0.001 m thick section changes the tip by about 3 EI / (kGA L^2) = 8e-7 L, below the errors studied.
Time is sinew's own set-up + statics time from its summary (MPI start-up and output excluded).
Usage: scripts/study_beam.py [build dir]   (default build)"""
import math
import os
import re
import subprocess
import sys
import time

import numpy as np
import yaml

import doc_tables

SRC = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = sys.argv[1] if len(sys.argv) > 1 else os.path.join(SRC, "build")
BIN = os.path.join(BUILD, "sinew")
WORK = os.path.join(BUILD, "study_beam")
NBEAMS = [1, 2, 4, 8, 16, 32, 64, 128]
RTOLS = [1e-4, 1e-6, 1e-8, 1e-10]
L, W, T, E = 1.0, 0.01, 0.001, 210e9
EI = E * W * T ** 3 / 12  # bending about local y (w along local y = orien = global z): deflection in y
ALPHA = 10.0


def elastica_elliptic(alpha):
    """Bisshopp & Drucker: tip angle theta0 from sqrt(alpha) = K(k) - F(phi1, k), k^2 = (1 + sin theta0)/2,
    sin phi1 = 1 / (k sqrt 2); tip x / L = sqrt(2 sin theta0 / alpha), tip deflection
    y / L = 1 - (2 / sqrt(alpha)) (E(k) - E(phi1, k))."""
    from scipy.optimize import brentq
    from scipy.special import ellipe, ellipeinc, ellipk, ellipkinc

    def parts(th0):
        m = (1 + math.sin(th0)) / 2
        phi1 = math.asin(min(1.0, 1 / math.sqrt(2 * m)))
        return m, phi1

    def f(th0):
        m, phi1 = parts(th0)
        return ellipk(m) - ellipkinc(phi1, m) - math.sqrt(alpha)

    th0 = brentq(f, 1e-9, math.pi / 2 - 1e-12, xtol=1e-15, rtol=1e-15)
    m, phi1 = parts(th0)
    x = math.sqrt(2 * math.sin(th0) / alpha)
    y = 1 - 2 / math.sqrt(alpha) * (ellipe(m) - ellipeinc(phi1, m))
    return th0, x, y


def elastica_shooting(alpha):
    """theta'' = -alpha cos(theta) on s in [0, 1] (length L = 1), theta(0) = 0, theta'(1) = 0; x' = cos, y' = sin."""
    from scipy.integrate import solve_ivp
    from scipy.optimize import brentq

    def end(k0):
        r = solve_ivp(lambda s, u: [u[1], -alpha * math.cos(u[0]), math.cos(u[0]), math.sin(u[0])], (0, 1),
                      [0, k0, 0, 0], rtol=1e-13, atol=1e-14, method="DOP853")
        return r.y[:, -1]

    k0 = brentq(lambda k: end(k)[1], 0.1 * alpha ** 0.5, alpha, xtol=1e-15)
    u = end(k0)
    return u[0], u[2], u[3]


def run(name, scene, rtol):
    os.makedirs(WORK, exist_ok=True)
    path = os.path.join(WORK, name + ".yaml")
    with open(path, "w") as f:
        yaml.safe_dump(scene, f, default_flow_style=None, sort_keys=False)
    out = os.path.join(WORK, name + ".h5")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    t0 = time.perf_counter()
    p = subprocess.run([BIN, path, "-o", out, "-snes_rtol", str(rtol), "-max_cuts", "3"], env=env,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=300)
    wall = time.perf_counter() - t0
    # the solver's own time (set-up + statics from the summary), free of MPI start-up
    m = re.search(r"wall time: setup ([0-9.]+) s, (?:constraint check [0-9.]+ s, )?statics ([0-9.]+) s", p.stdout)
    if m:
        wall = float(m.group(1)) + float(m.group(2))
    its = sum(int(m.group(1)) for m in re.finditer(r"^\s+\d+\s+\S+\s+(\d+)\s+\d+\s+\S+$", p.stdout, re.M))
    if p.returncode != 0:
        return None, wall, its
    import h5py
    with h5py.File(out, "r") as f:
        tip = f["node/p"][-1, -1]
    return tip, wall, its


def scene(title, load, nbeams, steps, flex):
    return {"title": title, "nodes": [[0, 0, 0], [L, 0, 0]], "elements": [[1, 2]],
            "nprops": {1: {"fix": True}, 2: load},
            "eprops": [{"elems": [1], "flex": flex, "emod": E, "smod": 80e9,
                        "cshape": "rect", "dim": [W, T], "orien": [0, 0, 1], "nbeams": nbeams}],
            "opt": {"loadsteps": steps, "calccompl": False}}


def main():
    t_start = time.perf_counter()
    th_e, x_e, y_e = elastica_elliptic(ALPHA)
    th_s, x_s, y_s = elastica_shooting(ALPHA)
    print(f"elastica alpha = {ALPHA}: elliptic tip angle {th_e:.12f}, x/L {x_e:.12f}, y/L {y_e:.12f}")
    print(f"                    shooting tip angle {th_s:.12f}, x/L {x_s:.12f}, y/L {y_s:.12f}")
    refdiff = max(abs(x_e - x_s), abs(y_e - y_s))
    assert refdiff < 1e-9, "elliptic and shooting elastica disagree"
    problems = {
        "roll-up": (lambda n: scene("roll-up", {"moment": [0, 0, 2 * math.pi * EI / L]}, n, 20, [1, 2, 3, 4, 5, 6]),
                    np.zeros(3)),
        "cantilever": (lambda n: scene("elastica", {"force": [0, ALPHA * EI / L ** 2, 0]}, n, 10, [2, 3, 4, 5, 6]),
                       np.array([x_e * L, y_e * L, 0.0])),
    }
    rows = []
    for prob, (make, exact) in problems.items():
        for n in NBEAMS:
            for rtol in RTOLS:
                tip, wall, its = run(f"{prob}_{n}_{rtol:g}", make(n), rtol)
                err = float(np.linalg.norm(tip - exact)) / L if tip is not None else float("nan")
                rows.append((prob, n, rtol, err, wall, its))
                print(f"{prob:10s} nbeams {n:3d} rtol {rtol:.0e}: tip error {err:.3e} L, wall {wall:.2f} s, "
                      f"{its} Newton its" + ("" if tip is not None else " (did not converge)"), flush=True)
    total = time.perf_counter() - t_start
    load = open("/proc/loadavg").read().split()[:3]
    write_doc(rows, (th_e, x_e, y_e, refdiff), total, load)
    plot(rows)
    print(f"study runtime {total:.0f} s, load average {' '.join(load)}")


def write_doc(rows, ref, total, load):
    """The generated blocks of docs/accuracy_beam.md (the problem statement and findings are hand-written)."""
    th, x, y, refdiff = ref
    doc_tables.write_block("accuracy_beam.md", "beam_study_run",
                           "Generated by `scripts/study_beam.py` (one rank, Release build); every number in the "
                           f"tables is from that run (study runtime {total:.0f} s, load average {' '.join(load)} at its "
                           "end, on a machine shared by several engineers: wall times are indicative).")
    doc_tables.write_block("accuracy_beam.md", "beam_reference",
                           f"Reference from the elliptic integrals: tip angle {th:.10f} rad, tip x = {x:.10f} L, "
                           f"deflection y = {y:.10f} L (a shooting ODE integration agrees to {refdiff:.1e}).")

    def table(prob):
        d = ["| nbeams | " + " | ".join(f"rtol {r:.0e}" for r in RTOLS) + " |", "|---|" + "---|" * len(RTOLS)]
        for n in NBEAMS:
            cells = []
            for r in RTOLS:
                row = next(x for x in rows if x[0] == prob and x[1] == n and x[2] == r)
                cells.append(("no conv." if math.isnan(row[3]) else f"{row[3]:.2e}") + f" ({row[4]:.2f} s, {row[5]})")
            d.append(f"| {n} | " + " | ".join(cells) + " |")
        conv = [x for x in rows if x[0] == prob and x[2] == 1e-10 and not math.isnan(x[3])]
        if len(conv) >= 2:
            a, b = conv[-2], conv[-1]
            d.append(f"\nObserved order between nbeams {a[1]} and {b[1]} (rtol 1e-10): "
                     f"{math.log(a[3] / b[3]) / math.log(b[1] / a[1]):.2f}.")
        return "\n".join(d)

    doc_tables.write_block("accuracy_beam.md", "beam_rollup", table("roll-up"))
    doc_tables.write_block("accuracy_beam.md", "beam_cantilever", table("cantilever"))


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, prob in zip(axes, ("roll-up", "cantilever")):
        for r, mk in zip(RTOLS, "os^D"):
            pts = [(x[4], x[3], x[1]) for x in rows if x[0] == prob and x[2] == r and not math.isnan(x[3])]
            if pts:
                ax.loglog([p[0] for p in pts], [max(p[1], 1e-16) for p in pts], mk + "-", label=f"rtol {r:.0e}")
                for p in pts:
                    if r == RTOLS[0]:
                        ax.annotate(str(p[2]), (p[0], max(p[1], 1e-16)), fontsize=7)
        ax.set_xlabel("set-up + statics time per run [s]")
        ax.set_ylabel("tip error / L")
        ax.set_title(f"{prob} (labels: nbeams)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(SRC, "docs", "accuracy_beam.png"), dpi=110)


if __name__ == "__main__":
    main()
