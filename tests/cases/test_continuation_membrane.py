#!/usr/bin/python3
"""Issue 11 item 1: path following of a form-found membrane with edge cables (membrane + 3D cable
elements), 2 ranks. The four-point sail of ffscenes.sail_scene (unit square, 8 x 8 cells of 4
triangles, corners (1,0), (0,1) lifted by 0.5 m, membrane prestress 1 N/m, edge cables 4 N, 10 URS
steps with elastic_restart_method FORCE), then a follower pressure of 1 Pa (reference load; the load
factor is the pressure in Pa) followed by arc length from the form-found state (the state that
already carries the lifted corners, prestress kept). The membrane has no wrinkling model: under the
pressure its stresses turn compressive and it snaps (a limit point near 9.4 Pa, then further
critical points; at the first limit point three eigenvalues turn negative within one
step, so the count goes 0 -> 3, not by one). Checked:
  (1) the path starts from the form-found state (its first point's centre node near the found
      z = 0.25 m) and passes the first limit point: the load factor decreases after it and rises
      again beyond it (the path continues past 9.4 Pa, to 11.8 Pa);
  (2) on the stable part (no negative eigenvalue) the path points agree with load stepping (10 load
      steps to the same pressure) to 1e-8 m (measured 6e-15 m);
  (3) the stability checks take the symmetric part of the tangent (the follower pressure makes it
      unsymmetric): SLEPc's lowest eigenvalue of it is negative exactly where MUMPS' inertia counts
      negative eigenvalues;
  (4) 1 and 2 ranks: the same path (load factors and positions to 1e-9, the same counts);
  (5) restart (-restart) of the path after form finding: stopped after 15 rows (10 form-finding steps,
      5 path points), continued on 2 ranks: the file equals the uninterrupted one to 1e-10 (measured:
      state 6.5e-14, at most 8.1e-12 in /path/lowest_eigenvalue; the form-found element states come
      from the checkpoint)."""
import numpy as np

import ffscenes as ff
import restartutil as ru
import sinewtest as st

n = 8
sc, idx = ff.sail_scene(n=n, steps=10, pressure=1.0, tol=0.0)
c = idx[("v", n // 2, n // 2)] + 1
sc["opt"] = {"calccompl": False, "continuation": {"method": "arclength", "ds": 0.01, "ds_max": 0.05, "node": c,
                                                   "direction": "z", "max_steps": 9}}
runs = {}
for np_ in (2, 1):
    h5, out = st.run(f"continuation_sail_{np_}", ff.to_yaml(sc), np_=np_, args=["-continuation_lowest_eigenvalue"])
    with st.h5(h5) as f:
        nff = len(f["formfinding/residual"][:])
        runs[np_] = (f["load_factor"][nff:], f["node/p"][nff:], f["path/negative_eigenvalues"][nff:])
        if np_ == 2:
            crit, low = f["path/critical_points"][:], f["path/lowest_eigenvalue"][nff:]
            zfound = f["node/p"][nff - 1, c - 1, 2]
            conv = int(f.attrs["converged"])
lam, p, neg = runs[2]
print("  load factors (pressure, Pa)", np.array2string(lam, precision=4))
print("  negative eigenvalues", neg.astype(int))
print("  lowest eigenvalues", np.array2string(low, precision=3))
st.check(conv == 1 and len(lam) == 9, f"path converged, 9 points ({len(lam)})")
st.check(abs(zfound - 0.25) < 1e-3 and abs(p[0, c - 1, 2] - zfound) < 0.01,
         f"the path starts from the form-found shape (centre z {zfound:.6f} found, {p[0, c - 1, 2]:.6f} at the first point)")
if st.check(len(crit) >= 1 and crit[0, 0] == 1, f"the first critical point is a limit point ({crit[:2]})"):
    k = int(crit[0, 1])
    st.check(np.all(neg[:k] == 0) and neg[k] > 0, "stable before the first limit point, unstable after it")
    st.check(lam[k] < crit[0, 2] and lam[k + 1] < lam[k] and lam[-1] > crit[0, 2] + 2,
             f"the load falls after the limit point ({crit[0, 2]:.4f} Pa) and the path continues beyond it ({lam[-1]:.4f} Pa)")
st.check(np.array_equal(low < 0, neg > 0), "SLEPc's lowest eigenvalue < 0 exactly where the inertia counts negative eigenvalues")
lam1, p1, neg1 = runs[1]
if st.check(len(lam1) == len(lam), "1 and 2 ranks: same number of path points"):
    st.close(lam1, lam, atol=1e-9 * lam.max(), what="1 vs 2 ranks: load factors [Pa]")
    st.close(p1, p, atol=1e-9, what="1 vs 2 ranks: positions [m]")
    st.check(np.array_equal(neg1, neg), "1 vs 2 ranks: negative eigenvalue counts")
# (2) load stepping to the pressure of stable path points
for k in (2, 4):
    st.check(neg[k] == 0, f"path point {k + 1} is stable")
    s2, _ = ff.sail_scene(n=n, steps=10, pressure=float(lam[k]), tol=0.0)
    s2["opt"] = {"calccompl": False, "loadsteps": 10}
    h5s, _ = st.run(f"continuation_sail_ls{k + 1}", ff.to_yaml(s2))
    with st.h5(h5s) as f:
        ps = f["node/p"][-1]
    st.close(p[k], ps, atol=1e-8, what=f"path point {k + 1} ({lam[k]:.4f} Pa) vs load stepping: positions [m]")
# (5) restart after form finding
src = ru.stopped("continuation_sail_stop", ff.to_yaml(sc), 2, 15, args=["-continuation_lowest_eigenvalue"])
got, out = ru.restarted("continuation_sail_restarted", ff.to_yaml(sc), 2, src, args=["-continuation_lowest_eigenvalue"])
st.check("continuing the path following" in out, "restart: continues the path following")
ru.compare(st.WORK + "/continuation_sail_2.h5", got, "sail path stopped after 15 rows, restarted", tol=1e-10)
st.done()
