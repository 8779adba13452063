"""Every example scene runs (issue 24 item 8): each runs/*.yaml on 2 ranks exits 0 with converged = 1
and writes the dataset of its analysis (read from the scene: /path for opt.continuation, /time for
opt.dynamics, /statespace for opt.transfer, /buck for calcbuck, /freq when frequencies are computed,
/formfinding for a formfinding block, /sensors/<name> for each sensor; /load_factor otherwise).
The examples with a check by hand (the number in the scene's comment and its doc) are compared with
their closed form or published value:
  cantilever          tip deflection P L^3 / (3 E I) and f1 = 1.8751^2 / (2 pi) sqrt(E I / (rho A L^4))
  column_buckling     mu_1 = pi^2 E I / (4 L^2) / P (Euler), twice (round section)
  lee_frame           first limit load P L^2 / EI = 18.5 (Schweizerhof & Wriggers 1986), path 0 -> 1 -> 0
  cantilever_step     first peak near 2 P L^3 / (3 E I) (sudden load), back to the start after T1
  parallel_guide_bode static gain L^3 / (24 E I), f1 = sqrt(k / (m + 13/35 m_leaves)) / (2 pi)
  parallel_guide_sensors  held state L^3 / (24 E I) F, mean foot moment F L / 4, a = -(2 pi f1)^2 u
  membrane_drum       f11 = sqrt(n0 / m) sqrt(2) / (2 L) of the square membrane, the centre swinging
                      about the static 0.07367 p L^2 / n0 (series solution of n0 lap w = -p)
The older scenes carry their reference values in their comments (Exudyn's tip of A1 and A5, the C1
and C2 form-finding values; test_ancf_* and test_ff_reference check those models); here they are run. Long scenes get reduced flags
(FLAGS) that keep what is checked.
Then every example runs in-process on 2 ranks (sinew._core) against its command-line file.
Not in the smoke tier: 160 s on 2 ranks on the shared 2-core machine at load average 8 (2026-11-26;
the six new examples 93 s of it; on 1 rank each new example runs in 1 to 4 s)."""
import glob
import math
import os
import re
import sys
import time

import numpy as np
import yaml

import sinewtest as st

RUNS = os.path.join(st.SOURCE, "runs")
FLAGS = {"crosshinge": ["-loadsteps", "4"]}  # 10 steps of a 54-unknown hinge: the same analyses in 4


def expected_datasets(scene):
    opt = scene.get("opt") or {}
    names = []
    if opt.get("continuation"):
        names += ["path/critical_points", "path/negative_eigenvalues"]
    if opt.get("dynamics"):
        names.append("time")
    else:
        names.append("load_factor")
    if opt.get("transfer") not in (None, False):
        names += ["statespace/A", "statespace/B", "statespace/C", "statespace/D"]
    if opt.get("calcbuck"):
        names.append("buck")
    if opt.get("calcfreq") is True:
        names.append("freq")
    if scene.get("formfinding"):
        names.append("formfinding")
    names += ["sensors/" + s["name"] for s in scene.get("sensors") or []]
    return names


os.makedirs(st.WORK, exist_ok=True)
results, timings = {}, {}
for path in sorted(glob.glob(os.path.join(RUNS, "*.yaml"))):
    name = os.path.splitext(os.path.basename(path))[0]
    with open(path) as f:
        scene = yaml.safe_load(f)
    start = time.time()
    h5, out = st.run("example_" + name, path, args=FLAGS.get(name, []))
    timings[name] = time.time() - start
    if not os.path.exists(h5):
        continue
    with st.h5(h5) as f:
        st.check(int(f.attrs["converged"]) == 1, f"{name}: converged = 1")
        missing = [d for d in expected_datasets(scene) if d not in f]
        st.check(not missing, f"{name}: datasets {expected_datasets(scene)} written (missing {missing})")
    results[name] = h5
    print(f"  {name}: {timings[name]:.1f} s on 2 ranks {' '.join(FLAGS.get(name, []))}")
    if "continuation" in scene.get("opt", {}):
        # the summary's step table gives each path point's residual (it printed 0 for every point)
        rows = [ln.split() for ln in out.splitlines() if re.match(r"^\s+\d+\s+[-\d.e+]+\s+\d+\s+\d+\s+[\d.e+-]+$", ln)]
        st.check(rows and all(float(r[4]) > 0 for r in rows), f"{name}: |residual| of every path point in the summary > 0")

# The same scenes run in-process (sinew._core through Scene.run, issue 25) on 2 ranks: every dataset
# of these command-line files in every rank's results (tests/python/inprocess_compare.py: 1e-12, the
# 2-rank exceptions named there); the 1-rank comparison is python_inprocess_*_1ranks.
sys.path.insert(0, os.path.join(st.SOURCE, "tests", "python"))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import inprocess_compare  # noqa: E402

work = os.path.join(st.WORK, "examples_inprocess")
os.makedirs(work, exist_ok=True)
for old in glob.glob(os.path.join(work, "*")):
    os.remove(old)
st.check(not inprocess_compare.compare_in_process(results, 2, work, st.MPIEXEC, flags=FLAGS,
                                                   env=dict(st.ENV, PYTHONDONTWRITEBYTECODE="1")),
         "every example in-process on 2 ranks equals its command-line result file")

E, G, RHO = 210e9, 80e9, 7800.0

if "cantilever" in results:
    with st.h5(results["cantilever"]) as f:
        tip = f["node/p"][-1, 1] - f["node/p"][0, 1]
        f1 = f["freq"][0, 0]
    L, w, t, P = 0.1, 0.01, 0.001, 1.0
    EI = E * w * t ** 3 / 12
    st.close(-tip[1], P * L ** 3 / (3 * EI), rtol=1e-3, what="cantilever: tip deflection vs P L^3 / (3 E I) (measured -3e-4)")
    st.close(f1, 1.875104 ** 2 / (2 * math.pi) * math.sqrt(EI / (RHO * w * t * L ** 4)), rtol=2e-4,
             what="cantilever: f1 of the unloaded step vs Euler-Bernoulli (measured -6e-5)")

if "column_buckling" in results:
    with st.h5(results["column_buckling"]) as f:
        mu = f["buck"][-1]
    EI = E * math.pi * 0.01 ** 4 / 64
    mu1 = math.pi ** 2 * EI / 4 / 100.0
    st.close(mu[:2], [mu1, mu1], rtol=2e-4, what="column_buckling: mu_1 (twice) vs Euler's P_cr / P (measured -3.9e-5)")
    st.close(mu[2:4], [9 * mu1, 9 * mu1], rtol=1e-3, what="column_buckling: mu_2 (twice) vs 9 P_cr / P (measured -3.4e-4)")

if "lee_frame" in results:
    with st.h5(results["lee_frame"]) as f:
        crit, neg = f["path/critical_points"][:], f["path/negative_eigenvalues"][:].astype(int)
    if st.check(crit.shape[0] == 2 and np.all(crit[:, 0] == 1), f"lee_frame: two limit points ({crit})"):
        st.close(crit[0, 2], 18.5, rtol=3e-3, what="lee_frame: first limit load P L^2 / EI vs 18.5 (measured 18.4738)")
        st.check(crit[1, 2] < -9, f"lee_frame: second limit load {crit[1, 2]:.4f} (Simo & Vu-Quoc: -9.47 / -9.23)")
        k1, k2 = int(crit[0, 1]), int(crit[1, 1])
        st.check(np.all(neg[:k1] == 0) and np.all(neg[k1:k2] == 1) and np.all(neg[k2:] == 0),
                 f"lee_frame: negative eigenvalues 0 -> 1 -> 0 ({neg})")

if "cantilever_step" in results:
    with st.h5(results["cantilever_step"]) as f:
        tt, u = f["time"][:], f["sensors/tip"][:, 1]
    L, w, t, P = 0.1, 0.01, 0.001, 1.0
    EI = E * w * t ** 3 / 12
    T1 = 1 / (1.875104 ** 2 / (2 * math.pi) * math.sqrt(EI / (RHO * w * t * L ** 4)))
    first = tt < T1
    i = np.argmin(u[first])
    st.close(-u[i], 2 * P * L ** 3 / (3 * EI), rtol=0.03,
             what="cantilever_step: first peak vs 2 P L^3 / (3 E I) (measured -2.3 %; modal sum -1.7 %)")
    st.close(tt[i], T1 / 2, atol=0.5e-3, what="cantilever_step: time of the first peak vs T1 / 2 [s]")
    back = (tt > 0.75 * T1) & (tt < 1.25 * T1)
    j = np.argmax(u[back])
    st.close(tt[back][j], T1, atol=0.5e-3, what="cantilever_step: back at the start after T1 [s]")
    st.check(abs(u[back][j]) < 0.02 * abs(u[i]), f"cantilever_step: back at the start ({u[back][j]:.3e} m)")

L, t, wd, m = 0.1, 0.0005, 0.02, 0.5
EI = E * wd * t ** 3 / 12
k = 24 * EI / L ** 3
m_leaves = 2 * RHO * wd * t * L
f_guide = math.sqrt(k / (m + 13 / 35 * m_leaves)) / (2 * math.pi)
if "parallel_guide_bode" in results:
    with st.h5(results["parallel_guide_bode"]) as f:
        A, B, C, D = (f["statespace/" + s][:] for s in "ABCD")
        hz = f["statespace/freq"][:]
    gain = (-C @ np.linalg.solve(A, B))[0, 0]
    st.close(gain, 1 / k, rtol=1e-3, what="parallel_guide_bode: static gain [m/N] vs L^3 / (24 E I) (measured +1.8e-4)")
    st.close(hz[0], f_guide, rtol=1e-3, what="parallel_guide_bode: f1 [Hz] vs sqrt(k / (m + 13/35 m_leaves)) / 2 pi (measured -9e-5)")

if "parallel_guide_sensors" in results:
    with st.h5(results["parallel_guide_sensors"]) as f:
        lf, tt = f["load_factor"][:], f["time"][:]
        u, a = f["sensors/payload"][:, 0], f["sensors/payload_acc"][:, 0]
        m1, m2 = f["sensors/leaf1_foot"][:, 1], f["sensors/leaf2_foot"][:, 1]
    held = int(np.flatnonzero(lf == 1)[0])
    F = 2.0
    st.close(u[held], F / k, rtol=1e-3, what="parallel_guide_sensors: held payload [m] vs F L^3 / (24 E I) (measured -1.1e-4)")
    st.close(-(m1[held] + m2[held]) / 2, F * L / 4, rtol=1e-3,
             what="parallel_guide_sensors: mean foot moment [N m] vs F L / 4 (measured -1.5e-4)")
    swing = np.isnan(lf) & (tt > 0.01)
    w2 = -np.sum(a[swing] * u[swing]) / np.sum(u[swing] ** 2)
    st.close(math.sqrt(w2) / (2 * math.pi), f_guide, rtol=3e-3,
             what="parallel_guide_sensors: f1 [Hz] from -a/u of the sensors (measured -8.4e-4)")

print("  timings [s]: " + ", ".join(f"{n} {s:.1f}" for n, s in timings.items()) + f"; total {sum(timings.values()):.1f}")
if "membrane_drum" in results:
    with st.h5(results["membrane_drum"]) as f:
        tt, w, f1 = f["time"][:], f["node/p"][:, 40, 2] - f["node/p0"][40, 2], f["freq"][-1, 0]
    n0, mass, L, p = 1000.0, 1.0, 1.0, 10.0
    f11 = math.sqrt(n0 / mass) * math.sqrt(2) / (2 * L)
    st.close(f1, f11, rtol=1e-2, what="membrane_drum: f1 [Hz] vs sqrt(n0/m) sqrt(2) / 2L (measured +6.5e-3, the 8 x 8 mesh)")
    st.close(np.mean(w[tt <= 1 / f11]), 0.0736713 * p * L ** 2 / n0, rtol=2e-3,
             what="membrane_drum: centre's mean over the first period vs the static 0.07367 p L^2 / n0 (measured -5.7e-4)")

st.done()
