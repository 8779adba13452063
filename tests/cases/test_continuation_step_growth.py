"""Issue 24 item 4: without ds_max the arc-length step grows from the first ds within a bound from the
model (2 % of its size in the arc-length metric: |s| with s = the bounding-box diagonal at every free
translation and 1 rad at every free rotation), and the turn of the path per step bounds it where the
path curves. The issue's deep arch (DaDeppo & Schmidt's 215 degree circular arch, R = 100, EI = 1e6,
EA = 1e8, clamped at one end, pinned at the other, 1000 N at the apex = load factor 1, 40 elements)
with `ds: 1` spent 400 points reaching load factor 0.69 of its 0.886 limit, the step capped at ds.
Measured (1 rank): with ds_max = ds = 1 the limit point 0.886467 (apex -113.229) is between path points
601 and 602, the second limit -0.0727491 after point 1095; by default after point 51 (0.886467 at
-113.228) and 103 (-0.0727491). Checks (2 ranks):
  (1) default: the first limit point within 60 points, its load factor 0.886467 to 1e-5 (DaDeppo &
      Schmidt's inextensible arch: P R^2/EI = 8.97; this extensible one with 40 elements 8.865);
  (2) `ds_max: 1` keeps its meaning: 60 points of length 1 stay below load factor 0.3."""
import numpy as np

import path_scenes as ps
import sinewtest as st

text, c = ps.deep_arch({"method": "arclength", "ds": 1.0, "max_steps": 60})
h5, out = st.run("continuation_growth_default", text)
with st.h5(h5) as f:
    lam, crit, conv = f["load_factor"][:], f["path/critical_points"][:], int(f.attrs["converged"])
print(f"  default: {len(lam)} points, critical points {crit.tolist()}")
if st.check(len(crit) >= 1 and crit[0, 0] == 1, "a limit point within 60 points"):
    print(f"  limit point after path point {int(crit[0, 1])}")
    st.close(crit[0, 2], 0.886467, rtol=1e-5, what="limit load factor (ds_max = ds = 1: 0.886467 after point 601)")
text, c = ps.deep_arch({"method": "arclength", "ds": 1.0, "ds_max": 1.0, "max_steps": 60})
h5, out = st.run("continuation_growth_explicit", text)
with st.h5(h5) as f:
    lam1 = f["load_factor"][:]
print(f"  ds_max 1: load factor {lam1[-1]:.5f} after 60 points")
st.check(lam1[-1] < 0.3 and len(lam1) == 60, f"ds_max 1: 60 points below 0.3 ({lam1[-1]:.4f})")
st.done()
