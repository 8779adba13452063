#!/usr/bin/python3
"""Issue 11 / docs/results.md "Restart": path following continued from a checkpoint. Lee's frame of
test_continuation_lee.py (20 beam elements per member, arc length, 38 path points through both limit
points and the snap-back) is stopped after k path points as on SIGTERM (-stop_after_step k: exit 5,
converged = 0), then continued with -restart: the checkpoint holds the state (U, reference rotations),
the last path increment (the predictor's direction), the step size, the points so far and the critical
points found. Checked: the restarted file equals the uninterrupted run's, every dataset (load factors,
positions, rotations, /path/negative_eigenvalues, /path/control_displacement, /path/critical_points):
  (1) stopped after 25 points (past the first limit point,
      located after point 14, and the snap-back) and after 37 (past the second, after point 36: both
      critical points in the checkpoint), restarted on 2 ranks: relative difference <= 1e-12
      (measured 0: the continued path is bit-identical);
  (2) stopped after 25 points on 2 ranks, restarted on 1 rank: <= 1e-9 (the 1 vs 2 rank floor;
      measured 8e-16 in the state);
  (3) a restart with another max_steps is refused (exit 2);
  (4) a branch switch (the perfect Euler column of test_continuation_euler.py, -branch_switch, which
      computes the lowest eigenvalue at every point): stopped at the first point past the bifurcation (the
      switch is then done by the restarted run) and at the switched point, restarted on 2 ranks:
      <= 1e-12 (measured 0)."""

import restartutil as ru
import path_scenes as ps
import sinewtest as st

text = ps.lee_frame()[0]
ref, _ = st.run("restart_path_ref", text)
ref1, _ = st.run("restart_path_ref1", text, np_=1)
with st.h5(ref) as f:
    crit = f["path/critical_points"][:]
    print("  uninterrupted: %d points, critical points after %s" % (len(f["load_factor"]), crit[:, 1]))
    st.check(len(f["load_factor"]) == 38 and len(crit) == 2 and 10 < crit[0, 1] < 25 and 25 < crit[1, 1] < 37,
             "the uninterrupted path: 38 points, limit points after points 14 and 36")
for k in (25, 37):
    src = ru.stopped(f"restart_path_stop{k}", text, 2, k)
    with st.h5(src) as f:
        st.check(int(f["checkpoint/scalars"][0]) == 4, f"stopped after {k}: a path-following checkpoint")
    got, out = ru.restarted(f"restart_path_go{k}", text, 2, src)
    st.check("continuing the path following" in out, f"restart after {k}: continues the path following")
    ru.compare(ref, got, f"stopped after {k}, restarted on 2 ranks", tol=1e-12)
got, _ = ru.restarted("restart_path_go25_1", text, 1, ru.stopped("restart_path_stop25b", text, 2, 25))
ru.compare(ref, got, "stopped after 25 on 2 ranks, restarted on 1", tol=1e-9, other_ranks=ref1)
ru.restarted("restart_path_other", ps.lee_frame(40)[0], 2, st.WORK + "/restart_path_stop25.h5", expect_exit=2)

# (4) branch switching across a restart
euler, Pcr = ps.euler_column(max_steps=12)
eref, out = st.run("restart_path_euler_ref", euler, args=["-branch_switch"])
with st.h5(eref) as f:
    ecrit = f["path/critical_points"][:]
    st.check("branch switched at path point" in out and len(ecrit) == 1,
             f"Euler column: switched after the bifurcation ({ecrit})")
kb = int(ecrit[0, 1]) if len(ecrit) == 1 else 3
for k in (kb + 1, kb + 2):
    src = ru.stopped(f"restart_path_euler_stop{k}", euler, 2, k, args=["-branch_switch"])
    got, out = ru.restarted(f"restart_path_euler_go{k}", euler, 2, src, args=["-branch_switch"])
    st.check(("branch switched at path point" in out) == (k == kb + 1),
             f"Euler column stopped after {k}: the switch is done {'by the restarted run' if k == kb + 1 else 'before the stop'}")
    ru.compare(eref, got, f"Euler column stopped after {k} (bifurcation after {kb}), restarted on 2 ranks", tol=1e-12)
st.done()
