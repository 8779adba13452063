# ctest-labels: smoke
"""Newton per time step on a fine cable (issue 12 item 2, growth to 65536 elements): A1g = the A1
ANCF cantilever (references A1: L = 2, EA = 1e6, EI = 833.33, rhoA = 78; clamp [1,1,0,1]) swinging
down under gravity from the horizontal, generalized-alpha rho = 0.6, h = 1e-3, on 4096 elements,
2 ranks, 30 steps.

The former start of each step, the extrapolation q_n + h qd_n + h^2/2 a_n, carried the algorithmic
accelerations of the axial and short bending waves that h = 1e-3 does not resolve (h omega >> 1):
Newton started at residuals of 1e5..5e8 N, full Newton diverged, modified Newton stalled and
refactored. Now Newton starts at q_n (-dynamics_predictor auto: state from 200 unknowns) and
converges on its update where the residual is round-off noise (src/dynamics/dynamic_analysis.cpp).

Reference: the tip of the former path, main at 77256a8 on the same scene and 2 ranks (116 Newton
iterations on 52 Jacobians, 3 steps retried): (-2.07697853e-06, -4.39164168e-03) m. Measured
(2 ranks, 2026-11-25): 60 Newton iterations on 7 Jacobians, no retried step; tip
(-2.08081006e-06, -4.39164166e-03) m, difference (3.8e-9, 2.0e-11) m at a deflection of 4.4e-3 m.
The x difference is the former path's: it accepted a step after one iteration at the residual floor;
this build with -dynamics_predictor acceleration gives (-2.08083020e-06, -4.39164168e-03), 2.0e-11 and
2.3e-11 from the default, at 101 iterations on 27 Jacobians with 1 retried step.
The test fails when the predictor is ignored (more than 2.5 iterations per step, retries).
Runtime: 17 s wall, 54 s at load average ~10 from other jobs on the shared 2 cores."""
import re

import numpy as np

import sinewtest as st
from ancf_scenes import cantilever, text, tip_displacement

N, STEPS, H = 4096, 30, 1e-3


def run(name, args=()):
    scene = cantilever(N, EA=1e6, EI=833.3333333333333, gravity=[0, -9.81],
                       dynamics={"tend": STEPS * H, "dt": H, "spectral_radius": 0.6, "output_every": STEPS})
    h5, out = st.run(name, text(scene), args=list(args))
    m = re.search(r"(\d+) Newton iterations on (\d+) Jacobians", out)
    r = re.search(r"(\d+) steps retried", out)
    with st.h5(h5) as f:
        st.close(f["time"][-1], STEPS * H, rtol=1e-12, what=f"{name}: end time reached")
        tip = np.array(tip_displacement(f))
    its, jac, retried = int(m.group(1)), int(m.group(2)), int(r.group(1)) if r else 0
    print(f"  {name}: {its} Newton iterations on {jac} Jacobians, {retried} steps retried, tip {tip}")
    return its, jac, retried, tip


its, jac, retried, tip = run("a1g_fine")
tip0 = np.array([-2.07697853e-06, -4.39164168e-03])  # main at 77256a8, the former predictor
d = np.abs(tip - tip0)
print(f"  tip difference to the former path: {d} m (tip deflection {np.linalg.norm(tip):.3g} m)")
st.check(its <= 2.5 * STEPS, f"{its} Newton iterations in {STEPS} steps: at most 2.5 per step expected (measured 60)")
st.check(jac <= 10, f"{jac} Jacobians in {STEPS} steps: at most 10 expected (measured 7)")
st.check(retried == 0, f"{retried} steps retried: none expected (measured 0; the former path 3)")
st.check(d.max() < 1e-8, f"tip differs from the former path's by {d} m: 1e-8 m expected (measured 3.8e-9, 2.0e-11)")
st.done()
