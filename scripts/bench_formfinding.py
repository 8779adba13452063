#!/usr/bin/python3
"""Form-finding benchmark: four-point sail (meshes/sail.geo with a small lc, >= 1e5 triangles) plus
edge cables, 3 URS steps, on 1 and 2 ranks. Writes the generated block "bench_formfinding" of
docs/performance.md (section "Form finding"; the rest is kept, scripts/doc_tables.py). Usage: scripts/bench_formfinding.py [build dir] [lc]"""
import os
import re
import subprocess
import sys
import time

import doc_tables

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.join(ROOT, "build")
LC = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0 / 230
WORK = os.path.join(BUILD, "bench_ff")
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
os.makedirs(WORK, exist_ok=True)
geo = open(os.path.join(ROOT, "meshes", "sail.geo")).read()
geo = re.sub(r"lc = [^;]*;", f"lc = {LC!r};", geo)
open(os.path.join(WORK, "sail_big.geo"), "w").write(geo)
subprocess.run(["gmsh", "-2", "sail_big.geo", "-format", "msh4", "-o", "sail_big.msh"], cwd=WORK, check=True,
               stdout=subprocess.DEVNULL)
scene = open(os.path.join(ROOT, "runs", "sail.yaml")).read()
scene = scene.replace("../meshes/sail.msh", "sail_big.msh").replace("formfinding_step: 20", "formfinding_step: 3")
scene = scene.replace("formfinding_tolerance: 1e-5", "formfinding_tolerance: 0").replace("loadsteps: 5", "loadsteps: 1")
open(os.path.join(WORK, "sail_big.yaml"), "w").write(scene)
rows = []
for n in (1, 2):
    load0 = open("/proc/loadavg").read().split()[0]
    t0 = time.time()
    p = subprocess.run(["/usr/bin/time", "-v", "mpirun", "-n", str(n), os.path.join(BUILD, "sinew"), "sail_big.yaml",
                        "-o", f"sail_big_{n}.h5"], cwd=WORK, env=ENV, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    wall = time.time() - t0
    out = p.stdout
    m = re.search(r"form-finding time ([0-9.]+) s \(([0-9.]+) s per step", out)
    unk = re.search(r"(\d+) unknowns", out)
    ntri = re.search(r"(\d+) form-found elements", out)
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", out)
    if p.returncode != 0 or not m:
        print(out)
        sys.exit(f"run on {n} ranks failed")
    rows.append(dict(n=n, load=f"{load0} / {open('/proc/loadavg').read().split()[0]}",
                     total=float(m.group(1)), step=float(m.group(2)), wall=wall, unknowns=int(unk.group(1)),
                     elements=int(ntri.group(1)), rss=int(rss.group(1)) / 1024 if rss else float("nan")))
    print(rows[-1])
speed = rows[0]["step"] / rows[1]["step"]
sec = [f"`scripts/bench_formfinding.py` (lc = {LC:.5g}): four-point sail `meshes/sail.geo` meshed with gmsh, "
       f"{rows[0]['elements']} form-found elements (membrane triangles + edge cables), {rows[0]['unknowns']} "
       "unknowns, 3 URS steps (homotopy 0, one Newton iteration each: assemble, linear solve, update references), "
       "then one elastic load step. Time per step excludes result output. Memory: the largest resident set "
       "of the processes started by mpirun as reported by /usr/bin/time (mpirun's children; per process).", "",
       "| ranks | time per form-finding step (s) | form finding total (s) | run wall time (s) | max RSS (MB) | "
       "load average before / after the run (1 min) |",
       "|---|---|---|---|---|---|"]
for r in rows:
    sec.append(f"| {r['n']} | {r['step']:.3f} | {r['total']:.3f} | {r['wall']:.2f} | {r['rss']:.0f} | {r['load']} |")
sec += ["", f"2-rank speedup of the form-finding step: {speed:.2f}x (target 1.6x; the machine has 2 cores shared "
        "with other jobs: a load average above 2 means the ranks did not have a core each, so the speedup is a lower "
        "bound)."]
doc_tables.write_block("performance.md", "bench_formfinding", "\n".join(sec))
print("\n".join(sec))
