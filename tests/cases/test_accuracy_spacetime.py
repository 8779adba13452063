"""-target_error refining space and time together (docs/accuracy.md, "Dynamics: space and time"),
2 ranks: a steel leaf cantilever (1 m x 20 mm x 2 mm, nbeams 1) under a tip force that rises smoothly
over half the first period to 0.3 x 3 EI / L^3 (`smoothstep`; large motion, the tip moves by up to
0.29 L, 0.05 L of it along the beam, so the corotational beam's nodal positions converge as h^2; a step load would excite every mode
of the finer meshes and make the orders erratic), generalized-alpha rho = 0.9 to t = T1 / 2 (11 rows),
from dt = T1 / 40. On the first levels the spatial error (one element: 1.3e-2 of the largest
displacement) dominates the time error (2.9e-3). With `accuracy_refine: both` every level doubles
nbeams and halves dt; the tip's history converges to the continuum. With time refinement alone (the
default) the levels converge to the one-element history: the estimate meets the target while the true
error stays at the spatial error, a hundred times above it. Reference: nbeams x4 of the reported level
(its spatial error about 1/30 of the reported level's) at dt_L / 4 and dt_L / 8, extrapolated in time
with order 2.
Checks: both: met, levels refine nbeams and dt, the true error within the target, the estimate within
a factor 3 of it, the rows at the scene's output times; time alone: the true error above 3 x the target
(the option is not ignored); accuracy_refine: time without opt.dynamics is refused (exit 2)."""
import numpy as np

import beamtools as bt
import sinewtest as st

L, W, T = 1.0, 0.02, 0.002
sec = bt.rect_section(W, T)
F = 0.3 * 3 * sec["EIy"] / L ** 3  # large motion: the linear static tip deflection would be 0.3 L
T1 = 2 * np.pi / (1.875104068711961 ** 2 * np.sqrt(sec["EIy"] / (7800 * sec["A"] * L ** 4)))
DT0, ROWS, NBEAMS, TARGET = T1 / 40, 11, 1, 1e-4


def scene(nbeams, dt, opt=None, dynamics=True):
    o = {"calccompl": False}
    if dynamics:
        o["dynamics"] = {"tend": T1 / 2, "dt": dt, "spectral_radius": 0.9, "output_every": int(round(T1 / 20 / dt))}
    o.update(opt or {})
    force = f"{F!r} * smoothstep(t, 0, {T1 / 2!r}, 0, 1)"
    return bt.yaml_text({"title": "leaf, smooth tip load", "nodes": [[0, 0, 0], [L, 0, 0]], "elements": [[1, 2]],
                         "nprops": {1: {"fix": True}, 2: {"force": [0, force, 0]}},
                         "eprops": [bt.beam_set([1], W, T, dens=7800, nbeams=nbeams)], "opt": o})


def tip_history(path):
    with st.h5(path) as f:
        return f["time"][:], f["node/p"][:, 1, :] - f["node/p0"][1, :]


def study(name, refine):
    opt = {"target_error": TARGET} if refine is None else {"target_error": TARGET, "accuracy_refine": refine}
    path, out = st.run(name, scene(NBEAMS, DT0, opt))
    t, u = tip_history(path)
    with st.h5(path) as f:
        g = f["accuracy"]
        names = [n for n in g.attrs["quantities"].split("\n") if n]
        info = dict(levels=len(g["level"]), factor=int(g["nbeams_factor"][-1]), unknowns=int(g["unknowns"][-1]),
                    time=float(np.sum(g["wall_time"][:])), met=int(g.attrs["met"]), refinement=g.attrs["refinement"],
                    est=float(g["error"][-1][names.index("node 2 p(t)")]),
                    orders=np.array2string(g["order"][:, names.index("node 2 p(t)")], precision=2))
    return t, u, info, out


def reference(name, nbeams, dt):
    """nbeams at dt / 4 and dt / 8, extrapolated in time with order 2."""
    _, u4 = tip_history(st.run(f"{name}_ref4", scene(nbeams, dt / 4), np_=1)[0])
    _, u8 = tip_history(st.run(f"{name}_ref8", scene(nbeams, dt / 8), np_=1)[0])
    return u8 + (u8 - u4) / 3


def true_error(u, ref):
    return np.max(np.linalg.norm(u - ref, axis=1)) / np.max(np.linalg.norm(ref, axis=1))


t, u, info, out = study("accuracy_spacetime_both", "both")
k = info["factor"]
ref = reference("accuracy_spacetime_both", NBEAMS * k * 4, DT0 / k)
true = true_error(u, ref)
print(f"  both: {info['levels']} levels (nbeams {NBEAMS * k}, dt / {k}), {info['unknowns']} unknowns x steps, "
      f"{info['time']:.2f} s, orders {info['orders']}; true error {true:.2e}, estimate {info['est']:.2e} "
      f"(ratio {info['est'] / true:.2f})")
st.check(info["met"] == 1 and info["refinement"] == "elements and dt / 2^level", f"both: met, levels refine both ({info})")
st.check(k >= 4, f"both: refined beyond the scene (x{k})")
st.check(len(t) == ROWS and abs(t[-1] - T1 / 2) < 1e-12 * T1, f"both: {len(t)} rows at the scene's output times")
st.check(true <= TARGET, f"both: true error {true:.2e} above the target {TARGET:g}")
st.check(1 / 3 <= info["est"] / true <= 3, f"both: estimate {info['est']:.2e} vs true error {true:.2e}: outside a factor 3")
st.check(f"met at level {info['levels'] - 1} (nbeams x{k}, dt / {k})" in out, "both: the summary names the level")

# time alone (the default): converges to the one-element mesh, whose spatial error the estimate cannot see
t, u, info, out = study("accuracy_spacetime_time", None)
k = info["factor"]
true = true_error(u, ref)
print(f"  time alone: {info['levels']} levels (dt / {k}), estimate {info['est']:.2e}, true error {true:.2e}")
st.check(info["refinement"] == "dt / 2^level", "time alone: the default refines dt")
st.check(true > 3 * TARGET, f"time alone: true error {true:.2e}, the spatial error of nbeams 1 (above the target)")

_, out = st.run("accuracy_spacetime_static", scene(NBEAMS, DT0, {"target_error": 1e-3, "accuracy_refine": "time"},
                                                   dynamics=False), expect_exit=2)
st.check("opt.accuracy_refine" in out, "accuracy_refine: time without opt.dynamics is refused")
st.done()
