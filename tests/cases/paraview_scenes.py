"""Scenes and checks shared by test_xdmf_convention.py (the XDMF resolved with h5py, runs
everywhere) and test_paraview.py (the same XDMF files opened by ParaView's pvpython): the ParaView
convention of docs/results.md, "Opening the XDMF in ParaView".

A "view" is what a reader shows of one XDMF file: {"times": [t per ParaView time step],
"steps": [[block, ...] per time step]}, block = {"points": reference geometry [n, 3],
"warped": points moved by Warp By Vector with the "displacement" array and scale factor 1,
"point_max" / "cell_max": {array name: max |value| over the block (NaN ignored)},
"field": {field data name: value}}."""
import os

import numpy as np

import sinewtest as st
from ancf_scenes import cantilever, text

# A leaf-spring cantilever (beams): a torsion mode (rotations only) among its first modes,
# buckling, stress per element.
LEAF = """
title: leaf spring cantilever
nodes: [[0, 0, 0], [0.1, 0, 0]]
elements: [[1, 2]]
nprops: {1: {fix: true}, 2: {force: [-5, 0, 0], mass: 0.01}}
eprops: [{elems: [1], flex: [1, 2, 3, 4, 5, 6], emod: 210e9, smod: 80e9, dens: 7800, cshape: rect,
          dim: [0.02, 0.0005], orien: [0, 0, 1], nbeams: 4}]
opt: {loadsteps: 2, calccompl: false, nfreq: 4, calcbuck: true, nbuck: 1, stressperelement: true}
"""


def scenes():
    """name -> (scene: a runs/*.yaml path or scene text, required point arrays, required cell arrays)."""
    runs = os.path.join(st.SOURCE, "runs")
    ancf = text(cantilever(4, force=1e5, dynamics={"tend": 0.01, "dt": 1e-3, "spectral_radius": 0.8,
                                                    "output_every": 2}))
    return {
        # the example: 10 load steps, frequencies, buckling, stress (beams, nbeams 4)
        "crosshinge": (os.path.join(runs, "crosshinge.yaml"),
                       ["displacement", "mode_freq_1", "mode_freq_1_rot", "mode_buck_1", "mode_buck_1_rot"],
                       ["stress"]),
        # 4 form-finding rows, then 5 load steps: 9 ParaView time steps
        "sail": (os.path.join(runs, "sail.yaml"), ["displacement"],
                 ["axial_force", "membrane_n11", "membrane_n22", "membrane_n12"]),
        "leaf": (LEAF, ["displacement", "mode_freq_1_rot"], ["stress"]),
        # ANCF dynamics: times
        "ancf": (ancf, ["displacement"], ["axial_force"]),
    }


def run_all(prefix):
    """Runs every scene on 2 ranks; returns name -> (h5 path, xdmf path, point arrays, cell arrays)."""
    os.makedirs(st.WORK, exist_ok=True)
    out = {}
    for name, (scene, points, cells) in scenes().items():
        h5, _ = st.run(prefix + name, scene, np_=2)
        out[name] = (os.path.abspath(h5), os.path.abspath(os.path.splitext(h5)[0] + ".xdmf"), points, cells)
    return out


def maxabs(v):
    v = np.abs(np.asarray(v, dtype=float))
    v = v[np.isfinite(v)]
    return float(v.max()) if v.size else float("nan")


def check_view(name, h5, view, points_required, cells_required, reader):
    """The convention, seen through `reader` (a label for the messages)."""
    tag = f"{reader} {name}"
    with st.h5(h5) as f:
        step_name = "time" if "time" in f else "load_factor"
        values = f[step_name][:]
        ns = len(values)
        nff = int(np.sum(np.isfinite(f["formfinding/step"][:]))) if "formfinding/step" in f else 0
        expected = np.concatenate([np.arange(nff) - nff, values[nff:]])
        times = np.array(view["times"], dtype=float)
        print(f"  {tag}: {ns} rows ({nff} form finding), time steps {np.array2string(times, precision=4)}")
        st.check(len(times) == ns, f"{tag}: {len(times)} time steps for {ns} rows")
        st.check(np.all(np.diff(times) > 0), f"{tag}: times distinct and increasing")
        if len(times) == ns:
            st.check(np.array_equal(times, expected), f"{tag}: times -nff..-1, then {step_name}: {times} vs {expected}")
        P0, P, NP = f["mesh/p0"][()], f["mesh/p"][()], f["node/p"][()]
        nn = NP.shape[1]
        st.check(np.array_equal(P0[:nn], f["node/p0"][()]), f"{tag}: /mesh/p0 begins with the scene nodes /node/p0")
        werr = nerr = gerr = 0.0
        for s, blocks in enumerate(view["steps"][:ns]):
            for b in blocks:
                pts, w = np.asarray(b["points"]), np.asarray(b["warped"])
                if not st.check(pts.shape == P0.shape and w.shape == P0.shape,
                                f"{tag} step {s}: {pts.shape} points, {w.shape} warped, expected {P0.shape}"):
                    continue
                gerr = max(gerr, float(np.max(np.abs(pts - P0))))
                werr = max(werr, float(np.max(np.abs(w - P[s]))))
                nerr = max(nerr, float(np.max(np.abs(w[:nn] - NP[s]))))
                st.check("displacement" in b["point_max"], f"{tag} step {s}: point array displacement")
                st.check(b["field"].get(step_name) == values[s] and b["field"].get("hdf5_row") == s,
                         f"{tag} step {s}: field data {step_name} = {values[s]}, hdf5_row = {s}: {b['field']}")
        print(f"  {tag}: geometry vs /mesh/p0 {gerr:.3e}; Warp By Vector (displacement, 1) vs /mesh/p {werr:.3e}, "
              f"vs /node/p {nerr:.3e}")
        st.check(gerr == 0.0, f"{tag}: the geometry is the reference /mesh/p0 at every step ({gerr:.3e})")
        st.check(werr <= 1e-12 and nerr <= 1e-12,
                 f"{tag}: warped by 1 = /mesh/p and /node/p to 1e-12 ({werr:.3e}, {nerr:.3e})")
        last = view["steps"][-1] if view["steps"] else []
        pa = sorted(set(a for b in last for a in b["point_max"]))
        ca = sorted(set(a for b in last for a in b["cell_max"]))
        print(f"  {tag}: last step point arrays {pa}")
        print(f"  {tag}: last step cell arrays {ca}")
        for a in points_required:
            st.check(a in pa, f"{tag}: point array {a}")
        for a in cells_required:
            st.check(a in ca, f"{tag}: cell array {a}")
        if name == "leaf" and last:
            # a rotation-only (torsion) mode: translations 0, rotation vectors nonzero (largest 1)
            pm = last[0]["point_max"]
            k = f["freq"].shape[1]
            tr = [pm.get(f"mode_freq_{j}", np.nan) for j in range(1, k + 1)]
            rot = [pm.get(f"mode_freq_{j}_rot", np.nan) for j in range(1, k + 1)]
            print(f"  {tag}: modes {np.array2string(f['freq'][-1], precision=5)} Hz, max |translation| {tr}, "
                  f"max |rotation| {rot}")
            # largest rotation vector 1 to round-off: the viewer's |r| = sqrt(rx^2 + ry^2 + rz^2) of the scaled
            # components (0.9999999999999999 on the leaf since 2026-11-27)
            torsion = [j for j in range(k) if tr[j] == 0.0 and abs(rot[j] - 1.0) <= 1e-12]
            st.check(len(torsion) >= 1, f"{tag}: a rotation-only mode shows nonzero rotation vectors")
            st.check(all(abs(tr[j] - 1.0) <= 1e-12 for j in range(k) if j not in torsion), f"{tag}: other modes: max |translation| 1")
        if name == "crosshinge" and last:
            # the numbers: min x of the reference -0.05, of the warped shape that of /mesh/p (-0.0708)
            x0 = min(float(np.min(np.asarray(b["points"])[:, 0])) for b in last)
            xw = min(float(np.min(np.asarray(b["warped"])[:, 0])) for b in last)
            print(f"  {tag}: min x reference {x0:.4f}, warped {xw:.4f}, /mesh/p {P[-1][:, 0].min():.4f}")


def prefix_xdmf(xdmf, k):
    """An XDMF as the writer leaves it between two rewrites (docs/results.md, "Crash safety"): the
    first k steps of `xdmf`, with the step axis of the step-indexed datasets declared as k rows
    while the HDF5 file holds more. Returns its path (beside `xdmf`)."""
    import xml.etree.ElementTree as ET
    tree = ET.parse(xdmf)
    temporal = tree.getroot().find("Domain/Grid")
    grids = temporal.findall("Grid")
    ns = len(grids)
    for g in grids[k:]:
        temporal.remove(g)
    for slab in tree.getroot().iter("DataItem"):
        if slab.get("ItemType") == "HyperSlab":  # [selection, dataset]: the dataset's step axis
            item = slab.findall("DataItem")[1]
            dims = item.get("Dimensions").split()
            assert dims[0] == str(ns), (dims, ns)
            item.set("Dimensions", " ".join([str(k)] + dims[1:]))
    path = os.path.splitext(xdmf)[0] + f"_prefix{k}.xdmf"
    tree.write(path, xml_declaration=True, encoding="utf-8")
    return path


def check_prefix(h5, view, k, reader):
    """The prefix XDMF of prefix_xdmf shows the first k rows, warped to /mesh/p."""
    with st.h5(h5) as f:
        P = f["mesh/p"][()]
        times = f["load_factor"][:k]
    werr = 0.0
    for s, blocks in enumerate(view["steps"]):
        for b in blocks:
            werr = max(werr, float(np.max(np.abs(np.asarray(b["warped"]) - P[s]))))
    print(f"  {reader} prefix of {k} steps: times {view['times']}, warped vs /mesh/p {werr:.3e}")
    st.check(np.array_equal(view["times"], times) and len(view["steps"]) == k and werr <= 1e-12,
             f"{reader}: an XDMF listing the first {k} steps of a longer file shows them")
