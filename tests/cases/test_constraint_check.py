"""Singular models are model errors (exit 2) reported before any solve, with what to fix:
a released mode that turns an arm into a mechanism, a frame whose supports leave a rigid-body
rotation, an over-constrained loop of rigid beams, and a line of beams whose middle element has
EA = 1e20 (a stand-in for a rigid part): the mechanism found there is blamed on the stiffness ratio,
naming the stiffest and the softest element (issue 24 item 13). No result file is left under the final
name (a stale one from an earlier run is removed). Run on 2 ranks."""
import os
import subprocess

import sinewtest as st

BEAM = "flex: [1, 2, 3, 4, 5, 6], emod: 210e9, smod: 80e9, cshape: rect, dim: [0.02, 0.005], orien: [0, 1, 0]"

# 1. released mode 3 of the rigid arm (element 2) = a hinge at node 2 about z: node 3 swings in y
arm = f"""
title: arm with a hinge
nodes: [[0, 0, 0], [0.5, 0, 0], [1.0, 0, 0]]
elements: [[1, 2], [2, 3]]
nprops: {{1: {{fix: true}}, 3: {{force: [0, 0, 1]}}}}
eprops: [{{elems: [1], {BEAM}}}]
opt: {{loadsteps: 1, rls: {{2: [3]}}}}
"""
out, log = st.run("cc_release", arm, np_=2, expect_exit=2)
print(log)
st.check("mechanism" in log, "release: reported as a mechanism")
st.check("node 3 translation y" in log and "node 3 rotation z" in log, "release: names node 3 translation y / rotation z")
st.check("element 2 (released modes 3)" in log, "release: names the released mode of element 2")
st.check("opt.rls" in log and "add a support" in log, "release: says what to fix")
st.check("likely cause" not in log, "release: a true mechanism is not blamed on the stiffness ratio")
st.check(not os.path.exists(out) and not os.path.exists(out + ".part"), "release: no result file")
st.check("nan" not in log.lower(), "release: no NaN printed")

# without the release the same arm solves
out, log = st.run("cc_release_ok", arm.replace("rls: {2: [3]}", "rls: {}"), np_=2)
st.check(os.path.exists(out), "without the release the arm solves and writes its result")

# 2. portal frame pinned at two base points on the x axis: it can turn about that axis
portal = f"""
title: portal pinned on a line
nodes: [[0, 0, 0], [0, 0, 1], [1, 0, 0], [1, 0, 1]]
elements: [[1, 2], [3, 4], [2, 4]]
nprops: {{1: {{fix_pos: true}}, 3: {{fix_pos: true}}, 2: {{force: [1, 0, 0]}}}}
eprops: [{{elems: [1, 2], {BEAM}}}]
opt: {{loadsteps: 1}}
"""
# a stale result of an earlier run under the same name must not survive as if valid
stale = os.path.join(st.WORK, "cc_portal.h5")
os.makedirs(st.WORK, exist_ok=True)
path = st.scene_file("cc_portal", portal)
with open(stale, "w") as f:
    f.write("stale")
p = subprocess.run([st.MPIEXEC, "-n", "2", st.BIN, path, "-o", stale], env=st.ENV, stdout=subprocess.PIPE,
                   stderr=subprocess.STDOUT, text=True, timeout=600)
print(p.stdout)
st.check(p.returncode == 2, f"portal: exit code {p.returncode}, expected 2")
st.check("mechanism" in p.stdout, "portal: reported as a mechanism")
st.check("node 2 translation y" in p.stdout and "node 4 translation y" in p.stdout,
         "portal: names the tops moving out of plane (nodes 2, 4 translation y)")
st.check(not os.path.exists(stale), "portal: the stale result file under the final name is removed")

# 3. triangle of rigid beams: 18 constraints on 12 free DOFs
loop = """
title: rigid loop
nodes: [[0, 0, 0], [0.5, 0, 0], [0.25, 0.4, 0]]
elements: [[1, 2], [2, 3], [3, 1]]
nprops: {1: {fix: true}, 3: {force: [0, 0, 1]}}
opt: {loadsteps: 1}
"""
out, log = st.run("cc_loop", loop, np_=2, expect_exit=2)
print(log)
st.check("over-constrained" in log, "loop: reported as over-constrained")
for e in (1, 2, 3):
    st.check(f"element {e}: modes" in log, f"loop: names element {e} and its modes")
st.check("release one of these modes" in log, "loop: says what to fix")
st.check(not os.path.exists(out), "loop: no result file")

# releasing the 6 redundant modes of element 3 (a ball joint plus free axial/torsion) makes it solvable
out, log = st.run("cc_loop_ok", loop.replace("loadsteps: 1}", "loadsteps: 1, rls: {3: [1, 2, 3, 4, 5, 6]}}"), np_=2)
st.check(os.path.exists(out), "loop with element 3 fully released solves")

# 4. a clamped line of three beams, the middle one with EA = 1e20 (emod 1e20, area 1 m^2) and the others
# steel (EA 1.6e7 N, 12 EI/L^3 1.2e3 N/m): the stiff element's round-off hides the others' stiffness
# (ratio 8e16 > 1/tol 1e11), so the check finds "free motions"; the message names the ratio and the
# elements, not the supports.
SOFT = "flex: [1, 2, 3, 4, 5, 6], emod: 2.1e11, smod: 8.1e10, cshape: circ, dim: [0.01]"
stiff_line = """
title: line with one very stiff element
nodes: [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]
elements: [[1, 2], [2, 3], [3, 4]]
nprops: {1: {fix: true}, 4: {force: [0, -10, 0]}}
eprops: [{elems: [1, 3], %s}, {elems: [2], flex: [1, 2, 3, 4, 5, 6], emod: EMOD, smod: SMOD, cshape: circ, dim: [1.1283791670955126]}]
opt: {loadsteps: 1, calccompl: false}
""" % SOFT
out, log = st.run("cc_stiff", stiff_line.replace("EMOD", "1e20").replace("SMOD", "4e19"), np_=2, expect_exit=2)
print(log)
st.check("mechanism" in log, "EA 1e20: the check reports free motions")
st.check("likely cause: the element stiffnesses, not the supports: element 2 is 8.1e+16 times stiffer than element 1" in log,
         "EA 1e20: the stiffness ratio 8.1e16 of element 2 to element 1 is named as the likely cause")
st.check("make element 2 rigid" in log, "EA 1e20: says to make element 2 rigid instead")
st.check("fix: add a support" not in log, "EA 1e20: the supports are not the first fix offered")
# a smaller ratio (emod 1e12: 8e8 < 1e10) solves
out, log = st.run("cc_stiff_ok", stiff_line.replace("EMOD", "1e12").replace("SMOD", "4e11"), np_=2)
st.check(os.path.exists(out) and "likely cause" not in log, "emod 1e12 (ratio 8e8): solves, no stiffness-ratio message")
st.done()
