"""-target_error on form finding (docs/accuracy.md "Form finding"), 2 ranks: the catenoid between two
rings of radius R = 1 at z = +-0.5 (ffscenes.catenoid_scene, 8 nodes per ring row, 4 cells in z: 64
triangles), URS towards the minimal surface r = a cosh(z/a), R = a cosh(0.5/a), a = 0.848338. Every
level splits the triangles in four; the new nodes of the ring edges go on the rings (the circle through
three supported boundary nodes), not on the chords. Watched: the found shape (RMS change of the scene's
moving nodes relative to the model size) and the neck node's position (relative to the largest
displacement). At the target the true errors against the catenoid (the scene nodes' radial distance to
r = a cosh(z/a), the neck radius against a) are within it and the estimates within a factor 3."""
import numpy as np

import ffscenes as ff
import sinewtest as st

R, H, NT, NZ = 1.0, 0.5, 8, 4
A = ff.catenoid_a(R, H)
NECK = (NZ // 2) * NT + 1  # first node of the ring row at z = 0 (1-based)
target = 4e-2

scene = ff.catenoid_scene(R=R, halfh=H, nt=NT, nz=NZ, steps=40, tol=1e-6)
scene["opt"].update({"target_error": target, "accuracy_quantities": ["shape", f"node {NECK} p"]})
path, out = st.run("accuracy_ff_catenoid", ff.to_yaml(scene))
with st.h5(path) as f:
    g = f["accuracy"]
    names = [n for n in g.attrs["quantities"].split("\n") if n]
    st.check(names == ["shape", f"node {NECK} p"], f"watched: {names}")
    rows = np.where(np.isfinite(f["formfinding/step"][:]))[0]
    x = f["node/p"][rows[-1]][: len(scene["nodes"])]
    x0 = np.array(scene["nodes"])
    moving = np.linalg.norm(x - x0, axis=1) > 1e-12
    size = np.linalg.norm(x0.max(axis=0) - x0.min(axis=0))
    r = np.hypot(x[:, 0], x[:, 1])
    radial = r - A * np.cosh(x[:, 2] / A)
    true_shape = np.sqrt(np.mean(radial[moving] ** 2)) / size
    umax = np.max(np.linalg.norm(x - x0, axis=1))
    true_neck = abs(r[NECK - 1] - A) / umax
    est = g["error"][-1]
    print(f"  catenoid: levels {g['level'][:].tolist()}, unknowns {g['unknowns'][:].tolist()}, "
          f"{float(sum(g['wall_time'][:])):.1f} s; shape: true {true_shape:.2e}, estimate {est[0]:.2e} "
          f"(order {g['order'][-1][0]:.2f}); neck r {r[NECK - 1]:.6f} (a {A:.6f}): true {true_neck:.2e}, "
          f"estimate {est[1]:.2e} (order {g['order'][-1][1]:.2f})")
    st.check(int(g.attrs["met"]) == 1, "/accuracy met = 1")
    st.check(int(g.attrs["level"]) >= 2, "refined: three levels at least")
    for what, true, e in (("shape", true_shape, est[0]), ("neck", true_neck, est[1])):
        st.check(true <= target, f"{what}: true error {true:.2e} above the target {target:g}")
        st.check(1 / 3 <= e / true <= 3, f"{what}: estimate {e:.2e} vs true error {true:.2e}: outside a factor 3")
    ring = np.abs(np.abs(f["mesh/p"][0][:, 2]) - H) < 1e-12
    rr = np.hypot(f["mesh/p"][0][ring, 0], f["mesh/p"][0][ring, 1])
    st.check(np.allclose(rr, R, atol=1e-12), f"the refined rings' nodes lie on the rings (radius {rr.min()}..{rr.max()})")
st.done()
