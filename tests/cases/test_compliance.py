# ctest-labels: smoke
"""Tip compliance of a clamped beam (6x6, closed form with the Timoshenko shear term) on 2 ranks;
CMloc = Q^T CMglob Q at a bent state; calccompl: false creates no compliance; compliance_nodes."""
import numpy as np

import sinewtest as st

E, G, w, t, L = 210e9, 80e9, 0.02, 0.005, 0.5
A = w * t
Iy, Iz = w * t**3 / 12, t * w**3 / 12          # local y = global y (orien), local z = global z
nu = E / (2 * G) - 1                            # 0.3125
kGA = 10 * (1 + nu) / (12 + 11 * nu) * G * A   # Cowper (1966) as SPACAR Light: 0.8497, not 5/6


def rect_torsion_constant(s1, s2):  # reference B6
    a, b = min(s1, s2) / 2, max(s1, s2) / 2
    n = np.arange(1, 2001, 2)
    return (1 / 3) * (2 * a)**3 * (2 * b) * (1 - 192 / np.pi**5 * (a / b) * np.sum(np.tanh(n * np.pi * b / (2 * a)) / n**5))


It = rect_torsion_constant(w, t)
SCENE = f"""
title: clamped beam compliance
nodes: [[0, 0, 0], [{L}, 0, 0]]
elements: [[1, 2]]
nprops: {{1: {{fix: true}}}}
eprops: [{{elems: [1], flex: [1, 2, 3, 4, 5, 6], emod: {E}, smod: {G}, cshape: rect, dim: [{w}, {t}], orien: [0, 1, 0], nbeams: 4}}]
opt: {{loadsteps: 1}}
"""

# closed form, order (ux, uy, uz, rx, ry, rz); force +y turns the tip about +z, force +z about -y
C = np.zeros((6, 6))
C[0, 0] = L / (E * A)
C[1, 1] = L**3 / (3 * E * Iz) + L / kGA
C[2, 2] = L**3 / (3 * E * Iy) + L / kGA
C[3, 3] = L / (G * It)
C[4, 4] = L / (E * Iy)
C[5, 5] = L / (E * Iz)
C[1, 5] = C[5, 1] = L**2 / (2 * E * Iz)
C[2, 4] = C[4, 2] = -L**2 / (2 * E * Iy)

out, log = st.run("compliance_cantilever", SCENE, np_=2, args=["-log_view"])
with st.h5(out) as f:
    st.check(f["node/CMglob"].shape == (1, 2, 6, 6), f"CMglob shape {f['node/CMglob'].shape}")
    Cg = f["node/CMglob"][0, 1]
    st.close(Cg, C, rtol=1e-9, what="tip CMglob vs closed form (max over the 6x6, rel. to max entry)")
    for i, j, what in [(0, 0, "L/EA"), (1, 1, "L^3/3EIz + L/kGA"), (2, 2, "L^3/3EIy + L/kGA"), (3, 3, "L/GIt"),
                       (4, 4, "L/EIy"), (5, 5, "L/EIz"), (1, 5, "L^2/2EIz"), (2, 4, "-L^2/2EIy")]:
        st.close(Cg[i, j], C[i, j], rtol=1e-9, what=f"C[{i+1},{j+1}] = {what}")
    # issue 10 item 11: the shear term uses SPACAR Light's (Cowper's) coefficient; with 5/6 the
    # closed form is 2.5e-5 relative higher (measured with Cowper: C[2,2] rel. error 3.3e-14)
    c56 = L**3 / (3 * E * Iz) + L / (5.0 / 6.0 * G * A)
    st.check(abs(Cg[1, 1] / c56 - 1) > 1e-5, f"C[2,2] is not the 5/6 value (rel. difference {abs(Cg[1, 1] / c56 - 1):.3e})")
    st.close(f["node/CMglob"][0, 0], np.zeros((6, 6)), atol=0, what="clamped node: zero compliance")
    st.close(f["node/CMloc"][0, 1], Cg, rtol=1e-12, what="CMloc = CMglob in the undeformed state")
st.check("SinewCompliance" in log, "-log_view lists SinewCompliance")

# bent state: tip moment about z -> CMloc = Q^T CMglob Q with Q = blockdiag(R, R) of the tip
bent = SCENE.replace("nprops: {1: {fix: true}}", f"nprops: {{1: {{fix: true}}, 2: {{moment: [0, 0, {0.5 * E * Iz / L}]}}}}")
bent = bent.replace("loadsteps: 1", "loadsteps: 2")
out, log = st.run("compliance_bent", bent, np_=2)
with st.h5(out) as f:
    q = f["node/r_quat"][-1, 1]
    Cg, Cl = f["node/CMglob"][-1, 1], f["node/CMloc"][-1, 1]
    st.check(f["node/CMglob"].shape[0] == 2, "one compliance row per load step")
w_, x, y, z = q  # scalar-first quaternion
R = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w_ * z), 2 * (x * z + w_ * y)],
              [2 * (x * y + w_ * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w_ * x)],
              [2 * (x * z - w_ * y), 2 * (y * z + w_ * x), 1 - 2 * (x * x + y * y)]])
angle = np.degrees(2 * np.arccos(min(1.0, abs(w_))))
st.close(angle, np.degrees(0.5), rtol=1e-2, what="tip rotation (deg) ~ ML/EI (4 elements: discretization error)")
Q = np.zeros((6, 6))
Q[:3, :3] = Q[3:, 3:] = R
st.close(Cl, Q.T @ Cg @ Q, rtol=1e-10, what="CMloc = Q^T CMglob Q at the bent tip")
st.check(abs(Cl[0, 0] - Cg[0, 0]) > 0.1 * abs(Cg[0, 0]), "the bent tip frame differs from the global axes")

# calccompl: false -> no compliance datasets, no SinewCompliance event
off = SCENE.replace("loadsteps: 1}", "loadsteps: 1, calccompl: false}")
out, log = st.run("compliance_off", off, np_=2, args=["-log_view"])
with st.h5(out) as f:
    st.check("node/CMglob" not in f and "node/CMloc" not in f, "calccompl: false writes no CMglob/CMloc")
st.check("SinewCompliance" not in log, "calccompl: false: no SinewCompliance event in -log_view")

# compliance_nodes limits the unit loads: node 1 only (clamped) -> zero matrices, no solves
sel = SCENE.replace("loadsteps: 1}", "loadsteps: 1, compliance_nodes: [1]}")
out, log = st.run("compliance_nodes", sel, np_=2)
with st.h5(out) as f:
    st.close(f["node/CMglob"][0, 1], np.zeros((6, 6)), atol=0, what="node 2 not requested: zeros")
st.check("0 unit loads per step" in log, "compliance_nodes: [1] (clamped) -> 0 unit loads")
st.done()
