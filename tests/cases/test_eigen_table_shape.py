"""Issue 24 item 6: /freq and /buck are [ns, k] as docs/results.md says, also for nfreq: 1 and
nbuck: 1 (they were written as [ns], and scripts/plot_results.py --mode 1 then ended in an
IndexError). A cantilever under an axial compressive tip load with mass, 2 load steps on 2 ranks:
the shapes (also of the error estimates), the rows of a restarted run (copied [ns, 1] rows stay a
table), and plot_results.py --mode 1 / --mode buck:1 (matplotlib Agg) on the file."""
import os

import sinewtest as st

SCENE = """title: one frequency, one buckling multiplier
nodes: [[0, 0, 0], [1, 0, 0]]
elements: [[1, 2]]
nprops:
  1: {fix: true}
  2: {force: [-10, 0, 0]}
eprops:
  - {elems: [1], flex: [1, 2, 3, 4, 5, 6], emod: 210e9, smod: 80e9, dens: 7800, cshape: rect, dim: [0.02, 0.01],
     orien: [0, 1, 0], nbeams: 4}
opt: {loadsteps: 2, load_ramp: uniform, nfreq: 1, nbuck: 1, calcbuck: true, calccompl: false}
"""
h5, _ = st.run("eigen_table_shape", SCENE)
with st.h5(h5) as f:
    for name in ("freq", "freq_error_estimate", "freq_backward_error", "buck", "buck_error_estimate", "buck_backward_error"):
        st.check(name in f and f[name].shape == (2, 1), f"/{name} shape {f[name].shape if name in f else None}, expected (2, 1)")
    st.check(f["freq"][1, 0] > 0 and f["buck"][1, 0] > 0, f"frequency {f['freq'][1, 0]} Hz, multiplier {f['buck'][1, 0]}")

# a restart copies the rows of the first run: the copies keep the [ns, 1] layout
first, _ = st.run("eigen_table_first", SCENE, args=["-stop_after_step", "1"], expect_exit=5)
cont, _ = st.run("eigen_table_restart", SCENE, args=["-restart", first])
with st.h5(cont) as f:
    st.check(f["freq"].shape == (2, 1) and f["buck"].shape == (2, 1),
             f"restarted: /freq {f['freq'].shape}, /buck {f['buck'].shape}, expected (2, 1)")

for mode in ("1", "buck:1"):
    png = os.path.join(st.WORK, f"eigen_table_mode_{mode.replace(':', '_')}.png")
    p = st.script("plot_results.py", h5, "--mode", mode, "-o", png)
    print(f"  $ plot_results.py --mode {mode}\n    " + (p.stdout + p.stderr).strip().replace("\n", "\n    "))
    st.check(p.returncode == 0 and os.path.getsize(png) > 5000 if os.path.exists(png) else False,
             f"plot_results.py --mode {mode}: exit {p.returncode}, picture written")
st.done()
