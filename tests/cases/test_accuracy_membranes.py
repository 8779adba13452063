"""-target_error on a prestressed square membrane's first frequency (docs/accuracy.md "Membranes"), 2
ranks, from 4 x 4 squares of two triangles: every level splits each triangle in four (unknowns about 4x
per level); at 1e-3 the true error against f11 = sqrt(n0 / m) sqrt(2) / (2 L) is within the target and
the estimate within a factor 3 of it, also on quads (split in four too); the result file holds the reported level's mesh. A cable along a
grid line of the membrane is split with the triangles' edges: its segments join the membrane's nodes."""
import numpy as np

import membrane_accuracy_cases as mc
import sinewtest as st

target = 1e-3
path, out = st.run("accuracy_membrane_drum", mc.drum(4, {"target_error": target}))
with st.h5(path) as f:
    g = f["accuracy"]
    names = [n for n in g.attrs["quantities"].split("\n") if n]
    st.check(names == ["freq 1"], f"watched: the frequency alone (no membrane reactions), got {names}")
    f1 = float(f["freq"][-1][0])
    true = abs(f1 / mc.F11 - 1)
    est = float(g["worst_error"][-1])
    unknowns = g["unknowns"][:]
    print(f"  drum: {len(unknowns)} levels, unknowns {unknowns.tolist()}, {float(np.sum(g['wall_time'][:])):.2f} s; "
          f"f1 {f1:.6f} Hz (f11 {mc.F11:.6f}), true error {true:.2e}, estimate {est:.2e}, order {float(g['order'][-1][0]):.2f}")
    st.check(int(g.attrs["met"]) == 1, "/accuracy met = 1")
    st.check(true <= target, f"true error {true:.2e} above the target {target:g}")
    st.check(1 / 3 <= est / true <= 3, f"estimate {est:.2e} vs true error {true:.2e}: outside a factor 3")
    growth = unknowns[1:] / unknowns[:-1]
    st.check(len(unknowns) >= 3 and np.all((growth > 3.5) & (growth < 6)),
             f"unknowns grow about 4x per level (the triangles are split): {unknowns.tolist()}")
    n_scene = 25
    st.check(f["mesh/p"].shape[1] > 16 * n_scene, f"/mesh/p has {f['mesh/p'].shape[1]} nodes: the reported level's mesh")
st.check("met at level" in out, "the summary's accuracy table says where the target was met")

# quads split in four: the same checks on the frequency
path, out = st.run("accuracy_membrane_quads", mc.drum(4, {"target_error": target}, quads=True))
with st.h5(path) as f:
    g = f["accuracy"]
    true = abs(float(f["freq"][-1][0]) / mc.F11 - 1)
    est = float(g["worst_error"][-1])
    print(f"  quad drum: unknowns {g['unknowns'][:].tolist()}, true error {true:.2e}, estimate {est:.2e}")
    st.check(int(g.attrs["met"]) == 1 and true <= target, f"quads: met, true error {true:.2e} within {target:g}")
    st.check(1 / 3 <= est / true <= 3, f"quads: estimate {est:.2e} vs true error {true:.2e}: outside a factor 3")
    level = int(g.attrs["level"])
    st.check(level >= 2 and f["mesh/quads"].shape[0] == 16 * 4**level, "quads: refined, 16 x 4^level quads in the mesh")

# an edge cable (scene elements 4-5, 5-6 on the line y = L/2 of a 2 x 2 drum) splits with the edges
scene = mc.drum(2, {"target_error": 1e-2, "accuracy_quantities": ["freq"]})
ne = len(scene["elements"])
scene["elements"] += [[4, 5], [5, 6]]
scene["eprops"].append({"elems": [ne + 1, ne + 2], "type": "cable", "emod": 1e9, "area": 1e-6, "dens": 1000,
                        "prestress": 1e3})
path, out = st.run("accuracy_membrane_cable", scene)
with st.h5(path) as f:
    level = int(f["accuracy"].attrs["level"])
    lines, tris = f["mesh/lines"][:], f["mesh/triangles"][:]
    st.check(level >= 2, f"refined (level {level})")
    st.check(len(lines) == 2 * 2**level, f"{len(lines)} cable segments at level {level}: 2 x 2^level")
    st.check(set(lines.ravel()) <= set(tris.ravel()), "every cable node is a membrane node (the cable stays connected)")
    st.check(f["mesh/p"].shape[1] == (2 * 2**level + 1) ** 2, "no nodes besides the membrane's")
st.done()
