"""Helpers of the restart tests (test_restart_*.py; docs/results.md "Restart"): partial runs
stopped after k step rows (-stop_after_step, the testing aid that stops a run as SIGTERM does),
restarted runs, and the comparison of a restarted run's file with the uninterrupted run's file."""
import re

import numpy as np

import sinewtest as st

# Partition-dependent datasets (cells are concatenated in rank order) and the restart state itself.
SKIP = ("checkpoint", "mesh/lines", "mesh/triangles", "mesh/quads")
# eigenvectors and compliance come from iterative eigen solves with a random start vector (SLEPc):
# equal to the solver's tolerance, not to round-off (the restart tests do not ask for them)
SKIP_EIGEN = ("mesh/mode_", "node/CM")


def datasets(f):
    out = []
    f.visititems(lambda n, o: out.append(n) if hasattr(o, "shape") and not n.startswith(SKIP + SKIP_EIGEN) else None)
    return out


def rel_errors(x, y):
    """(norm-wise, entry-wise) relative difference of two float arrays: ||x - y|| / ||x|| and
    max |x - y| / max |x| (NaN rows compared as equal patterns)."""
    d = np.nan_to_num(x - y)
    nx = np.linalg.norm(np.nan_to_num(x))
    mx = np.nanmax(np.abs(x)) if x.size else 0.0
    return (np.linalg.norm(d) / nx if nx > 0 else np.linalg.norm(d)), (np.max(np.abs(d)) / mx if mx > 0 else np.max(np.abs(d)))


STATE = ("load_factor", "time", "node/p", "node/r_", "node/slope", "mesh/p", "mesh/u", "sensors/")


def compare(ref_path, got_path, what, tol=1e-12, other_ranks=None, prefix=""):
    """Every dataset (under `prefix`) of the uninterrupted run's file against the restarted run's
    file: same shape and NaN pattern, norm-wise relative difference <= tol. With other_ranks (the
    uninterrupted run on another rank count), a derived dataset (reactions, stresses: sums of large
    element forces, which amplify the round-off of the state) may differ by up to three times its
    difference between the two uninterrupted runs, the round-off floor of the rank count (one sample
    of a random round-off: a restarted beam run with alpha damping gave 2.5 times it, 1.9e-12, once
    the element inertia was summed in the force loop); state
    datasets (positions, rotations, load factor/time, sensors) always by at most tol. Prints the
    largest differences; returns the largest norm-wise one."""
    worst, worst_entry, name, worst_state = 0.0, 0.0, "", 0.0
    with st.h5(ref_path) as a, st.h5(got_path) as b:
        c = st.h5(other_ranks) if other_ranks else None
        for n in datasets(a):
            if not n.startswith(prefix):
                continue
            if not st.check(n in b, f"{what}: /{n} missing in the restarted file"):
                continue
            x, y = a[n][()], b[n][()]
            if not st.check(x.shape == y.shape, f"{what}: /{n} shape {y.shape}, expected {x.shape}"):
                continue
            if x.dtype.kind != "f" or x.size == 0:
                st.check(np.array_equal(x, y), f"{what}: /{n} differs")
                continue
            st.check(np.array_equal(np.isnan(x), np.isnan(y)), f"{what}: /{n} NaN pattern differs")
            if n == "formfinding/residual":  # Newton's final residual: round-off noise (1e-15 absolute)
                st.check(np.nanmax(np.abs(x - y)) <= 1e-12, f"{what}: /{n} differs by {np.nanmax(np.abs(x - y)):.3e}")
                continue
            rel, entry = rel_errors(x, y)
            limit = tol
            if c is not None and not n.startswith(STATE) and n in c:
                floor = rel_errors(x, c[n][()])[0]
                limit = max(tol, 3 * floor)
                if rel > tol:
                    print(f"  {what}: /{n} {rel:.2e} (round-off floor of the rank count: {floor:.2e} between the "
                          f"uninterrupted runs)")
            st.check(rel <= limit, f"{what}: /{n} relative difference {rel:.3e} > {limit:.3g}")
            if n.startswith(STATE):
                worst_state = max(worst_state, rel)
            if rel > worst:
                worst, name = rel, n
            worst_entry = max(worst_entry, entry)
        if c is not None:
            c.close()
        st.check(int(b.attrs["converged"]) == 1, f"{what}: restarted file not converged")
    print(f"  {what}: largest relative difference {worst:.2e} (/{name}), entry-wise {worst_entry:.2e}; "
          f"state (positions, rotations, load factor/time, sensors) {worst_state:.2e}")
    return worst


def stopped(name, scene, np_, k, args=()):
    """A run stopped after k step rows as on SIGTERM: exit 5, converged = 0, k rows + a checkpoint."""
    h5, out = st.run(name, scene, np_=np_, args=["-stop_after_step", str(k)] + list(args), expect_exit=5)
    st.check("stopped by -stop_after_step" in out, f"{name}: stop message missing")
    with st.h5(h5) as f:
        st.check(int(f.attrs["converged"]) == 0, f"{name}: converged = 0 expected")
        rows = f["time" if "time" in f else "load_factor"].shape[0]
        st.check(rows == k, f"{name}: {rows} rows, expected {k}")
        st.check(int(f["checkpoint/scalars"][1]) == k, f"{name}: checkpoint of row {k} expected")
    return h5


def restarted(name, scene, np_, source, args=(), expect_exit=0):
    return st.run(name, scene, np_=np_, args=["-restart", source] + list(args), expect_exit=expect_exit)


def statics_table(out):
    """{step: Newton iterations} of the statics summary table."""
    return {int(m.group(1)): int(m.group(3))
            for m in re.finditer(r"^\s+(\d+)\s+([0-9.e+-]+)\s+(\d+)\s+(\d+)\s+[0-9.e+-]+$", out, re.M)}
