"""Output faults (issue 9, item 2): every bad output path is refused before the analysis starts with
a Sinew message and exit 1 (2 for -o without a value); a full disk ends with exit 1 and a message
naming "no space left on device", the file keeping the steps written before; two runs naming the
same output: the second is refused (naming the first one's pid), the first completes with its own data."""
import os
import re
import shutil
import subprocess


from batchrun import CROSSHINGE, Run, read_result, remove_outputs, work
from sinewtest import BIN, ENV, MPIEXEC, check, done


def sinew(args, np_=2, timeout=300):
    p = subprocess.run([MPIEXEC, "-n", str(np_), BIN] + args, env=ENV, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, timeout=timeout)
    return p.returncode, p.stdout


scene = work("batch_faults.yaml")
shutil.copy(CROSSHINGE, scene)
original = open(scene).read()
adir = work("batch_faults_dir")
os.makedirs(adir, exist_ok=True)
faults = [
    ("a directory", ["-o", adir], 1, "is a directory"),
    ("a directory with /", ["-o", adir + "/"], 1, "is a directory"),
    ("no value", ["-o"], 2, "-o: expected a file name, got no value"),
    ("the scene", ["-o", scene], 1, "is the scene file itself"),
    ("a missing directory", ["-o", work("no_such_dir/x.h5")], 1, "does not exist"),
]
if os.path.exists("/dev/full"):
    faults.append(("a device", ["-o", "/dev/full"], 1, "not a regular file"))
for what, args, code, msg in faults:
    c, log = sinew([scene] + args + ["-loadsteps", "3"])
    errors = [l for l in log.splitlines() if l.startswith("error")]
    print(f"  -o {what}: exit {c}: {errors}")
    check(c == code, f"-o {what}: exit {c}, expected {code}\n{log[-1500:]}")
    check(any(msg in l for l in errors), f"-o {what}: no message containing '{msg}'")
    check("load step" not in log, f"-o {what}: the analysis ran before the output was checked")
check(open(scene).read() == original, "the scene file was changed")
check(os.listdir(adir) == [], f"files created in the directory given as -o: {os.listdir(adir)}")
check(os.path.exists("/dev/full") is False or not os.path.isfile("/dev/full"), "/dev/full replaced by a file")

# Full disk: a small tmpfs where mount works (root), else a file-size limit on one rank. Sinew stops
# committing when less than a chunk (1 MiB) plus two steps are free (HDF5 hitting ENOSPC inside a
# collective metadata flush can leave the ranks in different collective calls: a hang), so the tmpfs
# holds the two copies of the first steps and that reserve.
mnt = work("batch_small_fs")
os.makedirs(mnt, exist_ok=True)
mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=1500k", "tmpfs", mnt],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode == 0
try:
    out = os.path.join(mnt, "full.h5")
    if mounted:
        c, log = sinew([scene, "-o", out, "-loadsteps", "200", "-calcbuck", "false", "-calccompl", "false"])
        cause = "no space left on device"
    else:  # Open MPI's shared memory needs more than the limit: one rank, no shared-memory transport
        env = dict(ENV, OMPI_MCA_btl="self")
        p = subprocess.run([MPIEXEC, "-n", "1", "sh", "-c", f'ulimit -f 200; exec "$0" "$@"', BIN, scene, "-o",
                            work("full.h5"), "-loadsteps", "200", "-calcbuck", "false", "-calccompl", "false"],
                           env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=600)
        c, log, out, cause = p.returncode, p.stdout, work("full.h5"), "file size limit"
    errors = [l for l in log.splitlines() if l.startswith("error")]
    print(f"  full disk ({'tmpfs' if mounted else 'ulimit -f'}): exit {c}: {errors}")
    check(c == 1, f"full disk: exit {c}, expected 1\n{log[-1500:]}")
    check(any(cause in l for l in errors), f"full disk: no message naming '{cause}'")
    check("HDF5-DIAG" not in log and not re.search(r"SIGABRT|on signal|core dumped", log), "full disk: HDF5 dump or abort")
    converged, steps = read_result(out)
    printed = sum(1 for l in log.splitlines() if l.lstrip().startswith("load step "))
    print(f"  full disk: file holds {steps} steps ({printed} printed), converged = {converged}")
    check(converged == 0 and steps >= printed and steps > 0, "full disk: file does not keep the steps written")
finally:
    if mounted:
        subprocess.run(["umount", mnt])

# Two runs on one output path at once.
out = work("batch_mix.h5")
remove_outputs(out)
first = Run(scene, out, ["-loadsteps", "80", "-calcbuck", "false"])  # long enough to be running
check(first.wait_for_steps(1, timeout=300), "first run: no progress")
c, log = sinew([scene, "-o", out, "-loadsteps", "5", "-calcbuck", "false", "-calccompl", "false"])
errors = [l for l in log.splitlines() if l.startswith("error")]
print(f"  second run on the same output: exit {c}: {errors}")
check(c == 1, f"second run: exit {c}, expected 1")
check(any("being written by another run (pid" in l for l in errors), "second run: no message naming the other run")
code = first.wait(timeout=600)
check(code == 0, f"first run: exit {code}\n{first.text()[-1500:]}")
converged, steps = read_result(out)
print(f"  first run: exit {code}, file holds {steps} steps, converged = {converged}")
check(converged == 1 and steps == 80, "the first run's file does not hold its own 80 steps")
check(not os.path.exists(out + ".lock"), "lock file left after a normal end")
done()
