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
Times: the run's "step analyses" phase (the eigen solve with its factorization) and the sum of
all phases of the run summary. With --doc the tables go to docs/performance.md (bench_eigen) and
docs/accuracy_ancf.md (ancf_frequencies), rewritten after every model (partial tables say so).
--reuse takes a run whose result and log are already in build/bench/eigen instead of running it
again (the tables then mix runs of different times: see the load averages in the logs).

usage: scripts/bench_eigen.py [--quick] [--doc] [--reuse] [--skip leaf32768 ...]"""
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


REUSE = False


def phases(text):
    """step analyses time and the sum of the summary phases (s) of a run's output, or None."""
    m = re.search(r"wall time: (.*)", text)
    s = re.search(r"step analyses ([0-9.]+) s", text)
    if not m or not s:
        return None, None
    return float(s.group(1)), sum(float(v) for v in re.findall(r"([0-9.]+) s", m.group(1)))


def run(name, text, np_, method, extra=()):
    os.makedirs(WORK, exist_ok=True)
    path = os.path.join(WORK, name + ".yaml")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(WORK, f"{name}_{method}.h5")
    if REUSE and os.path.exists(out) and os.path.exists(out[:-3] + ".log"):
        with open(out[:-3] + ".log") as f:
            t, total = phases(f.read())
        if t is not None:
            with h5py.File(out, "r") as h:
                data = {k: h[k][-1] for k in ("freq", "buck") if k in h}
            return data, t, total
    cmd = ["nice", "mpirun", "-n", str(np_), os.path.join(BUILD, "sinew"), path, "-o", out, "-eigen_operator", method,
           "-constraint_check", "false"] + list(extra)
    load = os.getloadavg()[0]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    with open(out[:-3] + ".log", "w") as f:
        f.write(p.stdout + p.stderr + f"\nload average (1 min) at the start: {load:.1f}\n")
    t, total = phases(p.stdout)
    if p.returncode != 0 or t is None:
        print(f"{name} {method}: exit {p.returncode}", flush=True)
        return None, None, None
    with h5py.File(out, "r") as h:
        data = {k: h[k][-1] for k in ("freq", "buck") if k in h}
    return data, t, total


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="smaller meshes (a check of the script)")
    ap.add_argument("--doc", action="store_true")
    ap.add_argument("--reuse", action="store_true")
    ap.add_argument("--skip", nargs="*", default=[], help="runs left out, e.g. leaf32768 (model and elements)")
    a = ap.parse_args()
    global REUSE
    REUSE = a.reuse
    t_all = time.time()
    ancf_n = [64, 512, 4096] if a.quick else [64, 512, 4096, 16384, 65536]
    ancf_assembled_max = 4096 if a.quick else 16384
    rows, acc = [], []
    state = {"lref": None, "cref": None}

    def emit(partial):
        lref, cref = state["lref"], state["cref"]
        eb = cantilever_hz(1.0, 0.01, 0.001, 1)[0]
        perf = ("Generated by `scripts/bench_eigen.py`%s (%.0f s; load average at the start %.1f, 2 cores shared "
                "with other jobs: times are indicative). Error: ANCF max over the 10 lowest frequencies of "
                "|f / analytic - 1| (the discrete reference, see docs/accuracy_ancf.md); leaf spring f1 against "
                "the element-wise value at 1024 elements%s; column mu1 against the element-wise value at 512 "
                "elements%s. Times: the `step analyses` phase of the summary (the eigen solve with its "
                "factorization) and the sum of all summary phases.\n\n"
                % (" (partial: the run was cut short)" if partial else "", time.time() - t_all, LOAD0,
                   "" if lref is None else f" ({lref:.10g} Hz; Euler-Bernoulli {eb:.10g} Hz, difference "
                   f"{lref / eb - 1:.1e}: shear and rotary inertia)",
                   "" if cref is None else f" ({cref:.10g}; Euler 2)"))
        perf += ("| model | elements | ranks | method | relative error | step analyses [s] | all phases [s] |\n"
                 "|---|---|---|---|---|---|---|\n") + "\n".join(rows) + "\n"
        accb = ("Generated by `scripts/bench_eigen.py` (1 rank): relative error of the natural frequencies of the "
                "unloaded A1 cantilever against the analytic Euler-Bernoulli bending / axial-bar values, with the "
                "element-wise operator (default) and with the assembled stiffness and its LU alone "
                "(`-eigen_operator assembled`, run up to %d elements).\n\n| elements | f1 assembled | f1 element-wise "
                "| max of f1..f10 element-wise | f10 element-wise |\n|---|---|---|---|---|\n"
                % ancf_assembled_max) + "\n".join(acc) + "\n"
        print(perf)
        print(accb, flush=True)
        if a.doc:
            doc_tables.write_block("performance.md", "bench_eigen", perf)
            doc_tables.write_block("accuracy_ancf.md", "ancf_frequencies", accb)
    for n in ancf_n:
        res = {}
        for method in ("assembled", "elementwise"):
            if (method == "assembled" and n > ancf_assembled_max) or f"ancf{n}" in a.skip:
                continue
            d, t, wall = run(f"ancf{n}", cable(n), 1, method)
            res[method] = (d, t, wall)
            print(f"ancf {n} {method}: {t} s", flush=True)
        if "elementwise" not in res or res["elementwise"][0] is None:
            continue
        e = {m: (r[0]["freq"] / REF - 1 if r[0] else None) for m, r in res.items()}
        fmt = lambda v: "-" if v is None else f"{v:.1e}"  # noqa: E731
        acc.append(f"| {n} | {fmt(e.get('assembled', [None])[0] if e.get('assembled') is not None else None)} "
                   f"| {fmt(e['elementwise'][0] if e.get('elementwise') is not None else None)} "
                   f"| {fmt(np.max(np.abs(e['elementwise'])) if e.get('elementwise') is not None else None)} "
                   f"| {fmt(e['elementwise'][9] if e.get('elementwise') is not None else None)} |")
        for m, (d, t, wall) in res.items():
            rows.append(f"| ANCF cantilever, f1..f10 | {n} | 1 | {m} | "
                        f"{fmt(np.max(np.abs(e[m])) if e[m] is not None else None)} | "
                        f"{'-' if t is None else f'{t:.2f}'} | {'-' if wall is None else f'{wall:.1f}'} |")
        emit(True)
    # leaf spring
    leaf_n = [64, 1024, 8192] if a.quick else [64, 1024, 8192, 32768]
    leaf = {}
    for n in leaf_n:
        for method in ("assembled", "elementwise"):
            if (method == "assembled" and n > 8192) or f"leaf{n}" in a.skip:
                continue
            d, t, wall = run(f"leaf{n}", beam_x(1.0, 0.01, 0.001, n, {1: {"fix": True}}, opt={"calcfreq": True, "nfreq": 3}),
                             2, method)
            leaf[(n, method)] = (d, t, wall)
            print(f"leaf {n} {method}: {t} s", flush=True)
            if (1024, "elementwise") in leaf and leaf[(1024, "elementwise")][0] is not None:
                state["lref"] = leaf[(1024, "elementwise")][0]["freq"][0]
            if state["lref"] is not None:
                for (n2, m2), (d2, t2, w2) in list(leaf.items()):
                    err = "-" if d2 is None else f"{d2['freq'][0] / state['lref'] - 1:.1e}"
                    rows.append(f"| leaf spring, f1 | {n2} | 2 | {m2} | {err} | {'-' if t2 is None else f'{t2:.2f}'} | "
                                f"{'-' if w2 is None else f'{w2:.1f}'} |")
                    del leaf[(n2, m2)]
                emit(True)
    # buckling
    Lc, W, T = 1.0, 0.01, 0.001
    pe = np.pi**2 * E * W * T**3 / 12 / (2 * Lc) ** 2
    col_n = [512, 4096] if a.quick else [512, 4096, 16384]
    col = {}
    for n in col_n:
        for method in ("assembled", "elementwise"):
            if (method == "assembled" and n > 4096) or f"column{n}" in a.skip:
                continue
            d, t, wall = run(f"column{n}", beam_x(Lc, W, T, n, {1: {"fix": True}, 2: {"force": [-0.5 * pe, 0, 0]}}, dens=0,
                                                  opt={"loadsteps": 1, "calcbuck": True, "nbuck": 2}),
                             2, method, ["-force_rtol", "1e-6"])
            col[(n, method)] = (d, t, wall)
            print(f"column {n} {method}: {t} s", flush=True)
            if (512, "elementwise") in col and col[(512, "elementwise")][0] is not None:
                state["cref"] = col[(512, "elementwise")][0]["buck"][0]
            if state["cref"] is not None:
                for (n2, m2), (d2, t2, w2) in list(col.items()):
                    err = "-" if d2 is None else f"{d2['buck'][0] / state['cref'] - 1:.1e}"
                    rows.append(f"| beam column, buckling mu1 | {n2} | 2 | {m2} | {err} | "
                                f"{'-' if t2 is None else f'{t2:.2f}'} | {'-' if w2 is None else f'{w2:.1f}'} |")
                    del col[(n2, m2)]
                emit(n != col_n[-1] or method != "elementwise")


LOAD0 = os.getloadavg()[0]
if __name__ == "__main__":
    main()
