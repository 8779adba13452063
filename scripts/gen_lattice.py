#!/usr/bin/python3
"""A 3D beam lattice scene: nx x ny x nz nodes on a cubic grid (spacing h), beams along every grid
line (steel, rect 0.01 x 0.01), the z = 0 layer clamped, the top layer loaded by a lateral and a
downward force. 6 unknowns per free node: n^3 nodes give about 6 n^3 unknowns (n = 12: 1e4,
n = 26: 1e5, n = 56: 1e6). The YAML is written with plain string formatting (PyYAML would take
minutes at 1e6 unknowns).
Usage: scripts/gen_lattice.py n [out.yaml] [--loadsteps k]"""
import argparse
import time


def lattice(n, path, loadsteps=1, h=0.1):
    t0 = time.perf_counter()
    idx = lambda i, j, k: 1 + i + n * (j + n * k)
    elems = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                a = idx(i, j, k)
                if i + 1 < n:
                    elems.append((a, idx(i + 1, j, k)))
                if j + 1 < n:
                    elems.append((a, idx(i, j + 1, k)))
                if k + 1 < n:
                    elems.append((a, idx(i, j, k + 1)))
    with open(path, "w") as f:
        f.write(f"title: beam lattice {n}x{n}x{n}\nnodes:\n")
        f.write("".join(f"  - [{h * i:.6g}, {h * j:.6g}, {h * k:.6g}]\n"
                        for k in range(n) for j in range(n) for i in range(n)))
        f.write("elements:\n")
        f.write("".join(f"  - [{a}, {b}]\n" for a, b in elems))
        f.write("nprops:\n")
        for j in range(n):
            for i in range(n):
                f.write(f"  {idx(i, j, 0)}: {{fix: true}}\n")
        for j in range(n):
            for i in range(n):
                f.write(f"  {idx(i, j, n - 1)}: {{force: [20, 10, -50]}}\n")
        f.write("eprops:\n  - elems: [" + ", ".join(map(str, range(1, len(elems) + 1))) + "]\n")
        f.write("    flex: [1, 2, 3, 4, 5, 6]\n    emod: 210e9\n    smod: 80e9\n    cshape: rect\n"
                "    dim: [0.01, 0.01]\n    orien: [0.3, 0.5, 0.8]\n")
        f.write(f"opt:\n  loadsteps: {loadsteps}\n  calccompl: false\n")
    return 6 * n * n * (n - 1), len(elems), time.perf_counter() - t0


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("n", type=int)
    ap.add_argument("out", nargs="?")
    ap.add_argument("--loadsteps", type=int, default=1)
    a = ap.parse_args()
    ndof, ne, dt = lattice(a.n, a.out or f"lattice{a.n}.yaml", a.loadsteps)
    print(f"lattice {a.n}^3: {ne} elements, about {ndof} unknowns, written in {dt:.1f} s")
