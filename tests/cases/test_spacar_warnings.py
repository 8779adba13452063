#!/usr/bin/python3
"""Warnings about rect sections (issue 10, item 9), 2 ranks.
1. cshape rect without orien (the seed requires it): a warning naming the set and its elements; the
   default is the one docs/scene.md states (width dim[0] along global z): a cantilever along x with
   dim [w, t] = [0.01, 0.001] and no orien deflects under a tip force F along y by F L^3 / (3 E w t^3 / 12)
   (thickness along y), and along z by F L^3 / (3 E t w^3 / 12).
2. The L/w < 3 constrained-warping warning only where torsion (mode 2) is flexible.
3. runs/crosshinge.yaml prints no warning."""
import os

import numpy as np

import sinewtest as st

E, G, L, w, t, F = 210e9, 80e9, 1.0, 0.01, 0.001, 1e-3


def cantilever(force, orien=None, elems=2):
    nodes = [[L * k / elems, 0, 0] for k in range(elems + 1)]
    ep = {"elems": list(range(1, elems + 1)), "flex": [1, 2, 3, 4, 5, 6], "emod": E, "smod": G, "cshape": "rect",
          "dim": [w, t]}
    if orien:
        ep["orien"] = orien
    return {"nodes": nodes, "elements": [[k + 1, k + 2] for k in range(elems)],
            "nprops": {1: {"fix": True}, elems + 1: {"force": force}}, "eprops": [ep],
            "opt": {"loadsteps": 1, "calccompl": False}}


out, log = st.run("warn_rect_y", cantilever([0, F, 0]))
st.check("warning: eprops(1) elements 1, 2: cshape rect without orien" in log and "global z" in log,
         "rect without orien: warning naming the set and the elements: " + log[:400])
with st.h5(out) as f:
    uy = f["node/p"][-1, 2, 1]
st.close(uy, F * L**3 / (3 * E * w * t**3 / 12), rtol=2e-3, what="no orien, force along y: weak-axis deflection")
out, _ = st.run("warn_rect_z", cantilever([0, 0, F]))
with st.h5(out) as f:
    uz = f["node/p"][-1, 2, 2]
st.close(uz, F * L**3 / (3 * E * t * w**3 / 12), rtol=2e-3, what="no orien, force along z: strong-axis deflection")
out, log = st.run("warn_rect_orien", cantilever([0, F, 0], orien=[0, 0, 1]))
st.check("warning" not in log, "orien given: no warning")

# L/w < 3 (L = 0.02, w = 0.01): the warping warning only with flexible torsion
short = {"nodes": [[0, 0, 0], [0.02, 0, 0]], "elements": [[1, 2]], "nprops": {1: {"fix": True}},
         "eprops": [{"elems": [1], "flex": [1, 2, 3, 4, 5, 6], "emod": E, "smod": G, "cshape": "rect",
                     "dim": [w, t], "orien": [0, 1, 0]}], "opt": {"loadsteps": 1, "calccompl": False}}
_, log = st.run("warn_lw_torsion", short)
st.check("warning: eprops(1) element 1: L/w = 2 < 3 without cw" in log, "flexible torsion, L/w = 2: warping warning")
no_torsion = dict(short, eprops=[dict(short["eprops"][0], flex=[1, 3, 4, 5, 6])])
_, log = st.run("warn_lw_no_torsion", no_torsion)
st.check("L/w" not in log, "torsion rigid (flex without 2): no warping warning")

# the default example does not warn about itself
_, log = st.run("warn_crosshinge", os.path.join(st.SOURCE, "runs", "crosshinge.yaml"), args=["-showinputonly", "true"])
st.check("warning" not in log, "runs/crosshinge.yaml: no warning: " + "\n".join(ln for ln in log.splitlines() if "warning" in ln))
st.done()
