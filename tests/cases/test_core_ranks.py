"""Results do not depend on the number of ranks: the cross-flexure hinge (runs/crosshinge.yaml,
with frequencies and stress) and a braced 3D tower (hundreds of DOFs, rigid members) on 1, 2 and
3 ranks give the same positions, rotations, reactions and stresses to 1e-9 (relative to each
field's largest value)."""
import os

import numpy as np

import beamtools as bt
import frames
import sinewtest as st

FIELDS = ["node/p", "node/r_quat", "node/Freac", "node/Mreac", "stressmax", "freq"]
hinge = os.path.join(st.SOURCE, "runs", "crosshinge.yaml")
tower = st.scene_file("ranks_tower", bt.yaml_text(frames.tower(nx=3, ny=2, nz=5)[0]))
for name, path in (("crosshinge", hinge), ("tower", tower)):
    res = {}
    for n in (1, 2, 3):
        out, log = st.run(f"ranks_{name}_{n}", path, np_=n)
        with st.h5(out) as f:
            res[n] = {k: f[k][:] for k in FIELDS if k in f}
            st.check(f.attrs["nranks"] == n, f"{name}: nranks attribute")
    for k in res[1]:
        ref = res[1][k]
        scale = max(np.abs(ref).max(), 1e-300)
        for n in (2, 3):
            st.close(res[n][k] / scale, ref / scale, atol=1e-9, what=f"{name} {k}: {n} ranks vs 1 rank (scaled)")
st.done()
