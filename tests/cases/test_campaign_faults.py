"""Issue 24 item 16: faults a 720-run campaign found, each now a documented error on rank 0 with the
same exit code on 1 and 2 ranks, before any analysis runs and without a result file, never a signal,
a hang or an unreadable .part:
- opt.continuation with displacement control of a supported node (was SIGABRT, exit 134): exit 2
  naming opt.continuation.node, the node (1-based) and the direction;
- -restart from a file another run is writing (was exit 5, 2 "cannot open" or 1): exit 2, "being
  written by another run";
- a checkpoint whose steps done is 1e15 (the step counter wrapped to -2147483647 and the run wrote
  rows for ever): exit 2 naming the scalar (scalar_names entry);
- opt.continuation.max_steps 1e9 (was std::bad_alloc): exit 2 naming max_steps;
- -output_steps 0, 11, 99 with 10 load steps (wrote only the last step): exit 2 naming the flag and
  the range 1..10;
- -o a -o b (used b): exit 2 naming -o;
- opt.dynamics on a model without mass, after form finding (failed after form finding ran): exit 2
  naming opt.dynamics, no form-finding step printed."""
import os
import time

import h5py

import batchrun
import sinewtest as st

CROSSHINGE = os.path.join(st.SOURCE, "runs", "crosshinge.yaml")
QUICK = ["-calcbuck", "false", "-calccompl", "false", "-calcfreq", "false"]


def refused(name, scene, args, words, np_, code=2):
    """Runs, expects exit `code` with one error line holding `words`, and no result file."""
    out, log = st.run(f"{name}_np{np_}", scene, np_=np_, args=args, expect_exit=code)
    errors = [l for l in log.splitlines() if l.startswith("error:")]
    st.check(len(errors) == 1 and all(w in errors[0] for w in words),
             f"{name} on {np_} ranks: one error line with {words}: {errors}")
    st.check(not os.path.exists(out) and not os.path.exists(out + ".part"), f"{name} on {np_} ranks: no result file")
    return log


CONTINUATION = """title: displacement control of a supported node
nodes: [[0, 0, 0], [1, 0, 0]]
elements: [[1, 2]]
nprops: {1: {fix: true}, 2: {force: [0, 0, -20]}}
eprops: [{elems: [1], flex: [1, 2, 3, 4, 5, 6], emod: 210e9, smod: 80e9, cshape: rect, dim: [0.02, 0.01], orien: [0, 1, 0], nbeams: 4}]
opt: {calccompl: false, continuation: {method: displacement, node: NODE, direction: z, ds: -0.001, max_steps: STEPS}}
"""
NO_MASS = open(os.path.join(st.SOURCE, "runs", "cable_patch.yaml")).read()
NO_MASS = NO_MASS.replace("  loadsteps: 1", "  dynamics: {tend: 0.01, dt: 0.001}").replace("emod: 0", "emod: 1e6")

# a checkpoint with steps done 1e15: a statics run stopped after 3 of 5 steps, its scalar edited
source, _ = st.run("campaign_checkpoint_source", CROSSHINGE, np_=1, args=QUICK + ["-loadsteps", "5", "-stop_after_step", "3"],
                   expect_exit=5)
damaged = os.path.join(st.WORK, "campaign_checkpoint_damaged.h5")
with h5py.File(source, "r") as f, h5py.File(damaged, "w") as g:
    for k in f:
        f.copy(k, g)
    for k, v in f.attrs.items():
        g.attrs[k] = v
    s = g["checkpoint/scalars"][()]
    s[2] = 1e15  # steps done
    g["checkpoint/scalars"][...] = s

for np_ in (1, 2):
    refused("campaign_control_supported", CONTINUATION.replace("NODE", "1").replace("STEPS", "5"), [],
            ["opt.continuation.node", "node 1", "z translation", "supported"], np_)
    refused("campaign_max_steps", CONTINUATION.replace("NODE", "2").replace("STEPS", "1e9"), [],
            ["opt.continuation.max_steps", "at most 100000"], np_)
    refused("campaign_damaged_checkpoint", CROSSHINGE, QUICK + ["-restart", damaged],
            ["-restart", "step", "scalar_names", "1e+15", "damaged"], np_)
    for steps in ("0", "11", "99"):
        refused(f"campaign_output_steps_{steps}", CROSSHINGE, QUICK + ["-output_steps", steps],
                ["opt.output_steps", f"step {steps} ", "1..10", f"-output_steps {steps}"], np_)
    refused("campaign_output_twice", CROSSHINGE, QUICK + ["-o", os.path.join(st.WORK, "campaign_other.h5")],
            ["-o is given 2 times"], np_)
    log = refused("campaign_dynamics_no_mass", NO_MASS, [], ["opt.dynamics", "no mass"], np_)
    st.check("form-finding step" not in log, f"no mass on {np_} ranks: refused before form finding")

# -restart from a file another run is writing: 1 rank writes 100000 statics steps while the restarts try
busy = os.path.join(st.WORK, "campaign_busy.h5")
batchrun.remove_outputs(busy)
writer = batchrun.Run(CROSSHINGE, busy, args=QUICK + ["-loadsteps", "100000"], np_=1)
try:
    st.check(writer.wait_for_steps(3, timeout=120), "the writer runs")
    for np_ in (1, 2, 1):  # the same answer on every try
        refused("campaign_restart_busy", CROSSHINGE, QUICK + ["-restart", busy], ["-restart", "being written by another run"], np_)
    st.check(writer.proc.poll() is None, "the writer was still running during the restarts")
finally:
    for pid in writer.ranks():
        os.kill(pid, 15)  # SIGTERM: it stops after its current step
    writer.wait(timeout=120)
st.done()
