# ctest-labels: smoke
"""Issue 11, path following (opt.continuation), first step: the von Mises truss (two pinned bars,
half span a = 1, rise H = 0.1, EA = 1e4, apex load P down). Closed form (equilibrium of the apex,
engineering strain as Sinew's axial mode e1 = |l| - l0): P(w) = 2 EA (L0 - L)/L0 (H - w)/L with
L = sqrt(a^2 + (H - w)^2); limit points P = +-3.810872 at w = 0.042361 and 2H - 0.042361
(snap-through: load control stops at the first; see e.g. Crisfield 1991, Vol. 1, section 9.1).
  (1) arc length (cylindrical), 2 ranks: every path point on P(w) to 1e-9 P_max; the path goes
      through both limit points to w = 0.25; both located by the Hermite interpolant: load factor
      within 1e-4 of P_max, displacement within 1e-3 of the closed form (measured in the output);
  (2) negative eigenvalues of the tangent (MUMPS inertia) = 1 exactly where dP/dw < 0, 0 elsewhere:
      the count changes by one at each limit point;
  (3) 1 rank and 2 ranks identical to 1e-9 along the whole path;
  (4) displacement control of the apex gives points on the same curve; stop_load_factor stops."""
import math

import numpy as np

import path_scenes
import sinewtest as st

a, H, EA = path_scenes.TRUSS_A, path_scenes.TRUSS_H, 1e4  # A = 1e-3, E = 1e7 (path_scenes.von_mises_truss)
L0 = math.hypot(a, H)


def P(w):
    L = np.hypot(a, H - w)
    return 2 * EA * (L0 - L) / L0 * (H - w) / L


def dP(w):
    return (P(w + 1e-7) - P(w - 1e-7)) / 2e-7


ws = np.linspace(0, H, 200001)
wlim = ws[np.argmax(P(ws))]
Pmax = P(wlim)


scene = path_scenes.von_mises_truss


def path(h5):
    with st.h5(h5) as f:
        return (f["load_factor"][:], H - f["node/p"][:, 1, 1], f["path/negative_eigenvalues"][:],
                f["path/critical_points"][:], int(f.attrs["converged"]))


arc = {"method": "arclength", "ds": 0.005, "node": 2, "direction": "y", "stop_displacement": -0.25}
runs = {}
for np_ in (2, 1):
    h5, out = st.run(f"continuation_truss_{np_}", scene(arc), np_=np_)
    runs[np_] = path(h5)
lam, w, neg, crit, conv = runs[2]
st.check(conv == 1 and w[-1] >= 0.25 - 1e-12, f"path reaches w = 0.25 (w = {w[-1]:.4f}, converged {conv})")
st.close(lam, P(w), atol=1e-9 * Pmax, what="path points vs P(w) [N]")
print(f"  path: {len(lam)} points, load factors {np.array2string(lam, precision=4)}")
unstable = dP(w) < 0
st.check(np.array_equal(neg, unstable.astype(float)),
         f"negative eigenvalues {neg} = 1 exactly where dP/dw < 0 ({unstable.astype(int)})")
st.check(np.all(np.abs(np.diff(neg)) <= 1), "the count changes by one at a time")
st.check(crit.shape == (2, 4) and np.all(crit[:, 0] == 1), f"two limit points found: {crit}")
if crit.shape == (2, 4):
    st.close(crit[:, 2], [Pmax, -Pmax], rtol=1e-4, what="limit loads [N] (closed form +-3.810872)")
    st.close(-crit[:, 3], [wlim, 2 * H - wlim], rtol=1e-3, what="displacement at the limit points [m]")
lam1, w1, neg1, crit1, _ = runs[1]
st.check(len(lam1) == len(lam), "1 and 2 ranks: same number of path points")
if len(lam1) == len(lam):
    st.close(lam1, lam, atol=1e-9 * Pmax, what="1 vs 2 ranks: load factors")
    st.close(w1, w, atol=1e-9, what="1 vs 2 ranks: apex displacement [m]")
    st.check(np.array_equal(neg1, neg), "1 vs 2 ranks: negative eigenvalue counts")

# (4) displacement control and stop_load_factor
h5, out = st.run("continuation_truss_displ", scene({"method": "displacement", "ds": -0.01, "node": 2, "direction": "y",
                                                     "max_steps": 20}))
lam, w, neg, crit, conv = path(h5)
st.check(len(lam) == 20 and conv == 1, f"displacement control: 20 points ({len(lam)})")
st.close(w, 0.01 * np.arange(1, len(w) + 1), atol=1e-12, what="displacement control: prescribed apex path [m]")
st.close(lam, P(w), atol=1e-9 * Pmax, what="displacement control: points vs P(w) [N]")
h5, out = st.run("continuation_truss_stop", scene({"method": "arclength", "ds": 0.002, "stop_load_factor": 2.0}))
lam, w, neg, crit, conv = path(h5)
st.check(lam[-1] >= 2.0 and np.all(lam[:-1] < 2.0), f"stop_load_factor 2: stops at the first point past it ({lam[-1]:.4f})")
st.done()
