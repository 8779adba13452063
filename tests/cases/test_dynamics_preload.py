"""Dynamics from the end of the static load steps (opt.dynamics start: static; issue 14 item 2) on
2 ranks. The steel leaf cantilever of test_beam_dynamics.py (1 m x 20 mm x 2 mm, 16 elements, dens
7800) carries an axial compression P = 0.3 P_cr (P_cr = pi^2 EI / (4 L^2), thin direction) as a
constant tip load, and a transverse tip load dF step(t - t0) (tip deflection ~1e-5 L: linear) that
is zero in the load steps (its value at t = 0). The run does 4 load steps (P ramped in), then the
time loop from their end at rest: rho = 1, dt = T1/100, t0 = 50.5 dt, to t0 + 2 T1.
References, from Sinew's own static run of the same scene with the total load (P and dF constant,
loadsteps 4, calcfreq): the static tip deflection u_s and the frequencies of the loaded state
(f1 = 0.84 of the unloaded f1: the compression softens the beam, which only a preloaded start shows).
Linear theory about the preloaded state: until t0 the beam stays at rest; after it the tip
oscillates about u_s with the loaded state's modes, the first with w1 = 2 pi f1 (the trapezoidal
rule lengthens the period by (w1 dt)^2 / 12 = 3.3e-4), mean u_s, peak ~2 u_s.
MEASURED (2 ranks, 10-29 s on the shared, loaded machine): displacement change until t0 0.0 m
(26 rows); f1 = 1.4184485 Hz loaded, 1.6763767 Hz unloaded (ratio 0.846); fitted w1 / (2 pi f1) - 1
= -3.19e-4 against the scheme's -3.29e-4 (difference 9.9e-6, tolerance 2e-5); mean / u_s - 1 =
4.5e-5 (tolerance 1e-4); peak 1.9934 u_s; fit rms 1.4e-3 u_s.
Started at rest instead (start: rest, P applied suddenly at t = 0; checked once by hand): the
layout checks fail, and 4.1e-7 m of axial motion before t0 fails the rest check. The frequency
fit alone would pass (-3.17e-4): the axial oscillation is fast and its mean is P either way.
Also: the layout (/load_factor on the load-step rows, NaN on the time rows; /time 0 on the load
steps), and the scene errors of opt.dynamics.start (exit 2)."""
import numpy as np
from scipy.optimize import least_squares

import beamtools as bt
import sinewtest as st

L, w, t, nel = 1.0, 0.02, 0.002, 16
sec = bt.rect_section(w, t)
Pcr = np.pi ** 2 * sec["EIy"] / (4 * L ** 2)
P = 0.3 * Pcr
dF = 1e-5 * 3 * sec["EIy"] / L ** 3  # along global y = the thin direction (EIy)
nodes, elems = bt.chain([0, 0, 0], [L, 0, 0], nel)
NSTEPS = 4


def scene(opt, fy):
    return {"title": "preloaded leaf", "nodes": nodes, "elements": elems,
            "nprops": {1: {"fix": True}, nel + 1: {"force": [-P, fy, 0]}},
            "eprops": [bt.beam_set(range(1, nel + 1), w, t, dens=7800)], "opt": opt}


hs, _ = st.run("preload_static", bt.yaml_text(scene({"loadsteps": NSTEPS, "calccompl": False, "nfreq": 3}, dF)))
with st.h5(hs) as f:
    us = (f["node/p"][-1] - f["node/p0"][:])[nel]
    freq = f["freq"][-1][:3]
    f10 = f["freq"][0][0]  # SPACAR ramp: load step 1 is the unloaded state
f1 = freq[0]
T1, w1 = 1 / f1, 2 * np.pi * f1
dt = T1 / 100
t0 = 50.5 * dt
dyn = {"tend": t0 + 2 * T1, "dt": dt, "spectral_radius": 1.0, "output_every": 2, "start": "static"}
text = bt.yaml_text(scene({"loadsteps": NSTEPS, "calccompl": False, "calcfreq": False, "dynamics": dyn},
                          f"{dF!r}*step(t - {t0!r})"))
hd, out = st.run("preload_leaf", text)
with st.h5(hd) as f:
    lf, tt = f["load_factor"][:], f["time"][:]
    p = f["node/p"][:] - f["node/p0"][:]
static = ~np.isnan(lf)
ns = int(np.sum(static))
st.check(ns == NSTEPS and np.all(static[:ns]) and np.all(tt[:ns] == 0.0),
         f"layout: {ns} load-step rows first (/load_factor {lf[:ns]}, /time 0), then {len(tt) - ns} time rows")
st.close(lf[ns - 1], 1.0, atol=1e-15, what="last load step at load factor 1")
st.check(tt[ns] == 0.0 and np.max(np.abs(p[ns] - p[ns - 1])) == 0.0, "the time loop starts from the last load step (t = 0 row)")
# the preload acts: the tip's axial shortening is that of the static run (whose dF deflection
# shortens the tip by a further ~u_s^2 / L = 1.2e-10 m, 5e-4 of it)
st.close(p[ns - 1, nel, 0], us[0], rtol=1e-3, what="tip axial shortening under the preload vs the static run")
rest = (tt >= 0) & (tt < t0) & ~static
drift = np.max(np.abs(p[rest] - p[ns - 1]))
print(f"  at rest until t0: largest displacement change {drift:.2e} m over {int(np.sum(rest))} rows "
      f"(axial shortening {abs(us[0]):.3e} m, u_s = {us[1]:.3e} m)")
st.check(drift < 1e-9 * abs(us[1]), "constant preload: the beam stays at rest to round-off (1e-9 u_s)")

after = (tt > t0) & ~static
ta, uy = tt[after] - t0, p[after, nel, 1]


def model(q, t_):
    r = np.full_like(t_, q[0])
    for k in range(3):
        r += q[1 + 3 * k] * np.cos(q[3 + 3 * k] * t_) + q[2 + 3 * k] * np.sin(q[3 + 3 * k] * t_)
    return r


ws = 2 * np.pi * freq
q0 = [us[1], -us[1], 0, ws[0], -1e-2 * us[1], 0, ws[1], -1e-3 * us[1], 0, ws[2]]
scale = [us[1], us[1], us[1], ws[0], 1e-2 * us[1], 1e-2 * us[1], ws[0], 1e-3 * us[1], 1e-3 * us[1], ws[0]]
q = least_squares(lambda x: (model(x, ta) - uy) / us[1], q0, x_scale=scale).x
ew, em, peak = q[3] / w1 - 1, q[0] / us[1] - 1, uy.max() / us[1]
pred = -(w1 * dt) ** 2 / 12
print(f"  f1 loaded {f1:.8g} Hz (unloaded {f10:.8g} Hz, ratio {f1 / f10:.4f}); fitted w1 / (2 pi f1) - 1 = {ew:.2e} "
      f"(scheme {pred:.2e}, difference {ew - pred:.1e}); mean / u_s - 1 = {em:.2e}; peak / u_s = {peak:.4f}; "
      f"fit rms {np.sqrt(np.mean((model(q, ta) - uy) ** 2)) / us[1]:.1e} u_s")
st.check(abs(ew - pred) < 2e-5, "step on the preload: first period = 1/f1 of the preloaded state (scheme error removed, 2e-5)")
st.check(abs(em) < 1e-4, "step on the preload: oscillation about the static equilibrium of the total load (mean to 1e-4)")
st.check(abs(peak - 2) < 3e-2, "step on the preload: peak = 2 x the extra static deflection (to 3e-2; higher modes)")

# scene errors of opt.dynamics.start (exit 2, naming the field)
bad = dict(dyn, start="statics")
_, o = st.run("preload_bad_start", bt.yaml_text(scene({"loadsteps": 2, "dynamics": bad}, 0.0)), np_=1, expect_exit=2)
st.check("opt.dynamics.start" in o and "static" in o, "start: statics refused naming opt.dynamics.start")
cont = {"loadsteps": 2, "dynamics": dyn, "continuation": {"ds": 0.1}}
_, o = st.run("preload_continuation", bt.yaml_text(scene(cont, 0.0)), np_=1, expect_exit=2)
st.check("opt.dynamics.start" in o, "start: static with opt.continuation refused naming opt.dynamics.start")
st.done()
