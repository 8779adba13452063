"""-target_error's reuse between levels in time (docs/accuracy.md, "Reuse between levels"), 2 ranks: a
level that halves dt starts each time step's Newton from the coarser level's time steps (its state at
every other step, the cubic Hermite in time of its positions, rotations and velocities in between)
instead of the scheme's predictor. A steel leaf (1 m x 20 mm x 2 mm, nbeams 4) under a tip force rising
smoothly over T1 / 2 to 0.3 x 3 EI / L^3 (large motion: the tip turns by 0.4 rad), generalized-alpha
rho = 0.9 to T1 / 2 from dt = T1 / 40, target 1e-4, with -accuracy_reuse 1 (default) and 0: the same
levels, estimates and orders, the level values to Newton's tolerance, every step of every level after
the first started from the coarser level (/accuracy reused_starts), and fewer Newton iterations on the
two finest levels with reuse (measured 482 against 637)."""
import numpy as np

import leaf_dynamics_scene as leaf
import sinewtest as st


def study(path):
    with st.h5(path) as f:
        g = f["accuracy"]
        return {k: g[k][:] for k in ("level", "worst_error", "limiting", "order", "status", "value",
                                     "newton_iterations", "reused_starts")}


runs, outs = {}, {}
for reuse in (1, 0):
    path, outs[reuse] = st.run(f"accuracy_time_reuse_{reuse}", leaf.smooth_large(),
                               args=["-target_error", "1e-4", "-accuracy_reuse", str(reuse)])
    runs[reuse] = study(path)
on, off = runs[1], runs[0]
its_on, its_off = on["newton_iterations"].astype(int), off["newton_iterations"].astype(int)
print(f"  levels {list(on['level'])}, Newton iterations per level {list(its_on)} with reuse, {list(its_off)} without "
      f"({its_on.sum()} against {its_off.sum()}); steps started from the coarser level {list(on['reused_starts'])}")
st.check(len(on["level"]) >= 3 and np.array_equal(on["level"], off["level"]), "the same levels (at least 3)")
st.check(np.array_equal(on["limiting"], off["limiting"]), "the same limiting quantities")
st.check(np.array_equal(on["status"], off["status"]), "the same statuses")
# the histories to Newton's tolerance, relative to each history's largest row on that level
v_on, v_off = np.nan_to_num(on["value"]), np.nan_to_num(off["value"])
rows_on = v_on.reshape(v_on.shape[0], v_on.shape[1], -1, 3)
rows_off = v_off.reshape(rows_on.shape)
size = np.maximum(np.max(np.linalg.norm(rows_off, axis=3), axis=2), 1e-300)
change = np.max(np.max(np.linalg.norm(rows_on - rows_off, axis=3), axis=2) / size)
print(f"  largest relative change of a level's history {change:.1e}")
st.check(change < 1e-8, f"the level histories do not depend on the Newton start ({change:.1e})")
st.check(np.allclose(on["worst_error"][2:], off["worst_error"][2:], rtol=1e-5, atol=0), "the same worst estimates")
st.check(np.allclose(on["order"][2:], off["order"][2:], rtol=0, atol=1e-4, equal_nan=True), "the same observed orders")
st.check(np.all(off["reused_starts"] == 0), "-accuracy_reuse 0 starts no step from a coarser level")
steps = leaf.STEPS0 * 2 ** on["level"][1:].astype(int)
st.check(np.array_equal(on["reused_starts"][1:].astype(int), steps),
         f"with reuse every step of every level after the first starts from the coarser level "
         f"({list(on['reused_starts'][1:])} of {list(steps)})")
st.check("steps started from the coarser level" in outs[1], "the reported level's summary counts its coarse starts")
fine_on, fine_off = int(its_on[-2:].sum()), int(its_off[-2:].sum())
st.check(fine_on < 0.85 * fine_off, f"reuse saves Newton iterations on the two finest levels ({fine_on} against {fine_off})")
st.done()
