"""Restart with step analyses at some rows only (issue 24 point 1, opt.step_analyses): the leaf
cantilever of test_step_analyses (frequencies and compliance, 50 time steps of 2 ms) stopped after
20 rows on 1 rank and continued on 2 ranks, with the default (last row) and with every:7. The
restarted file has the uninterrupted run's /step_analysis_rows ([50]; [0, 7, 14, 21, 28, 35, 42,
49, 50]): the stopped run's analysed rows are copied as step-analysis rows of their steps (the stop
itself analyses nothing extra), the continued run appends its own after them. /freq and
/node/CMglob equal the uninterrupted run's to the eigen solver's tolerance (1e-9 relative; their
error estimates are the solver's noise: rows only), /time, /node/*, /mesh/* as in restartutil.compare."""
import numpy as np

import beamtools as bt
import sinewtest as st
from restartutil import compare, restarted, stopped

L, w, t, nel = 1.0, 0.02, 0.002, 4
nodes, elems = bt.chain([0, 0, 0], [L, 0, 0], nel)
tip = nel + 1
scene = bt.yaml_text({"title": "leaf", "nodes": nodes, "elements": elems,
                      "nprops": {1: {"fix": True}, tip: {"force": [0, 0.5, 0]}},
                      "eprops": [bt.beam_set(range(1, nel + 1), w, t, dens=7800)],
                      "opt": {"dynamics": {"tend": 0.1, "dt": 0.002}}})
for tag, args, expected in (("last", [], [50]), ("every7", ["-step_analyses", "every:7"], [0, 7, 14, 21, 28, 35, 42, 49, 50])):
    ref, _ = st.run(f"rs_stepan_ref_{tag}", scene, np_=2, args=args)
    part = stopped(f"rs_stepan_part_{tag}", scene, 1, 20, args=args)
    rest, _ = restarted(f"rs_stepan_rest_{tag}", scene, 2, part, args=args)
    with st.h5(ref) as a, st.h5(rest) as b, st.h5(part) as p:
        st.check(list(a["step_analysis_rows"][:]) == expected, f"{tag}: uninterrupted rows {a['step_analysis_rows'][:]}")
        st.check(list(b["step_analysis_rows"][:]) == expected, f"{tag}: restarted rows {b['step_analysis_rows'][:]}")
        before = [r for r in expected if r < 20]
        got = list(p["step_analysis_rows"][:]) if "step_analysis_rows" in p else []
        st.check(got == before and ("freq" in p) == bool(before), f"{tag}: the stopped run analysed rows {got} (expected {before})")
        for n in ("freq", "node/CMglob"):
            x, y = a[n][()], b[n][()]
            st.check(x.shape == y.shape, f"{tag}: /{n} shape {y.shape}, expected {x.shape}")
            if x.shape == y.shape:
                st.close(y, x, rtol=1e-9, atol=1e-9 * np.max(np.abs(x)), what=f"{tag}: /{n} restarted vs uninterrupted")
        for n in ("freq_error_estimate", "freq_backward_error"):  # the eigen solver's own noise: rows only
            st.check(a[n].shape == b[n].shape, f"{tag}: /{n} shape {b[n].shape}, expected {a[n].shape}")
    for prefix in ("time", "node/", "mesh/"):
        compare(ref, rest, f"leaf dynamics, step analyses {tag}, 1 -> 2 ranks (stopped after 20 rows)", tol=1e-10, prefix=prefix)
st.done()
