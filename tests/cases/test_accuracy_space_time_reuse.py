"""-target_error's reuse between dynamics levels that refine the elements (docs/accuracy.md, "Reuse between
levels in space and time"), 2 ranks: with `accuracy_refine: both` every level doubles nbeams and halves dt,
so its nodes, unknowns and partition differ from the coarser level's; the coarser level records the state
and rates of every FE node at every time step (gathered by node number), and the finer level starts each
time step's Newton from its own q_n plus the coarser level's motion over the step, interpolated in time
(cubic Hermite, rotations on SO(3)) and mapped onto its nodes (inherited nodes their own, midside nodes the
element's cubic and the rotation turned to its tangent). The steel leaf of test_accuracy_time_reuse from one
element (nbeams 1; large motion, the tip turns by 0.4 rad), target 1e-4 (4 levels: nbeams 1 .. 8, dt / 1 ..
dt / 8), with -accuracy_reuse 1 (default) and 0: the same levels, limiting quantities, statuses, estimates
and orders, the level histories to Newton's tolerance, every step of every level after the first started
from the coarser level, none without reuse, and fewer Newton iterations on the finest level with reuse
(measured 320 against 412: 0.78; the check asks below 0.9)."""
import numpy as np

import leaf_dynamics_scene as leaf
import sinewtest as st


def study(path):
    with st.h5(path) as f:
        g = f["accuracy"]
        return {k: g[k][:] for k in ("level", "worst_error", "limiting", "order", "status", "value",
                                     "newton_iterations", "reused_starts")}


scene = leaf.smooth_large(1).replace("opt:", "opt:\n  accuracy_refine: both", 1)
runs = {}
for reuse in (1, 0):
    path, _ = st.run(f"accuracy_space_time_reuse_{reuse}", scene,
                     args=["-target_error", "1e-4", "-accuracy_reuse", str(reuse)])
    runs[reuse] = study(path)
on, off = runs[1], runs[0]
its_on, its_off = on["newton_iterations"].astype(int), off["newton_iterations"].astype(int)
print(f"  levels {list(on['level'])}, Newton iterations per level {list(its_on)} with reuse, {list(its_off)} without; "
      f"steps started from the coarser level {list(on['reused_starts'])}")
st.check(len(on["level"]) >= 4 and np.array_equal(on["level"], off["level"]), "the same levels (at least 4)")
st.check(np.array_equal(on["limiting"], off["limiting"]), "the same limiting quantities")
st.check(np.array_equal(on["status"], off["status"]), "the same statuses")
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
st.check(its_on[-1] < 0.9 * its_off[-1], f"reuse saves Newton iterations on the finest level ({its_on[-1]} against {its_off[-1]})")
st.done()
