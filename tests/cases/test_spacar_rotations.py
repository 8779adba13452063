#!/usr/bin/python3
"""SPACAR Light's rotation vocabulary (issue 10, items 2 and 3). A rigid arm from node 1 (position
held) to node 2 = (1, 0, 0); node 1 has rot_initial in the seed's 1x4 form [angle, axis] = [0.3, 0, 0, 2]
(axis normalized) and a ramped rot given as a rotation vector [0, 0, 0.3]. Over 3 SPACAR Light steps the
arm is at 0.3, 0.45, 0.6 rad about z: node 2 at (cos a, sin a, 0), and /node/r_axang is
[angle; axis] = [a, 0, 0, 1] in the seed's order."""
import numpy as np

import sinewtest as st

scene = {
    "nodes": [[0, 0, 0], [1, 0, 0]],
    "elements": [[1, 2]],
    "nprops": {1: {"fix_pos": True, "rot_initial": [0.3, 0, 0, 2], "rot": [0, 0, 0.3]}},
    "opt": {"loadsteps": 3, "calccompl": False},
}
out, log = st.run("spacar_rotations", scene)
a = np.array([0.3, 0.45, 0.6])
with st.h5(out) as f:
    p, aa = f["node/p"][:], f["node/r_axang"][:]
st.close(p[:, 1, :], np.stack([np.cos(a), np.sin(a), 0 * a], axis=1), atol=1e-10, what="arm tip positions")  # Newton tolerance of the rigid arm
for node in (0, 1):
    st.close(aa[:, node, :], np.stack([a, 0 * a, 0 * a, 1 + 0 * a], axis=1), atol=1e-12,
             what=f"node {node + 1} r_axang = [angle, axis]")

# a zero axis is a scene error naming the field
bad = dict(scene, nprops={1: {"fix_pos": True, "rot_initial": [0.3, 0, 0, 0]}})
_, log = st.run("spacar_rotations_zero_axis", bad, expect_exit=2)
st.check("nprops(1).rot_initial" in log and "axis" in log, "zero axis: " + log.strip()[-200:])
st.done()
