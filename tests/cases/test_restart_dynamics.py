#!/usr/bin/python3
"""Checkpoint and restart of dynamics (issue 9 item 3; docs/results.md "Restart") on an ANCF
cantilever under gravity with bending/axial damping and user-function force laws (a sensor
samples the tip): a finished run to t = 0.05 on 1 rank continued on 2 ranks to a later tend = 0.1;
a run stopped after 14 rows on 2 ranks continued on 1; both equal the uninterrupted 2-rank run
(norm-wise relative difference of every dataset <= 1e-12; derived ones within twice the
rank-count round-off floor). Another dt is refused (exit 2) naming the earlier dt."""
import os

import sinewtest as st
from ancf_scenes import cantilever, text
from restartutil import compare, restarted, stopped

os.makedirs(st.WORK, exist_ok=True)
a5 = cantilever(16, EA=1e5, EI=2000.0, rhoA=78.0, gravity=[0, -9.81],
                dynamics={"tend": 0.1, "dt": 5e-3, "spectral_radius": 0.9},
                sensors=[{"element": 1, "x": 2.0, "variable": "Position", "name": "tip"}])
ep = a5["eprops"][0]
ep["physicsBendingDamping"] = 0.1 * 2000.0
ep["physicsAxialDamping"] = 0.05 * 1e5
ep["bendingMomentUserFunction"] = "physicsBendingStiffness*0.1*atan(10*curvature)+physicsBendingDamping*curvature_t"
ep["axialForceUserFunction"] = "max(0.02, 2-sqrt(t))*physicsAxialStiffness*axialStrain+physicsAxialDamping*axialStrain_t"
dyn = text(a5)
dref, _ = st.run("rs_dyn_ref2", dyn, np_=2)
dref1, _ = st.run("rs_dyn_ref1", dyn, np_=1)
dhalf, _ = st.run("rs_dyn_half1", dyn.replace('"tend": 0.1', '"tend": 0.05'), np_=1)  # a finished run to t = 0.05
drest, out = restarted("rs_dyn_later_tend", dyn, 2, dhalf)             # 1 -> 2, continued to tend = 0.1
st.check("11 step rows copied" in out and "20 of 20 steps" in out, "dynamics: 11 rows copied, steps to 20 of 20")
compare(dref, drest, "dynamics 1 -> 2, tend 0.05 -> 0.1", other_ranks=dref1)
dpart = stopped("rs_dyn_part2", dyn, 2, 14)
drest1, _ = restarted("rs_dyn_rest1", dyn, 1, dpart)                   # 2 -> 1
compare(dref, drest1, "dynamics 2 -> 1 (stopped at t = 0.065)", other_ranks=dref1)
_, out = restarted("rs_dyn_dt", dyn.replace('"dt": 0.005', '"dt": 0.0025'), 2, dpart, expect_exit=2)
st.check("dt = 0.005" in out, "dynamics with another dt: refused, naming dt")
st.done()
