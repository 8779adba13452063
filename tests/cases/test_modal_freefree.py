"""Free-free ANCF cable (reference A4, Exudyn computeODE2EigenvaluesTest.py): L = 2, 32 elements,
EI = 172.5, rhoA = 0.78, EA = 2.07e6, reduced integration, no supports. K is singular (3 rigid-body
modes); the shift -1e-8 s (s = min K_ii/M_ii) keeps K - sigma M regular and the rigid-body modes
come out at round-off level (reported 0 when omega^2 is a round-off negative), never NaN.
The static step of an unloaded free body needs -constraint_check false (it is a mechanism) and an
absolute residual tolerance (its residual is round-off)."""
import numpy as np

import sinewtest as st
from modal_util import yaml_text

scene = yaml_text({
    "title": "free-free ANCF cable (A4)", "nodes": [[0, 0], [2, 0]], "elements": [[1, 2]],
    "eprops": [{"elems": [1], "type": "ancf_cable2d", "physicsMassPerLength": 0.78,
                "physicsBendingStiffness": 172.5, "physicsAxialStiffness": 2.07e6,
                "useReducedOrderIntegration": 1, "nbeams": 32}],
    "opt": {"loadsteps": 1, "nfreq": 6}})
path, out = st.run("modal_freefree_ancf", scene, args=["-constraint_check", "false", "-snes_atol", "1e-6"])
ref = np.array([83.17966459, 229.28844645, 449.50021798])  # rad/s (A4)
with st.h5(path) as f:
    w = 2 * np.pi * f["freq"][0]
    st.check(np.all(np.isfinite(w)), "no NaN frequency")
    st.close(w[:3], [0, 0, 0], atol=1e-5 * ref[0], what="3 rigid-body modes (rad/s)")
    st.close(w[3:], ref, rtol=1e-7, what="first three flexible omega (rad/s) vs A4")
    print("  relative errors:", np.array2string(w[3:] / ref - 1, precision=3))
    st.close(w[3], 83.179636974620, rtol=1e-6, what="first flexible omega vs analytic")
st.done()
