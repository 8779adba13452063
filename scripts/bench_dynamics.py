#!/usr/bin/python3
"""Dynamics cost against Exudyn (issue 12 item 2; not a ctest). Model A3 of
../shared/references/README.md (Exudyn's ANCFCable2DBendingTest: L = 2, EA = 2.07e9, EI = 1.725e6,
rhoA = 78, tip step load 3 EI / L^2 at t = 0, clamp [1,1,0,1], generalized-alpha rho = 0.6 with
initial accelerations, h = 1e-4, 1000 steps to t = 0.1) split into n elements.

Side by side: with --exudyn DIR (the main/ directory of an Exudyn source tree built with
`python3 setup.py --noglfw --nofast --parallel build_ext --inplace`) every model runs alternately
in Sinew and in Exudyn, --repeat times, so both see the same machine load; the tables give the
median of the repeats. Exudyn runs its own A3 settings (full Newton) and its modified Newton, with
its dense solver up to 8 elements and EigenSparse above; the faster of the two is the comparison.
Without --exudyn only Sinew runs, and the Exudyn columns are the figures of the last side-by-side
table in docs/performance.md (marked "ref.": not measured in this run).

Measured per run: integration time (Sinew: the summary's "dynamics" phase; Exudyn: the time of
mbs.SolveDynamic), whole process (wall time of the command: Sinew started without mpirun as a
singleton, or under mpirun -n 2; Exudyn: python3 with the import and the model set-up) and its
peak resident memory (wait4). Output: Sinew writes only the first and the last step (output_every =
steps), Exudyn no solution file. The growth table runs Sinew alone on 2 ranks with 20 steps of
h = 1e-5 for n up to --max-elements (default 65536).

usage: scripts/bench_dynamics.py [--exudyn DIR] [--repeat 3] [--doc] [--quick] [--max-elements N]"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import time

import doc_tables

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
sys.path.insert(0, os.path.join(SOURCE, "tests", "cases"))
from ancf_scenes import cantilever, text  # noqa: E402

BUILD = os.path.join(SOURCE, "build")
WORK = os.path.join(BUILD, "bench", "dynamics")
F = 1.29375e6  # 3 EI / L^2
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_pml="ob1", OMPI_MCA_btl="self,vader",
           OMPI_MCA_btl_vader_single_copy_mechanism="none")

EXUDYN_SCRIPT = r'''
import sys, time, json
t0 = time.perf_counter()
import exudyn as exu
from exudyn.itemInterface import *
n, steps, h, modified, sparse = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), sys.argv[4] == "1", sys.argv[5] == "1"
model = sys.argv[6]
SC = exu.SystemContainer(); mbs = SC.AddSystem()
L, EA, EI, rhoA = (2.0, 2.07e9, 1.725e6, 78.0) if model == "A3" else (2.0, 1e6, 833.3333333333333, 78.0)
f = 3 * EI / L**2 if model == "A3" else 0.0
nc0 = mbs.AddNode(Point2DS1(referenceCoordinates=[0, 0, 1, 0]))
le = L / n
for i in range(n):
    last = mbs.AddNode(Point2DS1(referenceCoordinates=[le * (i + 1), 0, 1, 0]))
    o = mbs.AddObject(Cable2D(physicsLength=le, physicsMassPerLength=rhoA, physicsBendingStiffness=EI,
                              physicsAxialStiffness=EA, nodeNumbers=[int(nc0) + i, int(nc0) + i + 1]))
    if model == "A1g":
        mbs.AddLoad(Gravity(markerNumber=mbs.AddMarker(MarkerBodyMass(bodyNumber=o)), loadVector=[0, -9.81, 0]))
if model == "A3":
    mbs.AddLoad(Force(markerNumber=mbs.AddMarker(MarkerNodePosition(nodeNumber=last)), loadVector=[0, -f, 0]))
nG = mbs.AddNode(NodePointGround(referenceCoordinates=[0, 0, 0]))
mG = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=nG, coordinate=0))
for c in (0, 1, 3):
    mbs.AddObject(CoordinateConstraint(markerNumbers=[mG, mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=nc0, coordinate=c))]))
mbs.Assemble()
s = exu.SimulationSettings()
s.solutionSettings.writeSolutionToFile = False
s.timeIntegration.numberOfSteps = steps
s.timeIntegration.endTime = steps * h
s.timeIntegration.verboseMode = 0
s.timeIntegration.newton.useModifiedNewton = modified
s.timeIntegration.generalizedAlpha.spectralRadius = 0.6
s.timeIntegration.generalizedAlpha.computeInitialAccelerations = True
if sparse:
    s.linearSolverType = exu.LinearSolverType.EigenSparse
t1 = time.perf_counter()
mbs.SolveDynamic(s)
t2 = time.perf_counter()
q = mbs.systemData.GetODE2Coordinates()
print(json.dumps({"integration": t2 - t1, "setup": t1 - t0, "tip": [q[-4], q[-3]]}))
'''


def run_timed(cmd, env=ENV):
    """(stdout, wall time, peak RSS in MiB of the command and its children)"""
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    out = p.stdout.read()
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {p.returncode}\n{out[-3000:]}")
    return out, wall, ru.ru_maxrss / 1024.0


def sinew(n, steps, h, ranks, model="A3"):
    os.makedirs(WORK, exist_ok=True)
    dyn = {"tend": steps * h, "dt": h, "spectral_radius": 0.6, "output_every": steps}
    if model == "A3":
        scene = cantilever(n, force=F, dynamics=dyn)
    else:  # A1 (EA = 1e6, EI = 833.33) swinging down under gravity from the horizontal
        scene = cantilever(n, EA=1e6, EI=833.3333333333333, gravity=[0, -9.81], dynamics=dyn)
    name = f"{model.lower()}_{n}_{steps}_{h:g}_{ranks}"
    path = os.path.join(WORK, name + ".yaml")
    with open(path, "w") as f:
        f.write(text(scene))
    h5 = os.path.join(WORK, name + ".h5")
    binary = os.path.join(BUILD, "sinew")
    cmd = [binary, path, "-o", h5] if ranks == 0 else ["mpirun", "-n", str(ranks), binary, path, "-o", h5]
    out, wall, rss = run_timed(cmd)
    m = re.search(r"dynamics ([0-9.]+) s \((\d+) Newton iterations\)", out)
    j = re.search(r"(\d+) Newton iterations on (\d+) Jacobians", out)
    return {"integration": float(m.group(1)), "process": wall, "rss": rss,
            "its": int(j.group(1)), "jacobians": int(j.group(2))}


def exudyn(exudyn_dir, n, steps, h, modified, model="A3"):
    os.makedirs(WORK, exist_ok=True)
    script = os.path.join(WORK, "exudyn_a3.py")
    with open(script, "w") as f:
        f.write(EXUDYN_SCRIPT)
    env = dict(ENV, PYTHONPATH=os.path.join(exudyn_dir, "pythonDev") + os.pathsep + exudyn_dir)
    try:
        out, wall, rss = run_timed(["/usr/bin/python3", script, str(n), str(steps), str(h), "1" if modified else "0",
                                    "1" if n > 8 else "0", model], env=env)
    except RuntimeError as err:  # Exudyn's solver gave up ("DYNAMIC SOLVER FAILED")
        print(f"  exudyn {n} elements, {'modified' if modified else 'full'} Newton failed: {str(err).splitlines()[0]}")
        return {"integration": float("nan"), "process": float("nan"), "rss": float("nan"), "failed": True}
    r = json.loads(out.strip().splitlines()[-1])
    r.update(process=wall, rss=rss)
    return r


def med(rows, key):
    return statistics.median(r[key] for r in rows)


def reference_exudyn():
    """Exudyn's figures of the last side-by-side table in docs/performance.md: {n: (integration, process)}."""
    path = os.path.join(SOURCE, "docs", "performance.md")
    ref = {}
    if os.path.exists(path):
        for m in re.finditer(r"^\| (\d+) \| (\d+) \| [^|]+ \| [^|]+ \| ([0-9.]+) \| ([0-9.]+) \|", open(path).read(), re.M):
            ref[int(m.group(1))] = (float(m.group(3)), float(m.group(4)))
    return ref


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exudyn", help="main/ directory of an Exudyn source tree built in place")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--doc", action="store_true")
    ap.add_argument("--quick", action="store_true", help="1 and 8 elements, 1 repeat, growth to 4096")
    ap.add_argument("--max-elements", type=int, default=65536)
    a = ap.parse_args()
    sizes = [1, 8] if a.quick else [1, 8, 64, 512]
    repeat = 1 if a.quick else a.repeat
    steps, h = 1000, 1e-4
    load0 = os.getloadavg()[0]
    rows = {n: {"sinew": [], "exu_full": [], "exu_mod": []} for n in sizes}
    for rep in range(repeat):
        for n in sizes:
            rows[n]["sinew"].append(sinew(n, steps, h, 0))
            if a.exudyn:
                rows[n]["exu_full"].append(exudyn(a.exudyn, n, steps, h, False))
                rows[n]["exu_mod"].append(exudyn(a.exudyn, n, steps, h, True))
            print(f"  repeat {rep + 1}/{repeat}, {n} elements: sinew {rows[n]['sinew'][-1]['integration']:.4f} s"
                  + (f", exudyn {rows[n]['exu_full'][-1]['integration']:.4f} / {rows[n]['exu_mod'][-1]['integration']:.4f} s"
                     if a.exudyn else ""), flush=True)
    ref = reference_exudyn()
    lines = [f"A3 (h = 1e-4, {steps} steps), 1 process, median of {repeat} interleaved repeats"
             f" (load average {load0:.1f} at the start, {os.getloadavg()[0]:.1f} at the end)."
             " Integration: per step in us and in total; process: the whole command.", "",
             "| elements | unknowns | Sinew its / Jacobians | Sinew integration [s] | Exudyn integration [s] | Exudyn process [s] |"
             " Sinew process [s] | per step Sinew / Exudyn [us] | integration ratio | process ratio | Exudyn Newton |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for n in sizes:
        s = rows[n]["sinew"]
        si, sp = med(s, "integration"), med(s, "process")
        if a.exudyn:
            full, mod = rows[n]["exu_full"], rows[n]["exu_mod"]
            best = min(("full", full), ("modified", mod), key=lambda kv: med(kv[1], "integration"))
            ei, ep, which = med(best[1], "integration"), med(best[1], "process"), best[0]
        elif n in ref:
            ei, ep, which = ref[n][0], ref[n][1], "ref."
        else:
            ei = ep = float("nan"); which = "-"
        lines.append(f"| {n} | {4 * n + 4 - 3} | {s[0]['its']} / {s[0]['jacobians']} | {si:.4f} | {ei:.4f} | {ep:.3f} | {sp:.3f} |"
                     f" {1e6 * si / steps:.1f} / {1e6 * ei / steps:.1f} | {si / ei:.2f} | {sp / ep:.2f} | {which} |")
    table = "\n".join(lines)
    print(table)

    # growth in elements: Sinew alone, 2 ranks, 20 steps of h = 1e-5
    gsizes = [n for n in ([512, 4096] if a.quick else [1024, 4096, 16384, 65536]) if n <= a.max_elements]
    g = ["", f"Growth (Sinew, 2 ranks, A3 load, 20 steps of h = 1e-5; load average {os.getloadavg()[0]:.1f}):", "",
         "| elements | unknowns | integration [s] | per step and element [us] | Newton its / Jacobians | process [s] | peak memory [MiB] | memory per element [KiB] |",
         "|---|---|---|---|---|---|---|---|"]
    for n in gsizes:
        r = sinew(n, 20, 1e-5, 2)
        g.append(f"| {n} | {4 * n + 1} | {r['integration']:.3f} | {1e6 * r['integration'] / (20 * n):.2f} |"
                 f" {r['its']} / {r['jacobians']} | {r['process']:.2f} | {r['rss']:.0f} | {1024 * r['rss'] / n:.1f} |")
        print(g[-1], flush=True)
    g.append("")
    g.append("Peak memory: the largest process of the mpirun tree (wait4), so one rank's share plus what it holds alone.")
    text_ = table + "\n" + "\n".join(g)
    if a.doc:
        doc_tables.write_block("performance.md", "bench_dynamics", text_)


if __name__ == "__main__":
    main()
