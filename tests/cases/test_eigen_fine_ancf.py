"""Eigenvalues of fine meshes (docs/modal.md, "Eigenvalues on fine meshes"): the ANCF cantilever
(A1 cable unloaded: L = 2, EI = 833.33, rhoA = 78, EA = 1e6, clamp [1, 1, 0, 1]) at 4096 elements
and a finely meshed beam column (buckling), 2 ranks.

Discrete reference of the cable: the analytic Euler-Bernoulli bending and axial-bar frequencies.
The cubic Hermite discretization error of an eigenvalue falls like h^4: measured below at 64
elements (up to 7.2e-6 for the 10th frequency), so at 4096 = 64 x 64 elements it is below
7.2e-6 / 64^4 ~ 4e-13: the analytic values are the 4096-element discrete values to far better
than the 1e-8 asked. The assembled stiffness and its LU alone (-eigen_operator assembled, the
former method) lose eps * cond ~ n^4 of the lowest eigenvalue: f1 off by 2.3e-2 at 4096 elements.

Buckling: fixed-free column (L = 1, rect 10 x 1 mm, P = P_E / 2, compliant plane x-z) at 4096
elements against the same column at 512 elements (8x refinement; at 64 elements the second
multiplier still has a discretization error of 4e-8) and against Euler's mu = 2, 18 (modelling
difference of the beam: measured -5.4e-7, -5.7e-6)."""
import numpy as np
from scipy.optimize import brentq

import sinewtest as st
from modal_util import E, beam_x, yaml_text

EI, RHOA, EA, L = 833.3333333333333, 78.0, 1e6, 2.0
beta = [brentq(lambda x: np.cos(x) * np.cosh(x) + 1, (k + 0.5) * np.pi - 1, (k + 0.5) * np.pi + 1) for k in range(10)]
bending = [b**2 * np.sqrt(EI / (RHOA * L**4)) / (2 * np.pi) for b in beta]
axial = [(2 * k - 1) / (4 * L) * np.sqrt(EA / RHOA) for k in range(1, 6)]
ref = np.sort(bending + axial)[:10]


def cable(n):
    return {"title": "ANCF cantilever frequencies", "nodes": [[0, 0], [L, 0]], "elements": [[1, 2]],
            "nprops": {1: {"fix_coords": [1, 1, 0, 1]}},
            "eprops": [{"elems": [1], "type": "ancf_cable2d", "nbeams": n, "physicsMassPerLength": RHOA,
                        "physicsBendingStiffness": EI, "physicsAxialStiffness": EA, "useReducedOrderIntegration": 0}],
            "opt": {"loadsteps": 1, "calcfreq": True, "nfreq": 10}}


def frequencies(name, n, args=()):
    path, out = st.run(name, yaml_text(cable(n)), args=args)
    with st.h5(path) as f:
        return f["freq"][-1], f["freq_error_estimate"][-1], f["freq_backward_error"][-1], out


f64, _, _, _ = frequencies("eigen_fine_ancf64", 64)
err64 = f64 / ref - 1
print("  64 elements, relative error vs analytic:", np.array2string(err64, precision=2))
st.check(np.all(np.abs(err64) < 1e-5), "64 elements: the 10 frequencies within their discretization error (< 1e-5)")
bound = np.max(np.abs(err64)) / 64**4
st.check(bound < 1e-11, f"discretization error bound at 4096 elements {bound:.1e} < 1e-11")

f, est, back, out = frequencies("eigen_fine_ancf4096", 4096)
err = f / ref - 1
print("  4096 elements, relative error vs analytic (= discrete reference):", np.array2string(err, precision=2))
st.close(f / ref, 1.0, atol=1e-8, what="4096 elements: 10 frequencies / discrete reference")
st.check(np.all(est <= 1e-8) and np.all(back <= 1e-8),
         f"/freq_error_estimate (max {np.max(est):.1e}) and /freq_backward_error (max {np.max(back):.1e}) below -eps_tol")
st.check("warning" not in out, "no residual warning")

fa, _, _, _ = frequencies("eigen_fine_ancf4096_assembled", 4096, args=["-eigen_operator", "assembled"])
print(f"  assembled K and its LU (former method): f1 relative error {fa[0] / ref[0] - 1:.2e}")
st.check(abs(fa[0] / ref[0] - 1) > 1e-4, "the assembled operator alone is off (documents the cause)")

# buckling of a finely meshed column (beam elements)
Lc, W, T = 1.0, 0.01, 0.001
pe = np.pi**2 * E * W * T**3 / 12 / (2 * Lc) ** 2
mu = {}
for n in (512, 4096):
    path, out = st.run(f"eigen_fine_buckling{n}", beam_x(Lc, W, T, n, {1: {"fix": True}, 2: {"force": [-0.5 * pe, 0, 0]}}, dens=0,
                                                         opt={"loadsteps": 1, "calcbuck": True, "nbuck": 2}),
                       args=["-force_rtol", "1e-6", "-constraint_check", "false"])
    with st.h5(path) as f:
        mu[n] = f["buck"][-1]
        be = f["buck_backward_error"][-1]
    print(f"  column, {n} elements: mu = {mu[n]}, vs Euler (2, 18) - 1: {mu[n][0] / 2 - 1:.2e} {mu[n][1] / 18 - 1:.2e}, "
          f"backward error {np.max(be):.1e}")
st.close(mu[4096] / mu[512], 1.0, atol=1e-8, what="buckling multipliers, 4096 vs 512 elements")
st.close(mu[4096] / [2, 18], 1.0, atol=1e-5, what="buckling multipliers vs Euler (beam modelling difference)")
st.done()
