"""showinputonly (SPACAR Light's input check; issue 10 item 12): nothing is solved; the summary says
only what was read (nodes, elements, sets, supports, loads) and how to draw it: no analyses line, no
reaction/stress/compliance tables; the result file holds the input geometry (/node/p0, /mesh/p0, the
cells) without step rows (no /load_factor, /node/p), with converged = 0 and showinputonly = 1; the
XDMF shows one grid "input"; scripts/plot_input.py draws it (PNG produced, non-empty). silent: no
warnings, header or summary tables, errors still shown."""
import os
import subprocess

import numpy as np

import sinewtest as st

SCENE = """
title: short leaf and rigid arm
nodes: [[0, 0, 0], [0.02, 0, 0], [0.05, 0.01, 0]]
elements: [[1, 2], [2, 3]]
nprops: {1: {fix: true}, 3: {force: [0, 0, 0.1]}}
eprops: [{elems: [1], flex: [1, 2, 3, 4, 5, 6], emod: 210e9, smod: 80e9, cshape: rect, dim: [0.02, 0.0005], orien: [0, 1, 0]}]
opt: {loadsteps: 3}
"""
out, log = st.run("showinput", SCENE.replace("loadsteps: 3}", "loadsteps: 3, showinputonly: true}"), np_=2)
print(log)
with st.h5(out) as f:
    st.check(all(k not in f for k in ("load_factor", "node/p", "node/Freac", "stressmax", "node/CMglob")),
             f"showinputonly: no step rows ({sorted(f.keys())})")
    st.close(f["node/p0"][()], [[0, 0, 0], [0.02, 0, 0], [0.05, 0.01, 0]], atol=0, what="showinputonly: /node/p0 = input")
    st.check(f["mesh/p0"].shape == (3, 3) and f["mesh/lines"].shape == (2, 2), "showinputonly: /mesh/p0 and cells")
    st.check(f.attrs["converged"] == 0 and f.attrs["showinputonly"] == 1, "showinputonly: converged = 0, showinputonly = 1")
xdmf = open(os.path.splitext(out)[0] + ".xdmf").read()
st.check('<Grid Name="input"' in xdmf and "step_0" not in xdmf, "showinputonly: the XDMF shows the grid 'input', no steps")
for said in ("input (opt.showinputonly: read and checked, nothing solved)", "nodes: 3 (3D)", "elements: 2",
             "eprops(1) beam, element 1: flex [1, 2, 3, 4, 5, 6], rect [0.02, 0.0005]",
             "rigid, massless (in no set): element 2", "node 1: fix", "node 3: force [0, 0, 0.1]",
             "picture: scripts/plot_input.py"):
    st.check(said in log, f"showinputonly summary says '{said}'")
for unsaid in ("analyses:", "reactions", "Von Mises", "compliance", "load factor", "converged", "wall time", "partition"):
    st.check(unsaid not in log, f"showinputonly summary has no '{unsaid}'")
png = os.path.join(st.WORK, "showinput.png")
if os.path.exists(png):
    os.remove(png)
p = subprocess.run(["/usr/bin/python3", os.path.join(st.SOURCE, "scripts", "plot_input.py"), out, "-o", png],
                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=300)
print(p.stdout)
st.check(p.returncode == 0, "plot_input.py exits 0")
st.check(os.path.exists(png) and os.path.getsize(png) > 10000, "plot_input.py writes a non-empty PNG")

# silent: the L/w = 1 warning, the header and the tables disappear; the solve still runs
out, loud = st.run("silent_off", SCENE, np_=2)
out, quiet = st.run("silent_on", SCENE.replace("loadsteps: 3}", "loadsteps: 3, silent: true}"), np_=2)
print(f"  output lines: {len(loud.splitlines())} without silent, {len(quiet.splitlines())} with silent")
st.check("warning" in loud and "reactions" in loud, "without silent: warning and tables printed")
st.check(len(quiet.strip()) == 0, f"silent: nothing printed on success ({len(quiet)} characters)")
with st.h5(out) as f:
    st.check(f.attrs["converged"] == 1 and f["node/p"].shape[0] == 3, "silent: the result file is complete")
# errors are still reported
bad = SCENE.replace("loadsteps: 3}", "loadsteps: 3, silent: true, rls: {2: [3]}}")
out, log = st.run("silent_error", bad, np_=2, expect_exit=2)
st.check("error: the model is a mechanism" in log, "silent: model errors are still printed")
st.done()
