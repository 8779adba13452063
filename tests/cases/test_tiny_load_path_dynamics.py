"""Issue 24 item 5 beyond load-stepped statics (test_statics_tiny_load): a load below the round-off of
the residual is still a load in path following and in dynamics. Each scene runs with its load at 1e-6
and at 1e-12 on 2 ranks; the second's response, scaled by 1e6, must be the first's (the response is
linear at both sizes), never zero motion with converged = 1.
- Path following (arc length, 2 points) on the cross-flexure hinge of runs/crosshinge.yaml with the
  initial loads [5, -20, 0] N on the stage and the path load [P, 0, 0] on the same node. The load
  vector q = -dR/dlambda is a central difference of the residual at lambda -+ 1e-4; at the start, 5 + 1e-4
  x 1e-12 rounds to 5, so q was 0 and every path step failed (exit 3 after 10 halvings). Now the
  difference step grows until the difference stands above the residual's round-off: the path in
  P lambda and the displacements agree to 1e-9 (measured 3e-13 and 5e-14).
- Dynamics (no change needed; guards): the leaf spring of runs/cantilever_step.yaml under a sudden
  tip force (beams, Lie-group generalized alpha) and a 2 m ANCF cantilever (8 elements) under a
  sudden tip force: every step takes a Newton iteration and the tip's deflection history, scaled,
  agrees to 1e-9 (measured 1e-15; the tip lies on y = 0, so the tiny deflection is not lost in the
  position's round-off)."""
import re

import numpy as np

import sinewtest as st

LOADS = (1e-6, 1e-12)

# path following: initial loads and a path load on the same node component
hinge = open(st.SOURCE + "/runs/crosshinge.yaml").read().split("\nopt:")[0]
hinge = hinge.replace("force_initial: [0, -20, 0], moment: [0, 0, 0.5]", "force_initial: [5, -20, 0], force: [LOAD, 0, 0]")
st.check("LOAD" in hinge, "crosshinge scene: loads replaced")
hinge += ("\nopt:\n  calcfreq: false\n  calccompl: false\n  calcbuck: false\n"
          "  continuation: {method: arclength, ds: 0.001, max_steps: 2}\n")
path = {}
for P in LOADS:
    out, _ = st.run(f"tiny_path_{P:g}", hinge.replace("LOAD", repr(P)), args=["-continuation_inertia", "false"])
    with st.h5(out) as f:
        st.check(f.attrs["converged"] == 1, f"path, P = {P:g}: converged = 1")
        path[P] = (P * f["load_factor"][:], f["node/p"][:] - f["node/p"][0])
big, small = path[LOADS[0]], path[LOADS[1]]
if st.check(len(big[0]) == 2 and len(small[0]) == 2, "path: 2 points at both loads"):
    st.close(small[0], big[0], rtol=1e-9, what="path: applied load P lambda at the points [N], 1e-12 vs 1e-6")
    st.close(small[1], big[1], rtol=1e-9, what="path: displacements [m], 1e-12 vs 1e-6")

# dynamics: a sudden tip force on a beam and on an ANCF cantilever, 10 steps
leaf = open(st.SOURCE + "/runs/cantilever_step.yaml").read()
leaf = leaf.replace("force: [0, -1.0, 0]", "force: [0, -LOAD, 0]").replace("tend: 0.024", "tend: 0.001")
ancf = """title: ANCF cantilever, sudden tip force
nodes: [[0, 0], [2, 0]]
elements: [[1, 2]]
nprops:
  1: {fix_coords: [1, 1, 0, 1]}
  2: {force: [0, -LOAD]}
eprops:
  - {elems: [1], type: ancf_cable2d, nbeams: 8, physicsMassPerLength: 78,
     physicsBendingStiffness: 833.3333333333333, physicsAxialStiffness: 1e6, useReducedOrderIntegration: 0}
opt:
  calcfreq: false
  calccompl: false
  dynamics: {tend: 0.01, dt: 1e-3, spectral_radius: 0.9}
"""
for name, text in (("beam", leaf), ("ancf", ancf)):
    st.check("LOAD" in text, f"{name}: load replaced")
    tip = {}
    for P in LOADS:
        out, log = st.run(f"tiny_dyn_{name}_{P:g}", text.replace("LOAD", repr(P)))
        with st.h5(out) as f:
            st.check(f.attrs["converged"] == 1, f"{name}, P = {P:g}: converged = 1")
            tip[P] = f["node/p"][:, -1, 1] - f["node/p"][0, -1, 1]
        m = re.search(r"dynamics: (\d+) of \d+ steps.*?, (\d+) Newton iterations", log)
        if st.check(m is not None, f"{name}, P = {P:g}: dynamics summary line"):
            st.check(int(m.group(2)) >= int(m.group(1)), f"{name}, P = {P:g}: a Newton iteration per step ({m.group(0)})")
    st.check(np.abs(tip[LOADS[1]]).max() > 0, f"{name}: the 1e-12 N tip force moves the tip")
    st.close(tip[LOADS[1]] / LOADS[1], tip[LOADS[0]] / LOADS[0], rtol=1e-9,
             what=f"{name}: tip deflection per newton [m/N], 1e-12 vs 1e-6")
st.done()
