"""Beams in dynamics (Lie-group generalized-alpha, docs/dynamics.md) on 2 ranks: a steel leaf
cantilever (1 m x 20 mm x 2 mm, 16 elements, dens 7800) under a tip force along its thin direction
applied suddenly at t = 0, undamped (spectral_radius 1). References, all from Sinew's own runs of
the same scene: the static deflection u_s (opt.loadsteps 1) and the first natural frequency f1
(frequency analysis, calcfreq). Linear theory: u(t) = sum_i u_i (1 - cos w_i t) with sum u_i = u_s,
so the time mean of u is u_s, the first mode oscillates with w1 = 2 pi f1 (the trapezoidal rule,
rho = 1, lengthens the period by (w1 dt)^2 / 12 = 8.2e-5 at dt = T1/200), and the peak is 2 u_s
less the higher modes' phase lag. Measured over 1.5 T1 (every 2nd step written, a 3-mode least-
squares fit): fitted w1 vs 2 pi f1 -8.4e-5 (predicted -8.2e-5, difference 1.4e-6), fitted mean vs
u_s -5.7e-6, peak / u_s 1.9894. The tip displacement is 1e-5 L, so the geometric nonlinearity is
below 1e-9 relative.
Also: 1 vs 2 ranks identical (measured 6.5e-14 u_s), and -dynamics_scheme tsalpha2 refused for
beams (exit 2)."""
import numpy as np
from scipy.optimize import least_squares

import beamtools as bt
import sinewtest as st

L, w, t, nel = 1.0, 0.02, 0.002, 16
sec = bt.rect_section(w, t)
F = 1e-5 * 3 * sec["EIy"] / L ** 3  # along global y = the thin direction (EIy)
nodes, elems = bt.chain([0, 0, 0], [L, 0, 0], nel)


def scene(opt):
    return {"title": "leaf", "nodes": nodes, "elements": elems,
            "nprops": {1: {"fix": True}, nel + 1: {"force": [0, F, 0]}},
            "eprops": [bt.beam_set(range(1, nel + 1), w, t, dens=7800)], "opt": opt}


hs, _ = st.run("beamdyn_static", bt.yaml_text(scene({"loadsteps": 1, "calccompl": False})))
with st.h5(hs) as f:
    us = (f["node/p"][-1] - f["node/p0"][:])[nel, 1]
    f1 = f["freq"][-1][0]
T1, w1 = 1 / f1, 2 * np.pi * f1
dyn = {"tend": 1.5 * T1, "dt": T1 / 200, "spectral_radius": 1.0, "output_every": 2}
text = bt.yaml_text(scene({"calccompl": False, "calcfreq": False, "dynamics": dyn}))
series = {}
for np_ in (2, 1):
    hd, out = st.run(f"beamdyn_leaf_{np_}", text, np_=np_)
    with st.h5(hd) as f:
        series[np_] = (f["time"][:], f["node/p"][:, nel, :] - f["node/p0"][nel, :], f["node/r_quat"][:, nel, :])
tt, u, q = series[2]
st.check(len(tt) == 151 and abs(tt[-1] - 1.5 * T1) < 1e-12, "leaf: 151 written steps to t = 1.5 T1")
d = max(np.max(np.abs(series[1][1] - u)), np.max(np.abs(series[1][2] - q)) * L)
print(f"  1 vs 2 ranks: max tip difference {d / us:.2e} of u_s")
st.check(d <= 1e-9 * us, "leaf: 1 and 2 ranks identical to 1e-9")

uy = u[:, 1]


def model(p, t_):
    r = np.full_like(t_, p[0])
    for k in range(3):
        r += p[1 + 3 * k] * np.cos(p[3 + 3 * k] * t_) + p[2 + 3 * k] * np.sin(p[3 + 3 * k] * t_)
    return r


# three modes (w2 ~ 6.27 w1, w3 ~ 17.5 w1 for a cantilever): mean, amplitudes and frequencies
p0 = [us, -us, 0, w1, -1e-2 * us, 0, 6.27 * w1, -1e-3 * us, 0, 17.5 * w1]
scale = [us, us, us, w1, 1e-2 * us, 1e-2 * us, w1, 1e-3 * us, 1e-3 * us, w1]
p = least_squares(lambda x: (model(x, tt) - uy) / us, p0, x_scale=scale).x
ew, em, peak = p[3] / w1 - 1, p[0] / us - 1, uy.max() / us
print(f"  u_s = {us:.6e} m, f1 = {f1:.10g} Hz; fitted w1 / (2 pi f1) - 1 = {ew:.2e}, mean / u_s - 1 = {em:.2e}, "
      f"peak / u_s = {peak:.5f}, fit rms {np.sqrt(np.mean((model(p, tt) - uy) ** 2)) / us:.1e} u_s")
pred = -(w1 * dyn["dt"]) ** 2 / 12  # trapezoidal rule (rho = 1): w_h = w (1 - (w h)^2 / 12 + ...)
print(f"  predicted frequency error of the scheme {pred:.2e}; fitted - predicted {ew - pred:.1e}")
st.check(abs(ew) < 1e-4, "leaf: period of the first mode = 1/f1 of the frequency analysis (to 1e-4; dt = T1/200)")
st.check(abs(ew - pred) < 1e-5, "leaf: the period error is the scheme's (w1 dt)^2 / 12 (to 1e-5)")
st.check(abs(em) < 1e-4, "leaf: mean deflection = static deflection (to 1e-4)")
st.check(abs(peak - 2) < 2e-2, "leaf: peak deflection = 2 x static (to 2e-2; higher modes)")
st.close(np.max(np.abs(u[:, 2])), 0.0, atol=1e-12 * us, what="leaf: no out-of-plane motion")

# PETSc's TSALPHA2 works on a vector space: refused for beams
_, out = st.run("beamdyn_tsalpha2", text, args=["-dynamics_scheme", "tsalpha2"], expect_exit=2)
st.check("arnold_bruls" in out, "tsalpha2 with beams: refusal names the default scheme")
st.done()
