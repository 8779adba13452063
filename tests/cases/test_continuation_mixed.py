#!/usr/bin/python3
"""Issue 11 item 1: path following of a mixed model, beams + a 3D cable, 2 ranks. The von Mises truss
of test_continuation.py (half span a = 1, rise H = 0.1, two beam elements as pinned bars, EA = 1e4,
apex load P down as the reference load) with its right support on a roller (free in x) and the two
supports tied by a `cable` element (EA_c = 2e4, no prestress: it is slack-free from the first load).
The roller spreads by s, the tie carries T = EA_c s / (2a) (Sinew's cable: N = N0 + EA (l/L - 1)),
the apex moves to x = s/2 (symmetry of the bars). Closed form per apex deflection w: bar length
L = sqrt((a + s/2)^2 + (H - w)^2), bar force N = EA (L - L0)/L0, roller balance N (a + s/2)/L + T = 0
(a root in s), apex balance P = -2 N (H - w)/L. The tie lowers the snap load: P_max = +-2.544791 N
(+-3.810872 N with fixed supports). The path stops at w = 0.18 < 2H: past w = 2H the bars pull, the tie
goes slack and the roller is a mechanism. Checked:
  (1) arc length through both limit points to w = 0.18: every path point on P(w) to 1e-9 P_max
      (measured 2.8e-10 N), the roller on s(w) to 1e-9 m (3.9e-13 m), the apex at x = s/2;
  (2) both limit points located (load factors within 1e-4 of the closed form's extremes; measured
      1.5e-8), the negative-eigenvalue count 1 exactly where dP/dw < 0."""
import math

import numpy as np
from scipy.optimize import brentq

import beamtools as bt
import sinewtest as st

a, H, EA, EAc = 1.0, 0.1, 1e4, 2e4
d = math.sqrt(4 * 1e-3 / math.pi)  # A = 1e-3, E = 1e7
L0 = math.hypot(a, H)


def state(w):
    """(P, s) on the closed-form path at apex deflection w."""
    def f(s):
        L = math.hypot(a + s / 2, H - w)
        return EA * (L - L0) / L0 * (a + s / 2) / L + EAc * s / (2 * a)
    s = brentq(f, 0.0, 0.5) if f(0.0) < 0 else 0.0
    L = math.hypot(a + s / 2, H - w)
    return -2 * EA * (L - L0) / L0 * (H - w) / L, s


ws = np.linspace(0, 2 * H, 40001)
Ps = np.array([state(w)[0] for w in ws])
Pmax, Pmin = Ps.max(), Ps.min()
print(f"  closed form: limit loads {Pmax:.6f} N at w = {ws[Ps.argmax()]:.5f} m, {Pmin:.6f} N at w = {ws[Ps.argmin()]:.5f} m")

scene = bt.yaml_text({"title": "tied von Mises truss (beams + cable)", "nodes": [[-a, 0, 0], [0, H, 0], [a, 0, 0]],
                      "elements": [[1, 2], [3, 2], [1, 3]],
                      "nprops": {"1": {"fix": True}, "3": {"fix_y": True, "fix_z": True, "fix_orien": True},
                                 "2": {"fix_z": True, "fix_orien": True, "force": [0, -1, 0]}},
                      "eprops": [{"elems": [1, 2], "flex": [1], "emod": 1e7, "smod": 4e6, "cshape": "circ", "dim": [d]},
                                 {"elems": [3], "type": "cable", "area": 1e-3, "emod": EAc / 1e-3}],
                      "opt": {"rls": {"1": [2, 3, 4, 5, 6], "2": [2, 3, 4, 5, 6]}, "calccompl": False,
                              "continuation": {"method": "arclength", "ds": 0.005, "node": 2, "direction": "y",
                                               "stop_displacement": -0.18}}})
h5, out = st.run("continuation_mixed", scene)
with st.h5(h5) as f:
    lam, p, neg = f["load_factor"][:], f["node/p"][:], f["path/negative_eigenvalues"][:]
    crit, conv = f["path/critical_points"][:], int(f.attrs["converged"])
w = H - p[:, 1, 1]
s = p[:, 2, 0] - a
print(f"  path: {len(lam)} points, load factors {np.array2string(lam, precision=4)}")
print("  negative eigenvalues", neg.astype(int))
st.check(conv == 1 and w[-1] >= 0.18 - 1e-12, f"path reaches w = 0.18 (w = {w[-1]:.4f}, converged {conv})")
ref = np.array([state(x) for x in w])
st.close(lam, ref[:, 0], atol=1e-9 * Pmax, what="path points vs P(w) [N]")
st.close(s, ref[:, 1], atol=1e-9, what="roller spread s(w) [m]")
st.close(p[:, 1, 0], s / 2, atol=1e-9, what="apex x = s/2 [m]")
dP = np.array([(state(x + 1e-7)[0] - state(x - 1e-7)[0]) / 2e-7 for x in w])
st.check(np.array_equal(neg, (dP < 0).astype(float)), f"negative eigenvalues = 1 exactly where dP/dw < 0 ({(dP < 0).astype(int)})")
if st.check(crit.shape == (2, 4) and np.all(crit[:, 0] == 1), f"two limit points found: {crit}"):
    st.close(crit[:, 2], [Pmax, Pmin], rtol=1e-4, what="limit loads [N]")
st.done()
