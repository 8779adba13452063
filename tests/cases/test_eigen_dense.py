"""The dense eigensolver path (-eigen_dense_max_unknowns, src/step/dense_eigen.*) gives SLEPc's results:
each scene runs on 2 ranks with the dense path (default bound) and with -eigen_dense_max_unknowns 0
(SLEPc), and every dataset of the two files is compared. Scenes: the crosshinge (frequencies with the
element-wise operator and rigid-body multipliers, buckling with the assembled operator), a loaded
cantilever (buckling with the element-wise operator, nfreq: all) and a free-free beam (rigid-body
modes at omega = 0). Mode shapes are compared where they are defined: the first 12, of isolated
nonzero eigenvalues. Eigenvalues agree to 1e-10 relative (measured: 1e-13 frequencies, 4e-12
buckling); mode shapes to 2e-6 after the sign (measured: crosshinge 4.1e-9 on the fifth mode's
rotations, where SLEPc itself differs by 9.4e-9 between 1 and 2 ranks, 2.7e-10 buckling modes;
free-free beam 7.6e-7 on its third elastic mode); the
error datasets hold accuracy figures below -eps_tol on both paths; every other dataset is equal.
The summary names the dense solver only when it ran, so an ignored option fails the test."""
import os

import numpy as np

import sinewtest as st
from modal_util import beam_x

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
with open(os.path.join(ROOT, "runs", "crosshinge.yaml")) as f:
    crosshinge = f.read().replace("loadsteps: 10", "loadsteps: 3")
cantilever = beam_x(0.2, 0.02, 1e-3, 8, {1: {"fix": True}, 2: {"force": [-10, 0, 0]}},
                    opt={"loadsteps": 2, "calcbuck": True, "nfreq": "all"})
freefree = beam_x(0.2, 0.02, 1e-3, 6, {}, opt={"nfreq": 9})
MARK = "eigensolver: dense LAPACK"


def isolated(values, j):
    """Mode j's shape is defined (up to sign): among the first 12, value nonzero and 1e-4 apart from its neighbours
    (rigid-body modes of a free-free beam span a 6-dimensional space: any basis of it is right)."""
    v = np.asarray(values)
    if j >= min(len(v), 12) or not np.isfinite(v[j]) or abs(v[j]) <= 1e-6 * np.nanmax(np.abs(v)):
        return False  # rigid-body modes: omega^2 at round-off
    others = np.delete(v, j)
    return bool(np.all(np.abs(others - v[j]) > 1e-4 * abs(v[j])))


def datasets(f):
    out = []
    f.visititems(lambda n, o: out.append(n) if hasattr(o, "shape") and not n.startswith(("checkpoint", "timing")) else None)
    return out


def rel(x, y):
    d = np.nan_to_num(x - y)
    nx = np.linalg.norm(np.nan_to_num(x))
    return np.linalg.norm(d) / nx if nx > 0 else np.linalg.norm(d)


for name, scene in (("crosshinge", crosshinge), ("cantilever", cantilever), ("freefree", freefree)):
    dense, log_d = st.run(f"dense_{name}", scene)
    slepc, log_s = st.run(f"slepc_{name}", scene, args=["-eigen_dense_max_unknowns", "0"])
    st.check(MARK in log_d, f"{name}: the dense run names the dense eigensolver in its summary")
    st.check(MARK not in log_s, f"{name}: -eigen_dense_max_unknowns 0 runs SLEPc")
    st.check("warning" not in log_d, f"{name}: no warning on the dense path")
    with st.h5(dense) as a, st.h5(slepc) as b:
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
            if n.endswith(("_error_estimate", "_backward_error")):  # accuracy figures, each path its own
                ok = np.all(np.nan_to_num(x) <= 1e-8) and np.all(np.nan_to_num(y) <= 1e-8)
                st.check(ok, f"{name}: /{n} below -eps_tol on both paths")
                continue
            if n.startswith("mesh/mode_"):
                kind, j = n.split("_")[1], int(n.split("_")[2]) - 1
                if not isolated(b[kind][-1], j):
                    continue
                r, tol = rel(np.abs(x), np.abs(y)), 2e-6
            elif n in ("freq", "buck") or n.startswith("statespace"):
                r, tol = rel(x, y), 1e-10
            else:
                r, tol = rel(x, y), 1e-12
            group = n.rstrip("0123456789_rot") if n.startswith("mesh/mode_") else n
            worst[group] = max(worst.get(group, 0.0), r)
            st.check(r <= tol, f"{name}: /{n} differs by {r:.2e} (> {tol:g})")
        print(f"  {name}: " + ", ".join(f"{g} {w:.1e}" for g, w in sorted(worst.items()) if w > 0 or g in ("freq", "buck")))
st.done()
