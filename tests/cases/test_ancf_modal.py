# ctest-labels: smoke
"""ANCF cable free-free eigenvalues on 2 ranks: reference A4 (Exudyn
TestModels/computeODE2EigenvaluesTest.py): L = 2, 32 elements, EI = 172.5, rhoA = 0.78, EA = 2.07e6,
useReducedOrderIntegration 1, no supports and no loads. The scene runs as given (no flags): a model
whose only singularity is rigid-body motion and that carries no load passes the constraint check
when frequencies are asked for, and its static step accepts the unloaded reference state (residual
at round-off) without a Newton step. The same body with a load is still refused as a mechanism."""
import re

import numpy as np

import sinewtest as st
from ancf_scenes import text


def freefree(nfreq=6, nprops=None):
    return {"title": "free-free ANCF cable (A4)", "nodes": [[0, 0], [2, 0]], "elements": [[1, 2]],
            "nprops": nprops or {},
            "eprops": [{"elems": [1], "type": "ancf_cable2d", "physicsMassPerLength": 0.78,
                        "physicsBendingStiffness": 172.5, "physicsAxialStiffness": 2.07e6,
                        "useReducedOrderIntegration": 1, "nbeams": 32}],
            "opt": {"loadsteps": 1, "nfreq": nfreq}}


ref = np.array([83.17966459, 229.28844645, 449.50021798])  # rad/s (A4)
path, out = st.run("ancf_a4", text(freefree()))
st.check("rigid-body modes" in out and "no loads" in out, "A4: the free-free note is printed")
m = re.search(r"^\s+1\s+1\s+(\d+)\s+1\s", out, re.M)
st.check(m is not None and int(m.group(1)) == 0, "A4: the unloaded start state is accepted without a Newton iteration")
with st.h5(path) as f:
    w = 2 * np.pi * f["freq"][0]  # Hz -> rad/s
    st.check(np.all(np.isfinite(w)), "A4: no NaN frequency")
    # rigid-body modes (2 translations, 1 rotation): omega ~ 0 (measured below 3e-4 rad/s)
    st.close(w[:3], [0, 0, 0], atol=1e-5 * ref[0], what="A4 3 rigid-body modes (rad/s)")
    st.close(w[3:6], ref, rtol=1e-7, what="A4 first three flexible omega (rad/s)")
    print("  relative errors:", np.array2string(w[3:6] / ref - 1, precision=3))
    p = f["node/p"][-1]
    st.close(p[:, :2] - f["node/p0"][:, :2], 0.0, atol=1e-12, what="A4 unloaded body does not move")

# the same body under a tip force is a mechanism: refused before any result (exit 2)
_, out = st.run("ancf_a4_loaded", text(freefree(nprops={2: {"force": [0, -1]}})), expect_exit=2)
st.check("mechanism" in out, "loaded free-free cable: reported as a mechanism")
st.done()
