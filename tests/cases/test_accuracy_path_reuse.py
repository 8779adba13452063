"""-target_error's reuse between the levels of a path (docs/accuracy.md, "Reuse between levels"), 2 ranks:
an arc-length step of a level predicts from the coarser level's path, interpolated onto its nodes: its
increment over the step's arc length from the coarser path's point nearest to the step's start. Lee's
frame from 10 elements to v = -0.5 (tests/cases/test_accuracy_path.py's scene with ds 0.1), target 1e-3,
with -accuracy_reuse 1 (default) and 0: the same levels and limiting quantities, the first limit load of
every level within 1e-5 relative and the finest one's within 1e-6 (measured 1.6e-6 on level 1 and 4.4e-8 on
the finest: the levels' steps differ, see the docs; the limit point is located by the cubic Hermite over the
step that straddles it), the same worst estimates to 1e-3 relative,
fewer Newton iterations (/accuracy newton_iterations) in all and on the finest level with reuse, whose steps
started from the coarser path (/accuracy reused_starts). The coarser level's steps are the plan of the finer
(/accuracy planned_steps): every level after the first follows all of its coarser level's steps, none is
rejected, the finest level takes fewer steps than without reuse, and the end state at the stop (landed on
v = -0.5 with the plan) agrees with the one without reuse within the estimate."""
import numpy as np

import lee_frame_scene as lf
import sinewtest as st


def lee():
    return lf.lee("Lee's frame, reuse between levels", 0.1)


runs = {}
for reuse in (1, 0):
    path, out = st.run(f"accuracy_path_reuse_{reuse}", lee(), args=["-target_error", "1e-3", "-accuracy_reuse", str(reuse)])
    with st.h5(path) as f:
        g = f["accuracy"]
        names = [n for n in g.attrs["quantities"].split("\n") if n]
        runs[reuse] = {k: g[k][:] for k in ("level", "worst_error", "limiting", "value", "newton_iterations", "reused_starts",
                                            "path_steps", "rejected_steps", "planned_steps", "error")}
        runs[reuse]["limit"] = g["value"][:, names.index("limit 1"), 0]
        runs[reuse]["end"] = g["value"][:, names.index("node 3 p"), :3]
        runs[reuse]["end_error"] = g["error"][:, names.index("node 3 p")]
on, off = runs[1], runs[0]
its_on, its_off = int(on["newton_iterations"].sum()), int(off["newton_iterations"].sum())
change = float(np.max(np.abs(on["limit"] / off["limit"] - 1)))
print(f"  Lee's frame: levels {list(on['level'])}, Newton iterations per level {list(on['newton_iterations'])} with reuse, "
      f"{list(off['newton_iterations'])} without ({its_on} against {its_off}); steps from the coarser path "
      f"{list(on['reused_starts'])}; limit loads {list(on['limit'])}, largest relative change {change:.1e}")
print(f"  path steps per level {list(on['path_steps'])} with reuse ({list(on['planned_steps'])} planned, "
      f"{list(on['rejected_steps'])} rejected), {list(off['path_steps'])} without")
st.check(np.array_equal(on["level"], off["level"]), "the same levels")
st.check(np.array_equal(on["limiting"], off["limiting"]), "the same limiting quantities")
fine_change = float(abs(on["limit"][-1] / off["limit"][-1] - 1))
st.check(change < 1e-5, f"the limit loads do not depend on the reuse beyond 1e-5 ({change:.1e}; estimates from 4e-3 down)")
st.check(fine_change < 1e-6, f"nor the finest level's beyond 1e-6 ({fine_change:.1e}; estimate 2.4e-4)")
st.check(np.allclose(on["worst_error"][2:], off["worst_error"][2:], rtol=1e-3, atol=0), "the same worst estimates")
st.check(np.all(off["reused_starts"] == 0), "-accuracy_reuse 0 starts no step from the coarser path")
st.check(np.all(on["reused_starts"][1:] > 0), "with reuse every level after the first predicts from the coarser path")
st.check(its_on < its_off, f"reuse saves Newton iterations ({its_on} against {its_off})")
fine_on, fine_off = int(on["newton_iterations"][-1]), int(off["newton_iterations"][-1])
st.check(fine_on < 0.6 * fine_off, f"reuse saves Newton iterations on the finest level ({fine_on} against {fine_off})")
st.check(np.all(off["planned_steps"] == 0), "-accuracy_reuse 0 follows no plan")
st.check(np.array_equal(on["planned_steps"][1:], on["path_steps"][:-1]),
         "every level after the first follows all of its coarser level's steps as its plan")
st.check(np.all(on["rejected_steps"] == 0), "no planned step is rejected")
st.check(on["path_steps"][-1] < 0.75 * off["path_steps"][-1],
         f"the plan saves steps on the finest level ({on['path_steps'][-1]:.0f} against {off['path_steps'][-1]:.0f})")
end_change = float(np.linalg.norm(on["end"][-1] - off["end"][-1]) / np.linalg.norm(off["end"][-1]))
st.check(end_change < on["end_error"][-1], f"the end state at the stop within the estimate of the reuse's ({end_change:.1e} "
         f"against {on['end_error'][-1]:.1e})")
st.done()
