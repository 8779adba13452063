#!/usr/bin/python3
"""Form-finding messages name only what the model has (issue 10 item 17), 2 ranks:
A: a catenoid beyond its stability limit (rings 1.4 radii apart, 16 x 8) collapses: the hint names
   no edge cables and no loads (it has neither) but says no surface spans the boundary;
B: a membrane strip supported on two opposite edges collapses: the hint counts its free edges;
C: a pure cable net (C1 patch) prints no "membrane mesh quality" line; a form-found cable set with
   zero prestress (between two supports, so the model is still regular) is a warning naming it, and
   the run ends normally (exit 0)."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from sinewtest import run, check, done, WORK  # noqa: E402
from ffscenes import catenoid_scene, to_yaml  # noqa: E402

os.makedirs(WORK, exist_ok=True)


def error_line(log):
    return next((l for l in log.splitlines() if l.startswith("error")), "")


# A
out, log = run("ffm_catenoid", to_yaml(catenoid_scene(halfh=0.7, nt=16, nz=8, steps=300, tol=1e-8)), expect_exit=3)
e = error_line(log)
print("  A:", e)
check("collapsed" in e and "eprops(1) (membrane set)" in e, "A: collapse naming the membrane set")
# before: "... the prestress is too low against the edge cables or loads"
check("against the edge cables" not in e and "too low for" not in e and "unsupported" not in e,
      "A: the hint blames no edge cables, loads or free edges (the catenoid has none)")
check("no surface with this prestress spans this boundary" in e, "A: the hint says no surface spans the boundary")

# B: 6 x 6 triangles on the unit square, edges x = 0 and x = 1 fixed, edges y = 0 and y = 1 free
m = 6
nid = lambda i, j: j * (m + 1) + i
tris = []
for j in range(m):
    for i in range(m):
        tris += [[nid(i, j) + 1, nid(i + 1, j) + 1, nid(i + 1, j + 1) + 1], [nid(i, j) + 1, nid(i + 1, j + 1) + 1, nid(i, j + 1) + 1]]
sc = {"nodes": [[i / m, j / m, 0.0] for j in range(m + 1) for i in range(m + 1)], "elements": tris,
      "nprops": {nid(i, j) + 1: {"fix": True} for j in range(m + 1) for i in (0, m)},
      "eprops": [{"elems": list(range(1, len(tris) + 1)), "type": "membrane", "thickness": 1, "emod": 1000, "nu": 0,
                  "prestress": [1, 1, 0]}],
      "formfinding": {"formfinding_step": 60, "equilibrium_accuracy": 1e-10}, "opt": {"loadsteps": 1}}
out, log = run("ffm_strip", to_yaml(sc), expect_exit=3)
e = error_line(log)
print("  B:", e)
check(f"{2 * m} membrane edges lie on no support and no cable" in e, "B: the hint counts the 12 free membrane edges")
check("against the edge cables" not in e and "too low for" not in e, "B: no edge cables or loads named")

# C: C1 cable patch plus a zero-prestress cable between the fixed nodes 1 and 2
net = {"title": "cable patch with an unstressed cable",
       "nodes": [[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0], [1, 0, 0]],
       "elements": [[1, 5], [2, 5], [3, 5], [4, 5], [1, 2]],
       "nprops": {str(i): {"fix": True} for i in range(1, 5)},
       "eprops": [{"elems": [1, 2, 3, 4], "type": "cable", "area": 1, "emod": 100, "prestress": 1},
                  {"elems": [5], "type": "cable", "area": 1, "emod": 100}],
       "formfinding": {"formfinding_step": 30, "formfinding_tolerance": 1e-12, "equilibrium_accuracy": 1e-12},
       "opt": {"loadsteps": 1}}
out, log = run("ffm_net", to_yaml(net))
w = [l for l in log.splitlines() if l.startswith("warning") and "zero prestress" in l]
print("  C:", w)
check(len(w) == 1 and "eprops(2) (cable set)" in w[0], "C: warning naming the zero-prestress cable set")
check("membrane mesh quality" not in log, "C: no membrane mesh quality line for a cable net")
check("form finding (URS)" in log, "C: the form-finding summary is printed")
done()
