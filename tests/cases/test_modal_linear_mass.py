# ctest-processors: 1
"""Natural frequencies with the linear beam mass (-beam_mass linear: Simo and Vu-Quoc's constant mass of
linearly interpolated velocities on the translations, the sections' rotary inertia lumped on the nodes;
docs/dynamics.md "Energy-momentum scheme"): the cantilever of test_modal_cantilever.py (1 m, rect
10 x 0.1 mm, bending in its compliant plane) against reference B3 (Euler-Bernoulli, beta_n L) converges
as h^2 (the translations' inertia interpolated linearly under cubic displacements), as the lumped mass
does; the consistent Hermite mass converges as h^4.
Measured (1 rank, 2026-11-27), relative errors of f1..f5 with 8 / 16 / 32 elements:
  f1 -1.2e-3 / -2.8e-4 / -7.0e-5, f2 1.7e-2 / 4.3e-3 / 1.1e-3, f5 2.0e-1 / 5.6e-2 / 1.4e-2;
observed orders 16 -> 32: 2.01 1.99 1.99 1.99 1.99 (-beam_mass lumped: 2.00 1.99 1.99 1.99 1.99,
errors -4.5e-4 .. -4.6e-3 at 32; consistent: 3.98 .. 6.8, errors -1.1e-9 .. 2.6e-5 at 32)."""
import numpy as np

import sinewtest as st
from modal_util import beam_x, cantilever_hz

L, W, T = 1.0, 0.01, 1e-4
ref = cantilever_hz(L, W, T)
err = {}
for n in (8, 16, 32):
    h5, _ = st.run(f"modal_linear_{n}", beam_x(L, W, T, n, {1: {"fix": True}}, opt={"nfreq": 6}), np_=1,
                   args=["-beam_mass", "linear"])
    with st.h5(h5) as f:
        err[n] = f["freq"][0, :5] / ref - 1
    print(f"  -beam_mass linear, {n} elements: relative errors f1..f5 {' '.join(f'{e:.2e}' for e in err[n])}")
order = np.log2(np.abs(err[16] / err[32]))
print(f"  observed orders 16 -> 32: {np.array2string(order, precision=2)}")
st.check(np.all(np.abs(err[32]) < 1.5e-2), "linear mass, 32 elements: f1..f5 within 1.5e-2 of B3")
st.check(np.all((order > 1.9) & (order < 2.1)), "linear mass: the frequencies converge as h^2")
st.check(np.all(np.abs(err[32]) < np.abs(err[16])) and np.all(np.abs(err[16]) < np.abs(err[8])),
         "linear mass: errors fall with every refinement")
st.done()
