"""The sections' bending rotary inertia in the consistent beam mass (docs/dynamics.md, "Inertia"): the
frequencies of a thick cantilever against beam theory with and without it. A steel cantilever L = 1 m,
rect section 100 mm (y) x 50 mm (z), E = 210e9, G = 80e9, rho = 7800, 40 elements, 1 rank. Sinew's
beams always have the Timoshenko shear stiffness kGA (Cowper's kappa), so the reference is Timoshenko's
beam, rhoA w_tt = (kGA (w' - phi))', rho I phi_tt = EI phi'' + kGA (w' - phi), clamped at x = 0
(w = phi = 0), free at x = L (phi' = 0, w' - phi = 0): its frequencies are the zeros of the 2 x 2
determinant of the transfer matrix exp(A L) of the state (w, w', phi, phi'), found by bisection;
"without rotary inertia" is the same with rho I = 0 (the shear beam; rho I = 0 and kGA -> infinity is
Euler-Bernoulli). The rotary inertia lowers the higher frequencies: mode 4 in the thin plane (r / L =
0.0144) by 1.3 %, in the wide plane (r / L = 0.0289) by 3.4 %.
Measured (2026-11-27): the first four frequencies of each plane above Timoshenko's by 1.3e-7 .. 3.8e-4
(mode 4 of the wide plane; 80 elements: 3.1e-8 .. 9.5e-5, the mesh's h^2); 1.2e-2 and 3.4e-2 below the
beam without rotary inertia in mode 4 (before the bending rotary inertia was in the mass, the computed
frequencies were that beam's, 1.4e-4 and 4.2e-4 above it, and this test failed). With the rotary
inertia on the Hermite slopes v' instead of the Timoshenko section rotation the wide plane's mode 4 came
out 1.8e-2 below Timoshenko's (the slopes carry the shear strain too)."""
# ctest-processors: 1
import numpy as np
from scipy.linalg import expm

import sinewtest as st
from modal_util import E, G, RHO, yaml_text

L, W, T, n = 1.0, 0.1, 0.05, 40
A = W * T
scene = {"title": "thick cantilever (rotary inertia)", "nodes": [[0, 0, 0], [L, 0, 0]], "elements": [[1, 2]],
         "nprops": {1: {"fix": True}},
         "eprops": [{"elems": [1], "flex": [1, 2, 3, 4, 5, 6], "emod": E, "smod": G, "cshape": "rect",
                     "dim": [W, T], "orien": [0, 1, 0], "nbeams": n, "dens": RHO}],
         "opt": {"loadsteps": 1, "calccompl": False, "calcfreq": True, "nfreq": 12}}
path, out = st.run("beam_rayleigh_frequencies", yaml_text(scene), np_=1)
with st.h5(path) as h:
    f = np.sort(h["freq"][-1])

nu = E / (2 * G) - 1
kGA = 10 * (1 + nu) / (12 + 11 * nu) * G * A  # Cowper's rect coefficient, as src/elements/beam_section.cpp


def timoshenko_hz(I, nmodes, rotary=True):
    """The first cantilever bending frequencies of Timoshenko's beam (rotary inertia rho I or none)."""
    EI, rI = E * I, (RHO * I if rotary else 0.0)

    def det(om):
        w2 = om * om
        a = np.array([[0, 1, 0, 0], [-RHO * A * w2 / kGA, 0, 0, 1], [0, 0, 0, 1],
                      [0, -kGA / EI, (kGA - rI * w2) / EI, 0]])
        m = expm(a * L)[:, [1, 3]]  # the clamp leaves w'(0), phi'(0) free
        end = np.array([m[3], m[1] - m[2]])  # phi'(L) = 0, w'(L) - phi(L) = 0
        return np.linalg.det(end)

    grid = np.linspace(1.0, 1.05 * 14.14 ** 2 * np.sqrt(EI / (RHO * A * L ** 4)), 4000)
    vals = [det(x) for x in grid]
    roots = []
    for i in range(len(grid) - 1):
        if np.sign(vals[i]) != np.sign(vals[i + 1]) and len(roots) < nmodes:
            lo, hi, flo = grid[i], grid[i + 1], vals[i]
            for _ in range(100):
                mid = 0.5 * (lo + hi)
                fm = det(mid)
                if np.sign(fm) == np.sign(flo):
                    lo, flo = mid, fm
                else:
                    hi = mid
            roots.append(0.5 * (lo + hi))
    return np.array(roots) / (2 * np.pi)


Iy, Iz = W * T ** 3 / 12, T * W ** 3 / 12  # bending along z (thin plane) and along y (wide plane)
ref = np.concatenate([timoshenko_hz(Iy, 4), timoshenko_hz(Iz, 4)])
shear = np.concatenate([timoshenko_hz(Iy, 4, rotary=False), timoshenko_hz(Iz, 4, rotary=False)])
# each reference frequency's nearest computed one (the axial and torsion modes are left aside)
got = np.array([f[np.argmin(np.abs(f - x))] for x in ref])
dev, dev_shear = got / ref - 1, got / shear - 1
for i in range(8):
    print(f"  {'thin' if i < 4 else 'wide'} plane mode {i % 4 + 1}: {got[i]:10.4f} Hz, Timoshenko {ref[i]:10.4f} "
          f"({dev[i]:+.1e}), without rotary inertia {shear[i]:10.4f} ({dev_shear[i]:+.1e})")
st.check("warning" not in out, "no residual warning")
st.close(got / ref, 1.0, atol=5e-4, what="thick cantilever: 4 bending frequencies per plane vs Timoshenko")
st.check(dev_shear[3] < -0.005 and dev_shear[7] < -0.02,
         "the rotary inertia lowers mode 4 below the beam without it (thin plane > 0.5 %, wide > 2 %)")
st.done()
