# ctest-labels: smoke
"""A Newton that cannot converge, and a mechanism.
1. One beam element under an end moment: the element's bending modes are l0 sin(.) measures, so its
   end moment is bounded and a moment beyond that bound has no equilibrium (load control past the
   limit point). With 10 load steps to 20 N m (6 EI/L) and -max_cuts 2 the first steps converge and a
   later one fails: exit code 3, a message naming the load step, the residual norm and what to try,
   a result file holding exactly the converged steps (load factors (k-1)/9, SPACAR Light's steps:
   step 1 is the unloaded beam) with root attribute converged = 0.
2. A clamped-clamped shallow arch with pinned ends instead (fix_pos): the rotation of the whole arch
   about the chord is a free motion. That is a model error (exit 2, the mechanism named, no result
   file), never a NaN result."""
import os
import re

import numpy as np

import beamtools as bt
import sinewtest as st

# ---- 1. no equilibrium beyond the limit moment
w, t, E = 0.02, 0.01, 2e9
EI = E * w * t ** 3 / 12
scene = {"title": "one-element limit moment", "nodes": [[0, 0, 0], [1, 0, 0]], "elements": [[1, 2]],
         "nprops": {"1": {"fix": True}, "2": {"moment": [0, 0, 6 * EI]}},
         "eprops": [{"elems": [1], "flex": [1, 2, 3, 4, 5, 6], "emod": E, "smod": 0.8e9, "cshape": "rect",
                     "dim": [w, t], "orien": [0, 0, 1]}],
         "opt": {"loadsteps": 10, "calccompl": False}}
out, log = st.run("core_newton_limit", bt.yaml_text(scene), args=["-max_cuts", "2", "-snes_max_it", "25"], expect_exit=3)
err = [ln for ln in log.splitlines() if ln.startswith("error:")]
print("message:", err[0] if err else "(none)")
st.check(len(err) == 1, f"the failure is reported {len(err)} times, expected once")
m = re.search(r"load step (\d+) of 10 did not converge", err[0] if err else "")
st.check(m is not None, "the message names the load step")
st.check("residual norm" in log and "Try more load steps (-loadsteps)" in log, "the message gives the residual and what to try")
st.check(os.path.exists(out), "result file kept")
if m and os.path.exists(out):
    k = int(m.group(1))
    with st.h5(out) as f:
        conv = int(f.attrs["converged"])
        lam = f["load_factor"][:] if "load_factor" in f else np.zeros(0)
    print(f"failed at load step {k}; result file: {len(lam)} converged steps {lam}, converged = {conv}")
    st.check(conv == 0, "root attribute converged = 0")
    st.check(k >= 2, "at least one step converged before the failure")
    st.close(lam, np.arange(0, k - 1) / 9, atol=1e-14, what="load factors of the converged steps")
    st.check(not os.path.exists(out + ".part"), "no .part file left")

# ---- 2. a mechanism is a model error
n, h = 16, 0.05
x = np.linspace(-0.5, 0.5, n + 1)
arch = {"title": "arch on pins", "nodes": [[float(a), 0.0, float(h * (1 - (2 * a) ** 2))] for a in x],
        "elements": [[i + 1, i + 2] for i in range(n)],
        "nprops": {"1": {"fix_pos": True}, str(n + 1): {"fix_pos": True}, str(n // 2 + 1): {"force": [0, 0, -2000]}},
        "eprops": [{"elems": list(range(1, n + 1)), "flex": [1, 2, 3, 4, 5, 6], "emod": 210e9, "smod": 80e9,
                    "cshape": "rect", "dim": [0.02, 0.005], "orien": [0, 1, 0]}],
        "opt": {"loadsteps": 4, "calccompl": False}}
out, log = st.run("core_mechanism", bt.yaml_text(arch), expect_exit=2)
err = [ln for ln in log.splitlines() if ln.startswith("error:")]
print("mechanism message:", err[0] if err else "(none)")
st.check(len(err) == 1 and "the model is a mechanism" in err[0], "one message naming the mechanism")
st.check("translation y" in log, "the moving DOFs are listed")
st.check("nan" not in log.lower(), "no NaN in the output")
st.check(not os.path.exists(out) and not os.path.exists(out + ".part"), "no result file")
st.done()
