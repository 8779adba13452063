"""Shared by the rank-consistency tests (test_consistency_*.py): runs under a timeout, edited runs/ scenes."""
import os
import re
import subprocess

import sinewtest as st

RUNS = os.path.join(st.SOURCE, "runs")
os.makedirs(st.WORK, exist_ok=True)


def run(name, path, np_, args=(), timeout=400):
    """Runs sinew under a timeout; returns (exit code, log, result path). A hang fails the test."""
    out = os.path.join(st.WORK, f"{name}_{np_}.h5")
    for stale in (out, out + ".part"):
        if os.path.exists(stale):
            os.remove(stale)
    cmd = st.launcher(np_) + [path, "-o", out] + list(args)
    try:
        p = subprocess.run(cmd, env=st.ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        st.fail(f"{name} on {np_} ranks: no exit within {timeout} s (hang)")
        return None, "", out
    return p.returncode, p.stdout, out


def edited(name, fname, old, new):
    with open(os.path.join(RUNS, fname)) as f:
        text = f.read()
    st.check(old in text, f"{name}: {old!r} in runs/{fname}")
    return st.scene_file(name, text.replace(old, new))


def no_signal(name, n, log):
    st.check(not re.search(r"Signal|Aborted|MPI_ABORT|terminate called", log), f"{name} on {n} ranks: no signal/abort")


