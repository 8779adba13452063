"""Issue 24 point 1, simulate only what the scene asks for: opt.step_analyses (flag -step_analyses)
chooses the written rows at which the step analyses (frequencies, buckling, compliance, state
space) run. A leaf cantilever (4 beams, 1 m x 20 mm x 2 mm, steel, mass: frequencies and
compliance on by default) under a sudden tip force, 50 time steps of 2 ms (51 rows with t = 0):
  (1) default in dynamics: the last row only, /freq and /node/CMglob [1, ...], /step_analysis_rows
      = [50], the mode shapes only in the XDMF grid of the last step; the summary says what ran,
      where and why;
  (2) -step_analyses all: /freq [51, 6] with no /step_analysis_rows (every row, the datasets of
      earlier versions), its last row equal to (1)'s (the same state);
  (3) opt.step_analyses: every:20 -> rows 0, 20, 40 and the last (50);
  (4) -step_analyses none: no /freq, /node/CMglob, /step_analysis_rows;
  (5) load-stepped statics keep SPACAR Light's per-step out.freq / CMglob: [loadsteps, ...];
  (6) path following (von Mises truss with a mass, arc length, 6 points): the last path point only,
      known after the path ended;
  (7) an unknown value is a scene error (exit 2) naming opt.step_analyses and the accepted values;
  (8) issue 24 point 10: the developer counters (assemblies, commits) only with -verbose.
Sensors stay on every row (/sensors/tip [51, 3] with the default)."""
import re

import numpy as np

import beamtools as bt
import sinewtest as st

L, w, t, nel = 1.0, 0.02, 0.002, 4
nodes, elems = bt.chain([0, 0, 0], [L, 0, 0], nel)
tip = nel + 1


def leaf(opt):
    return {"title": "leaf", "nodes": nodes, "elements": elems,
            "nprops": {1: {"fix": True}, tip: {"force": [0, 0.5, 0]}},
            "eprops": [bt.beam_set(range(1, nel + 1), w, t, dens=7800)],
            "sensors": [{"node": tip, "variable": "Position", "name": "tip"}],
            "opt": opt}


dyn = {"dynamics": {"tend": 0.1, "dt": 0.002}}
ns = 51
h5d, out = st.run("stepan_default", leaf(dict(dyn)), np_=1)
with st.h5(h5d) as f:
    rows = f["step_analysis_rows"][:]
    fd, cm = f["freq"][:], f["node/CMglob"][:]
    st.check(f["time"].shape == (ns,), f"51 rows of /time ({f['time'].shape})")
    st.check(fd.shape == (1, 6) and cm.shape == (1, tip, 6, 6), f"(1) default: one row of /freq {fd.shape}, /node/CMglob {cm.shape}")
    st.check(list(rows) == [ns - 1], f"(1) /step_analysis_rows = [50] ({rows})")
    st.check(f["freq"].attrs.get("rows") == "step_analysis_rows", "(1) /freq names its rows")
    st.check(f["sensors/tip"].shape == (ns, 3), "sensors on every row")
xdmf = open(h5d[:-3] + ".xdmf").read()
grids = re.findall(r'<Grid Name="step_(\d+)".*?</Grid>', xdmf, re.S)
with_mode = [int(g) for g in re.findall(r'<Grid Name="step_(\d+)"(?:(?!<Grid Name="step_).)*?Name="mode_freq_1"', xdmf, re.S)]
st.check(len(grids) == ns and with_mode == [ns - 1], f"(1) XDMF: mode_freq_1 in the last grid only ({with_mode})")
st.check('Dimensions="1 5 3" NumberType="Float"' in xdmf, "(1) XDMF: the mode dataset has one row")
line = re.search(r"step analyses: .*", out)
print("  summary:", line.group(0) if line else None)
st.check(line is not None and line.group(0) == "step analyses: natural frequencies, compliance at the last of 51 rows "
         "(opt.step_analyses default, dynamics: last; -step_analyses all for every row)", "(1) summary line")
st.check("assemblies:" not in out and "commits" not in out, "(8) no developer counters without -verbose")

h5a, out = st.run("stepan_all", leaf(dict(dyn)), np_=1, args=["-step_analyses", "all", "-verbose"])
with st.h5(h5a) as f:
    st.check(f["freq"].shape == (ns, 6) and "step_analysis_rows" not in f, f"(2) all: /freq {f['freq'].shape}, no /step_analysis_rows")
    st.close(f["freq"][-1], fd[0], rtol=1e-12, what="(2) last row of all = the default's row")
    st.close(f["node/CMglob"][-1], cm[0], rtol=1e-10, atol=1e-18, what="(2) compliance of the last row")
st.check(re.search(r"assemblies: \d+ residuals", out) is not None and re.search(r"\d+ commits, \d+ forced", out) is not None,
         "(8) -verbose prints the developer counters")
st.check("at all 51 rows (opt.step_analyses: all)" in out, "(2) summary: all rows")

h5e, _ = st.run("stepan_every", leaf(dict(dyn, step_analyses="every:20")), np_=1)
with st.h5(h5e) as f:
    rows = list(f["step_analysis_rows"][:])
    st.check(rows == [0, 20, 40, 50] and f["freq"].shape == (4, 6), f"(3) every:20: rows {rows}, /freq {f['freq'].shape}")

h5n, _ = st.run("stepan_none", leaf(dict(dyn)), np_=1, args=["-step_analyses", "none"])
with st.h5(h5n) as f:
    st.check(not any(k in f for k in ("freq", "node/CMglob", "step_analysis_rows")), "(4) none: no step-analysis datasets")
    st.check(f["sensors/tip"].shape == (ns, 3), "(4) none: sensors still on every row")

h5s, _ = st.run("stepan_statics", leaf({"loadsteps": 3}), np_=1)
with st.h5(h5s) as f:
    st.check(f["freq"].shape == (3, 6) and f["node/CMglob"].shape[0] == 3 and "step_analysis_rows" not in f,
             f"(5) statics: a row per load step ({f['freq'].shape})")

# (6) von Mises truss (test_continuation.py) with a lumped apex mass: frequencies at the last point
d = (4 * 1e-3 / np.pi) ** 0.5
truss = {"title": "von Mises truss", "nodes": [[-1, 0, 0], [0, 0.1, 0], [1, 0, 0]], "elements": [[1, 2], [3, 2]],
         "nprops": {1: {"fix": True}, 3: {"fix": True},
                    2: {"force": [0, -1, 0], "fix_z": True, "fix_orien": True, "mass": 1.0}},
         "eprops": [{"elems": [1, 2], "flex": [1], "emod": 1e7, "smod": 4e6, "cshape": "circ", "dim": [d]}],
         "opt": {"rls": {1: [2, 3, 4, 5, 6], 2: [2, 3, 4, 5, 6]}, "calccompl": False, "nfreq": 1,
                 "continuation": {"method": "arclength", "ds": 0.02, "max_steps": 6}}}
h5c, out = st.run("stepan_path", truss, np_=1)
with st.h5(h5c) as f:
    n = f["load_factor"].shape[0]
    st.check(n == 6 and f["freq"].shape[0] == 1 and list(f["step_analysis_rows"][:]) == [n - 1],
             f"(6) path following: /freq at the last of {n} points ({f['freq'].shape}, rows {f['step_analysis_rows'][:]})")

_, out = st.run("stepan_bad", leaf(dict(dyn)), np_=1, args=["-step_analyses", "every:0"], expect_exit=2)
st.check("opt.step_analyses" in out and "all, last, every:k (k >= 1) or none" in out,
         f"(7) bad value named with the accepted values: {out.strip().splitlines()[-1] if out.strip() else ''}")
st.done()
