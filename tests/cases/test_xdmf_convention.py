#!/usr/bin/python3
"""The ParaView convention of the XDMF file (issue 9, item 5; docs/results.md, "Opening the XDMF
in ParaView"), checked without ParaView: the XDMF of four runs on 2 ranks (runs/crosshinge.yaml,
runs/sail.yaml with form finding, a leaf spring with a torsion mode, ANCF dynamics) is resolved with
h5py (xdmf_read.py: every DataItem must name an existing dataset of its declared dimensions) and
must show: the reference geometry /mesh/p0 at every step, a point array "displacement" that Warp By
Vector with scale factor 1 turns into /mesh/p and /node/p (to 1e-12), one time step per result row
with distinct increasing times (form-finding rows -nff .. -1), the field data (load_factor or time,
hdf5_row), the cell arrays (stress, axial_force, membrane_n11/n22/n12) and the mode rotations (a
torsion mode with translations 0 has rotation vectors of largest 1), and an XDMF listing a prefix of
the steps (as between two rewrites) stays valid. tests/cases/test_paraview.py
checks the same with ParaView itself where it is installed."""
import os

import numpy as np

import paraview_scenes as ps
import sinewtest as st
import xdmf_read


def view_of(xdmf):
    steps = xdmf_read.read(xdmf)
    view = {"times": [s["time"] for s in steps], "steps": []}
    for s in steps:
        blocks = []
        for g in s["grids"]:
            blocks.append({"points": g["points"], "warped": g["points"] + g["point"]["displacement"]
                           if "displacement" in g["point"] else None,
                           "point_max": {k: ps.maxabs(v) for k, v in g["point"].items()},
                           "cell_max": {k: ps.maxabs(v) for k, v in g["cell"].items()},
                           "field": {k: float(np.ravel(v)[0]) for k, v in g["field"].items()}})
            st.check(g["geometry_text"].endswith(":/mesh/p0"), f"{xdmf}: geometry {g['geometry_text']}")
        view["steps"].append(blocks)
    return view


for name, (h5, xdmf, points, cells) in ps.run_all("xc_").items():
    if not st.check(os.path.exists(xdmf), f"{name}: {xdmf} written"):
        continue
    try:
        view = view_of(xdmf)
    except xdmf_read.XdmfError as e:
        st.fail(f"{name}: {xdmf} does not resolve: {e}")
        continue
    ps.check_view(name, h5, view, points, cells, "XDMF (h5py)")
    if name == "crosshinge":
        ps.check_prefix(h5, view_of(ps.prefix_xdmf(xdmf, 5)), 5, "XDMF (h5py)")
st.done()
