# ctest-labels: smoke
"""Dynamics started from a form-found state (issue 14, item 2) on 2 ranks: the flat square membrane of
test_ff_frequencies.py (side 1 m, 8x8 quads, thickness 1 mm, density 1000, prestress 1 MPa, fixed
edges) is form-found (elastic_restart_method FORCE), then opt.dynamics starts from the found state at
rest (the prestress stays) and a transverse force at the every interior node acts from t = 0 (a
uniform gust as a step load), rho = 1, dt = T1/100, 3 T1. Reference, from Sinew's own run of the same scene with
opt.loadsteps 1 instead of opt.dynamics: the static centre deflection u_s and f1 (the frequency
analysis of the loaded, form-found state). Linear theory: u(t) = sum_i u_i (1 - cos w_i t), mean
u_s, first mode with w1 = 2 pi f1 (the trapezoidal rule lengthens its period by (w1 dt)^2 / 12).
Without the form-found prestress the flat membrane has no transverse stiffness: the motion would
not oscillate about u_s. Rows: form-finding steps first, then the time rows (/time; t = 0 is the
found state), as docs/results.md says.
MEASURED (2 ranks, 24 s): f1 = 22.504622 Hz, u_s = 4.77e-7 m; fitted w1 / (2 pi f1) - 1 = -3.59e-4
against the scheme's -3.29e-4 (difference 3.0e-5, tolerance 2e-4), mean / u_s - 1 = -6.3e-4
(tolerance 5e-3), peak 2.23 u_s (higher symmetric modes), fit rms 2.3e-2 u_s."""
import numpy as np
from scipy.optimize import least_squares

import ancf_scenes as A
import sinewtest as st

n = 8
nodes, idx = [], {}
for j in range(n + 1):
    for i in range(n + 1):
        idx[i, j] = len(nodes) + 1
        nodes.append([i / n, j / n, 0.0])
elems = [[idx[i, j], idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]] for j in range(n) for i in range(n)]
centre = idx[n // 2, n // 2]
P = 1e-4  # N per interior node (a uniform gust): centre deflection ~1e-6 m (linear)
nprops = {k: ({"fix": True} if i in (0, n) or j in (0, n) else {"force": [0, 0, P]}) for (i, j), k in idx.items()}


def scene(opt):
    return {"title": "membrane gust after form finding", "nodes": nodes, "elements": elems, "nprops": nprops,
            "eprops": [{"elems": list(range(1, len(elems) + 1)), "type": "membrane", "thickness": 1e-3,
                        "emod": 1e9, "nu": 0.3, "dens": 1000, "prestress": [1e6, 1e6, 0]}],
            "formfinding": {"formfinding_step": 3, "formfinding_elements": [1], "elastic_restart_method": "FORCE"},
            "opt": opt}


hs, _ = st.run("ffdyn_static", A.text(scene({"loadsteps": 1, "nfreq": 2, "calccompl": False})))
with st.h5(hs) as f:
    us = f["node/p"][-1, centre - 1, 2] - f["node/p0"][centre - 1, 2]
    f1 = f["freq"][-1][0]
T1, w1 = 1 / f1, 2 * np.pi * f1
dyn = {"tend": 3 * T1, "dt": T1 / 100, "spectral_radius": 1.0, "output_every": 2}
hd, out = st.run("ffdyn_gust", A.text(scene({"calccompl": False, "calcfreq": False, "dynamics": dyn})))
with st.h5(hd) as f:
    nff = int(np.sum(~np.isnan(f["formfinding/step"][:])))  # form-finding rows (their /time is 0)
    tt = f["time"][nff:]
    u = f["node/p"][nff:, centre - 1, 2] - f["node/p0"][centre - 1, 2]
    found = f["node/p"][nff - 1] if nff > 0 else None
    first = f["node/p"][nff]
st.check(nff > 0, f"form-finding rows first ({nff}), then {len(tt)} time rows")
st.check(found is not None and np.max(np.abs(first - found)) < 1e-12, "the time loop starts from the found shape (t = 0 row)")


def model(p, t_):
    r = np.full_like(t_, p[0])
    for k in range(4):
        r += p[1 + 3 * k] * np.cos(p[3 + 3 * k] * t_) + p[2 + 3 * k] * np.sin(p[3 + 3 * k] * t_)
    return r


# symmetric modes (m, n odd) of the square: w_mn / w_11 = sqrt((m^2 + n^2) / 2): 1, 2.236, 3, 3.606
p0 = [us, -us, 0, w1, -0.05 * us, 0, 2.236 * w1, -0.01 * us, 0, 3.0 * w1, -0.01 * us, 0, 3.606 * w1]
scale = [us, us, us, w1] + [0.05 * us, 0.05 * us, w1] * 3
p = least_squares(lambda x: (model(x, tt) - u) / us, p0, x_scale=scale).x
ew, em = p[3] / w1 - 1, p[0] / us - 1
pred = -(w1 * dyn["dt"]) ** 2 / 12
print(f"  u_s = {us:.4e} m, f1 (loaded, form-found) = {f1:.6f} Hz; fitted w1 / (2 pi f1) - 1 = {ew:.2e} "
      f"(scheme {pred:.2e}), mean / u_s - 1 = {em:.2e}, peak / u_s = {u.max() / us:.3f}, "
      f"fit rms {np.sqrt(np.mean((model(p, tt) - u) ** 2)) / us:.1e} u_s")
st.check(abs(ew - pred) < 2e-4, "gust after form finding: period of the first mode = 1/f1 of the loaded state (scheme error removed, to 2e-4)")
st.check(abs(em) < 5e-3, "gust after form finding: motion about the static deflection (mean to 5e-3)")
st.done()
