#!/usr/bin/python3
"""Restart after a kill (issue 9 items 2 and 3; docs/results.md "Restart"): a 2-rank statics run of
the cross-flexure hinge (60 load steps) killed by SIGKILL mid-run leaves a file whose checkpoint
belongs to its last committed step; continued on 1 rank with -restart it gives every /node dataset
of the uninterrupted 2-rank run (norm-wise relative difference <= 1e-12; reactions within twice
their round-off floor between the uninterrupted 1- and 2-rank runs, printed). A run stopped by
SIGTERM (exit 5) leaves a restartable file as well: continued on 2 ranks, bit for bit the
uninterrupted run."""
import os
import signal

import h5py

import sinewtest as st
from batchrun import CROSSHINGE, Run, read_result, remove_outputs, work
from restartutil import compare, restarted

opts = ["-loadsteps", "60", "-calcbuck", "false", "-calccompl", "false", "-calcfreq", "false"]
ref2, _ = st.run("rk_ref2", CROSSHINGE, np_=2, args=opts)
ref1, _ = st.run("rk_ref1", CROSSHINGE, np_=1, args=opts)

for sig in (signal.SIGKILL, signal.SIGTERM):
    name = signal.Signals(sig).name
    out = work(f"rk_{name.lower()}.h5")
    remove_outputs(out)
    run = Run(CROSSHINGE, out, opts, np_=2)
    st.check(run.wait_for_steps(8, timeout=300), f"{name}: fewer than 8 progress lines")
    for pid in run.ranks():
        os.kill(pid, sig)
    if sig == signal.SIGKILL:
        run.proc.kill()
    code = run.wait(timeout=300)
    printed = run.steps_printed()
    converged, steps = read_result(out)
    with h5py.File(out, "r") as f:
        rows = int(f["checkpoint/scalars"][1]) if "checkpoint/scalars" in f else -1
        step = int(f["checkpoint/scalars"][2]) if "checkpoint/scalars" in f else -1
    print(f"  {name}: exit {code}, {printed} steps printed, file holds {steps} steps (converged = {converged}), "
          f"checkpoint of row {rows} (load step {step})")
    st.check(converged == 0 and 8 <= steps < 60, f"{name}: {steps} steps, converged = {converged}")
    st.check(rows == steps and step == steps, f"{name}: checkpoint of row {rows}, file holds {steps} rows")
    if sig == signal.SIGTERM:
        st.check(code == 5 and steps == printed, f"{name}: exit {code} (5 expected), {steps} rows, {printed} printed")
    np_ = 1 if sig == signal.SIGKILL else 2
    got, text = restarted(f"rk_{name.lower()}_restart{np_}", CROSSHINGE, np_, out, opts)
    st.check(f"restart: {steps} step rows copied" in text, f"{name}: '{steps} step rows copied' expected")
    if sig == signal.SIGKILL:
        compare(ref2, got, f"SIGKILL at load step {steps} on 2 ranks, continued on 1 rank: /node",
                other_ranks=ref1, prefix="node/")
        compare(ref2, got, f"SIGKILL at load step {steps} on 2 ranks, continued on 1 rank: all datasets", other_ranks=ref1)
    else:
        st.check(compare(ref2, got, f"SIGTERM at load step {steps} on 2 ranks, continued on 2 ranks") == 0.0,
                 "SIGTERM 2 -> 2: bit-for-bit equal to the uninterrupted run expected")
    remove_outputs(out)
st.done()
