#!/usr/bin/python3
"""Benchmark of the natural-frequency analysis (not a ctest): the 10 lowest natural frequencies of
a 3D lattice frame of n x n x n cubic cells (steel tubes, every lattice edge one scene beam split
into `--nbeams` Timoshenko elements, the bottom face clamped), on `--np` ranks. The default
(n = 20, nbeams 8) has 9261 joints, 25200 members and 1.11e6 unknowns.

Reports the unknowns, the frequencies, the wall time (whole mpirun and the solver phases of the
summary), the SinewEigen event time from -log_view and the peak resident memory of every rank
(/usr/bin/time -f %M around each rank); the whole output is kept in build/bench/*.log. The time
outside the summary phases is mostly the start-up constraint check (a MUMPS factorization and
subspace iteration; `-- -constraint_check false` skips it). Extra arguments after `--` go to sinew, e.g.
  scripts/bench_modal.py -- -st_ksp_type cg -st_pc_type gamg      (iterative shift-and-invert)
With --doc it writes the result table into docs/performance.md (generated block bench_modal).

usage: scripts/bench_modal.py [--n 20] [--nbeams 8] [--np 2] [--nfreq 10] [--doc] [-- sinew flags]"""
import argparse
import os
import re
import subprocess
import time

import doc_tables

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def scene(n, nbeams, h=1.0, nfreq=10):
    """n^3 cells of edge h: joints (n+1)^3, members along x, y and z; joints at z = 0 clamped."""
    idx = lambda i, j, k: (k * (n + 1) + j) * (n + 1) + i + 1  # noqa: E731
    nodes = [f"[{i * h:g}, {j * h:g}, {k * h:g}]" for k in range(n + 1) for j in range(n + 1) for i in range(n + 1)]
    elems = []
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                if i < n:
                    elems.append(f"[{idx(i, j, k)}, {idx(i + 1, j, k)}]")
                if j < n:
                    elems.append(f"[{idx(i, j, k)}, {idx(i, j + 1, k)}]")
                if k < n:
                    elems.append(f"[{idx(i, j, k)}, {idx(i, j, k + 1)}]")
    fixed = [idx(i, j, 0) for j in range(n + 1) for i in range(n + 1)]
    ne = len(elems)
    lines = [f"title: modal benchmark lattice {n}^3 cells, nbeams {nbeams}",
             "nodes:"] + [f"  - {p}" for p in nodes] + ["elements:"] + [f"  - {e}" for e in elems]
    lines += ["nprops:"] + [f"  {f}: {{fix: true}}" for f in fixed]
    lines += ["eprops:",
              f"  - elems: [{', '.join(str(e) for e in range(1, ne + 1))}]",
              "    flex: [1, 2, 3, 4, 5, 6]",
              "    emod: 210e9",
              "    smod: 80e9",
              "    dens: 7800",
              "    cshape: circ",
              "    dim: [0.05]",
              "    orien: [0.3, 0.5, 0.8]",
              f"    nbeams: {nbeams}",
              f"opt: {{loadsteps: 1, calccompl: false, nfreq: {nfreq}}}"]
    return "\n".join(lines) + "\n", len(nodes), ne


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=20)
    ap.add_argument("--nbeams", type=int, default=8)
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--nfreq", type=int, default=10)
    ap.add_argument("--bin", default=os.path.join(SOURCE, "build", "sinew"))
    ap.add_argument("--doc", action="store_true", help="write the result table into docs/performance.md")
    ap.add_argument("extra", nargs="*", help="flags passed to sinew (after --)")
    a = ap.parse_args()
    text, nn, ne = scene(a.n, a.nbeams, nfreq=a.nfreq)
    work = os.path.join(SOURCE, "build", "bench")
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, f"modal_lattice{a.n}_{a.nbeams}.yaml")
    with open(path, "w") as f:
        f.write(text)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    cmd = ["mpirun", "-n", str(a.np), "/usr/bin/time", "-f", "peak_rss_kb %M", a.bin, path,
           "-o", path.replace(".yaml", ".h5"), "-log_view"] + a.extra
    load0 = os.getloadavg()
    t0 = time.time()
    p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.time() - t0
    load1 = os.getloadavg()
    out = p.stdout
    if p.returncode != 0:
        print(out[-6000:])
        raise SystemExit(f"sinew failed ({p.returncode})")
    unknowns = int(re.search(r"(\d+) unknowns", out).group(1))
    hz = [float(v) for v in re.search(r"natural frequencies \(Hz, last step\):([^\n]*)", out).group(1).split()]
    phases = re.search(r"wall time: setup ([\d.]+) s, (?:constraint check [\d.]+ s, )?statics ([\d.]+) s(?: \(\d+ Newton iterations\))?, "
                       r"step analyses ([\d.]+) s, output ([\d.]+) s", out)
    with open(path.replace(".yaml", ".log"), "w") as f:
        f.write(out)

    def event(name):  # (count, max time) of a -log_view event
        m = re.search(rf"^{name}\s+(\d+)\s+[\d.]+\s+([\d.e+-]+)", out, re.M)
        return (int(m.group(1)), float(m.group(2))) if m else (0, 0.0)

    eig = event("SinewEigen")
    lu = event("MatLUFactorNum")
    total = float(re.search(r"^Time \(sec\):\s+([\d.e+-]+)", out, re.M).group(1))
    outside = total - sum(float(v) for v in phases.groups())
    rss = [int(v) / 1024 for v in re.findall(r"peak_rss_kb (\d+)", out)]
    rows = [("lattice", f"{a.n}^3 cells, {nn} joints, {ne} members x {a.nbeams} elements"),
            ("unknowns", unknowns), ("ranks", a.np), ("sinew flags", " ".join(a.extra) or "(defaults)"),
            ("frequencies [Hz]", " ".join(f"{v:.6g}" for v in hz)),
            ("setup / statics / step analyses / output [s]", " / ".join(phases.groups())),
            ("SinewEigen (EPSSolve incl. factorization) [s]", f"{eig[1]:.1f}"),
            ("MUMPS numeric factorizations (count, total) [s]", f"{lu[0]}, {lu[1]:.1f}"),
            ("PETSc lifetime (-log_view Time) [s]", f"{total:.1f}"),
            ("outside the summary phases (constraint check) [s]", f"{outside:.1f}"),
            ("whole run (wall) [s]", f"{wall:.1f}"),
            ("peak RSS per rank [MB]", " / ".join(f"{v:.0f}" for v in rss)),
            ("load average before / after", f"{load0[0]:.2f} / {load1[0]:.2f}")]
    for k, v in rows:
        print(f"{k:48s} {v}")
    if a.doc:
        doc_tables.write_block("performance.md", "bench_modal",
                               "\n".join(["| quantity | value |", "|---|---|"] + [f"| {k} | {v} |" for k, v in rows]))


if __name__ == "__main__":
    main()
