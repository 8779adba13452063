"""Issue 24 item 5: a load far below the round-off floor of the residual (a 1e-9 N m moment on the
cross-flexure hinge of runs/crosshinge.yaml, 1e-12 in SPACAR Light's crosshinge_inertia) is still a
load. Newton used to accept the unloaded start state after 0 iterations (rule start-at-floor: the
whole load below 1e-2 of the floor 8 eps ||J|| max|X|) and the load steps kept rotation 0 with
converged = 1. Now every ramped load step takes a Newton step, and the rotation of the top body is
the linear compliance times the moment (CMglob[5, 5] M, the compliance the run itself writes), on
2 ranks, also through several load steps whose start residual is the round-off of the last one."""
import re

import sinewtest as st

SCENE = open(st.SOURCE + "/runs/crosshinge.yaml").read()
SCENE = SCENE.replace("force_initial: [0, -20, 0], moment: [0, 0, 0.5]", "moment: [0, 0, MOMENT]")
SCENE = SCENE.replace("calcbuck: true", "calcbuck: false")

for m, steps in ((1e-9, 2), (1e-9, 10), (1e-12, 2)):
    name = f"tiny_load_{steps}_{m:g}"
    out, log = st.run(name, SCENE.replace("MOMENT", repr(m)), args=["-loadsteps", str(steps), "-calcfreq", "false"])
    with st.h5(out) as f:
        st.check(f.attrs["converged"] == 1, f"{name}: converged = 1")
        r = f["node/r_axang"][-1, 4]
        rotation = r[0] * r[3]  # angle times the axis' z component
        compliance = f["node/CMglob"][-1, 4][5, 5]
        # 1e-12 N m turns the hinge by 6.5e-13 rad: its round-off (1e-16 rad) allows 1e-6 only in one step
        st.close(rotation, compliance * m, rtol=1e-6, what=f"{name}: rotation [rad] vs linear compliance x moment")
    its = [int(x) for x in re.findall(r"load step \d+/\d+ +load factor \S+ +Newton (\d+)", log)]
    st.check(len(its) == steps and all(n >= 1 for n in its[1:]),
             f"{name}: every ramped load step takes a Newton step (iterations {its})")
st.done()
