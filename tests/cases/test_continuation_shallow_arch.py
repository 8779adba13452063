"""Issue 24 item 4: the shallow pinned arch of the issue (circular, span 1 m, rise 10 mm, 20 x 4 mm
bending about the weak axis in the arch plane, steel, pins at both ends, 100 N down at mid-span = load
factor 1, 40 beam elements, ds 0.002 without ds_max) against shallow-arch theory
(tests/cases/shallow_arch_theory.py: Marguerre's equations, sine series exact for the point load).
With h/r = 8.66 the symmetric path is not a simple snap: the thrust reaches the antisymmetric mode's
load N2 = 4 pi^2 EI/L^2 at 38.10 N (u = -3.28 mm), before the symmetric limit 41.55 N (u = -5.16 mm),
so a real arch snaps asymmetrically there; the symmetric path (which a perfect symmetric model follows)
then falls to -61.95 N, its centre deflection turns back at u = -17.12 mm, the load rises again to
55.39 N near u = -6.08 mm, the deflection turns again at u = -5.66 mm, the load falls to -44.92 N and
rises through zero at the inverted state u = -20.15 mm. The turn-back is that loop, not a retrace, so
no turn-back warning. Checks (2 ranks, -continuation_lowest_eigenvalue):
  (1) the located critical points vs theory: the first bifurcation, the four limit points;
  (2) the centre deflection's two turns and the inverted state (load factor crossing 0) vs theory;
  (3) the count of negative eigenvalues: 0 before the bifurcation, 1 from it to the first limit point;
  (4) the path stays symmetric (the quarter-span points move alike);
  (5) no turn-back warning; the path reaches u = -22 mm in fewer than 150 points (116) (the step grows from
      ds by default: 400 points of ds = 0.002 reached u = -21.7 mm before)."""
import numpy as np

import path_scenes as ps
import sinewtest as st

# shallow-arch theory, from `shallow_arch_theory.py` run as a script (200 modes, h = 2e-3: 2 minutes,
# hence stored): (deflection [m], load [N]) in path order
bif = (-0.003282, 38.1027)  # N = N2: the antisymmetric mode bifurcates
limits = [(-0.005162, 41.5473), (-0.015532, -61.9547), (-0.006076, 55.3895), (-0.016500, -44.9183)]
turns = [-0.017115, -0.005661]  # the centre deflection turns back (P -45.22 N), then on again (P 49.04 N)
inverted = -0.020154  # the load rises through 0: the inverted state

text, c = ps.pinned_shallow_arch({"method": "arclength", "ds": 0.002, "max_steps": 400, "stop_displacement": -0.022})
h5, out = st.run("continuation_shallow_arch", text, args=["-continuation_lowest_eigenvalue"])
with st.h5(h5) as f:
    lam, u = f["load_factor"][:], f["path/control_displacement"][:]
    neg, crit = f["path/negative_eigenvalues"][:], f["path/critical_points"][:]
    p = f["node/p"][:]
    conv = int(f.attrs["converged"])
P = 100 * lam
print(f"  Sinew: {len(lam)} points, critical points\n{np.array2string(crit, precision=6)}")
st.check(conv == 1 and u[-1] <= -0.022, f"reaches u = -22 mm, converged ({u[-1]:.5f}, {conv})")
st.check(len(lam) < 150, f"fewer than 150 points ({len(lam)})")
# (1) critical points
lim = crit[crit[:, 0] == 1]
bifs = crit[crit[:, 0] == 2]
if st.check(len(lim) == 4, f"four limit points ({len(lim)})"):
    for (w, Pt), row in zip(limits, lim):
        st.close(100 * row[2], Pt, rtol=5e-3, what=f"limit load [N] (theory {Pt:.4f})")
        st.close(row[3], w, rtol=5e-3, what=f"deflection at the limit point [m] (theory {w:.6f})")
if st.check(len(bifs) >= 1, "a bifurcation before the first limit point"):
    st.check(bifs[0, 1] < lim[0, 1], "the bifurcation comes first")
    # located by the zero of the eigenvalue changing sign, linear over a step of the grown size
    st.close(100 * bifs[0, 2], bif[1], rtol=5e-2, what=f"first bifurcation [N] (theory N = N2 at {bif[1]:.4f})")
# (2) turns of the deflection and the inverted state
du = np.diff(u)
k = np.nonzero(np.sign(du[1:]) != np.sign(du[:-1]))[0] + 1
st.check(len(k) == 2, f"the deflection turns twice ({len(k)})")
for kk, w in zip(k, turns):
    st.close(u[kk], w, rtol=5e-3, what=f"turn of the deflection [m] (theory {w:.6f})")
z = np.nonzero((lam[:-1] < 0) & (lam[1:] >= 0))[0]
if st.check(len(z) >= 1, "the load factor rises through 0 at the end"):
    i = z[-1]
    uz = u[i] + (0 - lam[i]) / (lam[i + 1] - lam[i]) * (u[i + 1] - u[i])
    st.close(uz, inverted, rtol=5e-3, what=f"inverted state, load 0 [m] (theory {inverted:.6f})")
# (3) stability: 0 before the bifurcation, 1 up to the first limit point
b, l1 = int(bifs[0, 1]) if len(bifs) else 0, int(lim[0, 1]) if len(lim) else 0
st.check(np.all(neg[:b] == 0) and np.all(neg[b:l1] == 1), f"counts 0 then 1 ({neg[:l1 + 1].astype(int)})")
# (4) symmetry: nodes at x = L/4 and 3L/4 (11 and 31) move alike in y, opposite in x
n = 40
st.close(p[:, 10, 1], p[:, 30, 1], atol=1e-9, what="symmetric path: quarter-span deflections [m]")
# (5) no turn-back warning
st.check("turns back on itself" not in out, "no turn-back warning (the loop is the symmetric path)")
st.done()
