# ctest-labels: smoke
"""Small-load cantilevers against linear beam theory (Euler-Bernoulli bending plus the Timoshenko
shear term F L / (kGA) of the element; B6 torsion constant). Four separate cantilevers in one
scene, each loaded at its tip in one direction: axial force (F L / EA), force along global y
(bending about local y: F L^3 / (3 EIy) + F L / kGA, end rotation F L^2 / (2 EIy)), force along
global z (bending about local z, EIz), torque about the axis (T L / GIt). kGA with Cowper's
coefficient 0.8497 (beamtools.cowper_rect, issue 10 item 11): measured rel. errors 1.0e-10 (v, w),
8.0e-11 (rotations), 6.6e-12 (axial), 4.1e-12 (twist); with 5/6 the reference would be 1.5e-6 off. The loads give
displacements of 1e-5 L, so geometric nonlinearity is below 1e-9 relative."""
import numpy as np

import beamtools as bt
import sinewtest as st

L, w, t, nel, nb = 1.0, 0.02, 0.01, 3, 2
sec = bt.rect_section(w, t)
F_ax = 1e-5 * sec["EA"] / L
F_y = 1e-5 * 3 * sec["EIy"] / L ** 3
F_z = 1e-5 * 3 * sec["EIz"] / L ** 3
T_x = 1e-5 * sec["GIt"] / L
loads = [{"force": [F_ax, 0, 0]}, {"force": [0, F_y, 0]}, {"force": [0, 0, F_z]}, {"moment": [T_x, 0, 0]}]

nodes, elems, nprops, tips = [], [], {}, []
for c, load in enumerate(loads):
    n, e = bt.chain([0, 0.1 * c, 0], [L, 0.1 * c, 0], nel, first=len(nodes) + 1)
    nprops[str(len(nodes) + 1)] = {"fix": True}
    nodes += n
    elems += e
    tips.append(len(nodes) - 1)
    nprops[str(len(nodes))] = load
scene = {"title": "small-load cantilevers", "nodes": nodes, "elements": elems, "nprops": nprops,
         "eprops": [bt.beam_set(range(1, len(elems) + 1), w, t, nbeams=nb)],
         "opt": {"loadsteps": 1, "calccompl": False}}
out, log = st.run("beam_cantilever", bt.yaml_text(scene))
with st.h5(out) as f:
    p = f["node/p"][-1]
    p0 = f["node/p0"][:]
    q = f["node/r_quat"][-1]
u = p - p0


def rotvec(qq):
    qq = qq * np.sign(qq[0])
    s = np.linalg.norm(qq[1:])
    return 2 * np.arctan2(s, qq[0]) * qq[1:] / s if s > 0 else np.zeros(3)


i = tips
st.close(u[i[0], 0], F_ax * L / sec["EA"], rtol=1e-6, what="axial tip u = F L/EA")
eb = F_y * L ** 3 / (3 * sec["EIy"])
print(f"  (Euler-Bernoulli alone differs by {abs(u[i[1], 1] - eb) / eb:.3e} relative: the shear term matters)")
st.close(u[i[1], 1], eb + F_y * L / sec["kGA"], rtol=1e-6, what="tip v (force y) = F L^3/(3 EIy) + F L/kGA")
st.close(rotvec(q[i[1]]), [0, 0, F_y * L ** 2 / (2 * sec["EIy"])], rtol=1e-6, what="tip rotation (force y) = F L^2/(2 EIy) about z")
st.close(u[i[2], 2], F_z * L ** 3 / (3 * sec["EIz"]) + F_z * L / sec["kGA"], rtol=1e-6,
         what="tip w (force z) = F L^3/(3 EIz) + F L/kGA")
st.close(rotvec(q[i[2]]), [0, -F_z * L ** 2 / (2 * sec["EIz"]), 0], rtol=1e-6, what="tip rotation (force z) = F L^2/(2 EIz) about -y")
st.close(rotvec(q[i[3]]), [T_x * L / sec["GIt"], 0, 0], rtol=1e-6, what="tip twist = T L/GIt (B6 I_t)")
st.close(u[i[3]], [0, 0, 0], atol=1e-12, what="torsion: tip does not move")
st.done()
