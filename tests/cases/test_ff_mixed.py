# ctest-labels: smoke
"""Mixed tensile structure (issue 5, item 5): runs/sail_masts.yaml, a membrane sail with edge cables
whose low corners sit on two steel masts (3D beams), one model partitioned together. Form finding
(membrane + cables form-found, masts elastic), restart FORCE, wind suction in 5 load steps.
Checks: converged; 1-rank and 2-rank results identical (1e-10); the masts bend toward the sail
by the same amount (the geometry is symmetric about the diagonal x = y; the unstructured mesh nearly: |u| equal to 1e-4);
the mast-foot reactions carry a moment (the masts act as cantilevers)."""
import os

import numpy as np

import sinewtest as st

scene = os.path.join(st.SOURCE, "runs", "sail_masts.yaml")
h1, _ = st.run("sail_masts_1", scene, np_=1)
h2, out = st.run("sail_masts_2", scene, np_=2)
with st.h5(h1) as a, st.h5(h2) as b:
    st.check(int(b.attrs["converged"]) == 1, "converged")
    st.close(b["node/p"][:], a["node/p"][:], atol=1e-10, what="positions, 2 ranks vs 1 rank (all rows)")
    p, p0 = b["node/p"][-1], b["node/p0"][:]
    u3, u5 = p[2] - p0[2], p[4] - p0[4]  # mast tips = sail corners (scene nodes 3 and 5)
    print(f"  mast tip displacements: {u3}, {u5}")
    st.check(np.linalg.norm(u3) > 1e-4, "mast 1 deflects")
    # the unstructured Gmsh mesh is symmetric about x = y only approximately: measured 3.3e-5
    st.close(np.linalg.norm(u5), np.linalg.norm(u3), rtol=1e-4, what="mast tips deflect symmetrically |u|")
    M = b["node/Mreac"][-1]
    st.check(np.linalg.norm(M[0]) > 0 and np.linalg.norm(M[1]) > 0, f"mast feet carry moments {M[0]}, {M[1]}")
st.done()
