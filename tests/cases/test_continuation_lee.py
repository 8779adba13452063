"""Issue 11: Lee's frame under arc-length continuation (beams, 2 ranks; 1 vs 2 ranks).
Two members of length L = 120 (a column from the pinned base (0, 0) up to the rigid corner and a beam
to the pinned support (L, L)), E = 720, rectangular section b x h = 3 x 2 (A = 6, I = 2), a downward
load P at 24 from the corner; 20 beam elements per member, in-plane (every node fix_z). Units are
consistent (kN, cm): the nondimensional load is P L^2 / (E I) = 10 P.
Reference: the maximum load P_max L^2/(EI) = 18.5 reported for this frame by Schweizerhof & Wriggers
(1986, "Consistent linearization for path following methods in nonlinear FE analysis", CMAME 59) and
reproduced by Battini & Pacoste (2002, CMAME 191, Lee's frame example); tolerance 1%.
Checks:
  (1) the path passes the first limit point (load maximum), a snap-back in the load-point deflection v
      (v turns back while the load keeps falling: no critical point, the negative-eigenvalue count
      stays 1) and the second limit point (load minimum, with P < 0);
  (2) the count of negative eigenvalues of the tangent (MUMPS inertia) changes by exactly one at each
      limit point and nowhere else, and equals 1 exactly where SLEPc's lowest eigenvalue of the same
      tangent is negative (-continuation_lowest_eigenvalue);
  (3) first limit load vs 18.5 (literature); the second limit load and the deflections at both limit
      points are compared with this code's own values from a run with ds = 6 (regression, not a
      literature value, which we did not have at hand: -9.248, v = 48.66 and 58.29);
  (4) 1 and 2 ranks: the same path to 1e-9 (load factors and deflections)."""
import numpy as np

import path_scenes as ps
import sinewtest as st

L, E, n = 120.0, 720.0, 20
EI = E * 2.0


text, load = ps.lee_frame()
runs = {}
for np_ in (2, 1):
    args = ["-continuation_lowest_eigenvalue"] if np_ == 2 else []
    h5, out = st.run(f"continuation_lee_{np_}", text, np_=np_, args=args)
    with st.h5(h5) as f:
        runs[np_] = dict(lam=f["load_factor"][:], v=-f["path/control_displacement"][:],
                         neg=f["path/negative_eigenvalues"][:], crit=f["path/critical_points"][:],
                         low=f["path/lowest_eigenvalue"][:] if "path/lowest_eigenvalue" in f else None,
                         p=f["node/p"][:], conv=int(f.attrs["converged"]))
r = runs[2]
lam, v, neg, crit = r["lam"], r["v"], r["neg"], r["crit"]
st.check(r["conv"] == 1 and len(lam) == 38, f"38 path points, converged ({len(lam)}, {r['conv']})")
print("  load factors", np.array2string(lam, precision=4))
print("  deflection v", np.array2string(v, precision=3))
print("  negative eigenvalues", neg.astype(int))
# (1) snap-back in v: v rises, turns back (decreases) while the load falls, then rises again
dv = np.diff(v)
turns = np.nonzero(np.sign(dv[1:]) != np.sign(dv[:-1]))[0] + 1
st.check(len(turns) >= 2, f"the deflection v turns back twice (snap-back): at points {turns + 1}")
if len(turns):
    k = turns[0]
    st.check(neg[k] == 1 and neg[k + 1] == 1 and lam[k + 1] < lam[k],
             f"at the snap-back (point {k + 1}, v = {v[k]:.3f}) the load falls and the count stays 1")
# (2) inertia changes by one at each limit point only; SLEPc's lowest eigenvalue has the matching sign
st.check(np.all(np.abs(np.diff(neg)) <= 1), "the count changes by at most one between points")
changes = np.nonzero(np.diff(neg))[0]
st.check(len(changes) == 2 and neg[0] == 0 and neg[-1] == 0, f"0 -> 1 -> 0 negative eigenvalues (changes after {changes + 1})")
low = r["low"]
if st.check(low is not None, "/path/lowest_eigenvalue written with -continuation_lowest_eigenvalue"):
    print("  lowest eigenvalue", np.array2string(low, precision=3))
    st.check(np.array_equal(low < 0, neg == 1), "SLEPc's lowest eigenvalue < 0 exactly where the inertia counts 1")
# (3) limit loads
if st.check(crit.shape == (2, 4) and np.all(crit[:, 0] == 1), f"two limit points located: {crit}"):
    st.close(crit[0, 2] * L ** 2 / EI, 18.5, rtol=0.01, what="first limit load P L^2/EI (literature 18.5)")
    st.check(crit[1, 2] < 0, f"second limit load negative ({crit[1, 2]:.5f})")
    st.close(crit[1, 2] * L ** 2 / EI, -9.248, rtol=0.01, what="second limit load P L^2/EI (regression)")
    st.close(-crit[:, 3], [48.66, 58.29], rtol=0.01, what="deflection v at the limit points (regression)")
    st.check(lam.max() <= crit[0, 2] * (1 + 1e-9) and lam.min() >= crit[1, 2] * (1 + 1e-9),
             "no path point beyond the located limit loads")
# (4) 1 vs 2 ranks
r1 = runs[1]
if st.check(len(r1["lam"]) == len(lam), "1 and 2 ranks: same number of path points"):
    st.close(r1["lam"], lam, atol=1e-9 * np.abs(lam).max(), what="1 vs 2 ranks: load factors")
    st.close(r1["p"], r["p"], atol=1e-9 * L, what="1 vs 2 ranks: node positions along the path")
    st.check(np.array_equal(r1["neg"], neg), "1 vs 2 ranks: negative eigenvalue counts")
st.done()
