"""Issue 24 item 3: a restart continues the interrupted plan to its end. runs/crosshinge.yaml (opt
loadsteps 10) run with -loadsteps 12 and stopped after 4 steps; restarted without -loadsteps on 2
ranks it used to stop at the scene's step 10 (load factor 9/11 of 1) with converged = 1 and exit 0;
now it goes on to step 12 (load factor 1), equal to the uninterrupted run. -loadsteps 8 on the
restart is the end the command line asks for: 8 steps, a note that the ramp reaches 1 at step 12.
-output_steps on the restart lists steps of the plan the restart runs (load steps 1..12), not of
the scene's opt.loadsteps 10: -output_steps 6,11 was refused (exit 2, "expected load steps 1..10");
now it writes steps 6, 11 and 12 after the 4 copied rows. Step 13 is refused naming 1..12, and
step 11 with -loadsteps 8 naming 1..8."""
import os

import numpy as np

import sinewtest as st

CROSSHINGE = os.path.join(st.SOURCE, "runs", "crosshinge.yaml")
QUICK = ["-calcbuck", "false", "-calccompl", "false", "-calcfreq", "false"]

full, _ = st.run("plan_end_full", CROSSHINGE, np_=2, args=QUICK + ["-loadsteps", "12"])
first, _ = st.run("plan_end_first", CROSSHINGE, np_=1, args=QUICK + ["-loadsteps", "12", "-stop_after_step", "4"], expect_exit=5)
cont, contlog = st.run("plan_end_restart", CROSSHINGE, np_=2, args=QUICK + ["-restart", first])
st.check("statics (12 load steps)" in contlog, "the restart's header names the 12 load steps it runs (said 10, the scene's)")
with st.h5(cont) as f, st.h5(full) as g:
    lf = f["load_factor"][:]
    st.check(len(lf) == 12 and lf[-1] == 1.0 and f.attrs["converged"] == 1,
             f"restart without -loadsteps: {len(lf)} steps to load factor {lf[-1]} (converged {f.attrs['converged']}), expected 12 to 1")
    st.close(f["node/p"][-1], g["node/p"][-1], rtol=1e-12, what="last step's positions vs the uninterrupted run")
short, log = st.run("plan_end_asked", CROSSHINGE, np_=2, args=QUICK + ["-restart", first, "-loadsteps", "8"])
st.check("statics (8 load steps)" in log, "-loadsteps 8 on the restart: the header names 8 load steps")
with st.h5(short) as f:
    st.check(len(f["load_factor"]) == 8 and abs(f["load_factor"][-1] - 7 / 11) < 1e-15,
             f"-loadsteps 8 on the restart: {len(f['load_factor'])} steps to load factor {f['load_factor'][-1]}")
st.check("note: -loadsteps 8 ends this restart at load factor 0.636364" in log and "at step 12" in log,
         "the note says where the ramp ends")
listed, _ = st.run("plan_end_listed", CROSSHINGE, np_=2, args=QUICK + ["-restart", first, "-output_steps", "6,11"])
with st.h5(listed) as f:
    st.check(f.attrs["converged"] == 1, "-output_steps 6,11 on the restart: converged = 1")
    st.close(f["load_factor"][:] * 11, [0, 1, 2, 3, 5, 10, 11], atol=1e-12,
             what="-output_steps 6,11 on the restart: load factor x 11 of the rows (steps 1-4 copied, 6, 11, 12)")
for extra, step, bound in (([], "13", "1..12"), (["-loadsteps", "8"], "11", "1..8")):
    _, log = st.run("plan_end_listed_refused", CROSSHINGE, np_=2, args=QUICK + ["-restart", first, "-output_steps", step] + extra,
                    expect_exit=2)
    st.check(f"step {step} is not a step of this run: expected load steps {bound}" in log and f"-output_steps {step})" in log,
             f"-output_steps {step} {' '.join(extra)} on the restart: refused naming load steps {bound}")
st.done()
