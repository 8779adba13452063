"""Parallel leaf-spring guide (reference B4) from the compliance matrix of the stage node:
lateral stiffness 24 EI / L^3 and support stiffness 2 EA / L undeflected (rel. 1e-3); as the
stage is pushed sideways over the load steps the support stiffness drops. Run on 2 ranks."""
import numpy as np

import sinewtest as st

E, G, w, t, L, d = 210e9, 80e9, 0.01, 0.0002, 0.05, 0.02
A, I = w * t, w * t**3 / 12
k_lat, k_sup = 24 * E * I / L**3, 2 * E * A / L
F = 0.1 * L * k_lat  # pushes the stage about 0.1 L sideways
SCENE = f"""
title: parallel leaf-spring guide
nodes: [[0, 0, 0], [0, 0, {L}], [0, {d}, 0], [0, {d}, {L}], [0, {d / 2}, {L}]]
elements: [[1, 2], [3, 4], [2, 5], [5, 4]]
nprops: {{1: {{fix: true}}, 3: {{fix: true}}, 5: {{force: [0, {F}, 0]}}}}
eprops: [{{elems: [1, 2], flex: [1, 2, 3, 4, 5, 6], emod: {E}, smod: {G}, cshape: rect, dim: [{w}, {t}],
          orien: [1, 0, 0], nbeams: 6}}]
opt: {{loadsteps: 5, compliance_nodes: [5]}}
"""
out, log = st.run("leafspring_compliance", SCENE, np_=2)
with st.h5(out) as f:
    C = f["node/CMglob"][:, 4]
    uy = f["node/p"][:, 4, 1] - d / 2
# undeflected: a separate run without load
out0, _ = st.run("leafspring_compliance0", SCENE.replace(f"force: [0, {F}, 0]", "force: [0, 0, 0]").replace("loadsteps: 5", "loadsteps: 1"), np_=2)
with st.h5(out0) as f:
    C0 = f["node/CMglob"][0, 4]
st.close(1 / C0[1, 1], k_lat, rtol=1e-3, what="lateral stiffness 1/C_yy vs 24EI/L^3")
st.close(1 / C0[2, 2], k_sup, rtol=1e-3, what="support stiffness 1/C_zz vs 2EA/L")
ksup = 1 / C[:, 2, 2]
klat = 1 / C[:, 1, 1]
print("  stage displacement / L:", np.array2string(uy / L, precision=4))
print("  support stiffness / (2EA/L):", np.array2string(ksup / k_sup, precision=4))
print("  lateral stiffness / (24EI/L^3):", np.array2string(klat / k_lat, precision=5))
st.check(np.all(np.diff(uy) > 0) and uy[-1] > 0.08 * L, "the stage moves sideways step by step")
st.check(np.all(np.diff(ksup) < 0), "support stiffness decreases as the guide deflects")
st.check(ksup[-1] < 0.5 * k_sup, f"support stiffness at u = {uy[-1] / L:.3f} L is below half of 2EA/L")
# with the stage held sideways (K = CMglob^-1): per leaf 1/k = L/EA + u^2 L / (700 EI) (first-order theory)
Kzz = np.array([np.linalg.inv(c)[2, 2] for c in C])
first_order = 2 / (L / (E * A) + uy**2 * L / (700 * E * I))
st.check(np.all(np.diff(Kzz) < 0), "held-stage support stiffness decreases as the guide deflects")
st.close(Kzz, first_order, rtol=2e-2, what="held-stage support stiffness vs 2/(L/EA + u^2 L/700EI)")
st.done()
