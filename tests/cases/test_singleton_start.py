"""`sinew scene.yaml` without mpirun (an MPI singleton, as the README's one-rank runs and sinew.Scene.run
start it), several at once: a parameter sweep started with xargs -P, or a test running three at a time.

Open MPI gives every isolated singleton the same session directory <tmp>/ompi.<host>.<uid>/jf.0/1,
made at MPI_Init and removed at exit, so two singletons side by side raced on it and one aborted in
MPI_Init ("A call to mkdir was unable to create the desired directory: .../jf.0/1"; seen once in
test_flags under load 15). Sinew now gives each process its own (<tmp>/ompi.sinew.<pid>, removed at exit).
Checked: four singletons started together all finish with exit 0; while each runs, its own session
directory exists and no shared jf.0 directory is made; after the runs none is left. The test fails
without the change (the per-process directory never appears)."""
import glob
import os
import subprocess
import tempfile
import time

import sinewtest as st

tmp = tempfile.mkdtemp(prefix="singleton_", dir=st.WORK if os.path.isdir(st.WORK) else None)
env = dict(st.ENV, TMPDIR=tmp)
for k in ("OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "SLURM_PROCID"):
    env.pop(k, None)
scene = os.path.join(st.SOURCE, "runs", "crosshinge.yaml")
procs = [subprocess.Popen([st.BIN, scene, "-o", os.path.join(tmp, f"run{i}.h5"), "-silent", "true"],
                          env=env, cwd=tmp, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
         for i in range(4)]
seen, shared = set(), False
while any(p.poll() is None for p in procs):
    for p in procs:
        if os.path.isdir(os.path.join(tmp, f"ompi.sinew.{p.pid}")):
            seen.add(p.pid)
    shared = shared or bool(glob.glob(os.path.join(tmp, "ompi.*", "jf.0")))
    time.sleep(0.005)
outs = [p.communicate()[0] for p in procs]
codes = [p.returncode for p in procs]
print(f"  exit codes {codes}; own session directory seen for {len(seen)} of 4 runs; shared jf.0 seen: {shared}")
for code, out in zip(codes, outs):
    if code != 0:
        print(out)
st.check(codes == [0] * 4, f"four singletons side by side: exit codes {codes}, all 0 expected")
st.check(len(seen) == 4, f"each singleton in its own session directory <tmp>/ompi.sinew.<pid>: seen for {len(seen)} of 4")
st.check(not shared, "no shared session directory jf.0 made by the singletons")
left = glob.glob(os.path.join(tmp, "ompi.sinew.*"))
st.check(not left, f"session directories removed at exit (left: {left})")
st.done()
