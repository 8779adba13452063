"""-target_error watching a bifurcation load factor (docs/accuracy.md, "Path following"), 2 ranks: the
perfect fixed-free Euler column of test_continuation_bifurcation2 (L = 1 m, E = 210 GPa, in-plane) made
thin, circular d = 1 mm (the axial shortening before buckling and the shear flexibility are then about
1.5e-7 of the load: the column's model is Euler's to that), one element, pushed along its straight
primary path by arc length (ds = ds_max = 0.2 in units of P_cr) to stop_load_factor 1.1,
-continuation_lowest_eigenvalue (the bifurcation at the zero of the eigenvalue changing sign),
`accuracy_quantities: [bifurcation]`. Reference: P_cr = pi^2 EI / (4 L^2), load factor 1.
The path before the bifurcation is straight, so its load factor is the buckling eigenvalue of the
cubic beam and converges as h^4 (observed 3.85, 3.96), above the nodal h^2 band: the estimate trusts
either order for a bifurcation (measured before that: `erratic` at order 3.96, then `resolved` with an
estimate 180 times the true error).
For 1e-3 and 1e-5: met, the true error against 1 within the target and the estimate within a factor 3."""
import yaml

import path_scenes as ps
import sinewtest as st

text, _ = ps.euler_column(1, max_steps=40, d=0.001)
scene = yaml.safe_load(text)
scene["opt"]["continuation"].update({"ds": 0.2, "ds_max": 0.2, "stop_load_factor": 1.1})
scene["opt"]["accuracy_quantities"] = ["bifurcation"]

for target, levels in ((1e-3, 3), (1e-5, 4)):
    scene["opt"]["target_error"] = target
    name = f"accuracy_bifurcation_{target:g}"
    path, out = st.run(name, scene, args=["-continuation_lowest_eigenvalue"])
    with st.h5(path) as f:
        g = f["accuracy"]
        names = [n for n in g.attrs["quantities"].split("\n") if n]
        st.check(names == ["bifurcation 1"], f"{name}: the bifurcation load factor is watched: {names}")
        crit = f["path/critical_points"][:]
        value = float(crit[crit[:, 0] == 2][0, 2])
        est, order = float(g["error"][-1][0]), float(g["order"][-1][0])
        status, met, n = int(g["status"][-1][0]), int(g.attrs["met"]), len(g["level"])
    true = abs(value - 1)
    print(f"  target {target:g}: {n} levels (nbeams x{2 ** (n - 1)}), bifurcation {value:.10f}, true error {true:.2e}, "
          f"estimate {est:.2e} (ratio {est / true:.2f}), order {order:.2f}")
    st.check(met == 1 and status == 0, f"{name}: met with a converging estimate (status {status})")
    st.check(n == levels, f"{name}: {n} levels, expected {levels}")
    st.check(true <= target, f"{name}: true error {true:.2e} above the target")
    st.check(1 / 3 <= est / true <= 3, f"{name}: estimate {est:.2e} vs true error {true:.2e}: outside a factor 3")
st.done()
