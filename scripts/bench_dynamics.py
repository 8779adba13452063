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
steps), Exudyn no solution file. A second model, A1g, is the A1 cable (EA = 1e6, EI = 833.33)
swinging down under gravity from the horizontal (h = 1e-3, 100 steps; Exudyn stopped after 60 s).
The growth table runs Sinew alone on 2 ranks with 20 steps of A1g for n up to --max-elements
(default 131072), in --growth-repeat rounds over all sizes (default 3; the median of each size by
integration time is shown), each run stopped after --growth-timeout seconds; it has its own generated block
(bench_dynamics_growth), and --growth-only reruns just that table and rewrites just that block.

usage: scripts/bench_dynamics.py [--exudyn DIR] [--repeat 3] [--doc] [--quick] [--max-elements N]
                                 [--growth-only] [--growth-repeat 3] [--growth-timeout 900]"""
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


def run_timed(cmd, env=ENV, timeout=None):
    """(stdout, wall time, peak RSS in MiB, CPU time (user + system) of the command and its waited-for
    children, i.e. the ranks under mpirun); RuntimeError on a
    non-zero exit or when the command runs longer than timeout seconds (then it is killed)."""
    import tempfile
    with tempfile.TemporaryFile(mode="w+") as log:
        t0 = time.perf_counter()
        p = subprocess.Popen(cmd, env=env, stdout=log, stderr=subprocess.STDOUT, text=True, start_new_session=True)
        while True:
            pid, status, ru = os.wait4(p.pid, os.WNOHANG)
            if pid == p.pid:
                break
            if timeout is not None and time.perf_counter() - t0 > timeout:
                os.killpg(p.pid, 9)
                os.wait4(p.pid, 0)
                raise RuntimeError(f"{' '.join(cmd)}: did not finish in {timeout:g} s")
            time.sleep(0.002)
        wall = time.perf_counter() - t0
        log.seek(0)
        out = log.read()
    code = os.waitstatus_to_exitcode(status)
    if code != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {code}\n{out[-3000:]}")
    return out, wall, ru.ru_maxrss / 1024.0, ru.ru_utime + ru.ru_stime


def run_sinew_dynamics(work, name, scene_text, ranks, timeout=None):
    """Writes work/name.yaml, runs Sinew on it (ranks <= 1: one process started without mpirun, else
    mpirun -n ranks) and returns the summary's dynamics figures with the process measurements
    (run_timed) and the result file's path."""
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, name + ".yaml")
    with open(path, "w") as f:
        f.write(scene_text)
    h5 = os.path.join(work, name + ".h5")
    binary = os.path.join(BUILD, "sinew")
    cmd = [binary, path, "-o", h5] if ranks <= 1 else ["mpirun", "-n", str(ranks), binary, path, "-o", h5]
    out, wall, rss, cpu = run_timed(cmd, timeout=timeout)
    m = re.search(r"dynamics ([0-9.]+) s \((\d+) Newton iterations\)", out)
    j = re.search(r"(\d+) Newton iterations on (\d+) Jacobians( \((\d+) rebuilt)?", out)
    if not m or not j:
        raise RuntimeError(f"{name}: no dynamics line in the summary\n{out[-2000:]}")
    return {"integration": float(m.group(1)), "process": wall, "rss": rss, "cpu": cpu,
            "its": int(j.group(1)), "jacobians": int(j.group(2)), "rebuilt": int(j.group(4) or 0), "h5": h5}


def sinew(n, steps, h, ranks, model="A3", timeout=None):
    dyn = {"tend": steps * h, "dt": h, "spectral_radius": 0.6, "output_every": steps}
    if model == "A3":
        scene = cantilever(n, force=F, dynamics=dyn)
    else:  # A1 (EA = 1e6, EI = 833.33) swinging down under gravity from the horizontal
        scene = cantilever(n, EA=1e6, EI=833.3333333333333, gravity=[0, -9.81], dynamics=dyn)
    return run_sinew_dynamics(WORK, f"{model.lower()}_{n}_{steps}_{h:g}_{ranks}", text(scene), ranks, timeout)


def exudyn(exudyn_dir, n, steps, h, modified, model="A3", timeout=300):
    os.makedirs(WORK, exist_ok=True)
    script = os.path.join(WORK, "exudyn_a3.py")
    with open(script, "w") as f:
        f.write(EXUDYN_SCRIPT)
    env = dict(ENV, PYTHONPATH=os.path.join(exudyn_dir, "pythonDev") + os.pathsep + exudyn_dir)
    try:
        out, wall, rss, _ = run_timed(["/usr/bin/python3", script, str(n), str(steps), str(h), "1" if modified else "0",
                                    "1" if n > 8 else "0", model], env=env, timeout=timeout)
    except RuntimeError as err:  # Exudyn's solver gave up ("DYNAMIC SOLVER FAILED")
        why = "did not finish" if "did not finish" in str(err) else "failed"
        print(f"  exudyn {model} {n} elements, {'modified' if modified else 'full'} Newton {why}: {str(err).splitlines()[0]}")
        return {"integration": float("nan"), "process": float("nan"), "rss": float("nan"), "failed": why}
    r = json.loads(out.strip().splitlines()[-1])
    r.update(process=wall, rss=rss)
    return r


def med(rows, key):
    return statistics.median(r[key] for r in rows)


def reference_exudyn():
    """Exudyn's figures of the last side-by-side tables in docs/performance.md: {(model, n): (integration, process)}."""
    path = os.path.join(SOURCE, "docs", "performance.md")
    ref = {}
    if os.path.exists(path):
        for m in re.finditer(r"^\| (A3|A1g) \| (\d+) \| \d+ \| [^|]+ \| [^|]+ \| ([0-9.]+) \| [^|]+ \| ([0-9.]+) \|",
                             open(path).read(), re.M):
            ref[(m.group(1), int(m.group(2)))] = (float(m.group(3)), float(m.group(4)))
    return ref


def fmt(x, digits=4):
    return "-" if x != x else f"{x:.{digits}f}"


def side_by_side(a, model, sizes, steps, h, repeat, timeout):
    """Rows of the comparison table for one model (Sinew, then Exudyn full and modified Newton, interleaved)."""
    rows = {n: {"sinew": [], "full": [], "mod": []} for n in sizes}
    for rep in range(repeat):
        for n in sizes:
            rows[n]["sinew"].append(sinew(n, steps, h, 0, model))
            if a.exudyn:
                for kind, modified in (("full", False), ("mod", True)):
                    if rep > 0 and rows[n][kind][0].get("failed"):
                        continue  # failed or too slow once: not again
                    rows[n][kind].append(exudyn(a.exudyn, n, steps, h, modified, model, timeout))
            print(f"  {model} repeat {rep + 1}/{repeat}, {n} elements: sinew {rows[n]['sinew'][-1]['integration']:.4f} s", flush=True)
    ref = reference_exudyn()
    out = []
    for n in sizes:
        s = rows[n]["sinew"]
        si, sp = med(s, "integration"), med(s, "process")
        note = ""
        if a.exudyn:
            cands = [(k, rows[n][k]) for k in ("full", "mod") if rows[n][k] and not rows[n][k][0].get("failed")]
            if cands:
                k, best = min(cands, key=lambda kv: med(kv[1], "integration"))
                ei, ep, which = med(best, "integration"), med(best, "process"), "modified" if k == "mod" else "full"
            else:
                ei = ep = float("nan")
                which = " / ".join(f"{'modified' if k == 'mod' else 'full'}: {rows[n][k][0]['failed']}"
                                   + (f" in {timeout} s" if rows[n][k][0]["failed"] == "did not finish" else "")
                                   for k in ("full", "mod"))
        elif (model, n) in ref:
            (ei, ep), which = ref[(model, n)], "ref. (earlier run)"
        else:
            ei = ep = float("nan")
            which = "-"
        out.append(f"| {model} | {n} | {4 * n + 1} | {s[0]['its']} / {s[0]['jacobians']} | {fmt(si)} | {fmt(ei)} | {fmt(sp, 3)} |"
                   f" {fmt(ep, 3)} | {fmt(1e6 * si / steps, 1)} / {fmt(1e6 * ei / steps, 1)} | {fmt(si / ei, 2)} |"
                   f" {fmt(sp / ep, 2)} | {which}{note} |")
        print(out[-1], flush=True)
    return out


def growth(a):
    """The growth table (Sinew alone, 2 ranks, 20 steps of A1g) as lines of the bench_dynamics_growth block."""
    gsizes = [n for n in ([512, 4096] if a.quick else [1024, 4096, 16384, 32768, 65536, 131072]) if n <= a.max_elements]
    reps = 1 if a.quick else a.growth_repeat
    load0, t0 = os.getloadavg()[0], time.time()
    g = ["| elements | unknowns | integration [s] | per step and element [us] | Newton its / Jacobians (rebuilt) | process [s] |"
         " process CPU [s] | CPU per step and element [us] | peak memory [MiB] | memory per element [KiB] |",
         "|---|---|---|---|---|---|---|---|---|---|"]
    # rounds over all sizes (the machine's load drifts: each size sees the same spread of it), then
    # the median of each size's runs by integration time
    runs = {n: [] for n in gsizes}
    failed = {}
    for _ in range(reps):
        for n in gsizes:
            if n in failed:
                continue
            try:
                runs[n].append(sinew(n, 20, 1e-3, 2, "A1g", timeout=a.growth_timeout))
            except RuntimeError as err:
                failed[n] = str(err).splitlines()[0]
                print(f"  growth {n} elements: {failed[n]}", flush=True)
    for n in gsizes:
        if n in failed or not runs[n]:
            g.append(f"| {n} | {4 * n + 1} | - | - | - | - | - | - | - | - |")
            continue
        r = sorted(runs[n], key=lambda r: r["integration"])[len(runs[n]) // 2]
        g.append(f"| {n} | {4 * n + 1} | {r['integration']:.3f} | {1e6 * r['integration'] / (20 * n):.2f} |"
                 f" {r['its']} / {r['jacobians']} ({r['rebuilt']}) | {r['process']:.2f} | {r['cpu']:.2f} | {1e6 * r['cpu'] / (20 * n):.2f} |"
                 f" {r['rss']:.0f} | {1024 * r['rss'] / n:.1f} |")
        print(g[-1], flush=True)
    head = [f"Generated by `scripts/bench_dynamics.py{' --growth-only' if a.growth_only else ''}` on"
            f" {time.strftime('%Y-%m-%d')}: Sinew alone, 2 ranks (mpirun -n 2), A1g, 20 steps of h = 1e-3, the median of"
            f" {reps} runs per size (by integration time) from {reps} rounds over all sizes (each run stopped after"
            f" {a.growth_timeout:g} s); load average {load0:.1f} at the start and"
            f" {os.getloadavg()[0]:.1f} at the end on the 2 shared cores: times are indicative, compare the"
            " rows of one run only. Jacobians: fresh ones and those rebuilt from rotated element blocks"
            " (-dynamics_corotated_jacobian; in parentheses).", ""]
    tail = ["", "Peak memory: the largest process of the mpirun tree (wait4): one rank with its share of the model."
            " Process CPU: user + system time of the mpirun tree (both ranks, start-up and output included; MPI"
            " waits poll, so it also grows under load, less than the wall time).",
            f"Growth table: {time.time() - t0:.0f} s."]
    return head + g + tail


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exudyn", help="main/ directory of an Exudyn source tree built in place")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--doc", action="store_true")
    ap.add_argument("--quick", action="store_true", help="1 and 8 elements, 1 repeat, growth to 4096")
    ap.add_argument("--max-elements", type=int, default=131072)
    ap.add_argument("--growth-repeat", type=int, default=3, help="runs per size of the growth table (the median is shown)")
    ap.add_argument("--growth-only", action="store_true",
                    help="only the growth table; with --doc only its block (bench_dynamics_growth) is rewritten")
    ap.add_argument("--growth-timeout", type=float, default=900, help="seconds per growth run before it is stopped")
    a = ap.parse_args()
    if not a.growth_only:
        comparison(a)
    text_ = "\n".join(growth(a))
    print(text_)
    if a.doc:
        doc_tables.write_block("performance.md", "bench_dynamics_growth", text_)


def comparison(a):
    """The side-by-side tables (Sinew and Exudyn, one process), written to the bench_dynamics block."""
    repeat = 1 if a.quick else a.repeat
    load0 = os.getloadavg()[0]
    t0 = time.time()
    head = ["| model | elements | unknowns | Sinew its / Jacobians | Sinew integration [s] | Exudyn integration [s] |"
            " Sinew process [s] | Exudyn process [s] | per step Sinew / Exudyn [us] | integration ratio | process ratio |"
            " Exudyn Newton (the faster) |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    rows = side_by_side(a, "A3", [1, 8] if a.quick else [1, 8, 64, 512], 1000, 1e-4, repeat, 300)
    rows += side_by_side(a, "A1g", [64] if a.quick else [64, 512, 4096], 100, 1e-3, 1, 60)
    lines = [f"Generated by `scripts/bench_dynamics.py{' --exudyn DIR' if a.exudyn else ''}` on {time.strftime('%Y-%m-%d')}"
             f" (load average {load0:.1f} at the start, 2 cores). A3: h = 1e-4, 1000 steps, median of {repeat} interleaved"
             " repeats; A1g: the A1 cable (EA = 1e6, EI = 833.33) swinging down under gravity from the horizontal,"
             " h = 1e-3, 100 steps, one run (Exudyn stopped after 60 s). One process each; ratios are Sinew / Exudyn."
             + ("" if a.exudyn else " Exudyn columns: figures of an earlier side-by-side run (not measured now)."), ""] + head + rows
    lines += ["", f"Side-by-side tables: {time.time() - t0:.0f} s."]
    text_ = "\n".join(lines)
    print(text_)
    if a.doc:
        doc_tables.write_block("performance.md", "bench_dynamics", text_)


if __name__ == "__main__":
    main()
