#!/usr/bin/python3
"""ANCF cable benchmark: A1 (cantilever under gravity, L = 2, EA = 1e6, EI = 833.33) refined to n
elements, static, 1 load step. Two measurements, written to the section "ANCF cable" of
docs/performance.md (replaced; the rest of the file is kept):
  --converge n ...  full solve on 1 rank: converged (exit 0)?, Newton iterations, statics time
                    (solver phase from the run summary), peak memory (/usr/bin/time -v, largest
                    resident set of the ranks);
  --iteration n ... the cost of one Newton iteration (residual, tangent assembly, MUMPS LU and
                    solve, residual of the update: -snes_max_it 1 -max_cuts 0) on 1 and 2 ranks.
                    These runs stop after that iteration on purpose: time and memory only, no result.
usage: scripts/bench_ancf.py [--converge 1024 4096 ...] [--iteration 16384 1048576 ...] [--bin build/sinew]"""
import argparse
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "cases"))
from ancf_scenes import cantilever, text  # noqa: E402

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
WORK = "/tmp/sinew_bench_ancf"


def run(binary, n, np_, extra=()):
    scene = os.path.join(WORK, f"a1_{n}.yaml")
    if not os.path.exists(scene):
        with open(scene, "w") as f:
            f.write(text(cantilever(n, EA=1e6, EI=833.3333333333333, gravity=[0, -9.81])))
    cmd = ["/usr/bin/time", "-v", "mpirun", "-n", str(np_), binary, scene, "-o", os.path.join(WORK, f"a1_{n}_{np_}.h5")]
    t0 = time.time()
    p = subprocess.run(cmd + list(extra), env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.time() - t0
    m = re.search(r"statics ([0-9.]+) s", p.stdout)
    its = re.search(r"^\s+1\s+1\s+(\d+)\s+(\d+)\s", p.stdout, re.M)
    rss = max(int(x) for x in re.findall(r"Maximum resident set size \(kbytes\): (\d+)", p.stdout)) / 1024
    return {"n": n, "np": np_, "exit": p.returncode, "wall": wall, "statics": float(m.group(1)) if m else float("nan"),
            "its": int(its.group(1)) if its else None, "rss": rss}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--converge", type=int, nargs="*", default=[1024, 2048, 4096, 8192, 16384])
    ap.add_argument("--iteration", type=int, nargs="*", default=[16384, 65536, 262144, 1048576])
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "sinew"))
    args = ap.parse_args()
    os.makedirs(WORK, exist_ok=True)
    conv, iters = [], []
    load0 = os.getloadavg()[0]
    for n in args.converge:
        conv.append(run(args.bin, n, 1))
        print(conv[-1], flush=True)
    for n in args.iteration:
        for np_ in (1, 2):
            iters.append(run(args.bin, n, np_, ["-snes_max_it", "1", "-max_cuts", "0"]))
            print(iters[-1], flush=True)
    sec = ["## ANCF cable", "",
           "A1 refined (`scripts/bench_ancf.py`): static cantilever under gravity, 1 load step, Newton + MUMPS LU, "
           "`calcfreq: false`; 4 n unknowns. Statics = the solver phase of the run summary; memory = /usr/bin/time -v "
           "maximum resident set (largest process). Machine: 2 cores shared with other jobs; load average (1 min) "
           f"{load0:.1f} before and {os.getloadavg()[0]:.1f} after the runs.", "",
           "Full solve, 1 rank:", "",
           "| elements | converged | Newton iterations | statics [s] | wall [s] | peak RSS [MB] |", "|---|---|---|---|---|---|"]
    for r in conv:
        ok = r["exit"] == 0
        sec.append(f"| {r['n']} | {'yes' if ok else 'no (exit %d)' % r['exit']} | {r['its'] if ok else '-'} | "
                   f"{r['statics']:.3f} | {r['wall']:.2f} | {r['rss']:.0f} |")
    sec += ["", "One Newton iteration (`-snes_max_it 1 -max_cuts 0`: residual, tangent, LU factorization, solve, "
            "residual; the run then stops unconverged on purpose, so only its cost is reported):", "",
            "| elements | unknowns | ranks | one iteration [s] | wall [s] | peak RSS [MB] |", "|---|---|---|---|---|---|"]
    for r in iters:
        sec.append(f"| {r['n']} | {4 * r['n'] + 2} | {r['np']} | {r['statics']:.3f} | {r['wall']:.2f} | {r['rss']:.0f} |")
    path = os.path.join(ROOT, "docs", "performance.md")
    old = open(path).read() if os.path.exists(path) else "# Performance\n"
    m = re.search(r"## ANCF cable\n.*?(?=\n## |\Z)", old, flags=re.S)
    new = "\n".join(sec) + "\n"
    old = old[:m.start()] + new + old[m.end():] if m else old.rstrip() + "\n\n" + new
    open(path, "w").write(old)
    print("wrote", path)


if __name__ == "__main__":
    main()
