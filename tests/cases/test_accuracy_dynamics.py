"""-target_error in time (docs/accuracy.md, "Dynamics"): a steel leaf cantilever (1 m x 20 mm x 2 mm,
one element) under a tip force applied suddenly at t = 0, generalized-alpha with spectral radius
0.9 up to the first peak (t = T1 / 2), from dt = T1 / 40, 2 ranks. Levels halve dt; the quantity is the
tip's displacement history at the 11 written times, its error the worst row relative to the largest
displacement. True error: against the same scene at dt_L / 2 and dt_L / 4 of the reported level
dt_L, extrapolated with the scheme's order 2 (its own error about 1e-3 of the reported level's).
For 1e-3 and 1e-5: the true error is within the target, the estimate within a factor 3 of it, the
result file holds the reported level's finer steps at the scene's output times. Adaptive steps are
refused (exit 2)."""
import numpy as np

import beamtools as bt
import sinewtest as st

L, W, T = 1.0, 0.02, 0.002
sec = bt.rect_section(W, T)
F = 1e-5 * 3 * sec["EIy"] / L ** 3  # linear range: the tip moves 1e-5 L
T1 = 2 * np.pi / (1.875104068711961 ** 2 * np.sqrt(sec["EIy"] / (7800 * sec["A"] * L ** 4)))
DT0, ROWS = T1 / 40, 11


def scene(dt, opt=None, dynamics=None):
    dyn = {"tend": T1 / 2, "dt": dt, "spectral_radius": 0.9, "output_every": int(round(T1 / 20 / dt))}
    dyn.update(dynamics or {})
    o = {"calccompl": False, "dynamics": dyn}
    o.update(opt or {})
    return bt.yaml_text({"title": "leaf step response", "nodes": [[0, 0, 0], [L, 0, 0]], "elements": [[1, 2]],
                         "nprops": {1: {"fix": True}, 2: {"force": [0, F, 0]}},
                         "eprops": [bt.beam_set([1], W, T, dens=7800)], "opt": o})


def tip_history(path):
    with st.h5(path) as f:
        return f["time"][:], f["node/p"][:, 1, :] - f["node/p0"][1, :]


rows = []
for target in (1e-3, 1e-5):
    name = f"accuracy_dyn_{target:g}"
    path, out = st.run(name, scene(DT0, {"target_error": target}))
    t, u = tip_history(path)
    with st.h5(path) as f:
        g = f["accuracy"]
        factor = int(g["nbeams_factor"][-1])
        names = [n for n in g.attrs["quantities"].split("\n") if n]
        est = float(g["error"][-1][names.index("node 2 p(t)")])
        info = dict(levels=len(g["level"]), unknowns=int(g["unknowns"][-1]), time=float(np.sum(g["wall_time"][:])),
                    met=int(g.attrs["met"]), refinement=g.attrs["refinement"])
    st.check(info["met"] == 1 and info["refinement"] == "dt / 2^level", f"{name}: met, levels refine dt")
    st.check(factor >= 4, f"{name}: dt refined beyond the scene's (dt / {factor}): target_error not ignored")
    st.check(len(t) == ROWS and abs(t[-1] - T1 / 2) < 1e-12 * T1, f"{name}: {len(t)} rows at the scene's output times")
    # reference: dt / 2 and dt / 4 of the reported level, extrapolated with order 2
    _, u2 = tip_history(st.run(f"{name}_ref2", scene(DT0 / factor / 2), np_=1)[0])
    _, u4 = tip_history(st.run(f"{name}_ref4", scene(DT0 / factor / 4), np_=1)[0])
    ref = u4 + (u4 - u2) / 3
    scale = np.max(np.linalg.norm(ref, axis=1))
    true = np.max(np.linalg.norm(u - ref, axis=1)) / scale
    print(f"  target {target:g}: {info['levels']} levels (dt / {factor}), {info['unknowns']} unknowns x steps, "
          f"{info['time']:.2f} s; true error {true:.2e}, estimate {est:.2e} (ratio {est / true:.2f})")
    st.check(true <= target, f"{name}: true error {true:.2e} above the target")
    st.check(1 / 3 <= est / true <= 3, f"{name}: estimate {est:.2e} vs true error {true:.2e}: outside a factor 3")
    st.check(f"met at level {info['levels'] - 1} (dt / {factor})" in out, f"{name}: the summary names the level")

_, out = st.run("accuracy_dyn_adaptive", scene(DT0, {"target_error": 1e-3}, {"adaptive": {"control": "newton"}}),
                expect_exit=2)
st.check("opt.dynamics.adaptive" in out, "adaptive steps with -target_error: refused, naming opt.dynamics.adaptive")
st.done()
