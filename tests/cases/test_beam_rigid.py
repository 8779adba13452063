"""Exact constraints of rigid deformation modes under large motion.
1. A flexible cantilever rolled through about 2 rad carries a rigid bracket (two elements in no
   eprops set): bracket lengths, the angle between its arms and the triads of its three nodes
   (one common rotation, body-fixed arms) are kept to 1e-10.
2. A cantilever of partially flexible elements (flex: [1, 3, 4]: torsion and bending about the
   local z axis rigid) under a large moment about local y plus a force and a torque that load the
   rigid modes: e2 = 0, ny^p . lhat = 0, ny^q . lhat = 0 to 1e-10 at every step.
3. A free beam whose node 1 gets a prescribed rotation of 3 pi about (1,1,1)/sqrt(3) (nprops rot)
   follows rigidly: every node position and rotation equals the analytic rotation at every step."""
import numpy as np

import beamtools as bt
import sinewtest as st

w, t = 0.02, 0.01
EIy = bt.rect_section(w, t)["EIy"]
qm = lambda q: bt.quat_matrix(q)

# ---- 1. rigid bracket on a flexible cantilever
nodes, elems = bt.chain([0, 0, 0], [1, 0, 0], 4)
nodes += [[1, 0.2, 0], [1.1, 0.2, 0.1]]
elems += [[5, 6], [6, 7]]
scene = {"title": "rigid bracket", "nodes": nodes, "elements": elems,
         "nprops": {"1": {"fix": True}, "7": {"moment": [0, 0, 2 * EIy], "force": [0, 0, 5.0]}},
         "eprops": [bt.beam_set([1, 2, 3, 4], w, t)], "opt": {"loadsteps": 8, "calccompl": False}}
out, log = st.run("beam_rigid_bracket", bt.yaml_text(scene))
with st.h5(out) as f:
    p, q, p0 = f["node/p"][:], f["node/r_quat"][:], f["node/p0"][:]
ang = [2 * np.arccos(min(1, abs(qq[0]))) for qq in q[:, 4]]
print(f"bracket: node 5 rotates by {max(ang):.3f} rad; tip moves {np.linalg.norm(p[-1, 6] - p0[6]):.3f} m")
errs = []
for k in range(len(p)):
    R5 = qm(q[k, 4])
    for a, b in ((4, 5), (5, 6)):
        errs.append(abs(np.linalg.norm(p[k, b] - p[k, a]) - np.linalg.norm(p0[b] - p0[a])))
        errs.append(np.abs(R5.T @ (p[k, b] - p[k, a]) - (p0[b] - p0[a])).max())  # body-fixed arm
    c = np.dot(p[k, 5] - p[k, 4], p[k, 6] - p[k, 5])
    errs.append(abs(c - np.dot(p0[5] - p0[4], p0[6] - p0[5])))                  # angle between arms
    errs.append(max(np.abs(qm(q[k, j]) - R5).max() for j in (5, 6)))            # one rotation
st.close(max(errs), 0.0, atol=1e-10, what="rigid bracket: length/angle/triad errors over all steps")

# ---- 2. partially flexible elements
n = 4
nodes, elems = bt.chain([0, 0, 0], [1, 0, 0], n)
EIz = bt.rect_section(w, t)["EIz"]
scene = {"title": "flex 1 3 4", "nodes": nodes, "elements": elems,
         "nprops": {"1": {"fix": True}, str(n + 1): {"moment": [1.0, 0, 1.5 * EIy], "force": [0, 0, 50.0]}},
         "eprops": [bt.beam_set(range(1, n + 1), w, t, flex=[1, 3, 4])],
         "opt": {"loadsteps": 6, "calccompl": False}}
out, log = st.run("beam_flex134", bt.yaml_text(scene))
with st.h5(out) as f:
    p, q = f["node/p"][:], f["node/r_quat"][:]
ey0, ez0 = np.array([0, 0, 1.0]), np.array([0, -1.0, 0])  # orien z; ez = ex x ey
worst = 0.0
for k in range(len(p)):
    for e in range(n):
        Rp, Rq = qm(q[k, e]), qm(q[k, e + 1])
        lh = p[k, e + 1] - p[k, e]
        lh /= np.linalg.norm(lh)
        e2 = 0.5 * (np.dot(Rp @ ez0, Rq @ ey0) - np.dot(Rp @ ey0, Rq @ ez0))
        worst = max(worst, abs(e2), abs(np.dot(Rp @ ey0, lh)), abs(np.dot(Rq @ ey0, lh)))
tip = 2 * np.arccos(min(1, abs(q[-1, -1, 0])))
print(f"flex [1,3,4]: tip rotation {tip:.3f} rad")
st.check(tip > 1.0, "flex [1,3,4] case must undergo large rotation")
st.close(worst, 0.0, atol=1e-10, what="flex [1,3,4]: rigid modes e2/l0, e5/l0, e6/l0 over all steps")

# ---- 3. prescribed rotation of 3 pi at a node of a free beam
a = np.array([1.0, 1.0, 1.0]) / np.sqrt(3)
nodes = [[0, 0, 0], [0.4, 0.1, 0], [0.8, 0.1, 0.2], [1.0, 0.4, 0.3]]
elems = [[1, 2], [2, 3], [3, 4]]
steps = 12
scene = {"title": "prescribed rotation", "nodes": nodes, "elements": elems,
         "nprops": {"1": {"fix_pos": True, "rot": list(3 * np.pi * a)}},
         "eprops": [bt.beam_set([1, 2], w, t)],  # element 3 rigid
         "opt": {"loadsteps": steps, "calccompl": False}}
out, log = st.run("beam_prescribed_rot", bt.yaml_text(scene))
with st.h5(out) as f:
    p, q, lam = f["node/p"][:], f["node/r_quat"][:], f["load_factor"][:]
X = np.array(nodes)
perr = rerr = 0.0
for k in range(steps):
    R = bt.rotvec_matrix(lam[k] * 3 * np.pi * a)
    perr = max(perr, np.abs(p[k] - (X @ R.T)).max())
    rerr = max(rerr, max(np.abs(qm(q[k, j]) - R).max() for j in range(4)))
st.check(abs(lam[-1] - 1) < 1e-15 and len(lam) == steps, "all steps converged")
st.close(perr, 0.0, atol=1e-9, what="rotation 3 pi: node positions vs R(lambda 3 pi a) X, all steps")
st.close(rerr, 0.0, atol=1e-9, what="rotation 3 pi: node rotation matrices vs R(lambda 3 pi a), all steps")
st.done()
