"""-target_error's reuse between levels in time (docs/accuracy.md, "Reuse between levels"), 2 ranks: a
level that halves dt starts each time step's Newton from the coarser level's time steps (its state at
every other step, the cubic Hermite in time of its positions, rotations and velocities in between)
instead of the scheme's predictor. A steel leaf (1 m x 20 mm x 2 mm, nbeams 4) under a tip force rising
smoothly over T1 / 2 to 0.3 x 3 EI / L^3 (large motion: the tip turns by 0.4 rad), generalized-alpha
rho = 0.9 to T1 / 2 from dt = T1 / 40, target 1e-4, with -accuracy_reuse 1 (default) and 0: the same
levels, estimates and orders, the level values to Newton's tolerance, every step of every level after
the first started from the coarser level (/accuracy reused_starts), and fewer Newton iterations on the
two finest levels with reuse (measured 482 against 637)."""
import leaf_dynamics_scene as leaf
import sinewtest as st
from time_reuse_study import with_and_without_reuse

on, off, its_on, its_off, outs = with_and_without_reuse("accuracy_time_reuse", leaf.smooth_large(), min_levels=3)
st.check("steps started from the coarser level" in outs[1], "the reported level's summary counts its coarse starts")
fine_on, fine_off = int(its_on[-2:].sum()), int(its_off[-2:].sum())
st.check(fine_on < 0.85 * fine_off, f"reuse saves Newton iterations on the two finest levels ({fine_on} against {fine_off})")
st.done()
