"""-target_error from a coarse Gmsh membrane mesh (docs/accuracy.md "Membranes"), 2 ranks: the
prestressed square drum of test_accuracy_membranes read from a Gmsh 4.1 file (gmsh_drum.py: 4
boundary intervals per side, jittered interior nodes, 46 Delaunay triangles; the held edge is a
physical curve used as an nprops node group). Every level splits the file's triangles in four; at 5e-3
the true error of f1 against f11 = sqrt(n0 / m) sqrt(2) / (2 L) is within the target and the estimate
within a factor 3 of it, and the result file holds the split mesh. (Beams from nbeams 1 on 2 ranks:
test_accuracy_frequencies.)"""
import os

import gmsh_drum as gd
import membrane_accuracy_cases as mc
import sinewtest as st

target = 5e-3
msh = os.path.join(st.WORK, "accuracy_gmsh_drum.msh")
xy, tris = gd.write_msh(msh)
path, out = st.run("accuracy_gmsh_drum", gd.scene(msh, {"target_error": target}))
with st.h5(path) as f:
    g = f["accuracy"]
    f1 = float(f["freq"][-1][0])
    true = abs(f1 / mc.F11 - 1)
    est = float(g["worst_error"][-1])
    level = int(g.attrs["level"])
    print(f"  Gmsh drum ({len(tris)} triangles): unknowns {g['unknowns'][:].tolist()}, "
          f"{float(sum(g['wall_time'][:])):.2f} s; f1 {f1:.6f} Hz (f11 {mc.F11:.6f}), true error {true:.2e}, "
          f"estimate {est:.2e}, order {float(g['order'][-1][0]):.2f}")
    st.check(int(g.attrs["met"]) == 1, "/accuracy met = 1")
    st.check(level >= 2, f"refined (level {level}): the estimate needs three levels")
    st.check(true <= target, f"true error {true:.2e} above the target {target:g}")
    st.check(1 / 3 <= est / true <= 3, f"estimate {est:.2e} vs true error {true:.2e}: outside a factor 3")
    st.check(f["mesh/triangles"].shape[0] == len(tris) * 4 ** level,
             f"{f['mesh/triangles'].shape[0]} triangles: the file's {len(tris)} split in four {level} times")
st.done()
