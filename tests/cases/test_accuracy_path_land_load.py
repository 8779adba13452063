"""-target_error on a path that stops on stop_load_factor (docs/accuracy.md, "The coarser level's steps as the
plan of the finer path"), 2 ranks: a level with the plan lands its last step on the stop, the step that crosses
stop_load_factor repeated from its start by load control onto it, so its end state is a converged point of
the path and not a cubic interpolation between its points (whose error would keep level 0's step size under
the plan, where the estimate cannot see it). Lee's frame from 10 elements (tests/cases/lee_frame_scene.py,
ds 0.1) to stop_load_factor 12 on its rise to the limit point, target 1e-3: with the plan the result's (the
finest level's) last path point is at load factor 12 to round-off; with -accuracy_path_plan 0 the path steps
past it (12.59) and the end state is interpolated; the planned levels follow all of their coarser level's
steps, and the finest level's values of both runs agree within its estimates (with the landing switched off
the reactions differ by up to 1.8e-4 against an estimate of 1.6e-5)."""
import numpy as np

import lee_frame_scene as lf
import sinewtest as st

STOP = 12.0


def lee():
    s = lf.lee("Lee's frame to stop_load_factor 12", 0.1, stop=None)
    s["opt"]["continuation"]["stop_load_factor"] = STOP
    return s


runs = {}
for plan in (1, 0):
    path, out = st.run(f"accuracy_path_land_load_{plan}", lee(), args=["-target_error", "1e-3", "-accuracy_path_plan", str(plan)])
    with st.h5(path) as f:
        g = f["accuracy"]
        names = [n for n in g.attrs["quantities"].split("\n") if n]
        r = {k: g[k][:] for k in ("level", "path_steps", "planned_steps", "rejected_steps", "newton_iterations")}
        r["value"] = {q: g["value"][:, names.index(q), :] for q in names}
        r["error"] = {q: g["error"][-1, names.index(q)] for q in names}
        r["last"] = float(f["load_factor"][-1])
        r["names"] = names
        runs[plan] = r
on, off = runs[1], runs[0]
print(f"  levels {list(on['level'])}; last load factor {on['last']!r} with the plan, {off['last']!r} without; path steps "
      f"{list(on['path_steps'])} ({list(on['planned_steps'])} planned) and {list(off['path_steps'])}; Newton iterations "
      f"{list(on['newton_iterations'])} and {list(off['newton_iterations'])}")
st.check(abs(on["last"] - STOP) <= 1e-13 * STOP, f"the finest level's last step lands on stop_load_factor ({on['last']!r})")
st.check(off["last"] > STOP * (1 + 1e-6), f"without the plan the last step crosses it ({off['last']!r}): the check sees the landing")
st.check(len(on["level"]) >= 3 and np.array_equal(on["planned_steps"][1:], on["path_steps"][:-1]),
         "every level after the first follows all of its coarser level's steps")
st.check(np.all(on["rejected_steps"] == 0), "no planned step is rejected")
st.check(np.array_equal(on["level"], off["level"]), "the same levels")
for q in on["names"]:
    a, b = on["value"][q][-1], off["value"][q][-1]
    a, b = a[np.isfinite(a)], b[np.isfinite(b)]
    change = float(np.linalg.norm(a - b) / np.linalg.norm(b))
    st.check(change < on["error"][q], f"{q}: the finest level's value with and without the plan within its estimate "
             f"({change:.1e} against {on['error'][q]:.1e})")
st.done()
