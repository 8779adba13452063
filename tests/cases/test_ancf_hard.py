"""Hard case of issue 4: a very stiff cable, EA/EI = 1e8, with many elements converges in statics.
Cantilever L = 2, EI = 1, EA = 1e8, 1024 ANCF elements, tip force P = 3 EI / L^2 applied in ONE load
step (large deflection, nearly inextensible): Newton must converge, and the tip must match the
inextensible elastica (theta'' = -(P L^2/EI) cos theta, shooting with RK4 in numpy) within the
discretisation error plus the axial stretch P/EA (~1e-8)."""
import re

import ancf_scenes as A
import sinewtest as st

EI, EA, L = 1.0, 1e8, 2.0
alpha = 3.0  # P L^2 / EI




x_ref, y_ref = A.elastica(alpha)
scene = A.cantilever(1024, L=L, EA=EA, EI=EI, rhoA=1.0, force=alpha * EI / L**2, opt={"loadsteps": 1})
h5, out = st.run("ancf_hard_stiff", A.text(scene))
m = re.search(r"^\s+1\s+1\s+(\d+)\s+(\d+)", out, re.M)
st.check(m is not None and int(m.group(2)) == 1, "EA/EI = 1e8: one load step without cutting the increment")
if m:
    print(f"  Newton iterations: {m.group(1)}")
    st.check(int(m.group(1)) <= 15, "EA/EI = 1e8: at most 15 Newton iterations")
with st.h5(h5) as f:
    u = A.tip_displacement(f)
# the elastica (P fixed in direction, downward): tip at (x_ref L, -y_ref L)
st.close([L + u[0], u[1]], [x_ref * L, -y_ref * L], atol=1e-7 * L, what="tip vs inextensible elastica [m]")
st.done()
