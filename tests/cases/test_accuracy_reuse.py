"""-target_error's reuse between levels (docs/accuracy.md, "Reuse between levels"), 2 ranks: a level's
load steps start from the coarser level's converged states interpolated onto its nodes. The same
study with -accuracy_reuse 1 (default) and 0, on the beam roll-up to a quarter circle (4 load steps,
target 1e-3) and the ANCF cable A2 (10 load steps, target 1e-5): the same levels, estimates, orders
and level values to Newton's tolerance, and fewer Newton iterations (/accuracy newton_iterations) on the
two finest levels with reuse, whose increments started from the coarser level's states (/accuracy reused_starts)."""
import numpy as np

import sinewtest as st
from modal_util import E, beam_x


def rollup():
    """A cantilever (rect 10 x 1 mm) bent into a quarter circle by a tip moment M = (pi/2) EI / L."""
    w, t = 0.01, 0.001
    return beam_x(1.0, w, t, 1, {1: {"fix": True}, 2: {"moment": [0, -np.pi / 2 * E * w * t**3 / 12, 0]}}, dens=0,
                  opt={"loadsteps": 4})


def ancf_a2():
    """Exudyn's ANCFCable2DBendingTest: tip force 3 EI / L^2 on a 2 m cable, 10 load steps."""
    return {"title": "ANCF cantilever", "nodes": [[0, 0], [2, 0]], "elements": [[1, 2]],
            "nprops": {1: {"fix_coords": [1, 1, 0, 1]}, 2: {"force": [0, -3 * 1.725e6 / 4]}},
            "eprops": [{"elems": [1], "type": "ancf_cable2d", "nbeams": 1, "useReducedOrderIntegration": 0,
                        "physicsMassPerLength": 78, "physicsBendingStiffness": 1.725e6,
                        "physicsAxialStiffness": 2.07e9}],
            "opt": {"loadsteps": 10, "calcfreq": False}}


def study(path):
    with st.h5(path) as f:
        g = f["accuracy"]
        return {k: g[k][:] for k in ("level", "worst_error", "limiting", "error", "order", "status", "value",
                                     "newton_iterations", "reused_starts")}


for name, scene, target in (("rollup", rollup(), 1e-3), ("ancf_a2", ancf_a2(), 1e-5)):
    runs = {}
    for reuse in (1, 0):
        path, out = st.run(f"accuracy_reuse_{name}_{reuse}", scene,
                           args=["-target_error", f"{target:g}", "-accuracy_reuse", str(reuse)])
        runs[reuse] = study(path)
        st.check("Newton" in out, f"{name}: the accuracy table has a Newton column")
    on, off = runs[1], runs[0]
    its_on, its_off = int(on["newton_iterations"].sum()), int(off["newton_iterations"].sum())
    print(f"  {name}: levels {list(on['level'])}, Newton iterations per level {list(on['newton_iterations'])} "
          f"with reuse, {list(off['newton_iterations'])} without ({its_on} against {its_off})")
    st.check(np.array_equal(on["level"], off["level"]), f"{name}: the same levels")
    st.check(np.array_equal(on["limiting"], off["limiting"]), f"{name}: the same limiting quantities")
    # the level values to Newton's tolerance, relative to each quantity's size on that level
    v_on, v_off = np.nan_to_num(on["value"]), np.nan_to_num(off["value"])
    size = np.maximum(np.linalg.norm(v_off, axis=2), 1e-300)
    change = np.max(np.linalg.norm(v_on - v_off, axis=2) / size)
    print(f"  {name}: largest relative change of a level's value {change:.1e}")
    st.check(change < 1e-9, f"{name}: the level values do not depend on the Newton start ({change:.1e})")
    w_on, w_off = on["worst_error"][2:], off["worst_error"][2:]
    st.check(np.allclose(w_on, w_off, rtol=1e-6, atol=0), f"{name}: the same worst estimates")
    limiting = on["limiting"][-1].astype(int)
    st.check(abs(on["order"][-1, limiting] - off["order"][-1, limiting]) < 1e-6, f"{name}: the same observed order")
    st.check(np.all(off["reused_starts"] == 0), f"{name}: -accuracy_reuse 0 starts no increment from a coarser level")
    st.check(np.all(on["reused_starts"][1:] > 0), f"{name}: with reuse every level after the first starts from one")
    # the finest levels, which cost the most: a one-element level's states are a poor start (ANCF level 1
    # from level 0 needs more iterations than from the unloaded state), a fine level's are close
    fine_on, fine_off = int(on["newton_iterations"][-2:].sum()), int(off["newton_iterations"][-2:].sum())
    st.check(fine_on < 0.75 * fine_off, f"{name}: reuse saves Newton iterations on the two finest levels "
             f"({fine_on} against {fine_off})")
st.done()
