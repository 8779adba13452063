#!/usr/bin/python3
# ctest-labels: smoke
"""Checkpoint and restart of statics (issue 9 item 3; docs/results.md "Restart") on the
cross-flexure hinge (beams, large rotations): a run stopped after 4 load steps on 1 rank
(-stop_after_step: stopped as SIGTERM stops it), continued on 2 ranks and stopped after 7, then
continued on 1 rank to the end, equals the uninterrupted 2-rank run (norm-wise relative difference
<= 1e-12 of positions, rotations and load factors; reactions and stresses, which amplify the
round-off of the state, within twice their difference between the uninterrupted 1- and 2-rank
runs, measured and printed; the copied rows bit for bit; the same Newton iterations per step; on the
same rank count the continued rows equal the uninterrupted ones bit for bit). More load steps
continue the ramp past 1 (SPACAR Light's steps, issue 10 item 1: load factor (k - 1) / 9, step 1 under
the initial support load alone) and equal a run with the moment scaled by 14/9 in 15 steps. A changed
scene (a moved node, an added node and element, added gravity) or another opt.load_ramp is refused
with exit 2, naming what changed, before any file is written."""
import os
import shutil

import h5py
import numpy as np
import yaml

import sinewtest as st
from ffscenes import to_yaml
from restartutil import compare, restarted, statics_table, stopped

os.makedirs(st.WORK, exist_ok=True)
ch = os.path.join(st.SOURCE, "runs", "crosshinge.yaml")
opts = ["-calcbuck", "false", "-calccompl", "false", "-calcfreq", "false"]
ref2, out_ref2 = st.run("rs_ch_ref2", ch, np_=2, args=opts)
its_ref = statics_table(out_ref2)
st.check(sorted(its_ref) == list(range(1, 11)), f"statics: 10 steps in the uninterrupted table, got {sorted(its_ref)}")

part = stopped("rs_ch_part1", ch, 1, 4, opts)                       # stopped after step 4, 1 rank
mid, out_mid = restarted("rs_ch_mid2", ch, 2, part, opts + ["-stop_after_step", "7"], expect_exit=5)  # 1 -> 2
st.check("restart: 4 step rows copied" in out_mid and "after load step 7" in out_mid,
         "statics restart 1 -> 2: 4 rows copied, stopped after load step 7")
final, out_final = restarted("rs_ch_final1", ch, 1, mid, opts)      # 2 -> 1 to the end
its = statics_table(out_final)
st.check(sorted(its) == [8, 9, 10], f"statics restart 2 -> 1: steps 8..10 computed, got {sorted(its)}")
st.check(all(its[k] == its_ref[k] for k in its), f"statics restart: Newton iterations {its} vs uninterrupted {its_ref}")
st.check("restart: 7 step rows copied" in out_final, "statics: '7 step rows copied' expected")
ref1, _ = st.run("rs_ch_ref1", ch, np_=1, args=opts)
compare(ref2, final, "statics 1 -> 2 -> 1 vs uninterrupted 2 ranks", other_ranks=ref1)
with st.h5(part) as p, st.h5(final) as f:  # the first rows are copies
    st.check(np.array_equal(p["node/p"][:4], f["node/p"][:4]), "statics: rows 1..4 copied bit for bit")
# same rank count: the continued rows are those of the uninterrupted run, bit for bit
part2 = stopped("rs_ch_part2", ch, 2, 5, opts)
same, _ = restarted("rs_ch_same2", ch, 2, part2, opts)
st.check(compare(ref2, same, "statics 2 -> 2") == 0.0, "statics 2 -> 2: bit-for-bit equal rows expected")

# more load steps: the ramp (k - 1) / 9 continues past 1 (step 15 at 14/9) = a run with the ramped moment
# x 14/9 in 15 steps ((k - 1) / 14 of it; the initial support load is the same in both)
ext, out_ext = restarted("rs_ch_ext", ch, 2, ref2, opts + ["-loadsteps", "15"])
its = statics_table(out_ext)
st.check(sorted(its) == list(range(11, 16)), f"statics extension: steps 11..15 computed, got {sorted(its)}")
scene = yaml.safe_load(open(ch))
scene["nprops"][5]["moment"] = [0, 0, 0.5 * 14 / 9]
scene["opt"]["loadsteps"] = 15
scaled, _ = st.run("rs_ch_scaled", to_yaml(scene), np_=2, args=opts)
with st.h5(ext) as e, st.h5(ref2) as r, st.h5(scaled) as s:
    st.close(e["load_factor"][:], np.arange(0, 15) / 9, atol=1e-15, what="statics extension: load factors (k-1)/9")
    st.close(e["node/p"][:10], r["node/p"][:], rtol=1e-14, what="statics extension: rows 1..10 = the earlier run")
    st.close(e["node/p"][10:], s["node/p"][10:], rtol=1e-10, what="statics extension: rows 11..15 = moment x 14/9 in 15 steps")
    st.close(e["node/r_quat"][10:], s["node/r_quat"][10:], rtol=1e-10, what="statics extension: rotations 11..15")

# a changed scene is refused, naming what changed, and writes no file
scene = yaml.safe_load(open(ch))
scene["nodes"][4] = [0.0, 0.13, 0.0]
moved, out = restarted("rs_ch_moved", to_yaml(scene), 2, part, opts, expect_exit=2)
st.check("nodes(5,2) changed: 0.12 -> 0.13" in out, "moved node: the field, 1-based, and its values expected in the message")
st.check(not os.path.exists(moved), "refused restart: no result file expected")
scene = yaml.safe_load(open(ch))
scene["nodes"].append([0.0, 0.2, 0.0])
scene["elements"].append([5, 6])
_, out = restarted("rs_ch_added", to_yaml(scene), 2, part, opts, expect_exit=2)
st.check("nodes changed: 5 entries -> 6" in out and "elements changed: 4 entries -> 5" in out,
         "added node/element: node and element counts expected in the message")
# a changed property names its field and values (issue 24 item 13), also with the scene written anew
scene = yaml.safe_load(open(ch))
scene["eprops"][0]["emod"] = 2.0e11
_, out = restarted("rs_ch_emod", to_yaml(scene), 2, part, opts, expect_exit=2)
st.check("eprops(1).emod changed: 210e9 -> 200000000000" in out and "nbeams" not in out,
         "changed emod: 'eprops(1).emod changed: 210e9 -> 200000000000' (and nothing else) expected")
# a checkpoint without the scene text (a file from before the text was kept, or edited): the category
old_file = os.path.join(st.WORK, "rs_ch_noscene.h5")
shutil.copyfile(part, old_file)
with h5py.File(old_file, "r+") as f:
    del f.attrs["scene"]
_, out = restarted("rs_ch_emod_old", to_yaml(scene), 2, old_file, opts, expect_exit=2)
st.check("eprops changed" in out, "no scene text in the checkpoint file: the changed category ('eprops changed') expected")
_, out = restarted("rs_ch_gravity", ch, 2, part, opts + ["-gravity", "0,-9.81,0"], expect_exit=2)
st.check("loads" in out and "changed" in out, "added gravity during statics: refused, naming the loads")
_, out = restarted("rs_ch_ramp", ch, 2, part, opts + ["-load_ramp", "uniform"], expect_exit=2)
st.check("opt.load_ramp" in out and "spacar" in out, "another opt.load_ramp: refused, naming it")
_, out = restarted("rs_ch_nofile", ch, 1, part + ".missing", opts, expect_exit=2)
st.check("no result file" in out, "missing restart file: refused")
st.done()
