"""Energy-momentum scheme for ANCF cables (-dynamics_scheme energy_momentum; docs/dynamics.md,
"Energy-momentum scheme"; src/elements/ancf_cable2d_step_force.cpp; issue 27), 2 ranks, -dynamics_energy.

1. A pendulum: an ANCF cable of 8 elements (1 m, EA = 1e5 N, EI = 1 N m^2, rhoA = 0.1 kg/m), pinned at
   one end and released horizontal under gravity, 500 steps of 2 ms (highest axial omega h about 50):
   T + S - W constant to the Newton tolerance, checked 1e-11 of the largest T. The generalized-alpha
   scheme at rho_inf = 1 on a like pendulum keeps it to 2.2e-5 (test_ancf_dynamics), so the check fails
   if the scheme flag is ignored.
2. Free flight: the same cable free, struck at both ends by force pulses of 20 ms (sin^2, transverse at
   one end, axial and transverse at the other), then free for 480 steps of 1 ms: T + S, the linear and
   the angular momentum (positions and slopes: docs/dynamics.md "Energy and momentum") constant after the
   pulse, checked 1e-11 of themselves.
3. The same with -dynamics_energy_decay 0.1: T + S lower at every written row after the pulse, the
   momenta still constant.
4. A user force law (axialForceUserFunction) is not a potential: refused at set-up (exit 2) with a message
   naming the field.
MEASURED (2 ranks, 2026-11-27, 17 s on a loaded machine): pendulum T + S - W 1.45e-13 of max T (0.490 J);
free flight T + S 3.5e-13, p 1.2e-12, H 2.8e-13 after the pulse; with xi = 0.1 T + S loses 0.24 after the
pulse, lower at every row, p 4.5e-13, H 2.3e-13."""
import numpy as np

import sinewtest as st
from ancf_scenes import text

em = ["-dynamics_scheme", "energy_momentum", "-dynamics_energy"]
EA, EI, rhoA, n = 1e5, 1.0, 0.1, 8


def cable(nprops, tend, dt, gravity=None, every=10, extra_set=None):
    o = {"calccompl": False, "calcfreq": False,
         "dynamics": {"tend": tend, "dt": dt, "spectral_radius": 1.0, "output_every": every}}
    if gravity:
        o["gravity"] = gravity
    s = {"elems": [1], "type": "ancf_cable2d", "physicsMassPerLength": rhoA, "physicsBendingStiffness": EI,
         "physicsAxialStiffness": EA, "nbeams": n}
    s.update(extra_set or {})
    return {"title": "ANCF cable, energy-momentum", "nodes": [[0.0, 0.0], [1.0, 0.0]], "elements": [[1, 2]],
            "nprops": nprops, "eprops": [s], "opt": o}


def read(h):
    with st.h5(h) as f:
        return (f["time"][:], f["energy/kinetic"][:], f["energy/strain"][:], f["energy/external_work"][:],
                f["momentum/linear"][:], f["momentum/angular"][:, 2])


# 1. pendulum
h, _ = st.run("em_ancf_pendulum", text(cable({1: {"fix_x": True, "fix_y": True}}, 1.0, 2e-3, gravity=[0, -9.81])),
              args=em)
t, T, S, W, p, H = read(h)
drift = np.ptp(T + S - W) / T.max()
print(f"  pendulum, 500 steps: T + S - W varies by {drift:.2e} of max T ({T.max():.4g} J)")
st.check(drift < 1e-11, f"pendulum: T + S - W varies by {drift:.2e} of max T (expected < 1e-11)")
st.check(T.max() > 0.1, "pendulum: it swings")

# 2., 3. free flight after pulses
TP = 0.02
pulse = f"(t < {TP} ? sin(pi*t/{TP})^2 : 0)"
strike = {1: {"force": [f"3*{pulse}", f"-2*{pulse}"]}, 2: {"force": [0, f"5*{pulse}"]}}
for label, extra in (("energy_momentum", []), ("energy decay 0.1", ["-dynamics_energy_decay", "0.1"])):
    h, _ = st.run("em_ancf_free" + ("_decay" if extra else ""), text(cable(strike, 0.5, 1e-3, every=5)), args=em + extra)
    t, T, S, W, p, H = read(h)
    after = t >= TP + 1e-12
    E = (T + S)[after]
    dE = np.ptp(E) / E.mean()
    dp = np.max(np.ptp(p[after], axis=0)) / np.max(np.abs(p[after].mean(axis=0)))
    dH = np.ptp(H[after]) / abs(H[after].mean())
    print(f"  free flight, {label}: after the pulse T + S varies by {dE:.2e} of itself ({E.mean():.4g} J), "
          f"p by {dp:.2e}, H by {dH:.2e} (H = {H[after].mean():.4g})")
    st.check(dp < 1e-11 and dH < 1e-11, f"free flight, {label}: momenta constant (p {dp:.2e}, H {dH:.2e})")
    if not extra:
        st.check(dE < 1e-11, f"free flight: T + S varies by {dE:.2e} of itself (expected < 1e-11)")
    else:
        steps = np.diff(E)
        lost = 1 - E[-1] / E[0]
        print(f"    decay: lost {lost:.2e} of T + S after the pulse, largest row-to-row change {steps.max():.2e} J")
        st.check(np.all(steps < 0), "energy decay: T + S lower at every written row after the pulse")

# 4. a user force law is refused, naming the field
uf = cable(strike, 0.01, 1e-3, extra_set={"axialForceUserFunction": "physicsAxialStiffness*axialStrain"})
_, out = st.run("em_ancf_userfunction", text(uf), args=em, expect_exit=2)
print("  " + next((l for l in out.splitlines() if "error" in l), out.strip()))
st.check("axialForceUserFunction" in out and "energy_momentum" in out, "user force law: the refusal names the field")
st.done()
