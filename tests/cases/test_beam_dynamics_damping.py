"""Damping in dynamics (opt.dynamics modal_damping, mass_/stiffness_proportional_damping;
docs/dynamics.md "Damping") on 2 ranks: the steel leaf cantilever of test_beam_dynamics.py (1 m x
20 mm x 2 mm, 16 elements, dens 7800) under a tip force along its thin direction applied suddenly
at t = 0 (tip deflection 1e-5 L: linear), spectral_radius 1 (no numerical damping), dt = T1/200,
3 T1 (every 4th step written). Reference: a linear viscously damped mode with ratio zeta decays by the logarithmic decrement
delta = ln(u(t) / u(t + T_d)) = 2 pi zeta / sqrt(1 - zeta^2) per damped period (e.g. Clough &
Penzien, Dynamics of Structures, eq. 2-40). The tip history minus its mean is fitted by three
damped modes, u = m + sum_k exp(-s_k t) (a_k cos w_k t + b_k sin w_k t), and delta = 2 pi s_1 / w_1.
- modal_damping zeta = 0.02 (the lowest 10 modes of the start state, Sinew's own frequency
  analysis): delta / (2 pi zeta / sqrt(1 - zeta^2)) - 1 measured below (tolerance 2e-3).
- Rayleigh alpha M0 + beta (the beams' strain-rate damping, -stiffness_damping corotated; beta K0 for small
  motions) with zeta(w) = alpha / (2 w) + beta w / 2 = zeta at w1 and w2
  (alpha = 2 zeta w1 w2 / (w1 + w2), beta = 2 zeta / (w1 + w2)): the same decrement.
- Without damping the fitted s_1 is 0 (so the test fails if the damping is ignored).
MEASURED (this test's runs, 2 ranks, 209 s on the shared machine at load 9): modal delta / reference - 1 =
6.4e-7, Rayleigh 3.5e-5, undamped fitted s_1 T1 = 4.4e-5 (damped: 2 pi zeta = 0.126). Again with the
corotated beta (2026-11, 2 ranks): modal 1.24e-3 (the same result file as before the change, to 4.6e-19 m),
Rayleigh 5.3e-6, undamped 4.4e-5.
Also: negative coefficients and modal_damping_modes without modal_damping are refused naming the
field (exit 2)."""
import numpy as np
from scipy.optimize import least_squares

import beamtools as bt
import sinewtest as st

L, w, t, nel = 1.0, 0.02, 0.002, 16
sec = bt.rect_section(w, t)
F = 1e-5 * 3 * sec["EIy"] / L ** 3
nodes, elems = bt.chain([0, 0, 0], [L, 0, 0], nel)
zeta = 0.02


def scene(opt):
    return {"title": "leaf", "nodes": nodes, "elements": elems,
            "nprops": {1: {"fix": True}, nel + 1: {"force": [0, F, 0]}},
            "eprops": [bt.beam_set(range(1, nel + 1), w, t, dens=7800)], "opt": opt}


hs, _ = st.run("beamdamp_static", bt.yaml_text(scene({"loadsteps": 1, "calccompl": False})))
with st.h5(hs) as f:
    us = (f["node/p"][-1] - f["node/p0"][:])[nel, 1]
    fr = f["freq"][-1]
# the thin-direction bending modes: f1 and the second one of the same direction (6.27 f1)
f1 = fr[0]
f2 = [x for x in fr if abs(x / f1 - 6.27) < 0.1][0]
T1, w1, w2 = 1 / f1, 2 * np.pi * f1, 2 * np.pi * f2


def history(name, extra):
    dyn = {"tend": 3 * T1, "dt": T1 / 200, "spectral_radius": 1.0, "output_every": 4}
    dyn.update(extra)
    h, out = st.run(name, bt.yaml_text(scene({"calccompl": False, "calcfreq": False, "dynamics": dyn})))
    with st.h5(h) as f:
        return f["time"][:], (f["node/p"][:, nel, :] - f["node/p0"][nel, :])[:, 1], out


def model(p, t_):
    r = np.full_like(t_, p[0])
    for k in range(3):
        a, b, s, om = p[1 + 4 * k: 5 + 4 * k]
        r += np.exp(-s * t_) * (a * np.cos(om * t_) + b * np.sin(om * t_))
    return r


def decrement(tt, u):
    p0 = [us, -us, 0, 0, w1, -1e-2 * us, 0, 0, 6.27 * w1, -1e-3 * us, 0, 0, 17.5 * w1]
    scale = [us, us, us, 1e-2 * w1, w1, 1e-2 * us, 1e-2 * us, 1e-1 * w1, w1, 1e-3 * us, 1e-3 * us, w1, w1]
    p = least_squares(lambda x: (model(x, tt) - u) / us, p0, x_scale=scale).x
    rms = np.sqrt(np.mean((model(p, tt) - u) ** 2)) / us
    return 2 * np.pi * p[3] / p[4], p, rms


delta_ref = 2 * np.pi * zeta / np.sqrt(1 - zeta ** 2)
tt, u0, _ = history("beamdamp_none", {})
d0, p, rms = decrement(tt, u0)
print(f"  undamped: fitted s1 T1 = {p[3] * T1:.2e} (fit rms {rms:.1e} u_s)")
st.check(abs(d0) < 1e-3 * delta_ref, "undamped leaf: no decay of the first mode (the damped cases below measure damping)")

tt, um, out = history("beamdamp_modal", {"modal_damping": zeta})
dm, p, rms = decrement(tt, um)
em = dm / delta_ref - 1
print(f"  modal zeta = {zeta}: delta = {dm:.6f} vs 2 pi zeta / sqrt(1 - zeta^2) = {delta_ref:.6f}: {em:.2e} "
      f"(fit rms {rms:.1e} u_s, mean / u_s - 1 = {p[0] / us - 1:.1e})")
st.check(abs(em) < 2e-3, "modal damping: logarithmic decrement 2 pi zeta / sqrt(1 - zeta^2) (to 2e-3)")
st.check(abs(p[0] / us - 1) < 1e-3, "modal damping: the motion decays to the static deflection")

alpha, beta = 2 * zeta * w1 * w2 / (w1 + w2), 2 * zeta / (w1 + w2)
tt, ur, out = history("beamdamp_rayleigh", {"mass_proportional_damping": float(alpha),
                                             "stiffness_proportional_damping": float(beta)})
dr, p, rms = decrement(tt, ur)
er = dr / delta_ref - 1
print(f"  Rayleigh alpha = {alpha:.6g}, beta = {beta:.6g}: delta = {dr:.6f}: {er:.2e} (fit rms {rms:.1e} u_s)")
st.check(abs(er) < 2e-3, "Rayleigh damping (zeta at f1 and f2): the same logarithmic decrement (to 2e-3)")

# validation: the error names the field, exit 2
base = {"tend": T1, "dt": T1 / 10}
for bad, field in (({"modal_damping": -0.1}, "modal_damping"), ({"modal_damping": [0.01, -1]}, "modal_damping(2)"),
                   ({"stiffness_proportional_damping": -1e-4}, "stiffness_proportional_damping"),
                   ({"modal_damping_modes": 3}, "modal_damping_modes")):
    _, out = st.run("beamdamp_bad", bt.yaml_text(scene({"calccompl": False, "dynamics": {**base, **bad}})), expect_exit=2)
    st.check("opt.dynamics." + field in out, f"refused with the field named: {field}")
st.done()
