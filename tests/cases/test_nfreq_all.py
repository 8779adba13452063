"""nfreq: all (issue 24 item 15): every finite natural frequency, as SPACAR Light's out.freq (nndof per
step). On the cross-flexure hinge (ndof 42, mass on every coordinate): /freq has one column per finite
mode, no warning, and its lowest six equal those of nfreq: 6; on a model with more than 2000 unknowns
`nfreq: all` is a scene error naming opt.nfreq (exit 2). 2 ranks."""
import os

import numpy as np

import sinewtest as st

HINGE = os.path.join(st.SOURCE, "runs", "crosshinge.yaml")
base = ["-loadsteps", "2", "-calcbuck", "false", "-calccompl", "false"]
h5_all, out_all = st.run("nfreq_all", HINGE, args=base + ["-nfreq", "all"])
h5_six, _ = st.run("nfreq_six", HINGE, args=base + ["-nfreq", "6"])
with st.h5(h5_all) as f, st.h5(h5_six) as g:
    fa, f6, ndof = f["freq"][()], g["freq"][()], int(f.attrs["ndof"])
print(f"  nfreq all: /freq {fa.shape}, ndof {ndof}; lowest {fa[-1, :3]}")
st.check(fa.shape[1] > 6 and fa.shape[1] <= ndof, f"nfreq all: {fa.shape[1]} frequencies (more than 6, at most ndof {ndof})")
st.check(np.all(np.diff(fa, axis=1) >= 0) and np.all(np.isfinite(fa)), "all frequencies finite and ascending")
st.close(fa[:, :6], f6, rtol=1e-8, what="the lowest six of nfreq all against nfreq 6")
st.check("warning" not in out_all, "nfreq all: no warning about the number of finite modes")
# a model too big for all frequencies: a scene error before any analysis
n = 400  # a beam of 400 elements: 2406 unknowns
big = {"nodes": [[0, 0, 0], [1, 0, 0]], "elements": [[1, 2]], "nprops": {1: {"fix": True}},
       "eprops": [{"elems": [1], "cshape": "rect", "dim": [0.01, 0.001], "emod": 2e11, "smod": 8e10, "dens": 7800,
                   "orien": [0, 0, 1], "nbeams": n}],
       "opt": {"loadsteps": 1, "nfreq": "all", "calccompl": False}}
_, out = st.run("nfreq_all_big", big, expect_exit=2)
st.check("opt.nfreq" in out and "2000" in out, f"nfreq all on 2406 unknowns: exit 2 naming opt.nfreq: {out.strip()[-300:]}")
st.done()
