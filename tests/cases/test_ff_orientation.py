#!/usr/bin/python3
"""Form finding does not depend on the node order of the membrane triangles (issue 10 item 15), 2 ranks.
A: the catenoid 16 x 8 (ffscenes.catenoid_scene, tolerance 1e-6 on the normal shape change) with
   every other triangle reversed stops at the same step as the original and finds the same shape
   (before: the node normals were sums of signed area vectors, which cancel where neighbours are
   reversed, so the tangential drift counted as shape change: 300 steps instead of 24 on the
   issue's mesh).
B: the same reversed catenoid read from a Gmsh file: a warning with the count of reversed
   triangles, the orientation made consistent (every interior edge runs in opposite directions in
   its two triangles of /mesh/triangles), same step count and shape."""
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from sinewtest import run, h5, close, check, done, WORK  # noqa: E402
from ffscenes import catenoid_scene, to_yaml  # noqa: E402

os.makedirs(WORK, exist_ok=True)


def found(out):
    with h5(out) as f:
        nff = len(f["formfinding/residual"])
        return nff, f["node/p"][nff - 1][:], f["formfinding/shape_change_normal"][:], int(f.attrs["converged"])


base = catenoid_scene(halfh=0.5, nt=16, nz=8, steps=60, tol=1e-6)
n0, P0, sn0, c0 = found(run("ff_orient_base", to_yaml(base))[0])
flipped = dict(base)
flipped["elements"] = [[e[0], e[2], e[1]] if k % 2 else e for k, e in enumerate(base["elements"])]
n1, P1, sn1, c1 = found(run("ff_orient_half", to_yaml(flipped))[0])
print(f"  catenoid 16x8: {n0} steps (normal change {sn0[-1]:.2e}); half the triangles reversed: {n1} steps "
      f"(normal change {sn1[-1]:.2e})")
check(c0 == 1 and c1 == 1, "both converged")
check(n1 == n0, f"half the triangles reversed: same number of steps ({n1} vs {n0})")
close(sn1, sn0, rtol=1e-6, what="normal shape change per step, reversed vs original")
close(P1, P0, atol=1e-10, what="found shape, reversed vs original")

# B: Gmsh 4.1 file of the catenoid with every third triangle reversed (nodes and triangles only)
tris = [[e[0], e[2], e[1]] if k % 3 == 1 else e for k, e in enumerate(base["elements"])]
nrev = sum(1 for k in range(len(tris)) if k % 3 == 1)
nodes = base["nodes"]
msh = os.path.join(WORK, "ff_orient_catenoid.msh")
with open(msh, "w") as f:
    f.write("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n")
    f.write(f"$Nodes\n1 {len(nodes)} 1 {len(nodes)}\n2 1 0 {len(nodes)}\n")
    f.write("".join(f"{i + 1}\n" for i in range(len(nodes))))
    f.write("".join(f"{x!r} {y!r} {z!r}\n" for x, y, z in nodes))
    f.write("$EndNodes\n")
    f.write(f"$Elements\n1 {len(tris)} 1 {len(tris)}\n2 1 2 {len(tris)}\n")
    f.write("".join(f"{k + 1} {a} {b} {c}\n" for k, (a, b, c) in enumerate(tris)))
    f.write("$EndElements\n")
gm = dict(base)
del gm["nodes"], gm["elements"]
gm["mesh"] = msh
out, log = run("ff_orient_gmsh", to_yaml(gm))
m = re.search(r"warning: mesh .*: (\d+) of (\d+) triangles/quadrangles were inverted", log)
check(m is not None, "warning about inverted triangles")
if m:
    print("  " + m.group(0))
    check(int(m.group(1)) == nrev and int(m.group(2)) == len(tris),
          f"warning counts {m.group(1)} of {m.group(2)}, expected {nrev} of {len(tris)}")
n2, P2, sn2, c2 = found(out)
check(c2 == 1 and n2 == n0, f"Gmsh mesh: converged in the same number of steps ({n2} vs {n0})")
close(P2, P0, atol=1e-10, what="Gmsh mesh: found shape vs the scene mesh")
with h5(out) as f:
    T = f["mesh/triangles"][:]
directed = {}
for t in T:
    for j in range(3):
        a, b = int(t[j]), int(t[(j + 1) % 3])
        directed[(a, b)] = directed.get((a, b), 0) + 1
same = sum(1 for (a, b), k in directed.items() if k > 1)
opposite = sum(1 for (a, b) in directed if (b, a) in directed) // 2
print(f"  Gmsh mesh after reading: {same} edges traversed twice in the same direction, {opposite} interior edges consistent")
check(same == 0 and opposite > 0, "orientation made consistent: every shared edge runs in opposite directions")
done()
