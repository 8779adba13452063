#!/usr/bin/python3
"""Benchmark of the compliance analysis (not a ctest): an n x n grid of steel beams in the xy
plane (6 (n^2 - 4) unknowns, corners clamped), compliance of every node, one load step, on
`--np` ranks. Reports the factorization time, the time of the compliance blocks and their ratio,
and the load average; --method picks -compliance_method (selinv: MUMPS selected inverse entries,
sparse / dense: unit loads as sparse or dense right-hand-side blocks of --batch columns). With
--doc it writes the result table into docs/performance.md (generated block bench_compliance).

usage: scripts/bench_compliance.py [--n 129] [--np 2] [--method selinv] [--batch 96] [--doc]"""
import argparse
import os
import re
import subprocess
import time

import doc_tables

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def scene(n, h=0.05):
    idx = lambda i, j: i * n + j + 1  # noqa: E731
    nodes = [[i * h, j * h, 0.0] for i in range(n) for j in range(n)]
    elems = [[idx(i, j), idx(i, j + 1)] for i in range(n) for j in range(n - 1)]
    elems += [[idx(i, j), idx(i + 1, j)] for i in range(n - 1) for j in range(n)]
    corners = [idx(0, 0), idx(0, n - 1), idx(n - 1, 0), idx(n - 1, n - 1)]
    centre = idx(n // 2, n // 2)
    nprops = ", ".join(f"{c}: {{fix: true}}" for c in corners) + f", {centre}: {{force: [0, 0, 1]}}"
    return (f"title: compliance benchmark grid {n}x{n}\n"
            f"nodes: {nodes}\nelements: {elems}\nnprops: {{{nprops}}}\n"
            f"eprops: [{{elems: [1:{len(elems)}], flex: [1, 2, 3, 4, 5, 6], emod: 210e9, smod: 80e9, "
            f"cshape: circ, dim: [0.01]}}]\n"
            f"opt: {{loadsteps: 1}}\n"), len(elems)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=129)
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--method", choices=["selinv", "sparse", "dense"], default="selinv")
    ap.add_argument("--batch", type=int, default=96)
    ap.add_argument("--bin", default=os.path.join(SOURCE, "build", "sinew"))
    ap.add_argument("--doc", action="store_true", help="write the result table into docs/performance.md")
    a = ap.parse_args()
    text, ne = scene(a.n)
    # element list as a range is not YAML: write the explicit list
    text = text.replace(f"[1:{ne}]", "[" + ", ".join(str(e) for e in range(1, ne + 1)) + "]")
    work = os.path.join(SOURCE, "build", "bench")
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, f"compliance_grid{a.n}.yaml")
    with open(path, "w") as f:
        f.write(text)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    cmd = ["mpirun", "-n", str(a.np), a.bin, path, "-o", path.replace(".yaml", f"_{a.method}_np{a.np}.h5"),
           "-compliance_method", a.method, "-compliance_batch", str(a.batch)]
    load0 = os.getloadavg()
    t0 = time.time()
    p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.time() - t0
    load1 = os.getloadavg()
    if p.returncode != 0:
        print(p.stdout)
        raise SystemExit(f"sinew failed ({p.returncode})")
    unknowns = int(re.search(r"(\d+) unknowns", p.stdout).group(1))
    m = re.search(r"compliance: (\d+) unit loads per step, (\d+) factorizations?, (\d+) block solves; "
                  r"factor ([\d.]+) s, solves ([\d.]+) s", p.stdout)
    cols, nblk, tf, ts = int(m.group(1)), int(m.group(3)), float(m.group(4)), float(m.group(5))
    rows = [("grid", f"{a.n} x {a.n} beams ({ne} elements)"), ("unknowns", unknowns), ("ranks", a.np),
            ("method", a.method + ("" if a.method == "selinv" else f", {a.batch} columns per solve")),
            ("unit loads (columns)", cols), ("MUMPS solve calls", nblk),
            ("factorization (assembly + MUMPS LU)", f"{tf:.3f} s"), ("all compliance blocks", f"{ts:.3f} s"),
            ("blocks / factorization", f"{ts / tf:.2f}"), ("per unit load", f"{1e3 * ts / max(cols, 1):.4f} ms"),
            ("whole run (wall, incl. statics and output)", f"{wall:.1f} s"),
            ("load average (1 min) before / after", f"{load0[0]:.2f} / {load1[0]:.2f}")]
    for k, v in rows:
        print(f"{k:45s} {v}")
    if a.doc:
        doc_tables.write_block("performance.md", "bench_compliance",
                               "\n".join(["| quantity | value |", "|---|---|"] + [f"| {k} | {v} |" for k, v in rows]))


if __name__ == "__main__":
    main()
