#!/usr/bin/python3
"""out ndof as SPACAR Light counts it (issue 10, item 6): the kinematic degrees of freedom, free node
coordinates minus the rigid deformation modes held exactly, without Lagrange multipliers. Parallel
leaf springs: ground nodes 1, 2 fixed, leaf tops 3, 4 and the stage centre 5 free (18 coordinates),
two flexible leaves, two rigid stage elements (12 held modes): ndof = 6 (Sinew wrote 30, the
equations solved). The other counts are root attributes under their own names: nunknowns = 30,
nnodedofs = 18, nconstraints = 12."""
import sinewtest as st

leaf = {"flex": [1, 2, 3, 4, 5, 6], "emod": 210e9, "smod": 80e9, "cshape": "rect", "dim": [0.02, 0.0005],
        "orien": [0, 0, 1]}
scene = {
    "nodes": [[0, 0, 0], [0.1, 0, 0], [0, 0.05, 0], [0.1, 0.05, 0], [0.05, 0.05, 0]],
    "elements": [[1, 3], [2, 4], [3, 5], [5, 4]],
    "nprops": {1: {"fix": True}, 2: {"fix": True}, 5: {"force": [1, 0, 0]}},
    "eprops": [dict(leaf, elems=[1, 2])],
    "opt": {"loadsteps": 1, "calccompl": False},
}
out, log = st.run("spacar_ndof", scene)
with st.h5(out) as f:
    a = {k: int(f.attrs[k]) for k in ("ndof", "nunknowns", "nnodedofs", "nconstraints")}
print("  attributes:", a)
st.check(a == {"ndof": 6, "nunknowns": 30, "nnodedofs": 18, "nconstraints": 12}, f"counts {a}")
# nbeams adds intermediate nodes, each a free node of 6 coordinates (as SPACAR Light splits the beam)
out, log = st.run("spacar_ndof_nbeams", dict(scene, eprops=[dict(leaf, elems=[1, 2], nbeams=3)]))
with st.h5(out) as f:
    st.check(int(f.attrs["ndof"]) == 6 + 2 * 2 * 6, f"nbeams 3: ndof {int(f.attrs['ndof'])}, expected 30")
st.done()
