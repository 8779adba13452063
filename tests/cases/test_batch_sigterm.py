"""SIGTERM / SIGINT / SIGUSR1 (issue 9, item 2): the ranks finish the current step, write the file and
exit with code 5 (README); the file holds every step printed, converged = 0. SIGTERM goes to the
ranks (as a batch system's walltime signal does), SIGUSR1 to mpirun (which forwards it)."""
import os
import signal

from batchrun import CROSSHINGE, Run, read_result, remove_outputs, work
from sinewtest import check, done

for sig, target in ((signal.SIGTERM, "ranks"), (signal.SIGINT, "rank 0"), (signal.SIGUSR1, "mpirun")):
    name = signal.Signals(sig).name
    out = work(f"batch_{name.lower()}.h5")
    remove_outputs(out)
    run = Run(CROSSHINGE, out, ["-loadsteps", "400", "-calccompl", "false"])
    check(run.wait_for_steps(2, timeout=300), f"{name}: no progress lines")
    if target == "ranks":
        for pid in run.ranks():
            os.kill(pid, sig)
    elif target == "rank 0":
        os.kill(run.ranks()[0], sig)
    else:
        os.kill(run.proc.pid, sig)
    code = run.wait(timeout=300)
    printed = run.steps_printed()
    text = run.text()
    print(f"  {name} to {target}: exit {code}, {printed} steps printed")
    check(code == 5, f"{name}: exit code {code}, expected 5\n{text[-2000:]}")
    check(f"interrupted by {name}" in text, f"{name}: no 'interrupted by {name}' message")
    check(printed < 400, f"{name}: the run did not stop ({printed} steps)")
    converged, steps = read_result(out)
    print(f"  file: {steps} steps, converged = {converged}")
    check(converged == 0, f"{name}: converged = {converged}")
    check(steps == printed, f"{name}: file holds {steps} steps, {printed} printed")
    check(os.path.exists(os.path.splitext(out)[0] + ".xdmf"), f"{name}: no XDMF")
    check(not os.path.exists(out + ".part") and not os.path.exists(out + ".lock"), f"{name}: .part or .lock left")
done()
