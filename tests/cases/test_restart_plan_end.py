"""Issue 24 item 3: a restart continues the interrupted plan to its end. runs/crosshinge.yaml (opt
loadsteps 10) run with -loadsteps 12 and stopped after 4 steps; restarted without -loadsteps on 2
ranks it used to stop at the scene's step 10 (load factor 9/11 of 1) with converged = 1 and exit 0;
now it goes on to step 12 (load factor 1), equal to the uninterrupted run. -loadsteps 8 on the
restart is the end the command line asks for: 8 steps, a note that the ramp reaches 1 at step 12."""
import os

import numpy as np

import sinewtest as st

CROSSHINGE = os.path.join(st.SOURCE, "runs", "crosshinge.yaml")
QUICK = ["-calcbuck", "false", "-calccompl", "false", "-calcfreq", "false"]

full, _ = st.run("plan_end_full", CROSSHINGE, np_=2, args=QUICK + ["-loadsteps", "12"])
first, _ = st.run("plan_end_first", CROSSHINGE, np_=1, args=QUICK + ["-loadsteps", "12", "-stop_after_step", "4"], expect_exit=5)
cont, _ = st.run("plan_end_restart", CROSSHINGE, np_=2, args=QUICK + ["-restart", first])
with st.h5(cont) as f, st.h5(full) as g:
    lf = f["load_factor"][:]
    st.check(len(lf) == 12 and lf[-1] == 1.0 and f.attrs["converged"] == 1,
             f"restart without -loadsteps: {len(lf)} steps to load factor {lf[-1]} (converged {f.attrs['converged']}), expected 12 to 1")
    st.close(f["node/p"][-1], g["node/p"][-1], rtol=1e-12, what="last step's positions vs the uninterrupted run")
short, log = st.run("plan_end_asked", CROSSHINGE, np_=2, args=QUICK + ["-restart", first, "-loadsteps", "8"])
with st.h5(short) as f:
    st.check(len(f["load_factor"]) == 8 and abs(f["load_factor"][-1] - 7 / 11) < 1e-15,
             f"-loadsteps 8 on the restart: {len(f['load_factor'])} steps to load factor {f['load_factor'][-1]}")
st.check("note: -loadsteps 8 ends this restart at load factor 0.636364" in log and "at step 12" in log,
         "the note says where the ramp ends")
st.done()
