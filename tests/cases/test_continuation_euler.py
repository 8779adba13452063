# ctest-labels: smoke
"""Issue 11: a symmetric bifurcation under path following, the perfect Euler column (2 ranks).
A straight cantilever column (L = 1 m, circular d = 10 mm, E = 210 GPa, 20 beam elements, in-plane:
every node fix_z), clamped at the base, the reference load the Euler load P_cr = pi^2 EI / (4 L^2)
pressing the free top axially (the load factor is P / P_cr). No imperfection: the primary path stays
straight and the tangent loses positive definiteness at P_cr, a bifurcation (the load does not turn).
Arc length with the spherical constraint (psi = 1/P_cr so that ds = 0.1 is a load-factor step of 0.1 on
the primary path), -branch_switch.
Checks:
  (1) one bifurcation detected, located by the zero of the eigenvalue changing sign, here the lowest (interpolated between the
      two points around it, 0.9 and 1.2) at the Euler load: |lambda_c - 1| < 1e-3 (measured 6.4e-5;
      the midpoint would be 1.05);
  (2) branch switched: after the bifurcation the path leaves the straight state (tip deflection) and is
      stable (0 negative eigenvalues), while the straight state at the same load had 1;
  (3) the post-buckling path against the elastica (e.g. Timoshenko & Gere 1961, section 2.7):
      P / P_cr = (2 K(k) / pi)^2, k = sin(alpha / 2), alpha the tip rotation (from /node/r_quat), at
      every point of the new branch (at least 3; here 15 up to alpha = 2.26 rad): relative error < 0.5%
      (measured 0.11% at alpha = 1.19 to 0.43% at 2.26 with 20 elements; discretization error: with 40
      elements 0.03% to 0.10%, second order);
  (4) 1 and 2 ranks: the same path to 1e-9, through the switch."""
import numpy as np
from scipy.special import ellipk

import path_scenes as ps
import sinewtest as st

L, d, E, n = 1.0, 0.01, 210e9, 20
EI = E * np.pi * d ** 4 / 64
Pcr = np.pi ** 2 * EI / (4 * L ** 2)
scene, _ = ps.euler_column(n, max_steps=20, L=L, d=d, E=E)
h5_1, _ = st.run("continuation_euler_1", scene, np_=1, args=["-branch_switch"])
h5, out = st.run("continuation_euler", scene, args=["-branch_switch"])
with st.h5(h5_1) as f:
    lam1, p1 = f["load_factor"][:], f["node/p"][:]
with st.h5(h5) as f:
    p2 = f["node/p"][:]
    lam, ux, neg = f["load_factor"][:], f["path/control_displacement"][:], f["path/negative_eigenvalues"][:]
    crit, quat, conv = f["path/critical_points"][:], f["node/r_quat"][:, n, :], int(f.attrs["converged"])
alpha = 2 * np.arccos(np.clip(np.abs(quat[:, 0]), 0, 1))
print("  load factors", np.array2string(lam, precision=5))
print("  tip rotation", np.array2string(alpha, precision=4))
print("  negative eigenvalues", neg.astype(int))
st.check(conv == 1 and len(lam) == 20, f"20 path points, converged ({len(lam)}, {conv})")
# (1) the bifurcation
if st.check(crit.shape == (1, 4) and crit[0, 0] == 2, f"one bifurcation point ({crit})"):
    st.close(crit[0, 2], 1.0, atol=1e-3, what="bifurcation load factor vs the Euler load P_cr")
    st.check("zero of the eigenvalue changing sign" in out, "located by the eigenvalue changing sign (summary)")
# (2) the switch
k = int(crit[0, 1]) if crit.shape == (1, 4) else 0  # points k, k + 1 (1-based) straddle it
st.check("branch switched at path point" in out, "branch switched (progress line)")
after = np.arange(len(lam)) >= k + 1  # 0-based rows from the switched point on
st.check(k > 0 and neg[k] == 1 and np.all(np.abs(ux[:k + 1]) < 1e-9 * L), "the straight column past P_cr: 1 negative eigenvalue, no deflection")
st.check(np.all(np.abs(ux[after]) > 0.1 * L) and np.all(neg[after] == 0), "after the switch: deflected and stable")
# (3) the elastica
branch = after & (alpha > 0.1)
st.check(branch.sum() >= 3, f"{branch.sum()} points on the buckled branch (at least 3)")
kk = np.sin(alpha[branch] / 2)
ref = (2 * ellipk(kk ** 2) / np.pi) ** 2
err = lam[branch] / ref - 1
for a_, l_, r_, e_ in zip(alpha[branch], lam[branch], ref, err):
    print(f"    alpha {a_:.4f} rad: P/Pcr {l_:.6f}, elastica {r_:.6f}, error {e_:+.2e}")
st.close(lam[branch], ref, rtol=5e-3, what="post-buckling load factor vs the elastica (2 K(k)/pi)^2")
# (4) 1 and 2 ranks: the same branch (the eigenvector's sign is fixed by its largest entry) and path
if st.check(len(lam1) == len(lam), "1 and 2 ranks: same number of path points"):
    st.close(lam1, lam, atol=1e-9 * np.abs(lam).max(), what="1 vs 2 ranks: load factors")
    st.close(p1, p2, atol=1e-9 * L, what="1 vs 2 ranks: node positions along the path (through the switch)")
st.done()
