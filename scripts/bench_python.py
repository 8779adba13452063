#!/usr/bin/python3
"""Designs from Python in one process against one sinew process per design (issue 25, not a ctest):
runs/crosshinge.yaml (10 load steps, frequencies, buckling, compliance; 66 unknowns, 1 rank)
N times through `Scene.run()` (in-process, results in memory) and P times as the sinew executable
(`build/sinew runs/crosshinge.yaml -o file`, one process each, started without mpirun: the cheapest
process run) and P times through `mpirun -n 1` (as scripts/run starts it, and as a study script calling
mpirun once per design pays it), the three alternated in P batches (N/P in-process designs, then one
process run of each kind) so that the machine's load weighs on all alike. Every result is checked against the first in-process run: every dataset of
the result file (the restart checkpoint aside) and of memory, same names, shapes and values bit for
bit (NaN where NaN), and the root attributes converged and ndof.
Reported: wall time per design (median, 10 % and 90 % quantiles), CPU time per design (this
process's for in-process runs; the child's user + system time for process runs), the process runs
also with `sinew.load` of their file (what a script needs to get `out`), the ratio of the medians,
the first in-process run apart (it starts PETSc and SLEPc), the load average (1 min) before, during
and after, and where the time of an in-process design goes: the medians of its summary's phases
over the last in-process runs (`sinew._core.run` directly, the same run without the `out` object).
With --doc the table goes to docs/performance.md (block bench_python).

The issue asks for 1000 in-process designs against 1000 process runs: --n 1000 --processes 1000 (the
default; 822 s on 2 cores on 2026-11-27), one in-process design and one process run of each kind per
batch. Also reported: the median of the per-batch ratios (a process run over the in-process designs of
its own batch, both taken in the same phase of the host).

usage: scripts/bench_python.py [--n 1000] [--processes 1000] [--doc]"""
import argparse
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import doc_tables

SOURCE = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
sys.path.insert(0, os.path.join(SOURCE, "python"))
import sinew  # noqa: E402
from sinew.results import from_memory  # noqa: E402

PHASES = ("setup", "constraint check", "statics", "step analyses", "output")


def load1():
    return os.getloadavg()[0]


def same(a, b):
    """'' when two results (sinew.Results) are equal bit for bit, else what differs."""
    if set(a.data) != set(b.data):
        return f"datasets {sorted(set(a.data) ^ set(b.data))} in one only"
    for name, x in a.data.items():
        y = b.data[name]
        if x.shape != y.shape or x.dtype.kind != y.dtype.kind:
            return f"/{name}: {x.shape} {x.dtype} against {y.shape} {y.dtype}"
        if not np.array_equal(x, y, equal_nan=x.dtype.kind == "f"):
            return f"/{name} differs"
    for key in ("converged", "ndof"):
        if a.attrs.get(key) != b.attrs.get(key):
            return f"attribute {key}: {a.attrs.get(key)} against {b.attrs.get(key)}"
    return ""


def quantiles(v):
    q = np.quantile(v, [0.1, 0.5, 0.9])
    return q[1], q[0], q[2]


def ms(x):
    return f"{1e3 * x:.1f}"


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=1000, help="in-process designs")
    ap.add_argument("--processes", type=int, default=1000, help="process runs of each kind (and batches)")
    ap.add_argument("--scene", default=os.path.join(SOURCE, "runs", "crosshinge.yaml"))
    ap.add_argument("--binary", default=os.path.join(SOURCE, "build", "sinew"))
    ap.add_argument("--phase-runs", type=int, default=50, help="in-process runs for the phase medians")
    ap.add_argument("--doc", action="store_true", help="write the table into docs/performance.md")
    args = ap.parse_args()
    if sinew.core() is None:
        sys.exit("sinew._core is not built: cmake --build build")
    started = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    uptime_before = subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    loads = [load1()]
    sim = sinew.Scene.from_yaml(args.scene)
    t = time.perf_counter()
    ref = sim.run()
    first = time.perf_counter() - t
    work = tempfile.mkdtemp(prefix="bench_python_")
    h5 = os.path.join(work, "crosshinge.h5")
    env = dict(os.environ, OMPI_MCA_pml="ob1", OMPI_MCA_btl="self,vader")
    inproc, inproc_cpu, proc, proc_cpu, proc_load, problems = [], [], [], [], [], []
    mpi, mpi_cpu = [], []
    mpirun = shutil.which("mpirun")
    if mpirun is None:
        sys.exit("mpirun not found (openmpi-bin)")
    mpi_env = dict(env, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_rmaps_base_oversubscribe="1")
    batches = max(args.processes, 1)
    per_batch = [args.n // batches + (1 if b < args.n % batches else 0) for b in range(batches)]
    t_all = time.perf_counter()
    batch_inproc = []
    for b in range(batches):
        batch_inproc.append([])
        for _ in range(per_batch[b]):
            c, t = time.process_time(), time.perf_counter()
            out = sim.run()
            inproc.append(time.perf_counter() - t)
            inproc_cpu.append(time.process_time() - c)
            batch_inproc[b].append(inproc[-1])
            if (d := same(out, ref)):
                problems.append(f"in-process run {len(inproc)}: {d}")
        if b < args.processes:
            c, t = child_cpu(), time.perf_counter()
            p = subprocess.run([args.binary, args.scene, "-o", h5], cwd=os.path.dirname(args.scene), env=env,
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            proc.append(time.perf_counter() - t)
            proc_cpu.append(child_cpu() - c)
            if p.returncode != 0:
                sys.exit(f"sinew ended with exit {p.returncode}: {p.stderr}")
            t = time.perf_counter()
            out = sinew.load(h5)
            proc_load.append(proc[-1] + time.perf_counter() - t)
            if (d := same(out, ref)):
                problems.append(f"process run {len(proc)}: {d}")
            c, t = child_cpu(), time.perf_counter()
            p = subprocess.run([mpirun, "-n", "1", args.binary, args.scene, "-o", h5], cwd=os.path.dirname(args.scene),
                               env=mpi_env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            mpi.append(time.perf_counter() - t)
            mpi_cpu.append(child_cpu() - c)
            if p.returncode != 0:
                sys.exit(f"mpirun -n 1 sinew ended with exit {p.returncode}: {p.stderr}")
            if (d := same(sinew.load(h5), ref)):
                problems.append(f"mpirun run {len(mpi)}: {d}")
        loads.append(load1())
    elapsed = time.perf_counter() - t_all
    # where an in-process design's time goes: the phases of its summary (the run's own clock)
    phases = {k: [] for k in PHASES + ("core", "out")}
    for _ in range(args.phase_runs):
        t = time.perf_counter()
        run = sinew.core().run(sim.data, flags=[], base_dir=sim.base_dir)
        t1 = time.perf_counter()
        from_memory(run)
        phases["out"].append(time.perf_counter() - t1)
        phases["core"].append(t1 - t)
        line = re.search(r"wall time: (.*)", run["output"]).group(1)
        for k in PHASES:
            phases[k].append(float(re.search(k + r" ([0-9.]+) s", line).group(1)))
    uptime_after = subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    loads.append(load1())
    shutil.rmtree(work)

    mi, mp, mpl, mm = quantiles(inproc), quantiles(proc), quantiles(proc_load), quantiles(mpi)
    ci, cp, cm = statistics.median(inproc_cpu), statistics.median(proc_cpu), statistics.median(mpi_cpu)
    identical = "identical bit for bit" if not problems else f"{len(problems)} differ: {problems[0]}"
    ph = {k: statistics.median(v) for k, v in phases.items()}
    paired = [statistics.median(proc[b] / statistics.median(batch_inproc[b]) for b in range(len(proc)) if batch_inproc[b]),
              statistics.median(mpi[b] / statistics.median(batch_inproc[b]) for b in range(len(mpi)) if batch_inproc[b])]
    rest = ph["core"] - sum(ph[k] for k in PHASES)
    text = f"""Generated by `scripts/bench_python.py --n {args.n} --processes {args.processes}` on {started} ({elapsed:.0f} s; 2 cores
shared with other jobs: load average (1 min) {loads[0]:.1f} at the start, {statistics.median(loads):.1f} median over the
batches ({min(loads):.1f} .. {max(loads):.1f}), {loads[-1]:.1f} at the end; `uptime` before: `{uptime_before}`, after:
`{uptime_after}`). Scene runs/crosshinge.yaml (66 unknowns, 10 load steps, frequencies, buckling,
compliance), 1 rank; the three ways alternated in {batches} batches. Results of all {len(inproc)} in-process and
{len(proc) + len(mpi)} process runs against the first in-process run: {identical}.

| way | designs | wall per design, median [ms] | 10 % .. 90 % [ms] | CPU per design, median [ms] |
|---|---|---|---|---|
| in-process: `Scene.run()`, results in memory | {len(inproc)} | {ms(mi[0])} | {ms(mi[1])} .. {ms(mi[2])} | {ms(ci)} |
| process: `build/sinew crosshinge.yaml -o file` | {len(proc)} | {ms(mp[0])} | {ms(mp[1])} .. {ms(mp[2])} | {ms(cp)} |
| process + `sinew.load` of its file | {len(proc)} | {ms(mpl[0])} | {ms(mpl[1])} .. {ms(mpl[2])} | |
| process by `mpirun -n 1 build/sinew crosshinge.yaml -o file` | {len(mpi)} | {ms(mm[0])} | {ms(mm[1])} .. {ms(mm[2])} | {ms(cm)} |

Per design, process / in-process: **{mp[0] / mi[0]:.1f}x** in wall time against the process started alone
(medians; {mpl[0] / mi[0]:.1f}x with `sinew.load`), {cp / ci:.1f}x in CPU time; **{mm[0] / mi[0]:.1f}x** in wall
time and {cm / ci:.1f}x in CPU time against the process started by `mpirun -n 1`. Medians of the per-batch ratios
(each process run over the in-process designs of its batch): {paired[0]:.1f}x against the process started alone,
{paired[1]:.1f}x against `mpirun -n 1`.
The first in-process run (PETSc and SLEPc start) took {ms(first)} ms.
An in-process design, medians of {args.phase_runs} runs after the loop (`sinew._core.run`, its summary's
phases): setup {ms(ph['setup'])}, constraint check {ms(ph['constraint check'])}, statics {ms(ph['statics'])}, step analyses
{ms(ph['step analyses'])}, output {ms(ph['output'])}, the rest of the call (scene dict to YAML tree, settings, summary, numpy
arrays) {ms(rest)}, the `out` object {ms(ph['out'])} ms (the summary prints milliseconds)."""
    print(text)
    if args.doc:
        doc_tables.write_block("performance.md", "bench_python", text)


if __name__ == "__main__":
    main()
