"""showinputonly: one step with the input geometry, no solve; scripts/plot_input.py draws it
(PNG produced, non-empty). silent: no warnings, header or summary tables, errors still shown."""
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
with st.h5(out) as f:
    st.check(f["node/p"].shape == (1, 3, 3), f"showinputonly: one step ({f['node/p'].shape})")
    st.close(f["node/p"][0], f["node/p0"][()], atol=0, what="showinputonly: positions = input geometry")
    st.check("node/CMglob" not in f, "showinputonly: no compliance computed")
st.check("tangents" not in log or " 0 tangents" in log, "showinputonly: no tangent assembled")
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
