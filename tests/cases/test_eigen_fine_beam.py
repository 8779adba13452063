"""Eigenvalues of fine meshes, beams (docs/modal.md, "Eigenvalues on fine meshes"): a steel leaf
spring cantilever (L = 1, rect 10 x 1 mm, E = 210e9, G = 80e9, rho = 7800) at 8192 beam elements
on 2 ranks against the same spring at 128 elements (64x refinement; the first three frequencies of
128 and 8192 elements agree to the discretization error of 128 elements, measured 1.4e-9 since the
sections' bending rotary inertia is in the mass, below 1e-10 before), and f1 against Euler-Bernoulli
(the beam's shear and rotary inertia: -7.9e-7, of which the bending rotary inertia -1.9e-7). The assembled
stiffness and its LU alone gave 3.7e-3 at 8192 elements."""
import numpy as np

import sinewtest as st
from modal_util import beam_x, cantilever_hz

L, W, T = 1.0, 0.01, 0.001
f = {}
for n in (128, 8192):
    path, out = st.run(f"eigen_fine_beam{n}", beam_x(L, W, T, n, {1: {"fix": True}}, opt={"calcfreq": True, "nfreq": 3}),
                       args=["-constraint_check", "false"])
    with st.h5(path) as h:
        f[n] = h["freq"][-1]
        est, back = h["freq_error_estimate"][-1], h["freq_backward_error"][-1]
    print(f"  {n} elements: f = {np.array2string(f[n], precision=10)} Hz, error estimate <= {np.max(est):.1e}, "
          f"backward error <= {np.max(back):.1e}")
    st.check("warning" not in out, f"{n} elements: no residual warning")
st.close(f[8192] / f[128], 1.0, atol=1e-8, what="leaf spring: 3 frequencies, 8192 vs 128 elements")
eb = cantilever_hz(L, W, T, 1)[0]
print(f"  f1 vs Euler-Bernoulli: {f[8192][0] / eb - 1:.2e}")
st.close(f[8192][0] / eb, 1.0, atol=1e-6, what="f1 vs Euler-Bernoulli (shear, rotary inertia)")
st.done()
