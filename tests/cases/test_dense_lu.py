"""The dense LU of small one-process tangents (-dense_max_unknowns, PC type denselu, src/solvers/dense_lu.*)
gives MUMPS's results, and it is the path that runs: each scene runs on 1 rank with the default bound
(dense LU) and with -dense_max_unknowns 0 (MUMPS), both with -log_view. The dense run must log
SinewDenseLU factorizations (statics Newton, compliance, constraint check) and no MUMPS factorization
(MatLUFactorNum), the MUMPS run the reverse; its summary names the dense LU of the compliance, so an
ignored option fails the test. Every dataset of the two files is compared (relative 2-norm):
1e-12 for the state (measured 2e-16 on the crosshinge) and the load factors; 5e-12 for reactions and
stresses, sums of internal forces that cancel (measured 1.3e-12; MUMPS's own 1- and 2-rank results
differ by 8.4e-13 there); 1e-10 for the eigenvalues (measured 4e-12 buckling, 5e-13 frequencies);
5e-10 for the compliance matrices (measured 7.1e-11, 2.6e-10 before the dense solve's refinement
step; MUMPS's 1- and 2-rank results differ by 5.2e-11: the tangent's condition); 2e-6 for mode shapes
of isolated eigenvalues as test_eigen_dense (measured 1.1e-9 frequency modes); the error datasets
are accuracy figures at round-off, each path its own, below 1e-8."""
# ctest-processors: 1
import os
import re

import numpy as np

import sinewtest as st
from modal_util import beam_x

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
with open(os.path.join(ROOT, "runs", "crosshinge.yaml")) as f:
    crosshinge = f.read().replace("loadsteps: 10", "loadsteps: 3")
cantilever = beam_x(0.2, 0.02, 1e-3, 8, {1: {"fix": True}, 2: {"force": [-10, 0, 0]}},
                    opt={"loadsteps": 2, "calcbuck": True, "calccompl": True, "nfreq": 4})


def event_count(log, event):
    m = re.search(r"^" + event + r"\s+(\d+)", log, re.M)
    return int(m.group(1)) if m else 0


def datasets(f):
    out = []
    f.visititems(lambda n, o: out.append(n) if hasattr(o, "shape") and not n.startswith(("checkpoint", "timing")) else None)
    return out


def rel(x, y):
    d = np.nan_to_num(x - y)
    nx = np.linalg.norm(np.nan_to_num(x))
    return np.linalg.norm(d) / nx if nx > 0 else np.linalg.norm(d)


def isolated(values, j):
    v = np.asarray(values)
    if j >= len(v) or not np.isfinite(v[j]) or abs(v[j]) <= 1e-6 * np.nanmax(np.abs(v)):
        return False
    return bool(np.all(np.abs(np.delete(v, j) - v[j]) > 1e-4 * abs(v[j])))


for name, scene in (("crosshinge", crosshinge), ("cantilever", cantilever)):
    dense, log_d = st.run(f"denselu_{name}", scene, np_=1, args=["-log_view"])
    mumps, log_m = st.run(f"mumps_{name}", scene, np_=1, args=["-log_view", "-dense_max_unknowns", "0"])
    nd, nm = event_count(log_d, "SinewDenseLU"), event_count(log_m, "SinewDenseLU")
    st.check(nd > 0 and event_count(log_d, "MatLUFactorNum") == 0,
             f"{name}: the dense run factors by the dense LU only ({nd} SinewDenseLU, "
             f"{event_count(log_d, 'MatLUFactorNum')} MatLUFactorNum)")
    st.check(nm == 0 and event_count(log_m, "MatLUFactorNum") > 0, f"{name}: -dense_max_unknowns 0 factors with MUMPS")
    st.check("dense LU, up to -dense_max_unknowns" in log_d and "dense LU" not in log_m,
             f"{name}: the compliance summary names the solver that ran")
    with st.h5(dense) as a, st.h5(mumps) as b:
        names = datasets(a)
        st.check(sorted(names) == sorted(datasets(b)), f"{name}: the same datasets")
        worst = {}
        for n in names:
            x, y = a[n][()], b[n][()]
            if x.dtype.kind != "f":
                st.check(np.array_equal(x, y), f"{name}: /{n} equal")
                continue
            st.check(x.shape == y.shape, f"{name}: /{n} shape {x.shape} vs {y.shape}")
            st.check(np.array_equal(np.isnan(x), np.isnan(y)), f"{name}: /{n} NaN at the same places")
            if n.endswith(("_error_estimate", "_backward_error")):
                ok = np.all(np.nan_to_num(x) <= 1e-8) and np.all(np.nan_to_num(y) <= 1e-8)
                st.check(ok, f"{name}: /{n} below 1e-8 on both paths")
                continue
            if n.startswith("mesh/mode_"):
                kind, j = n.split("_")[1], int(n.split("_")[2]) - 1
                if not isolated(b[kind][-1], j):
                    continue
                r, tol = rel(np.abs(x), np.abs(y)), 2e-6
            elif n in ("freq", "buck"):
                r, tol = rel(x, y), 1e-10
            elif n in ("node/CMglob", "node/CMloc"):
                r, tol = rel(x, y), 5e-10
            elif n in ("node/Freac", "node/Mreac", "stressmax", "element/stressmax", "cell/lines/stress"):
                r, tol = rel(x, y), 5e-12
            else:
                r, tol = rel(x, y), 1e-12
            group = n.rstrip("0123456789_rot") if n.startswith("mesh/mode_") else n
            worst[group] = max(worst.get(group, 0.0), r)
            st.check(r <= tol, f"{name}: /{n} differs by {r:.2e} (> {tol:g})")
        print(f"  {name}: {nd} dense LU factorizations; " + ", ".join(f"{g} {w:.1e}" for g, w in sorted(worst.items())))
st.done()
