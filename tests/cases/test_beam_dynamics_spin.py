# ctest-labels: smoke
"""A free-floating rigid body in beam dynamics (2 ranks): two nodes with mass 1 kg and anisotropic
mominertia diag(0.01, 0.02, 0.03) kg m^2 joined by a stiff massless steel beam (0.2 m, 20 x 20 mm,
dens 0), no supports, a constant moment M0 = (0.05, 0.03, 0.02) N m at node 1 from t = 0, rho = 1,
dt = 0.02, 2 s (the body ends turned by 1.46 rad about a moving axis). Reference: the balance of
angular momentum, dH/dt = M0 with no forces, so H(t) = M0 t about the origin, and the centre of
mass stays at rest. H is evaluated from the written states by central differences (positions and
log(R_{n+1} R_{n-1}^T) / 2h), H = sum m x x v + R J0 R^T w, so the check carries the O(h^2)
differencing error as well as the scheme's: measured max |H - M0 t| / |M0 t| 5.4e-4 (in a 3 s
probe run: 2.4e-4 at dt = 0.01, 6.0e-5 at 0.005: second order). The gyroscopic term w x (J_s w)
integrated over the run is 0.70 of |M0 t| (printed), 350 times the tolerance, so a missing or
wrong gyroscopic moment fails the check."""
import numpy as np

import beamtools as bt
import sinewtest as st

M0 = np.array([0.05, 0.03, 0.02])
J0 = np.diag([0.01, 0.02, 0.03])
dt, tend = 0.02, 2.0
scene = {"title": "spin", "nodes": [[0, 0, 0], [0.2, 0, 0]], "elements": [[1, 2]],
         "nprops": {1: {"mass": 1.0, "mominertia": [0.01, 0, 0, 0.02, 0, 0.03], "moment": list(M0)},
                    2: {"mass": 1.0, "mominertia": [0.01, 0, 0, 0.02, 0, 0.03]}},
         "eprops": [bt.beam_set([1], 0.02, 0.02)],
         "opt": {"calcfreq": False, "calccompl": False, "dynamics": {"tend": tend, "dt": dt, "spectral_radius": 1.0}}}
h5, out = st.run("beamdyn_spin", bt.yaml_text(scene))
with st.h5(h5) as f:
    t, p, q = f["time"][:], f["node/p"][:], f["node/r_quat"][:]
st.check(len(t) == 101, "spin: 101 written steps")


def rot(qq):
    w, x, y, z = qq
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def log(Rm):
    a = np.arccos(np.clip((np.trace(Rm) - 1) / 2, -1, 1))
    v = np.array([Rm[2, 1] - Rm[1, 2], Rm[0, 2] - Rm[2, 0], Rm[1, 0] - Rm[0, 1]])
    return v / 2 if a < 1e-12 else a / (2 * np.sin(a)) * v


err, gyro, G = 0.0, 0.0, np.zeros(3)
for n in range(1, len(t) - 1):
    H = np.zeros(3)
    for i in range(2):
        v = (p[n + 1, i] - p[n - 1, i]) / (2 * dt)
        Rn = rot(q[n, i])
        w = log(rot(q[n + 1, i]) @ rot(q[n - 1, i]).T) / (2 * dt)
        Js = Rn @ J0 @ Rn.T
        H += np.cross(p[n, i], v) + Js @ w
        G += np.cross(w, Js @ w) * dt
    err = max(err, np.linalg.norm(H - M0 * t[n]) / np.linalg.norm(M0 * t[n]))
gyro = np.linalg.norm(G) / np.linalg.norm(M0 * t[-2])  # at the end of the run
turn = np.linalg.norm(log(rot(q[-1, 0])))
print(f"  turn {turn:.4f} rad; max |H - M0 t| / |M0 t| = {err:.2e}; gyroscopic impulse / |M0 t| at the end {gyro:.2e}")
st.check(turn > 0.3, "spin: the body turns")
st.check(err < 2e-3, "spin: angular momentum H = M0 t (to 2e-3 with the O(h^2) differencing)")
st.check(gyro > 10 * 2e-3, "spin: the gyroscopic term matters (the check is sensitive to it)")
xc = p.mean(axis=1)
st.close(np.abs(xc - xc[0]).max(), 0.0, atol=1e-12, what="spin: centre of mass at rest")
st.done()
