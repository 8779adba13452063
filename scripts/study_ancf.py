#!/usr/bin/python3
"""Accuracy study of the ANCF cable 2D (Exudyn ObjectANCFCable2D):
  statics: the A2 cantilever (tip force 3 EI / L^2) with 1, 2, 4, ..., 64 elements for each
           integration rule (useReducedOrderIntegration 0, 1, 2); tip error against the 256-element
           A2 value of ../shared/references (Exudyn, rule 0);
  dynamics: the A3 model (1 element, step tip load, generalized-alpha rho = 0.6, t = 0.1); tip error
           against a run with dt = 1e-6 for dt = 1e-2 ... 1e-5,
with the wall time of each run. Writes docs/accuracy_ancf.md and docs/accuracy_ancf.png; 1 rank,
222 s measured on the shared machine, most of it the dt = 1e-6 run.

usage: scripts/study_ancf.py [--bin build/sinew] [--np 1]"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "cases"))
from ancf_scenes import cantilever, text, tip_displacement  # noqa: E402
import doc_tables  # noqa: E402

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
A2_256 = np.array([-0.5085373043209689, -1.2072398545457785])  # reference A2, 256 elements
A3_EXUDYN = np.array([-1.0611305415798655, -1.4396907464589017])  # reference A3 (Exudyn, h = 1e-4)
F = 1.29375e6  # 3 EI / L^2


def run(args, scene, work, name):
    """Runs sinew; returns (tip displacement, wall time of the whole run, solver time from the summary)."""
    path = os.path.join(work, name + ".yaml")
    with open(path, "w") as f:
        f.write(text(scene))
    h5 = os.path.join(work, name + ".h5")
    t0 = time.time()
    p = subprocess.run(["mpirun", "-n", str(args.np), args.bin, path, "-o", h5], env=ENV,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.time() - t0
    if p.returncode:
        raise SystemExit(p.stdout)
    m = re.search(r"statics ([0-9.]+) s", p.stdout)
    with h5py.File(h5, "r") as f:
        return tip_displacement(f), wall, float(m.group(1))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "sinew"))
    ap.add_argument("--np", type=int, default=1)
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="sinew_study_ancf_")
    t_start = time.time()

    # ---- statics: elements x integration rule
    ns = [1, 2, 4, 8, 16, 32, 64]
    stat = {}
    for rule in (0, 1, 2):
        for n in ns:
            u, wall, solve = run(args, cantilever(n, force=F, integration=rule), work, f"a2_{rule}_{n}")
            err = np.linalg.norm(u - A2_256) / np.linalg.norm(A2_256)
            stat[rule, n] = (err, wall, solve)
            print(f"statics rule {rule} n {n:3d}: tip error {err:.3e}, wall {wall:.2f} s, solve {solve:.4f} s", flush=True)

    # ---- dynamics: time step
    dyn_scene = lambda dt: cantilever(1, force=F, dynamics={"tend": 0.1, "dt": dt, "spectral_radius": 0.6,
                                                            "output_every": 1000000})
    dt_ref = 1e-6
    u_ref, wall_ref, solve_ref = run(args, dyn_scene(dt_ref), work, "a3_ref")
    print(f"dynamics reference dt {dt_ref:g}: tip {u_ref}, wall {wall_ref:.2f} s", flush=True)
    dts = [1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5]
    dyn = {}
    for dt in dts:
        u, wall, solve = run(args, dyn_scene(dt), work, f"a3_{dt:g}")
        err = np.linalg.norm(u - u_ref) / np.linalg.norm(u_ref)
        dyn[dt] = (err, wall, solve, u)
        print(f"dynamics dt {dt:g}: tip error {err:.3e}, wall {wall:.2f} s, solve {solve:.4f} s", flush=True)
    exu = np.linalg.norm(dyn[1e-4][3] - A3_EXUDYN) / np.linalg.norm(A3_EXUDYN)
    total = time.time() - t_start

    # ---- figure
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for rule, mk in zip((0, 1, 2), ("o-", "s--", "^:")):
        ax[0].loglog(ns, [max(stat[rule, n][0], 1e-17) for n in ns], mk, label=f"useReducedOrderIntegration {rule}")
    ax[0].set_xlabel("elements")
    ax[0].set_ylabel("|tip - tip(A2, 256)| / |tip(A2, 256)|")
    ax[0].set_title("A2 statics: tip error vs elements")
    ax[0].grid(True, which="both", alpha=0.3)
    ax[0].legend()
    ax[1].loglog(dts, [dyn[dt][0] for dt in dts], "o-", label="tip error")
    ax[1].loglog(dts, [dyn[dts[0]][0] * (dt / dts[0]) ** 2 for dt in dts], "k:", label="slope 2")
    ax[1].set_xlabel("time step dt [s]")
    ax[1].set_ylabel(f"|tip - tip(dt = {dt_ref:g})| / |tip|")
    ax[1].set_title("A3 dynamics (t = 0.1): tip error vs dt")
    ax[1].grid(True, which="both", alpha=0.3)
    ax[1].legend()
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "docs", "accuracy_ancf.png"), dpi=110)

    # ---- report: the generated blocks of docs/accuracy_ancf.md (problem statements are hand-written)
    doc_tables.write_block("accuracy_ancf.md", "ancf_study_run",
                           f"Generated by `scripts/study_ancf.py` ({args.np} MPI rank{'s' if args.np > 1 else ''}, "
                           f"{total:.0f} s in total); every number in the tables comes from that run.")
    md = ["| elements | error rule 0 | error rule 1 | error rule 2 | wall 0 [s] | wall 1 [s] | wall 2 [s] | solve 0 [s] |",
          "|---|---|---|---|---|---|---|---|"]
    for n in ns:
        md.append(f"| {n} | {stat[0, n][0]:.2e} | {stat[1, n][0]:.2e} | {stat[2, n][0]:.2e} | {stat[0, n][1]:.2f} | "
                  f"{stat[1, n][1]:.2f} | {stat[2, n][1]:.2f} | {stat[0, n][2]:.4f} |")
    rates = [np.log2(stat[0, n][0] / stat[0, 2 * n][0]) for n in ns[:-1] if stat[0, 2 * n][0] > 0]
    md += ["", "Observed order of rule 0 between successive refinements (log2 of the error ratio): " +
           ", ".join(f"{r:.1f}" for r in rates) + "."]
    doc_tables.write_block("accuracy_ancf.md", "ancf_statics", "\n".join(md))
    md = [f"Error: |tip(dt) - tip(dt = {dt_ref:g})| / |tip(dt = {dt_ref:g})|; the fine run took {wall_ref:.1f} s (wall).",
          "", "| dt [s] | steps | tip error | wall [s] | solve [s] |", "|---|---|---|---|---|"]
    for dt in dts:
        md.append(f"| {dt:g} | {round(0.1 / dt)} | {dyn[dt][0]:.2e} | {dyn[dt][1]:.2f} | {dyn[dt][2]:.3f} |")
    drates = [np.log(dyn[a][0] / dyn[b][0]) / np.log(a / b) for a, b in zip(dts[:-1], dts[1:])]
    md += ["", "Observed order between successive time steps: " + ", ".join(f"{r:.2f}" for r in drates) + ".",
           f"At dt = 1e-4 the tip differs from Exudyn's A3 value (same dt) by {exu:.1e} relative."]
    doc_tables.write_block("accuracy_ancf.md", "ancf_dynamics", "\n".join(md))
    print("wrote docs/accuracy_ancf.png", flush=True)


if __name__ == "__main__":
    main()
