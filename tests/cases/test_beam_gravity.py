"""Gravity on beams (small load: tip sag 1e-6 L, nonlinearity below 1e-10).
A: cantilever with density (dens, opt.gravity): the element lumps rhoA l g / 2 on its nodes, so the
   tip sag must equal the exact linear response to those nodal loads (Euler-Bernoulli + shear, to
   1e-7), and approaches q L^4/(8 EI) + q L^2/(2 kGA) as O(h^2) (printed for 16 elements).
B: massless cantilever with a nodal mass m at the tip: sag m g L^3/(3 EI) + m g L/kGA.
The root reactions carry the whole weight."""
import numpy as np

import beamtools as bt
import sinewtest as st

L, w, t, n, rho, m = 1.0, 0.02, 0.01, 16, 7800.0, 0.05
sec = bt.rect_section(w, t)
EI, kGA = sec["EIy"], sec["kGA"]
g = 1e-6 * 8 * EI / (rho * sec["A"] * L ** 4)  # tip sag 1e-6 L
nA, eA = bt.chain([0, 0, 0], [L, 0, 0], n)
nB, eB = bt.chain([0, 0.2, 0], [L, 0.2, 0], n, first=n + 2)
scene = {"title": "gravity sag", "nodes": nA + nB, "elements": eA + eB,
         "nprops": {"1": {"fix": True}, str(n + 2): {"fix": True}, str(2 * n + 2): {"mass": m}},
         "eprops": [bt.beam_set(range(1, n + 1), w, t, dens=rho), bt.beam_set(range(n + 1, 2 * n + 1), w, t)],
         "opt": {"loadsteps": 1, "gravity": [0, -g, 0], "calcfreq": False, "calccompl": False}}
out, log = st.run("beam_gravity", bt.yaml_text(scene))
with st.h5(out) as f:
    u = f["node/p"][-1] - f["node/p0"][:]
    Fr = f["node/Freac"][-1]
q = rho * sec["A"] * g
h = L / n
x = h * np.arange(1, n + 1)
P = np.full(n, q * h)
P[-1] = q * h / 2
discrete = -np.sum(P * (x ** 2 * (3 * L - x) / (6 * EI) + x / kGA))
continuum = -(q * L ** 4 / (8 * EI) + q * L ** 2 / (2 * kGA))
st.close(u[n, 1], discrete, rtol=1e-7, what="A: tip sag vs exact response to the lumped nodal loads")
print(f"  A: tip sag vs q L^4/(8EI) + q L^2/(2kGA): rel. difference {abs(u[n, 1] / continuum - 1):.3e} "
      f"({n} elements; lumping error (h/L)^2/8 = {1 / (8 * n * n):.3e})")
st.check(abs(u[n, 1] / continuum - 1) < 1.0 / n ** 2, "A: lumped gravity converges to q L^4/8EI")
F = m * g
st.close(u[2 * n + 1, 1], -(F * L ** 3 / (3 * EI) + F * L / kGA), rtol=1e-7,
         what="B: nodal mass tip sag = m g L^3/(3EI) + m g L/kGA")
st.close(Fr[0, 1], q * L, rtol=1e-10, what="A: root reaction = rhoA L g")
# B's load (9e-5 N) sits near the residual's round-off floor (~eps EA / h = 1.5e-10 N measured)
st.close(Fr[n + 1, 1], F, rtol=1e-5, what="B: root reaction = m g (load at 6e5 x the round-off floor)")
st.done()
