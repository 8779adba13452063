"""scripts/run, the README's main command (issue 24 item 12): what a user sees under mpirun.
- A scene error prints Sinew's one line and exit 2, without Open MPI's ten lines of boilerplate
  after it ("Primary job terminated normally...", "mpirun detected that one or more processes...").
- SIGTERM to scripts/run (a batch system's walltime signal) stops the run cleanly at a step: exit 5,
  a readable result file (SIGTERM to mpirun itself would kill the ranks).
- A rank killed by a signal (Open MPI's own note about it is silenced with the boilerplate) is said
  by scripts/run with the signal's number and the exit status 128 + signal.
- -o given to scripts/run replaces its out/<scene>.h5.
- Without a rank count scripts/run chooses one from the model size and says so on one line: 1 rank
  for the 66 unknowns of crosshinge (issue 24 item 2); an explicit -n 2 (or -np 2) wins, with no
  such line."""
import os
import signal
import subprocess
import time

import h5py

import sinewtest as st

RUN = os.path.join(st.SOURCE, "scripts", "run")
env = dict(st.ENV, SINEW_BUILD_DIR=os.path.dirname(os.path.abspath(st.BIN)), SINEW_BUILD_TARGETS="sinew")
for k in ("OMPI_MCA_orte_execute_quiet", "SINEW_NP"):  # scripts/run's own settings, not the caller's
    env.pop(k, None)
BOILERPLATE = ("Primary job", "mpirun detected", "-------", "Per user-direction")

# 1. a scene error: one line, exit 2
bad = st.scene_file("scripts_run_bad", {"nodes": [[0, 0, 0], [1, 0, 0]], "elements": [[1, 2]],
                                        "nprops": {1: {"fix": True}, 3: {"force": [0, 1, 0]}},
                                        "eprops": [{"elems": [1], "cshape": "rect", "dim": [0.01, 0.01], "emod": 2e11,
                                                                    "smod": 8e10}]})
p = subprocess.run([RUN, bad, "-o", os.path.join(st.WORK, "scripts_run_bad.h5")], env=env, stdout=subprocess.PIPE,
                   stderr=subprocess.STDOUT, text=True, timeout=300)
lines = [ln for ln in p.stdout.splitlines() if ln.strip()]
print(f"scene error: exit {p.returncode}: {lines}")
st.check(p.returncode == 2, f"scene error through scripts/run: exit {p.returncode}, expected 2")
st.check(lines and "node 3" in lines[0], f"Sinew's message (naming node 3) comes first: {lines[:2]}")
st.check(not any(b in ln for ln in lines for b in BOILERPLATE), f"Open MPI's boilerplate after the error: {lines}")

# 2. SIGTERM to scripts/run during a long run: exit 5, the written steps readable
scene = os.path.join(st.SOURCE, "runs", "crosshinge.yaml")
out = os.path.join(st.WORK, "scripts_run_term.h5")
for stale in (out, out + ".part"):
    if os.path.exists(stale):
        os.remove(stale)
proc = subprocess.Popen([RUN, scene, "-o", out, "-loadsteps", "100000", "-calccompl", "false", "-calcbuck", "false", "-calcfreq", "false"], env=env,
                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
seen = []
for line in proc.stdout:  # the first progress lines: the run is under way
    seen.append(line.rstrip())
    if sum("step" in s and "load factor" in s for s in seen) >= 2:
        break
proc.send_signal(signal.SIGTERM)
rest, _ = proc.communicate(timeout=120)
seen += rest.splitlines()
print(f"SIGTERM: exit {proc.returncode}; last lines {seen[-3:]}")
st.check(proc.returncode == 5, f"SIGTERM to scripts/run: exit {proc.returncode}, expected 5 (interrupted)")
if os.path.exists(out):
    with h5py.File(out, "r") as f:
        rows = f["load_factor"].shape[0]
    st.check(rows >= 1, f"{rows} written steps after SIGTERM")
else:
    st.fail(f"no result file {out} after SIGTERM")

# 3. a rank killed by a signal: scripts/run says so
out = os.path.join(st.WORK, "scripts_run_kill.h5")
proc = subprocess.Popen([RUN, scene, "-o", out, "-loadsteps", "100000", "-calccompl", "false", "-calcbuck", "false", "-calcfreq", "false"], env=env,
                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
seen = []
for line in proc.stdout:
    seen.append(line.rstrip())
    if any("step" in s and "load factor" in s for s in seen):
        break
pids = subprocess.run(["pgrep", "-f", f"sinew .*{out}"], stdout=subprocess.PIPE, text=True).stdout.split()
st.check(len(pids) >= 1, f"sinew ranks found: {pids}")
if pids:
    os.kill(int(pids[-1]), signal.SIGKILL)
rest, _ = proc.communicate(timeout=120)
seen += rest.splitlines()
print(f"SIGKILL of a rank: exit {proc.returncode}; last lines {seen[-2:]}")
st.check(proc.returncode == 128 + signal.SIGKILL, f"a rank killed: exit {proc.returncode}, expected {128 + signal.SIGKILL}")
st.check(any("ended on signal 9" in s for s in seen), "scripts/run names the signal that ended a rank")
# 4. the rank count: chosen from the model size (1 rank for 66 unknowns), an explicit -n / -np wins
quick = ["-loadsteps", "1", "-calccompl", "false", "-calcbuck", "false", "-calcfreq", "false"]
for name, count, expect in (("auto", [], 1), ("n2", ["-n", "2"], 2), ("np2", ["-np", "2"], 2), ("n1", ["-n", "1"], 1)):
    o = os.path.join(st.WORK, f"scripts_run_ranks_{name}.h5")
    p = subprocess.run([RUN, scene, "-o", o] + count + quick, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, timeout=300)
    chose = [ln for ln in p.stdout.splitlines() if ln.startswith("scripts/run:")]
    ranks = [ln for ln in p.stdout.splitlines() if "unknowns" in ln and "scene " in ln]
    print(f"ranks {name}: exit {p.returncode}; {chose}; {ranks}")
    st.check(p.returncode == 0, f"ranks {name}: exit {p.returncode}")
    plural = "rank" if expect == 1 else "ranks"
    st.check(any(f", {expect} {plural}, 66 unknowns" in ln for ln in ranks), f"ranks {name}: the run used {expect} {plural}: {ranks}")
    if count:
        st.check(not chose, f"ranks {name}: an explicit count is not second-guessed: {chose}")
    else:
        st.check(len(chose) == 1 and chose[0].startswith("scripts/run: 1 rank (66 unknowns"),
                 f"ranks {name}: one line saying 1 rank for 66 unknowns and why: {chose}")
    if os.path.exists(o):
        os.remove(o)
for f in (out, out + ".part", os.path.join(st.WORK, "scripts_run_term.h5")):
    if os.path.exists(f):
        os.remove(f)
st.done()
