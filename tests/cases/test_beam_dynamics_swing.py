"""Beams in dynamics at large steps (2 ranks): the steel leaf cantilever of
scripts/study_beam_dynamics.py (1 m x 20 mm x 2 mm, 16 elements, dens 7800) released straight under
its weight (g along its thin direction: static tip deflection 0.135 m, a geometrically nonlinear
swing), generalized alpha rho = 0.6, to t = 0.3 s (T1 = 0.597 s).
Reference: the same scene with 192 steps (tip y -0.268012 m; 6144 steps: -0.267937 m).
With 12 steps (dt = T1/24) the defaults (Newton with mixed stresses, each step started at q_n)
give -0.265582 m (difference 2.4e-3 m, the scheme's error at that step) in 36 Newton iterations,
no retried step. The former defaults (displacement-based tangent, start extrapolated by the
accelerations) took 220 iterations with 2 retried steps and converged to another root of the step
equations: -0.318 m (5.0e-2 m off); the mixed stresses alone (extrapolated start) took 303
iterations with 5 retries, the q_n start alone 47 iterations. The test fails if either default is
lost: the tip bound catches the wrong root, the iteration bound (<= 42) the displacement tangent."""
import os
import re
import sys

import numpy as np

import sinewtest as st

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from study_beam_dynamics import sinew_scene  # noqa: E402  (the study's scene: one definition)


def scene(steps):
    return sinew_scene(16, steps)


tips, its = {}, {}
for steps in (192, 12):
    h5, out = st.run(f"beamdyn_swing_{steps}", scene(steps))
    with st.h5(h5) as f:
        tips[steps] = f["node/p"][-1, -1, :] - f["node/p0"][-1, :]
    m = re.search(r"(\d+) Newton iterations on \d+ Jacobians", out)
    its[steps] = int(m.group(1))
    retried = re.search(r"(\d+) steps retried", out)
    print(f"  {steps} steps: tip {tips[steps]}, {its[steps]} Newton iterations, "
          f"{retried.group(1) if retried else 0} steps retried")
d = np.linalg.norm(tips[12] - tips[192])
print(f"  12 vs 192 steps: tip difference {d:.3e} m")
st.close(tips[192][1], -0.268012, atol=2e-5, what="tip y with 192 steps [m] (regression of this scene)")
st.check(d < 5e-3, "12 steps: tip within 5e-3 m of the 192-step run (the right root of the step equations)")
st.check(its[12] <= 42, f"12 steps: at most 42 Newton iterations (measured {its[12]})")
st.done()
