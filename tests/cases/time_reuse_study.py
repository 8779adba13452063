"""The study of -target_error with -accuracy_reuse 1 and 0 on a dynamics scene, and the checks every
time-level reuse test makes (test_accuracy_time_reuse, test_accuracy_space_time_reuse): the same levels,
limiting quantities, statuses, estimates and orders, the level histories to Newton's tolerance, no
coarser start without reuse and every step of every level after the first started from the coarser
level with it."""
import numpy as np

import leaf_dynamics_scene as leaf
import sinewtest as st

FIELDS = ("level", "worst_error", "limiting", "order", "status", "value", "newton_iterations", "reused_starts")


def study(path):
    with st.h5(path) as f:
        g = f["accuracy"]
        return {k: g[k][:] for k in FIELDS}


def with_and_without_reuse(name, scene, min_levels, target="1e-4"):
    """Runs the study both ways (2 ranks) and checks what reuse must not change. Returns (on, off,
    Newton iterations per level with and without reuse, the runs' outputs by reuse 1/0)."""
    runs, outs = {}, {}
    for reuse in (1, 0):
        path, outs[reuse] = st.run(f"{name}_{reuse}", scene, args=["-target_error", target, "-accuracy_reuse", str(reuse)])
        runs[reuse] = study(path)
    on, off = runs[1], runs[0]
    its_on, its_off = on["newton_iterations"].astype(int), off["newton_iterations"].astype(int)
    print(f"  levels {list(on['level'])}, Newton iterations per level {list(its_on)} with reuse, {list(its_off)} without "
          f"({its_on.sum()} against {its_off.sum()}); steps started from the coarser level {list(on['reused_starts'])}")
    st.check(len(on["level"]) >= min_levels and np.array_equal(on["level"], off["level"]),
             f"the same levels (at least {min_levels})")
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
    return on, off, its_on, its_off, outs
