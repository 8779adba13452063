"""Fuzz test of the scene reader and validation (issue 13): a fixed set of mutated runs/*.yaml and
tests/scenes/good scenes (scripts/fuzz_corpus.py, seed 13: deleted lines, swapped types, extreme
numbers, truncations, duplicated keys and rows, wrong indentation, node numbers out of range, a
second document) runs on 1 and 2 ranks under a timeout. Most mutants stop after reading and
checking (-showinputonly true); mutants of the small scenes also solve one load step. Every
outcome must be exit 0, 2 or 3: never a signal, an MPI abort code or a hang; exit 2/3 print a line
starting with "error:"; exit 0 writes a result file without NaN in /node/p (/node/p0 of an input-only run). Each case prints its
mutation, so a failure is reproduced with
    scripts/fuzz_corpus.py --seed 13 --count 32 --out DIR   (the case's file name in DIR)."""
import concurrent.futures
import os
import subprocess
import sys

import numpy as np

import sinewtest as st

sys.path.insert(0, os.path.join(st.SOURCE, "scripts"))
import fuzz_corpus  # noqa: E402

SEED, COUNT = 13, 32
SMALL = {"crosshinge", "cable_patch", "ancf_cantilever", "membrane_5node"}  # full runs stay short
TIMEOUT = 90
DIR = os.path.join(st.WORK, "fuzz_scenes")
os.makedirs(DIR, exist_ok=True)

mutants = fuzz_corpus.generate(SEED, COUNT)
# The runs/ANCF fine cable (16384 elements) and the lattice net are read and checked only.
jobs = []
for name, source, kind, what, text in mutants:
    path = os.path.join(DIR, name + ".yaml")
    with open(path, "w") as f:
        f.write(text)
    stem = os.path.splitext(os.path.basename(source))[0]
    full = stem in SMALL
    flags = ["-loadsteps", "1"] if full else ["-showinputonly", "true"]
    for np_ in (1, 2):
        jobs.append((name, os.path.relpath(source, st.SOURCE), kind, what, path, np_, flags))


def run(job):
    name, source, kind, what, path, np_, flags = job
    out = os.path.join(DIR, f"{name}_{np_}.h5")
    for stale in (out, out + ".part"):
        if os.path.exists(stale):
            os.remove(stale)
    cmd = st.launcher(np_) + [path, "-o", out, "-silent", "true"] + flags
    try:
        p = subprocess.run(cmd, env=st.ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=TIMEOUT)
        return job, p.returncode, p.stdout.decode("utf-8", "replace"), out
    except subprocess.TimeoutExpired:
        return job, None, "", out


counts = {}
with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
    for job, code, log, out in pool.map(run, jobs):
        name, source, kind, what, path, np_, flags = job
        errors = [ln for ln in log.splitlines() if ln.startswith("error:")]
        label = f"{name} on {np_} rank{'s' if np_ > 1 else ''} ({source}, {kind}: {what}; {' '.join(flags)})"
        print(f"exit {code}: {label}: {errors[0][:160] if errors else ''}")
        counts[code] = counts.get(code, 0) + 1
        if code is None:
            st.fail(f"{label}: no answer within {TIMEOUT} s (hang)")
            continue
        if not st.check(code in (0, 2, 3), f"{label}: exit code {code} (a signal, an MPI abort or another failure)"):
            print(log[-2000:])
            continue
        if code in (2, 3):
            st.check(len(errors) >= 1, f"{label}: exit {code} without a line starting with 'error:'")
        else:
            if st.check(os.path.exists(out), f"{label}: exit 0 without a result file"):
                with st.h5(out) as f:  # an input-only run (-showinputonly) holds the input geometry only
                    p = f["node/p"][:] if "node/p" in f else f["node/p0"][:]
                st.check(np.all(np.isfinite(p)), f"{label}: NaN or inf in /node/p (/node/p0) of a run that exited 0")
        for leftover in (out, out + ".part"):
            if os.path.exists(leftover):
                os.remove(leftover)
print("outcomes (exit code: runs):", dict(sorted(counts.items(), key=lambda kv: (kv[0] is None, kv[0] or 0))))
st.done()
