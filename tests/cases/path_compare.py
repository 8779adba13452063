"""Two result files of one scene solved by two solver paths, compared dataset by dataset
(test_eigen_dense.py: dense eigensolver against SLEPc; test_dense_lu.py: dense LU against MUMPS).
Integer datasets must be equal; NaN at the same places; the error datasets (`*_error_estimate`,
`*_backward_error`) are accuracy figures at round-off, each path its own, checked below 1e-8 on both;
the mode shapes of isolated eigenvalues (any basis of a repeated one is right) to 2e-6 in their
absolute values; every other dataset to tolerance(name) in the relative 2-norm."""
import numpy as np

import sinewtest as st


def datasets(f):
    out = []
    f.visititems(lambda n, o: out.append(n) if hasattr(o, "shape") and not n.startswith(("checkpoint", "timing")) else None)
    return out


def rel(x, y):
    d = np.nan_to_num(x - y)
    nx = np.linalg.norm(np.nan_to_num(x))
    return np.linalg.norm(d) / nx if nx > 0 else np.linalg.norm(d)


def isolated(values, j, first=None):
    """Whether eigenvalue j is finite, not ~0 and apart from the others (1e-4 relative); with `first`,
    only among the first that many (the 6 rigid-body modes of a free-free beam span a space: any basis of
    it is right)."""
    v = np.asarray(values)
    if j >= min(len(v), first or len(v)) or not np.isfinite(v[j]) or abs(v[j]) <= 1e-6 * np.nanmax(np.abs(v)):
        return False
    return bool(np.all(np.abs(np.delete(v, j) - v[j]) > 1e-4 * abs(v[j])))


def compare_files(name, a, b, tolerance, first=None):
    """Checks every dataset of the open files a and b (see the module); returns {group: worst
    relative difference}, a mode shape's group without its number."""
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
            if not isolated(b[kind][-1], j, first):
                continue
            r, tol = rel(np.abs(x), np.abs(y)), 2e-6
        else:
            r, tol = rel(x, y), tolerance(n)
        group = n.rstrip("0123456789_rot") if n.startswith("mesh/mode_") else n
        worst[group] = max(worst.get(group, 0.0), r)
        st.check(r <= tol, f"{name}: /{n} differs by {r:.2e} (> {tol:g})")
    return worst
