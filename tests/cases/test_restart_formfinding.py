#!/usr/bin/python3
"""Checkpoint and restart of form finding (issue 9 item 3; docs/results.md "Restart") on a
four-point sail (cables and membranes, URS with stress adaption, 8 steps) followed by a pressure
load analysis (4 load steps): stopped during form finding on 1 rank and continued on 2; stopped
during the load analysis on 2 ranks and continued on 1; and a load analysis added to an earlier
run that had form finding without pressure (the restart starts the load analysis from the found
shape, /checkpoint_formfinding). Each equals the uninterrupted run (norm-wise relative difference
of every dataset <= 1e-12; derived ones within twice the rank-count round-off floor)."""
import os

import sinewtest as st
from ffscenes import sail_scene, to_yaml
from restartutil import compare, restarted, stopped

os.makedirs(st.WORK, exist_ok=True)
sail, _ = sail_scene(n=4, steps=8, adapt=True, pressure=50.0)
sail["opt"]["loadsteps"] = 4
sail_text = to_yaml(sail)
ffref, out_ff = st.run("rs_ff_ref2", sail_text, np_=2)
ffref1, _ = st.run("rs_ff_ref1", sail_text, np_=1)
with st.h5(ffref) as f:
    rows = f["load_factor"].shape[0]
    nff = f["formfinding/residual"].shape[0]
st.check(rows == nff + 4 and nff >= 4, f"form finding: {nff} form-finding rows + 4 load steps expected, got {rows} rows")
ffpart = stopped("rs_ff_part1", sail_text, 1, 3)                    # during form finding
ffrest, out = restarted("rs_ff_rest2", sail_text, 2, ffpart)        # 1 -> 2
st.check("continuing the form finding" in out, "form finding: restart continues the form finding")
compare(ffref, ffrest, "form finding 1 -> 2 (stopped in form-finding step 3)", other_ranks=ffref1)
ffpart2 = stopped("rs_ff_part2", sail_text, 2, nff + 2)             # during the load analysis
ffrest2, out = restarted("rs_ff_rest1", sail_text, 1, ffpart2)      # 2 -> 1
st.check("continuing the statics" in out, "form finding: restart continues the load analysis")
compare(ffref, ffrest2, "form finding + statics 2 -> 1 (stopped in load step 2 of 4)", other_ranks=ffref1)
# a load analysis added after an earlier form finding: the earlier scene had no pressure
sail0, _ = sail_scene(n=4, steps=8, adapt=True)
sail0["opt"]["loadsteps"] = 4
ff0, _ = st.run("rs_ff_noload", to_yaml(sail0), np_=2)
ffload, out = restarted("rs_ff_load", sail_text, 2, ff0)
st.check(f"{nff} step rows copied" in out, f"load analysis added: the {nff} form-finding rows are copied")
compare(ffref, ffload, "form finding without load, then restarted with pressure (2 -> 2)")
st.done()
