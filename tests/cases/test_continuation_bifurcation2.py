"""Issue 11: a second bifurcation on one path located by the eigenvalue that changes sign (2 ranks).
The perfect Euler column of test_continuation_euler (cantilever, L = 1 m, circular d = 10 mm, E = 210 GPa,
20 beam elements, in-plane), reference load P_cr = pi^2 EI / (4 L^2) at the top, pushed along the
straight primary path (no -branch_switch) with arc length ds = ds_max = 0.7 (path points every 0.7 P_cr)
to 9.8 P_cr, -continuation_lowest_eigenvalue. The column's buckling loads are (2 m - 1)^2 P_cr
(Timoshenko & Gere 1961, section 2.1): the first at P_cr, the second at 9 P_cr.
At the second bifurcation the count goes 1 -> 2 between the points at 8.4 and 9.1 P_cr; the lowest
eigenvalue of the tangent (the first mode's) is already negative at both (-76 and -83), so it cannot
locate it: the earlier rule put it at the midpoint 8.75 P_cr (-2.8%; this test run once with the
previous continuation_analysis.cpp: 8.750, checks (3) fail). The second smallest eigenvalue (with k negative eigenvalues before, the (k+1)-th smallest:
the smallest positive one at 8.4, the largest negative one at 9.1) changes sign there, and its linear
interpolation over the step gives the bifurcation.
Checks:
  (1) two bifurcations (kind 2), counts 0 -> 1 -> 2 changing at them only;
  (2) the first at P_cr: |lambda_1 - 1| < 1e-3 (measured 0.999762, -2.4e-4);
  (3) the second at 9 P_cr: |lambda_2 / 9 - 1| < 2e-3 (measured 8.99765, -2.6e-4; the midpoint rule
      gives 8.75, -2.8%, and fails), both located by the eigenvalue changing sign (summary);
  (4) the lowest eigenvalue is negative at both points around the second bifurcation (so the lowest one
      is not the one that crosses zero there)."""
import numpy as np
import yaml

import path_scenes as ps
import sinewtest as st

text, Pcr = ps.euler_column(20, max_steps=20)
scene = yaml.safe_load(text)
scene["opt"]["continuation"].update({"ds": 0.7, "ds_max": 0.7, "stop_load_factor": 9.5})
h5, out = st.run("continuation_bifurcation2", scene, args=["-continuation_lowest_eigenvalue"])
with st.h5(h5) as f:
    lam, neg, low = f["load_factor"][:], f["path/negative_eigenvalues"][:].astype(int), f["path/lowest_eigenvalue"][:]
    crit, conv = f["path/critical_points"][:], int(f.attrs["converged"])
print("  load factors", np.array2string(lam, precision=4))
print("  negative eigenvalues", neg)
print("  lowest eigenvalue", np.array2string(low, precision=3))
print("  critical points", crit.tolist())
st.check(conv == 1 and lam[-1] >= 9.5, f"path converged past 9.5 P_cr ({lam[-1]:.3f})")
if st.check(crit.shape == (2, 4) and np.all(crit[:, 0] == 2), f"two bifurcation points ({crit.tolist()})"):
    k1, k2 = int(crit[0, 1]), int(crit[1, 1])  # 1-based points before them: rows k - 1 and k straddle each
    st.check(np.all(neg[:k1] == 0) and np.all(neg[k1:k2] == 1) and np.all(neg[k2:] == 2),
             "counts 0 -> 1 -> 2, changing at the two bifurcations only")
    st.close(crit[0, 2], 1.0, atol=1e-3, what="first bifurcation vs P_cr")
    st.close(crit[1, 2], 9.0, rtol=2e-3, what="second bifurcation vs 9 P_cr")
    st.check(lam[k2 - 1] < 9.0 < lam[k2] and abs(0.5 * (lam[k2 - 1] + lam[k2]) / 9.0 - 1) > 2e-3,
             f"the second is bracketed by {lam[k2 - 1]:.3f} and {lam[k2]:.3f} (their midpoint is outside the tolerance)")
    st.check(low[k2 - 1] < 0 and low[k2] < 0, "the lowest eigenvalue is negative on both sides of the second bifurcation")
st.check(out.count("zero of the eigenvalue changing sign") == 2, "both located by the eigenvalue changing sign (summary)")
st.done()
