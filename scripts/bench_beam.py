#!/usr/bin/python3
"""Beam performance benchmarks -> the generated block "bench_beam" of docs/performance.md (section
"Beams"; the rest of the file is kept, scripts/doc_tables.py).
(a) element residual + tangent throughput on one core (tests/unit/bench_beam_kernel.cpp, g++ -O2);
(b) a lattice of >= 1e6 unknowns (scripts/gen_lattice.py 56), one nonlinear load step on 2 ranks:
    wall time, peak RSS per rank (/usr/bin/time -v around each rank), linear solver;
(c) assembly time per element and assembly from 1e4 to 1e6 unknowns: (SinewJacobian - SinewCOOSetup)
    / (Jacobians x elements), -log_view; the one-time COO pattern set-up of each matrix (SinewCOOSetup,
    once for the constraint check's matrix and once for the solver's) is reported on its own;
(d) 2-rank speedup of assembly (SinewJacobian - SinewCOOSetup + SinewResidual, 1 vs 2 ranks, 1e5
    unknowns, 4 load steps so that steady-state assemblies dominate; the gross figure is given too).
Run it under `flock /tmp/sinew_bench.lock` (one benchmark at a time on the machine).
Usage: scripts/bench_beam.py [--build DIR] [--solver "-ksp_type cg -pc_type gamg"] [--skip-big]"""
import argparse
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_lattice import lattice  # noqa: E402
import doc_tables  # noqa: E402

SRC = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")


def loadavg():
    return " ".join(open("/proc/loadavg").read().split()[:3])


def kernel_bench():
    exe = "/tmp/sinew_bench_beam_kernel"
    cmd = ["g++", "-std=c++20", "-O2", "-I" + os.path.join(SRC, "include"), "-I" + os.path.join(SRC, "src")] + \
          [os.path.join(SRC, f) for f in ("src/math/rotation.cpp", "src/elements/beam_section.cpp",
                                          "src/elements/beam_corotational.cpp", "src/elements/element_kernel.cpp",
                                          "tests/unit/bench_beam_kernel.cpp")] + \
          ["-o", exe]
    subprocess.run(cmd, check=True)
    out = subprocess.run(["taskset", "-c", "0", exe], stdout=subprocess.PIPE, text=True, check=True).stdout
    print(out, flush=True)
    return out.strip().splitlines(), loadavg()


def event(log, name):
    """(count, max time over ranks) of a -log_view event line."""
    m = re.search(r"^" + name + r"\s+(\d+)\s+\S+\s+(\S+)", log, re.M)
    return (int(m.group(1)), float(m.group(2))) if m else (0, 0.0)


def run_lattice(n, np_, solver=(), work="/tmp/sinew_bench_beam", extra=()):
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, f"lattice{n}.yaml")
    if not os.path.exists(path):
        lattice(n, path)
    ne = 3 * n * n * (n - 1)
    cmd = ["mpirun", "-n", str(np_), "/usr/bin/time", "-v", os.path.join(BUILD, "sinew"), path,
           "-o", os.path.join(work, f"lattice{n}_{np_}.h5"), "-log_view"] + list(solver) + list(extra)
    t0 = time.perf_counter()
    p = subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.perf_counter() - t0
    log = p.stdout
    rss = [int(x) / 1024 for x in re.findall(r"Maximum resident set size \(kbytes\): (\d+)", log)]
    m = re.search(r"(\d+) unknowns", log)
    t = re.search(r"wall time: setup ([\d.]+) s, (?:constraint check [\d.]+ s, )?statics ([\d.]+) s", log)
    its = re.search(r"^\s+1\s+1\s+(\d+)\s+(\d+)\s+(\S+)", log, re.M)
    r = dict(n=n, np=np_, ne=ne, ndof=int(m.group(1)) if m else 0, wall=wall, rss=rss, exit=p.returncode,
             setup=float(t.group(1)) if t else float("nan"), statics=float(t.group(2)) if t else float("nan"),
             newton=int(its.group(1)) if its else -1, jac=event(log, "SinewJacobian"), res=event(log, "SinewResidual"),
             coo=event(log, "SinewCOOSetup"), ksp=event(log, "KSPSolve"), load=loadavg())
    r["steady"] = r["jac"][1] - r["coo"][1]  # Jacobian assemblies without the one-time COO pattern set-up
    r["per_elem_us"] = 1e6 * r["steady"] / (r["jac"][0] * ne) if r["jac"][0] else float("nan")
    print({k: v for k, v in r.items()}, flush=True)
    if p.returncode != 0:
        print(log[-3000:])
    return r


def main():
    global BUILD
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(SRC, "build"))
    # MUMPS LU took 20 s per factorization already at n = 12 (9504 unknowns, 2 ranks, load average 13):
    # the lattices use an iterative solver unless told otherwise (--solver "" = MUMPS)
    ap.add_argument("--solver", default="-ksp_type cg -pc_type gamg -ksp_rtol 1e-8")
    ap.add_argument("--skip-big", action="store_true")
    a = ap.parse_args()
    BUILD = a.build
    kern, kload = kernel_bench()
    sizes = [12, 26] + ([] if a.skip_big else [56])
    runs = {}
    for n in sizes:
        runs[(n, 2)] = run_lattice(n, 2, a.solver.split())
    steady = {np_: run_lattice(26, np_, a.solver.split(), extra=["-loadsteps", "4"]) for np_ in (1, 2)}
    s = ["`scripts/bench_beam.py` (run under `flock /tmp/sinew_bench.lock`), Release build, on the shared 2-core "
         "machine; load average (1/5/15 min) noted per measurement. Lattice scenes: `scripts/gen_lattice.py n` "
         "(n^3 nodes on a cubic grid, beams along all grid lines, bottom layer clamped, top layer loaded), one "
         "load step.", "",
         f"(a) Element residual + tangent, one core (`tests/unit/bench_beam_kernel.cpp`, g++ -O2, taskset core 0; "
         f"load average {kload}):", ""]
    s += ["    " + k for k in kern]
    s += ["", "(b), (c) Lattices on 2 ranks (peak RSS per rank from /usr/bin/time -v around each rank):", "",
          "| n | elements | unknowns | linear solver | Newton its | setup [s] | statics [s] | wall [s] | "
          "SinewJacobian count / max time [s] | of which COO set-up (count) [s] | per element and assembly [us] | "
          "peak RSS per rank [MB] | exit | load avg |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for n in sizes:
        r = runs[(n, 2)]
        solver = a.solver or "MUMPS LU (default)"
        s.append(f"| {n} | {r['ne']} | {r['ndof']} | {solver} | {r['newton']} | {r['setup']:.2f} | {r['statics']:.2f} | "
                 f"{r['wall']:.1f} | {r['jac'][0]} / {r['jac'][1]:.3f} | {r['coo'][1]:.3f} ({r['coo'][0]}) | "
                 f"{r['per_elem_us']:.3f} | "
                 f"{', '.join(f'{x:.0f}' for x in r['rss'])} | {r['exit']} | {r['load']} |")
    pe = [runs[(n, 2)]["per_elem_us"] for n in sizes]
    s += ["", f"Per element and assembly: {' / '.join(f'{x:.2f}' for x in pe)} us from {runs[(sizes[0], 2)]['ndof']} to "
          f"{runs[(sizes[-1], 2)]['ndof']} unknowns (largest / smallest {max(pe) / min(pe):.2f}).", ""]
    r1, r2 = steady[1], steady[2]
    a1, a2 = r1["steady"] + r1["res"][1], r2["steady"] + r2["res"][1]
    g1, g2 = r1["jac"][1] + r1["res"][1], r2["jac"][1] + r2["res"][1]
    s += ["(d) Assembly speedup, lattice n = 26, 4 load steps, 1 vs 2 ranks (max time over ranks; Jacobian without "
          "the one-time COO set-up):", "",
          "| ranks | SinewJacobian [s] (count) | COO set-up [s] (count) | SinewResidual [s] (count) | "
          "assembly without set-up [s] | with set-up [s] | load avg |", "|---|---|---|---|---|---|---|",
          f"| 1 | {r1['jac'][1]:.3f} ({r1['jac'][0]}) | {r1['coo'][1]:.3f} ({r1['coo'][0]}) | {r1['res'][1]:.3f} ({r1['res'][0]}) | "
          f"{a1:.3f} | {g1:.3f} | {r1['load']} |",
          f"| 2 | {r2['jac'][1]:.3f} ({r2['jac'][0]}) | {r2['coo'][1]:.3f} ({r2['coo'][0]}) | {r2['res'][1]:.3f} ({r2['res'][0]}) | "
          f"{a2:.3f} | {g2:.3f} | {r2['load']} |",
          "", f"Speedup of assembly {a1 / a2:.2f}x ({g1 / g2:.2f}x with the one-time set-up)."]
    doc_tables.write_block("performance.md", "bench_beam", "\n".join(s))
    print("\n".join(s))


if __name__ == "__main__":
    main()
