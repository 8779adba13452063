# ctest-labels: smoke
"""Euler buckling multipliers (reference B2: P_cr = pi^2 EI / (K L)^2) for the four support cases,
from the split tangent K_m phi = -mu K_g phi at every load step: the column (L = 1, rect 10 x 1 mm,
20 elements, compliant plane x-z) carries P0 = P_cr / 2 at load factor 1, so mu = P_cr / (lambda P0)
at load factor lambda (2 steps: mu = 4, then 2). Fixed-pinned uses P_cr = 20.1907 EI / L^2.
Torsion of the pinned-pinned column is held by a rigid arm from node 1 to node 3 (fix_z).
Hard cases: P0 = 0.999 P_cr over 5 steps (mu -> 1.001001 at the last one, the tangent nearly
singular), and a column in tension (no positive multiplier: +inf).
The equilibrium residual of these axially loaded columns stalls at the round-off of the axial
forces (EA = 2.1e6 N against loads below 1 N: up to about 1e-7 of the load was seen), so the
static steps run with -force_rtol 1e-6; the multipliers depend on the axial force, which that
tolerance leaves exact to 1e-6."""
import numpy as np

import sinewtest as st
from modal_util import E, beam_x

L, W, T = 1.0, 0.01, 0.001
EI = E * W * T**3 / 12
# see the docstring; -load_ramp uniform: the references are at load factors k/n (2 steps: 0.5, 1), Sinew's
# former steps (SPACAR Light's step 1 would be the unloaded column, load factor 0, mu = +inf)
RTOL = ["-force_rtol", "1e-6", "-load_ramp", "uniform"]
arm = {"extra_nodes": [[0, 0.1, 0]], "extra_elements": [[1, 3]]}
cases = [  # name, P_cr, supports, tip constraints, extra geometry, higher multipliers / first
    ("fixed-free", np.pi**2 * EI / (2 * L) ** 2, {1: {"fix": True}}, {}, {}, [9, 25]),
    ("pinned-pinned", np.pi**2 * EI / L**2, {1: {"fix_pos": True}, 3: {"fix_z": True}}, {"fix_y": True, "fix_z": True}, arm,
     [4, 9]),
    ("fixed-fixed", np.pi**2 * EI / (0.5 * L) ** 2, {1: {"fix": True}}, {"fix_y": True, "fix_z": True, "fix_orien": True}, {},
     None),
    ("fixed-pinned", 20.1907 * EI / L**2, {1: {"fix": True}}, {"fix_y": True, "fix_z": True}, {}, None),
]
for name, pcr, sup, tip, geo, higher in cases:
    p0 = 0.5 * pcr
    nprops = dict(sup)
    nprops[2] = dict(tip, force=[-p0, 0, 0])
    path, out = st.run("buckling_" + name, beam_x(L, W, T, 20, nprops, dens=0,
                                                 opt={"loadsteps": 2, "calcbuck": True}, **geo), args=RTOL)
    with st.h5(path) as f:
        b = f["buck"][:]
        st.check(b.shape == (2, 3), f"{name}: /buck shape {b.shape}")
        st.close(b[:, 0], [4.0, 2.0], rtol=1e-4, what=f"{name}: mu at load factor 0.5, 1")
        if higher:
            st.close(b[1, 1:] / b[1, 0], higher, rtol=1e-3, what=f"{name}: higher multipliers / first")
        st.check(np.all(np.diff(b[1]) > 0), f"{name}: ascending")
        shape = f["mesh/mode_buck_1"][1]
        st.check(abs(np.max(np.abs(shape[:, 2])) - 1.0) < 1e-12 and np.max(np.abs(shape[:, 1])) < 1e-6,
                 f"{name}: buckling mode in the compliant plane (z), max |u| = 1")

# near-critical: P0 = 0.999 P_cr (fixed-free), 5 steps
pcr = cases[0][1]
path, out = st.run("buckling_near_critical", beam_x(L, W, T, 20, {1: {"fix": True}, 2: {"force": [-0.999 * pcr, 0, 0]}},
                                                   dens=0, opt={"loadsteps": 5, "calcbuck": True, "nbuck": 2}),
                   args=RTOL)
with st.h5(path) as f:
    b = f["buck"][:, 0]
    lam = f["load_factor"][:]
    st.close(b, 1.0 / (0.999 * lam), rtol=1e-4, what="near-critical mu at every step")
    print(f"  last step: mu = {b[-1]:.9f}, expected {1 / 0.999:.9f}")

# tension: no positive multiplier -> +inf (documented)
path, out = st.run("buckling_tension", beam_x(L, W, T, 10, {1: {"fix": True}, 2: {"force": [pcr, 0, 0]}}, dens=0,
                                             opt={"loadsteps": 1, "calcbuck": True}), args=RTOL)
with st.h5(path) as f:
    b = f["buck"][0]
    print("  tension: /buck =", b)
    st.check(np.all(np.isinf(b) & (b > 0)), "a column in tension has no positive multiplier (+inf)")
st.check("inf: no (further) positive multiplier" in out, "summary explains +inf")
st.done()
