"""-target_error on path following (docs/accuracy.md "Path following"), 2 ranks: Lee's frame from 10
elements (column 5, beam 1 + 4, the scale of runs/lee_frame.yaml: the load factor is P L^2 / EI),
arc length to the stop displacement v = -0.5 m of the load point, just past the first limit point.
Every level follows the path to that stop (max_steps x 2^level); the watched quantities are the first
limit load (/path/critical_points) and the end state interpolated to v = -0.5 exactly. Reference: the
converged first limit load 18.54475 (Richardson from the levels nbeams x32, x64, x128 of this frame at
1e-3 .. 1e-5, observed order 2.000; docs/accuracy.md); the published 18.5 (Schweizerhof & Wriggers 1986) has three digits. At
1e-2 the true error of the reported limit load is within the target and its estimate within a factor
3 of it. A path without a stop criterion is refused (exit 2): its end is a different point on every level."""
import lee_frame_scene as lf
import sinewtest as st

LIMIT = 18.54475
target = 1e-2


def lee(stop=-0.5):
    return lf.lee("Lee's frame, accuracy on demand", 0.15, stop, {"target_error": target})


path, out = st.run("accuracy_path_lee", lee())
with st.h5(path) as f:
    g = f["accuracy"]
    names = [n for n in g.attrs["quantities"].split("\n") if n]
    st.check("limit 1" in names, f"the first limit load is watched: {names}")
    i = names.index("limit 1")
    crit = f["path/critical_points"][:]
    limit = float(crit[crit[:, 0] == 1][0, 2])
    true = abs(limit / LIMIT - 1)
    est = float(g["error"][-1][i])
    print(f"  Lee's frame: levels {g['nbeams_factor'][:].tolist()}, unknowns {g['unknowns'][:].tolist()}, "
          f"{float(sum(g['wall_time'][:])):.1f} s; limit {limit:.5f} (converged {LIMIT}), true error {true:.2e}, "
          f"estimate {est:.2e}, order {float(g['order'][-1][i]):.2f}; worst {float(g['worst_error'][-1]):.2e} ({names})")
    st.check(int(g.attrs["met"]) == 1, "/accuracy met = 1")
    st.check(true <= target, f"true error {true:.2e} above the target {target:g}")
    st.check(1 / 3 <= est / true <= 3, f"estimate {est:.2e} vs true error {true:.2e}: outside a factor 3")
    st.check(len(g["unknowns"]) >= 3, "at least three levels")
    end = [n for n in names if n.startswith("node 3 p")]
    st.check(bool(end), f"the load point's end state is watched: {names}")
    st.check(abs(float(g["value"][-1][names.index("node 3 p")][1]) + 0.5) < 1e-12,
             "the end state is at the stop displacement exactly (interpolated between the last two points)")

# no stop criterion: max_steps ends the path at a different point on every level
path, out = st.run("accuracy_path_nostop", lee(stop=None), expect_exit=2)
st.check("stop_displacement" in out and "opt.target_error" in out, f"the refusal names the fix:\n{out[-400:]}")
st.done()
