#!/usr/bin/python3
"""SPACAR Light's load steps (issue 10, item 1): step 1 is the state under the full initial loads
and initial prescribed motions alone; the standard loads and motions ramp linearly over the
remaining steps and reach their value at the last step. Hand computation for 4 steps, a clamped
bar with force_initial = force = 1 N along its axis: reaction -1, -4/3, -5/3, -2 (Sinew's former
k/n ramp, kept as opt.load_ramp uniform: -1.25, -1.5, -1.75, -2); a second clamped beam whose tip has
displ_initial_z = 0.01 and displ_z = 0.03: tip z 0.01, 0.02, 0.03, 0.04 (uniform: 0.0175 ... 0.04)."""
import numpy as np

import sinewtest as st

scene = {
    "nodes": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]],
    "elements": [[1, 2], [3, 4]],
    "nprops": {1: {"fix": True}, 2: {"force_initial": [1, 0, 0], "force": [1, 0, 0]},
               3: {"fix": True}, 4: {"displ_initial_z": 0.01, "displ_z": 0.03}},
    "eprops": [{"elems": [1, 2], "flex": [1, 2, 3, 4, 5, 6], "emod": 210e9, "smod": 80e9, "cshape": "circ",
                "dim": [0.01]}],
    "opt": {"loadsteps": 4, "calccompl": False},
}

for ramp, args, lam_ref, reac_ref, z_ref in [
        ("spacar", [], [0, 1 / 3, 2 / 3, 1], [-1, -4 / 3, -5 / 3, -2], [0.01, 0.02, 0.03, 0.04]),
        ("uniform", ["-load_ramp", "uniform"], [0.25, 0.5, 0.75, 1], [-1.25, -1.5, -1.75, -2],
         [0.0175, 0.025, 0.0325, 0.04])]:
    out, log = st.run(f"spacar_loadsteps_{ramp}", scene, args=args)
    with st.h5(out) as f:
        lam, Fr, p = f["load_factor"][:], f["node/Freac"][:], f["node/p"][:]
    st.check(len(lam) == 4, f"{ramp}: 4 load steps written, got {len(lam)}")
    st.close(lam, lam_ref, atol=1e-14, what=f"{ramp}: /load_factor")
    st.close(Fr[:, 0, 0], reac_ref, rtol=1e-9, what=f"{ramp}: reaction Fx at the clamp")
    st.close(p[:, 3, 2], z_ref, rtol=1e-12, what=f"{ramp}: prescribed tip z")

# one load step: the full load (the last step reaches the standard loads' value)
out, _ = st.run("spacar_loadsteps_one", dict(scene, opt={"loadsteps": 1, "calccompl": False}))
with st.h5(out) as f:
    st.close(f["node/Freac"][:, 0, 0], [-2], rtol=1e-9, what="1 step: full load")
# initial loads that have no equilibrium (an end moment of 6 EI / L on one element, beyond the bound
# of its bending measures; test_core_newton_failure ramps the same moment): step 1 fails (exit 3)
# with a message that names SPACAR Light's step 1 and what to try, and no step is written
w, t, E = 0.02, 0.01, 2e9
limit = {"nodes": [[0, 0, 0], [1, 0, 0]], "elements": [[1, 2]],
         "nprops": {1: {"fix": True}, 2: {"moment_initial": [0, 0, 6 * E * w * t**3 / 12]}},
         "eprops": [{"elems": [1], "flex": [1, 2, 3, 4, 5, 6], "emod": E, "smod": 0.8e9, "cshape": "rect",
                     "dim": [w, t], "orien": [0, 0, 1]}],
         "opt": {"loadsteps": 4, "calccompl": False}}
out, log = st.run("spacar_loadsteps_initial_fails", limit, args=["-snes_max_it", "25"], expect_exit=3)
err = [ln for ln in log.splitlines() if ln.startswith("error:")]
print("  message:", err[0] if err else "(none)")
st.check(len(err) == 1 and "load step 1 of 4 did not converge" in err[0] and "SPACAR Light's step 1" in err[0]
         and "*_initial" in err[0], "step 1 under the initial loads alone fails with its own message")
with st.h5(out) as f:
    st.check("load_factor" not in f or len(f["load_factor"]) == 0, "no step written")
    st.check(int(f.attrs["converged"]) == 0, "converged = 0")
# a bad value is a scene error
out, log = st.run("spacar_loadsteps_bad", scene, args=["-load_ramp", "linear"], expect_exit=2)
st.check("load_ramp" in log, "opt.load_ramp: a bad value is named")
st.done()
