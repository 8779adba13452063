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
import leaf_dynamics_scene as leaf
import sinewtest as st
from time_reuse_study import with_and_without_reuse

scene = leaf.smooth_large(1).replace("opt:", "opt:\n  accuracy_refine: both", 1)
on, off, its_on, its_off, _ = with_and_without_reuse("accuracy_space_time_reuse", scene, min_levels=4)
st.check(its_on[-1] < 0.9 * its_off[-1], f"reuse saves Newton iterations on the finest level ({its_on[-1]} against {its_off[-1]})")
st.done()
