"""Crash safety (issue 9, item 2): a 2-rank run killed by SIGKILL at random moments always leaves a
result file that h5py opens, with converged = 0 and at least every step printed as converged
before the kill (the progress line of a step is printed after the step is committed)."""
import os
import random
import signal
import time

import h5py
import numpy as np

from batchrun import CROSSHINGE, Run, read_result, remove_outputs, work
from sinewtest import check, done

KILLS = 12
random.seed(9)
out = work("batch_sigkill.h5")
withSteps = 0
for i in range(KILLS):
    remove_outputs(out)
    run = Run(CROSSHINGE, out, ["-loadsteps", "400", "-calcbuck", "false", "-calccompl", "false"])
    # wait for the analysis to start, then kill at a random moment within the next 0.3 s (several
    # steps, each writing and committing: the kill lands at a random point of the step cycle; a longer
    # window only adds steps before the same kind of moment)
    run.wait_for_steps(1, timeout=120)
    time.sleep(random.uniform(0.0, 0.3))
    printed = run.steps_printed()
    for pid in run.ranks():
        os.kill(pid, signal.SIGKILL)
    run.proc.kill()
    run.wait(timeout=60)
    if not os.path.exists(out):
        check(printed == 0, f"kill {i}: {printed} steps printed but no result file")
        continue
    try:
        converged, steps = read_result(out)
    except Exception as e:  # noqa: BLE001 - any failure to open is the bug this test looks for
        check(False, f"kill {i}: h5py cannot open the result file after SIGKILL: {e}")
        continue
    print(f"  kill {i}: {printed} steps printed before the kill, file holds {steps}, converged = {converged}")
    check(converged == 0, f"kill {i}: converged = {converged} in a killed run")
    check(steps >= printed, f"kill {i}: file holds {steps} steps, {printed} were printed as converged")

    with h5py.File(out, "r") as f:
        lf = f["load_factor"][:]
        check(np.all(np.isfinite(f["node/p"][:])), f"kill {i}: node/p has non-finite values")
        # SPACAR Light's steps: step k at (k - 1) / (400 - 1) (step 1 = initial loads alone)
        check(np.allclose(lf, np.arange(0, steps) / 399), f"kill {i}: load factors {lf[:4]}...")
    withSteps += printed > 0
check(withSteps >= KILLS // 2, f"only {withSteps} of {KILLS} kills came after a converged step")
done()
