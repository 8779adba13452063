#!/usr/bin/python3
"""ANCF cable benchmark: A1 (cantilever under gravity, L = 2, EA = 1e6, EI = 833.33) refined to
n elements, static, 1 load step, 1 and 2 ranks; wall time and peak memory (/usr/bin/time -v, the
largest resident set of the ranks). Appends/replaces the section "ANCF cable" of docs/performance.md.
usage: scripts/bench_ancf.py [n ...]   (default 32 1024 16384 1048576)"""
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "cases"))
from ancf_scenes import cantilever, text  # noqa: E402

BIN = os.environ.get("SINEW_BIN", os.path.join(ROOT, "build-ancf", "sinew"))
WORK = "/tmp/sinew_bench_ancf"
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
os.makedirs(WORK, exist_ok=True)
sizes = [int(a) for a in sys.argv[1:]] or [32, 1024, 16384, 1048576]
rows = []
for n in sizes:
    scene = os.path.join(WORK, f"a1_{n}.yaml")
    with open(scene, "w") as f:
        f.write(text(cantilever(n, EA=1e6, EI=833.3333333333333, gravity=[0, -9.81])))
    for np_ in (1, 2):
        cmd = ["/usr/bin/time", "-v", "mpirun", "-n", str(np_), BIN, scene, "-o", os.path.join(WORK, f"a1_{n}_{np_}.h5")]
        t0 = time.time()
        p = subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        wall = time.time() - t0
        m = re.search(r"statics ([0-9.]+) s", p.stdout)
        rss = max(int(x) for x in re.findall(r"Maximum resident set size \(kbytes\): (\d+)", p.stdout))
        rows.append((n, np_, wall, float(m.group(1)) if m else float("nan"), rss / 1024, p.returncode))
        print(rows[-1], flush=True)
sec = ["## ANCF cable", "",
       "A1 refined (`scripts/bench_ancf.py`): static, 1 load step, Newton + MUMPS, `calcfreq: false`. "
       "Wall = whole mpirun; statics = the solver phase reported by the run; memory = /usr/bin/time -v "
       "maximum resident set (largest process).", "",
       "| elements | ranks | wall [s] | statics [s] | peak RSS [MB] | exit |", "|---|---|---|---|---|---|"]
sec += [f"| {n} | {r} | {w:.2f} | {s:.3f} | {m:.0f} | {c} |" for n, r, w, s, m, c in rows]
path = os.path.join(ROOT, "docs", "performance.md")
old = open(path).read() if os.path.exists(path) else "# Performance\n"
old = re.sub(r"## ANCF cable\n.*?(?=\n## |\Z)", "", old, flags=re.S).rstrip() + "\n\n"
open(path, "w").write(old + "\n".join(sec) + "\n")
print("wrote", path)
