"""Only what is asked is created (design.md section 4): a scene without density or nodal mass and
without calcbuck has no mass matrix and no EPS object, so -log_view lists neither SinewMassAsm,
SinewEigen, EPSSolve nor an "EPS Solver" object. The same beam with density (frequencies) and
calcbuck lists them, with the expected counts (1 mass assembly per step, 1 frequency solve per step
and 1 buckling solve per loaded step: SPACAR Light's step 1 is the unloaded beam, stress-free, whose
buckling multipliers are +inf without a solve; with -load_ramp uniform both steps are loaded)."""
import re

import sinewtest as st
from modal_util import beam_x

L, W, T = 1.0, 0.01, 1e-3
sup = {1: {"fix": True}, 2: {"force": [0, 0, -1e-3]}}


def event_count(log, name):
    m = re.search(r"^" + name + r"\s+(\d+)\s", log, re.M)
    return int(m.group(1)) if m else 0


_, log = st.run("eigen_not_asked", beam_x(L, W, T, 4, sup, dens=0, opt={"loadsteps": 2}), args=["-log_view"])
for ev in ("SinewMassAsm", "SinewEigen", "EPSSolve", "STSetUp"):
    n = event_count(log, ev)
    print(f"  without mass/calcbuck: {ev} count {n}")
    st.check(n == 0, f"{ev} ran {n} times although nothing asked for it")
st.check("EPS Solver" not in log, "no EPS object created")
st.check("SinewJacobian" in log, "-log_view output present (positive control)")

_, log = st.run("eigen_asked", beam_x(L, W, T, 4, sup, opt={"loadsteps": 2, "calcbuck": True}), args=["-log_view"])
counts = {ev: event_count(log, ev) for ev in ("SinewMassAsm", "SinewEigen", "SinewSplitTan")}
print("  with density and calcbuck:", counts)
st.check(counts["SinewMassAsm"] == 2, "one mass assembly per step")
st.check(counts["SinewEigen"] == 3, "one frequency solve per step, one buckling solve at the loaded step 2")
st.check(counts["SinewSplitTan"] == 2, "one split tangent per step")

_, log = st.run("eigen_asked_uniform", beam_x(L, W, T, 4, sup, opt={"loadsteps": 2, "calcbuck": True}),
                args=["-log_view", "-load_ramp", "uniform"])
counts = {ev: event_count(log, ev) for ev in ("SinewMassAsm", "SinewEigen", "SinewSplitTan")}
print("  with density and calcbuck, -load_ramp uniform:", counts)
st.check(counts["SinewEigen"] == 4, "uniform ramp: one frequency and one buckling solve per step")
st.done()
