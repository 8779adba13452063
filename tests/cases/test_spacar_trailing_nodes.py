#!/usr/bin/python3
"""Trailing unconnected nodes (issue 10, item 10): SPACAR Light allows nodes after the last node an
element connects. Sinew warns, holds them fixed (no unknowns: the solve is not singular) and reports
them at their input positions with zero reactions. On 2 ranks, an L-frame (two flexible beams, a tip
force and a tip mass; frequencies and compliance computed) with two trailing nodes gives the same
results as without them; a support on a trailing node is accepted. An unconnected node before the
last connected one stays an error naming it, and so does a load or a mass on a trailing node or a
path-following control node there."""
import numpy as np

import sinewtest as st

beam = {"flex": [1, 2, 3, 4, 5, 6], "emod": 210e9, "smod": 80e9, "dens": 7800, "cshape": "circ", "dim": 0.01}
base = {
    "nodes": [[0, 0, 0], [0.5, 0, 0], [0.5, 0.5, 0]],
    "elements": [[1, 2], [2, 3]],
    "nprops": {1: {"fix": True}, 3: {"force": [0, 0, -5], "mass": 0.5}},
    "eprops": [dict(beam, elems=[1, 2], nbeams=2)],
    "opt": {"loadsteps": 3, "nfreq": 4},
}
trailing = dict(base, nodes=base["nodes"] + [[2, 2, 2], [3, 0, 1]],
                nprops={**base["nprops"], 5: {"fix": True}})

ref, _ = st.run("trailing_ref", base)
out, log = st.run("trailing", trailing)
st.check("warning: nodes 4..5 are not connected to any element (trailing nodes, allowed as in SPACAR Light)" in log,
         "warning naming the trailing nodes: " + log[:300])
with st.h5(ref) as r, st.h5(out) as f:
    st.check(f["node/p"].shape == (3, 5, 3), f"/node/p has the 5 scene nodes, shape {f['node/p'].shape}")
    st.close(f["node/p"][:, :3], r["node/p"][:], rtol=1e-12, what="connected nodes as without the trailing ones")
    st.close(f["node/p"][:, 3:], np.broadcast_to([[2, 2, 2], [3, 0, 1]], (3, 2, 3)), atol=0,
             what="trailing nodes stay at their input positions")
    st.close(f["node/Freac"][:, 3:], 0 * f["node/Freac"][:, 3:], atol=0, what="no reactions at the trailing nodes")
    st.close(f["node/Freac"][:, :3], r["node/Freac"][:], rtol=1e-9, atol=1e-12, what="reactions of the connected nodes")
    st.close(f["freq"][:], r["freq"][:], rtol=1e-9, what="frequencies as without the trailing nodes")
    st.close(f["node/CMglob"][:, :3], r["node/CMglob"][:], rtol=1e-9, atol=1e-15, what="compliance of the connected nodes")
    st.check(np.all(np.isfinite(f["node/CMglob"][:])), "compliance finite everywhere")
    st.check(int(f.attrs["ndof"]) == int(r.attrs["ndof"]), "trailing nodes add no degrees of freedom")

# an unconnected node in the middle is still an error, naming it
middle = dict(base, nodes=[[0, 0, 0], [9, 9, 9], [0.5, 0, 0], [0.5, 0.5, 0]], elements=[[1, 3], [3, 4]],
              nprops={1: {"fix": True}, 4: {"force": [0, 0, -5]}})
_, log = st.run("trailing_middle", middle, expect_exit=2)
st.check("nodes(2)" in log and "node 2 is not connected to any element" in log, "middle unconnected node: " + log.strip()[-300:])
# a load or a mass on a trailing node has nothing to act on
for field, value in (("force", [1, 0, 0]), ("mass", 1.0)):
    bad = dict(trailing, nprops={**base["nprops"], 5: {field: value}})
    _, log = st.run("trailing_" + field, bad, expect_exit=2)
    st.check(f"nprops(5).{field}" in log and "not connected" in log, f"{field} on a trailing node: " + log.strip()[-300:])
# path following controlled at a trailing node: refused, naming the field
cont = dict(trailing, opt={"continuation": {"method": "arclength", "ds": 0.01, "node": 5, "direction": "y",
                                            "stop_displacement": -0.1}})
_, log = st.run("trailing_continuation", cont, expect_exit=2)
st.check("opt.continuation.node" in log and "not connected" in log, "continuation node on a trailing node: " + log.strip()[-300:])
st.done()
