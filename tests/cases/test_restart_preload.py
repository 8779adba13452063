"""Checkpoint and restart of a time integration that starts from the static load steps
(opt.dynamics start: static; docs/dynamics.md "Starting from a loaded state"): the preloaded leaf
of test_dynamics_preload.py (axial compression 0.3 P_cr in 4 load steps, then a transverse step
load on top from t0 = 10.5 dt, dt = T1/100 with T1 = 1/1.4184 Hz, 60 steps, every 2nd written).
- Stopped during the load steps (after 2 rows) on 2 ranks, continued on 1: the statics resumes and
  the time loop follows from its end; equal to the uninterrupted 2-rank run (every dataset,
  norm-wise relative difference <= 1e-12, derived ones within twice the rank-count floor).
- Stopped during the time loop (after 4 load-step + 8 time rows) on 1 rank, continued on 2: the
  dynamics resumes (no load step is redone); equal to the uninterrupted run likewise.
- A checkpoint of this run continued by the same scene with start: rest is refused (exit 2, naming
  opt.dynamics.start): the earlier run's rows are load-step rows the other run would not have."""
import os

import numpy as np

import beamtools as bt
import sinewtest as st
from restartutil import compare, restarted, stopped

os.makedirs(st.WORK, exist_ok=True)
L, w, t, nel = 1.0, 0.02, 0.002, 16
sec = bt.rect_section(w, t)
P = 0.3 * np.pi ** 2 * sec["EIy"] / (4 * L ** 2)
dF = 1e-5 * 3 * sec["EIy"] / L ** 3
nodes, elems = bt.chain([0, 0, 0], [L, 0, 0], nel)
dt = 1 / 1.4184485 / 100
t0 = 10.5 * dt


def scene(start):
    dyn = {"tend": 60 * dt, "dt": dt, "spectral_radius": 1.0, "output_every": 2, "start": start}
    return bt.yaml_text({"title": "preloaded leaf", "nodes": nodes, "elements": elems,
                         "nprops": {1: {"fix": True}, nel + 1: {"force": [-P, f"{dF!r}*step(t - {t0!r})", 0]}},
                         "eprops": [bt.beam_set(range(1, nel + 1), w, t, dens=7800)],
                         "opt": {"loadsteps": 4, "calccompl": False, "calcfreq": False, "dynamics": dyn}})


text = scene("static")
ref2, _ = st.run("rs_preload_ref2", text, np_=2)
ref1, _ = st.run("rs_preload_ref1", text, np_=1)
with st.h5(ref2) as f:
    st.check(f["time"].shape[0] == 4 + 31, f"reference: 4 load-step rows and 31 time rows ({f['time'].shape[0]} rows)")
part = stopped("rs_preload_part_statics", text, 2, 2)
rest, out = restarted("rs_preload_rest_statics", text, 1, part)
st.check("continuing the statics" in out and "60 of 60 steps" in out, "stopped in the load steps: statics continued, then 60 time steps")
compare(ref2, rest, "preload stopped at load step 2 (2 -> 1 ranks)", other_ranks=ref1)
part = stopped("rs_preload_part_dyn", text, 1, 12)
rest, out = restarted("rs_preload_rest_dyn", text, 2, part)
st.check("continuing the dynamics" in out and "load step" not in out.split("continuing the dynamics")[1].split("dynamics:")[0],
         "stopped in the time loop: the dynamics continues without load steps")
compare(ref2, rest, "preload stopped at time row 8 (1 -> 2 ranks)", other_ranks=ref1)
_, out = restarted("rs_preload_mismatch", scene("rest"), 1, part, expect_exit=2)
st.check("opt.dynamics.start" in out, "a start: static checkpoint continued with start: rest: refused naming opt.dynamics.start")
st.done()
