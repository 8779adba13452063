#!/usr/bin/python3
"""Eigenvalues on fine meshes (not a ctest): accuracy and cost of the frequency and buckling analyses
as the mesh is refined, with the element-wise rigid-motion-free stiffness inside shift-and-invert
(-eigen_operator elementwise, the default) and with the assembled stiffness and its LU alone
(-eigen_operator assembled, the former method). Models:
- ANCF cantilever (A1 cable unloaded: L = 2, EI = 833.33, rhoA = 78, EA = 1e6), 10 lowest
  frequencies, 1 rank, against the analytic Euler-Bernoulli bending and axial-bar values (the
  discrete reference from 512 elements on: the h^4 discretization error measured at 64 elements,
  7.2e-6 for f10, is below 1e-11 there);
- steel leaf spring cantilever (L = 1, rect 10 x 1 mm, beam elements), f1 on 2 ranks against the
  element-wise value at 1024 elements (and Euler-Bernoulli, printed);
- fixed-free beam column (same section, P = P_E / 2): buckling multiplier on 2 ranks against the
  element-wise value at 512 elements.
Times: the run's "step analyses" phase (the eigen solve with its factorization) and the whole
mpirun wall time. With --doc the tables go to docs/performance.md (bench_eigen) and
docs/accuracy_ancf.md (ancf_frequencies).

usage: scripts/bench_eigen.py [--quick] [--doc]"""
import argparse
import os
import re
import subprocess
import sys
import time

import h5py
import numpy as np
from scipy.optimize import brentq

import doc_tables

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
sys.path.insert(0, os.path.join(SOURCE, "tests", "cases"))
from modal_util import E, beam_x, cantilever_hz, yaml_text  # noqa: E402

BUILD = os.path.join(SOURCE, "build")
WORK = os.path.join(BUILD, "bench", "eigen")
EI, RHOA, EA, L = 833.3333333333333, 78.0, 1e6, 2.0
beta = [brentq(lambda x: np.cos(x) * np.cosh(x) + 1, (k + 0.5) * np.pi - 1, (k + 0.5) * np.pi + 1) for k in range(10)]
REF = np.sort([b**2 * np.sqrt(EI / (RHOA * L**4)) / (2 * np.pi) for b in beta] +
              [(2 * k - 1) / (4 * L) * np.sqrt(EA / RHOA) for k in range(1, 6)])[:10]


def cable(n):
    return yaml_text({"title": "ANCF cantilever frequencies", "nodes": [[0, 0], [L, 0]], "elements": [[1, 2]],
                      "nprops": {1: {"fix_coords": [1, 1, 0, 1]}},
                      "eprops": [{"elems": [1], "type": "ancf_cable2d", "nbeams": n, "physicsMassPerLength": RHOA,
                                  "physicsBendingStiffness": EI, "physicsAxialStiffness": EA,
                                  "useReducedOrderIntegration": 0}],
                      "opt": {"loadsteps": 1, "calcfreq": True, "nfreq": 10}})


def run(name, text, np_, method, extra=()):
    os.makedirs(WORK, exist_ok=True)
    path = os.path.join(WORK, name + ".yaml")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(WORK, f"{name}_{method}.h5")
    cmd = ["nice", "mpirun", "-n", str(np_), os.path.join(BUILD, "sinew"), path, "-o", out, "-eigen_operator", method,
           "-constraint_check", "false"] + list(extra)
    t0 = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.time() - t0
    with open(out[:-3] + ".log", "w") as f:
        f.write(p.stdout + p.stderr)
    m = re.search(r"step analyses ([0-9.]+) s", p.stdout)
    if p.returncode != 0 or not m:
        print(f"{name} {method}: exit {p.returncode}", flush=True)
        return None, None, wall
    with h5py.File(out, "r") as h:
        data = {k: h[k][-1] for k in ("freq", "buck") if k in h}
    return data, float(m.group(1)), wall


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="smaller meshes (a check of the script)")
    ap.add_argument("--doc", action="store_true")
    a = ap.parse_args()
    t_all = time.time()
    ancf_n = [64, 512, 4096] if a.quick else [64, 512, 4096, 16384, 65536]
    ancf_assembled_max = 4096 if a.quick else 16384
    rows, acc = [], []
    for n in ancf_n:
        res = {}
        for method in ("assembled", "elementwise"):
            if method == "assembled" and n > ancf_assembled_max:
                continue
            d, t, wall = run(f"ancf{n}", cable(n), 1, method)
            res[method] = (d, t, wall)
            print(f"ancf {n} {method}: {t} s", flush=True)
        e = {m: (r[0]["freq"] / REF - 1 if r[0] else None) for m, r in res.items()}
        fmt = lambda v: "-" if v is None else f"{v:.1e}"  # noqa: E731
        acc.append(f"| {n} | {fmt(e.get('assembled', [None])[0] if e.get('assembled') is not None else None)} "
                   f"| {fmt(e['elementwise'][0] if e.get('elementwise') is not None else None)} "
                   f"| {fmt(np.max(np.abs(e['elementwise'])) if e.get('elementwise') is not None else None)} "
                   f"| {fmt(e['elementwise'][9] if e.get('elementwise') is not None else None)} |")
        for m, (d, t, wall) in res.items():
            rows.append(f"| ANCF cantilever, f1..f10 | {n} | 1 | {m} | "
                        f"{fmt(np.max(np.abs(e[m])) if e[m] is not None else None)} | "
                        f"{'-' if t is None else f'{t:.2f}'} | {wall:.1f} |")
    # leaf spring
    leaf_n = [64, 1024, 8192] if a.quick else [64, 1024, 8192, 32768]
    leaf = {}
    for n in leaf_n:
        for method in ("assembled", "elementwise"):
            if method == "assembled" and n > 8192:
                continue
            d, t, wall = run(f"leaf{n}", beam_x(1.0, 0.01, 0.001, n, {1: {"fix": True}}, opt={"calcfreq": True, "nfreq": 3}),
                             2, method)
            leaf[(n, method)] = (d, t, wall)
            print(f"leaf {n} {method}: {t} s", flush=True)
    lref = leaf[(1024, "elementwise")][0]["freq"][0]
    eb = cantilever_hz(1.0, 0.01, 0.001, 1)[0]
    for (n, m), (d, t, wall) in leaf.items():
        err = "-" if d is None else f"{d['freq'][0] / lref - 1:.1e}"
        rows.append(f"| leaf spring, f1 | {n} | 2 | {m} | {err} | {'-' if t is None else f'{t:.2f}'} | {wall:.1f} |")
    # buckling
    Lc, W, T = 1.0, 0.01, 0.001
    pe = np.pi**2 * E * W * T**3 / 12 / (2 * Lc) ** 2
    col_n = [512, 4096] if a.quick else [512, 4096, 16384]
    col = {}
    for n in col_n:
        for method in ("assembled", "elementwise"):
            if method == "assembled" and n > 4096:
                continue
            d, t, wall = run(f"column{n}", beam_x(Lc, W, T, n, {1: {"fix": True}, 2: {"force": [-0.5 * pe, 0, 0]}}, dens=0,
                                                  opt={"loadsteps": 1, "calcbuck": True, "nbuck": 2}),
                             2, method, ["-force_rtol", "1e-6"])
            col[(n, method)] = (d, t, wall)
            print(f"column {n} {method}: {t} s", flush=True)
    cref = col[(512, "elementwise")][0]["buck"][0]
    for (n, m), (d, t, wall) in col.items():
        err = "-" if d is None else f"{d['buck'][0] / cref - 1:.1e}"
        rows.append(f"| beam column, buckling mu1 | {n} | 2 | {m} | {err} | {'-' if t is None else f'{t:.2f}'} | {wall:.1f} |")
    total = time.time() - t_all
    perf = ("Generated by `scripts/bench_eigen.py` in %.0f s (wall; load average before the run %s). Error: ANCF "
            "max over the 10 lowest frequencies of |f / analytic - 1| (the discrete reference, see docs/accuracy_ancf.md); "
            "leaf spring f1 against the element-wise value at 1024 elements (%.10g Hz; Euler-Bernoulli %.10g Hz, "
            "difference %.1e: shear and rotary inertia); column mu1 against the element-wise value at 512 elements "
            "(%.10g; Euler 2). Time: the `step analyses` phase of the summary (eigen solve incl. factorization) and "
            "the whole mpirun.\n\n" % (total, os.getloadavg()[0] if False else "%.1f" % LOAD0, lref, eb, lref / eb - 1, cref))
    perf += "| model | elements | ranks | method | relative error | step analyses [s] | wall [s] |\n|---|---|---|---|---|---|---|\n"
    perf += "\n".join(rows) + "\n"
    accb = ("Generated by `scripts/bench_eigen.py` (1 rank): relative error of the natural frequencies of the unloaded A1 "
            "cantilever against the analytic Euler-Bernoulli bending / axial-bar values, with the element-wise operator "
            "(default) and with the assembled stiffness and its LU alone (`-eigen_operator assembled`, run up to %d "
            "elements).\n\n| elements | f1 assembled | f1 element-wise | max of f1..f10 element-wise | f10 element-wise |\n"
            "|---|---|---|---|---|\n" % ancf_assembled_max) + "\n".join(acc) + "\n"
    print(perf)
    print(accb)
    if a.doc:
        doc_tables.write_block("performance.md", "bench_eigen", perf)
        doc_tables.write_block("accuracy_ancf.md", "ancf_frequencies", accb)


LOAD0 = os.getloadavg()[0]
if __name__ == "__main__":
    main()
