#!/usr/bin/python3
"""Fewer finite modes than nfreq (issue 10, item 8): a massless cantilever (L = 1, circ d = 0.01,
E = 210 GPa) with a point mass m = 1 at its tip (no mominertia) has exactly three finite modes:
two bending, f = sqrt(3 EI / L^3 / m) / (2 pi), and one axial, f = sqrt(E A / L / m) / (2 pi).
With nfreq = 6 Sinew reports the three, says that the model has three, and exits 0: no NaN
padding of /freq, no SLEPc breakdown message. A second scene, two point masses (6 finite modes)
with nfreq = 4, still reports 4."""
import numpy as np

import sinewtest as st

E, d, m = 210e9, 0.01, 1.0
I, A = np.pi * d**4 / 64, np.pi * d**2 / 4
scene = {
    "nodes": [[0, 0, 0], [1, 0, 0]],
    "elements": [[1, 2]],
    "nprops": {1: {"fix": True}, 2: {"mass": m}},
    "eprops": [{"elems": [1], "flex": [1, 2, 3, 4, 5, 6], "emod": E, "smod": 80e9, "cshape": "circ", "dim": d}],
    "opt": {"loadsteps": 2, "calccompl": False, "nfreq": 6},
}
out, log = st.run("point_masses", scene)
with st.h5(out) as f:
    hz = f["freq"][:]
st.check(hz.shape == (2, 3), f"/freq holds the 3 finite modes per step, shape {hz.shape}")
st.check(np.all(np.isfinite(hz)), "no NaN in /freq")
fb, fa = np.sqrt(3 * E * I / m) / (2 * np.pi), np.sqrt(E * A / m) / (2 * np.pi)
st.close(hz[-1], [fb, fb, fa], rtol=1e-6, what="frequencies vs the spring-mass values")
st.check("the model has 3 finite ones" in log, "the warning says how many finite modes exist")
st.check("BREAKDOWN" not in log.upper() and "nan" not in log.lower(), "no breakdown message, no nan: " + log[-600:])

# enough finite modes: nfreq is honoured
scene2 = dict(scene, nodes=[[0, 0, 0], [1, 0, 0], [2, 0, 0]], elements=[[1, 2], [2, 3]],
              nprops={1: {"fix": True}, 2: {"mass": m}, 3: {"mass": m}},
              eprops=[dict(scene["eprops"][0], elems=[1, 2])], opt=dict(scene["opt"], nfreq=4))
out, log = st.run("point_masses_enough", scene2)
with st.h5(out) as f:
    hz = f["freq"][:]
st.check(hz.shape == (2, 4) and np.all(np.isfinite(hz)), f"two masses, nfreq 4: 4 frequencies, shape {hz.shape}")
st.check("finite ones" not in log, "no finite-mode warning when nfreq modes exist")
st.done()
