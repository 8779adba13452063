"""ANCF cable (Exudyn ObjectANCFCable2D) statics on 2 ranks: A1 (Exudyn mini example), A2
(Exudyn ANCFCable2DBendingTest, Gerstmayr & Irschik 2008), roll-up into a circle, a pre-curved
cable, 1 vs 2 ranks, statics sensors, and 'only what is asked' (no mass matrix)."""
import math
import re

import numpy as np

import sinewtest as st
from ancf_scenes import cantilever, text, tip_displacement

# A1: L = 2, 32 elements, gravity; tip ux = -0.5013058140308901
a1 = cantilever(32, EA=1e6, EI=833.3333333333333, gravity=[0, -9.81],
                sensors=[{"element": 1, "x": 2.0, "variable": "Displacement", "name": "tip"},
                         {"element": 1, "x": 1.0, "variable": "Position", "name": "mid"}])
h5a, out = st.run("ancf_a1", text(a1), args=["-verbose"])  # -verbose: the force-law counters
with st.h5(h5a) as f:
    u = tip_displacement(f)
    st.close(u[0], -0.5013058140308901, rtol=1e-10, what="A1 tip ux")
    # sensors against node values: the tip is node 2; x = 1 is FE node 16 of the split (mesh row)
    st.close(f["sensors/tip"][-1][:2], u, atol=1e-14, what="A1 sensor tip Displacement = node 2")
    midnode = f["mesh/p"][-1][1 + 16]
    st.close(f["sensors/mid"][-1][:2], midnode[:2], atol=1e-14, what="A1 sensor mid Position = FE node at x = 1")
    ua2 = f["node/p"][-1]
# 'only what is asked': statics without gravity and calcfreq false assembles no mass matrix
st.check(re.search(r"\b0 mass\b", out) is not None, "A1 (gravity) without frequencies: no mass assembly expected")
# ... and no user function and no damping term is evaluated (force-law counters of the summary)
m = re.search(r"(\d+) user-function evaluations, (\d+) damping-term evaluations", out)
st.check(m is not None and int(m.group(1)) == 0 and int(m.group(2)) == 0,
         "A1: 0 user-function and 0 damping-term evaluations expected")
# massProportionalLoad [0, -9.81] on the set (Exudyn LoadMassProportional) instead of gravity: same tip
a1m = cantilever(32, EA=1e6, EI=833.3333333333333)
a1m["eprops"][0]["massProportionalLoad"] = [0, -9.81]
h5m, _ = st.run("ancf_a1_massload", text(a1m))
with st.h5(h5m) as f:
    st.close(tip_displacement(f)[0], -0.5013058140308901, rtol=1e-10, what="A1 with massProportionalLoad: tip ux")
a1_1rank, _ = st.run("ancf_a1_1rank", text(a1), np_=1)
with st.h5(a1_1rank) as f:
    st.close(f["node/p"][-1], ua2, atol=1e-12, what="A1 1 rank vs 2 ranks, node positions")

# A2: tip force f = 3 EI / L^2, 1..256 elements
A2 = {1: (-0.36224472989050654, -0.9941447587249747), 2: (-0.4889263083414858, -1.1752228650551666),
      4: (-0.5074287151188892, -1.2055337022335404), 8: (-0.5085092364970802, -1.2071977560198281),
      64: (-0.5085373029700947, -1.2072398533360738), 256: (-0.5085373043209689, -1.2072398545457785)}
for n, ref in A2.items():
    h5, _ = st.run(f"ancf_a2_{n}", text(cantilever(n, force=1.29375e6)))
    with st.h5(h5) as f:
        st.close(tip_displacement(f), ref, rtol=1e-9, what=f"A2 {n} elements tip (ux, uy)")

# Roll-up: M = 2 pi EI / L closes the cantilever into a circle; the tip returns to the root.
# Measured |tip - root| / L: 9.6e-5 (16 elements), 3.9e-7 (64): the Hermite interpolation error
# of the circle, O(h^4) (ratio 247 ~ 4^4). Tolerance 1e-6 L at 64 elements.
roll = cantilever(64, L=1.0, EA=1e4, EI=1.0, rhoA=1.0, opt={"loadsteps": 10})
roll["nprops"] = {1: {"fix_coords": [1, 1, 1, 1]}, 2: {"moment": [0, 0, 2 * math.pi]}}
h5, _ = st.run("ancf_rollup", text(roll))
with st.h5(h5) as f:
    st.close(np.linalg.norm(f["node/p"][-1][1, :2]), 0.0, atol=1e-6, what="roll-up |tip - root| / L (64 elements)")

# Pre-curved: quarter circle R = 1, 8 elements on the circle with exact reference slopes (nprops
# slope), physicsReferenceCurvature = 1/R, no load. The nodes stay on the circle up to the
# interpolation error of the Hermite circle (measured max radial deviation 8.1e-6 R).
R, n = 1.0, 8
th = [math.pi / 2 * i / n for i in range(n + 1)]
npr = {i + 1: {"slope": [math.cos(t), math.sin(t)]} for i, t in enumerate(th)}
npr[1]["fix_coords"] = [1, 1, 1, 1]
curved = {"title": "pre-curved", "nodes": [[R * math.sin(t), R * (1 - math.cos(t))] for t in th],
          "elements": [[i + 1, i + 2] for i in range(n)], "nprops": npr,
          "eprops": [{"elems": list(range(1, n + 1)), "type": "ancf_cable2d", "physicsMassPerLength": 1,
                      "physicsBendingStiffness": 1, "physicsAxialStiffness": 1e4, "physicsReferenceCurvature": 1 / R}],
          "opt": {"loadsteps": 1, "calcfreq": False}}
h5, _ = st.run("ancf_precurved", text(curved))
with st.h5(h5) as f:
    p = f["node/p"][-1]
    st.close(np.abs(np.hypot(p[:, 0], p[:, 1] - R) - R).max(), 0.0, atol=2e-5, what="pre-curved radial deviation")
# strainIsRelativeToReference = 1: the given shape is stress free, no motion at all
curved["eprops"][0]["strainIsRelativeToReference"] = 1
curved["eprops"][0]["physicsReferenceCurvature"] = 0
h5, _ = st.run("ancf_precurved_rel", text(curved))
with st.h5(h5) as f:
    st.close(f["node/p"][-1] - f["node/p0"][:], 0.0, atol=1e-14, what="strain relative to reference: displacement")
st.done()
