#!/usr/bin/python3
"""ANCF cable benchmark: A1 (cantilever under gravity, L = 2, EA = 1e6, EI = 833.33) refined to n
elements, static, 1 load step (loadsteps: 1; Sinew cuts the increment by itself when Newton fails).
Two measurements, written to the generated block "bench_ancf" of docs/performance.md (section
"ANCF cable"; scripts/doc_tables.py: the rest of the file is kept):
  --converge n ...  full solves on 1 and 2 ranks: converged (exit 0)?, Newton iterations, increments,
                    GMRES iterations, statics time and the sum of Sinew's phases (run summary), wall
                    time of mpirun, peak memory (/usr/bin/time -v, largest resident set of the ranks);
  --iteration n ... the cost of one plain Newton iteration (residual, tangent, LU factorization and
                    solve, residual: -tangent_operator assembled -snes_max_it 1 -max_cuts 0) on 1 and
                    2 ranks. These runs stop after that iteration on purpose: time and memory only.
Run it under `flock /tmp/sinew_bench.lock` (one benchmark at a time on the machine).
usage: scripts/bench_ancf.py [--converge 32 1024 16384 ...] [--iteration 16384 1048576 ...] [--bin build/sinew]"""
import argparse
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "cases"))
from ancf_scenes import cantilever, text  # noqa: E402
import doc_tables  # noqa: E402

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
WORK = "/tmp/sinew_bench_ancf"


def run(binary, n, np_, extra=()):
    scene = os.path.join(WORK, f"a1_{n}.yaml")
    if not os.path.exists(scene):
        with open(scene, "w") as f:
            f.write(text(cantilever(n, EA=1e6, EI=833.3333333333333, gravity=[0, -9.81])))
    cmd = ["/usr/bin/time", "-v", "mpirun", "-n", str(np_), binary, scene, "-o", os.path.join(WORK, f"a1_{n}_{np_}.h5"),
           "-ksp_converged_reason"]
    t0 = time.time()
    p = subprocess.run(cmd + list(extra), env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.time() - t0
    m = re.search(r"wall time: setup ([0-9.]+) s, constraint check ([0-9.]+) s, statics ([0-9.]+) s(?: \(\d+ Newton iterations\))?, "
                  r"step analyses ([0-9.]+) s, output ([0-9.]+) s", p.stdout)
    its = re.search(r"^\s+1\s+1\s+(\d+)\s+(\d+)\s", p.stdout, re.M)
    rss = max(int(x) for x in re.findall(r"Maximum resident set size \(kbytes\): (\d+)", p.stdout)) / 1024
    gmres = [int(x) for x in re.findall(r"Linear solve (?:converged|did not converge) due to \S+ iterations (\d+)", p.stdout)]
    return {"n": n, "np": np_, "exit": p.returncode, "wall": wall,
            "statics": float(m.group(3)) if m else float("nan"),
            "phases": sum(float(x) for x in m.groups()) if m else float("nan"),
            "its": int(its.group(1)) if its else None, "incr": int(its.group(2)) if its else None,
            "gmres": sum(gmres), "solves": len(gmres), "rss": rss}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--converge", type=int, nargs="*", default=[32, 1024, 16384, 65536, 262144, 1048576])
    ap.add_argument("--iteration", type=int, nargs="*", default=[16384, 262144, 1048576])
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "sinew"))
    args = ap.parse_args()
    os.makedirs(WORK, exist_ok=True)
    conv, iters = [], []
    load0 = os.getloadavg()[0]
    for n in args.converge:
        for np_ in (1, 2):
            conv.append(run(args.bin, n, np_))
            print(conv[-1], flush=True)
    for n in args.iteration:
        for np_ in (1, 2):
            iters.append(run(args.bin, n, np_, ["-tangent_operator", "assembled", "-snes_max_it", "1", "-max_cuts", "0"]))
            print(iters[-1], flush=True)
    sec = ["A1 refined (`scripts/bench_ancf.py`): static cantilever under gravity, `loadsteps: 1`, `calcfreq: false`; "
           "4 n + 1 unknowns. Solver (default for ANCF statics, docs/ancf_cable2d.md): Newton, each linear system solved "
           "by GMRES on the element-wise tangent operator, right-preconditioned by the LU factorization of the "
           "assembled tangent (PETSc LU: 1 rank in nested-dissection order; 2 ranks on every rank in reverse Cuthill-McKee order), from 1024 elements per "
           "scene element with the cable coarse space (two-level) and the coarse predictor. Phases = setup + "
           "constraint check + statics + output of the run summary; wall = mpirun as a whole (process start "
           "included); memory = /usr/bin/time -v maximum resident set (largest process). Machine: 2 cores; load "
           f"average (1 min) {load0:.1f} before and {os.getloadavg()[0]:.1f} after the runs.", "",
           "Full solves:", "",
           "| elements | ranks | converged | Newton its | increments | GMRES its (solves) | statics [s] | phases [s] | "
           "wall [s] | peak RSS [MB] |", "|---|---|---|---|---|---|---|---|---|---|"]
    for r in conv:
        ok = r["exit"] == 0
        sec.append(f"| {r['n']} | {r['np']} | {'yes' if ok else 'no (exit %d)' % r['exit']} | {r['its'] if ok else '-'} | "
                   f"{r['incr'] if ok else '-'} | {r['gmres']} ({r['solves']}) | {r['statics']:.3f} | {r['phases']:.3f} | "
                   f"{r['wall']:.2f} | {r['rss']:.0f} |")
    sec += ["", "One plain Newton iteration (`-tangent_operator assembled -snes_max_it 1 -max_cuts 0`: residual, "
            "tangent, LU factorization and solve, residual; the run then stops unconverged on purpose, so only its "
            "cost is reported: the machinery's growth with n):", "",
            "| elements | unknowns | ranks | KSP its | one iteration [s] | wall [s] | peak RSS [MB] |",
            "|---|---|---|---|---|---|---|"]
    for r in iters:
        sec.append(f"| {r['n']} | {4 * r['n'] + 1} | {r['np']} | {r['gmres']} | {r['statics']:.3f} | {r['wall']:.2f} | "
                   f"{r['rss']:.0f} |")
    doc_tables.write_block("performance.md", "bench_ancf", "\n".join(sec))


if __name__ == "__main__":
    main()
