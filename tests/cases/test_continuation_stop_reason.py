"""Issue 24 item 4: a path-following run says why it stopped (printed, and the /path attribute
stop_reason), and one that max_steps ends before the stop_displacement (or stop_load_factor) the
scene gave ends short of what it asked: exit 3, converged = 0 (it exited 0 with only "path: 200
points, load factor 0.58069"). The von Mises truss of test_continuation, 2 ranks: max_steps 5
before stop_displacement -0.25 (exit 3), the same path to its stop_displacement (exit 0), and
max_steps as the only end (exit 0, "max_steps 5 reached")."""

import path_scenes
import sinewtest as st

scene = path_scenes.von_mises_truss


def reason(h5):
    with st.h5(h5) as f:
        r = f["path"].attrs.get("stop_reason")
        return (r.decode() if isinstance(r, bytes) else r), int(f.attrs["converged"]), len(f["load_factor"])


cases = [  # continuation block, exit code, stop_reason start, converged
    ({"method": "arclength", "ds": 0.02, "node": 2, "direction": "y", "stop_displacement": -0.25, "max_steps": 5}, 3,
     "max_steps 5 reached before stop_displacement -0.25 (load factor ", 0),
    ({"method": "arclength", "ds": 0.02, "ds_max": 0.05, "node": 2, "direction": "y", "stop_displacement": -0.25}, 0,
     "stop_displacement -0.25 reached (control displacement -0.2", 1),
    ({"method": "arclength", "ds": 0.02, "node": 2, "direction": "y", "max_steps": 5}, 0, "max_steps 5 reached", 1),
]
for i, (cont, code, expected, conv) in enumerate(cases):
    h5, log = st.run(f"continuation_stop_reason_{i}", scene(cont), args=["-continuation_inertia", "false"], expect_exit=code)
    r, c, rows = reason(h5)
    print(f"  case {i}: exit {code}, {rows} points, stop_reason '{r}'")
    st.check(r is not None and r.startswith(expected), f"case {i}: /path stop_reason '{r}' starts with '{expected}'")
    st.check(c == conv, f"case {i}: converged = {c}, expected {conv}")
    st.check(f"path ended: {r}" in log, f"case {i}: the summary prints why the path ended")
    if code == 3:
        st.check("error: path following ended short: max_steps 5 reached before stop_displacement" in log,
                 f"case {i}: the error line says the path ended short")
st.done()
