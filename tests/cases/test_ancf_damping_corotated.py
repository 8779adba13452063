"""Stiffness-proportional damping on the strain rates of ANCF cables (-stiffness_damping corotated, the
default; docs/dynamics.md "Damping"; issue 27), 2 ranks: rigid rotation is not damped, bending decays as
zeta = beta w / 2.

1. Rigid rotation. A free straight ANCF cable (1 m along x about the origin, 4 elements, EA = 1e5 N,
   EI = 10 N m^2, rhoA = 0.1 kg/m; lowest bending mode about 224 rad/s) spun up in its plane about z by
   nodal loads m_i a(t) e_z x x_i(t) on the positions (m_i: lumped shares; a(t) = a0 sin^2(pi t / T),
   T = 0.05 s, 20 rad/s after the pulse; x_i(t) turned by the angle of that rotation), then free to
   t = 0.3 s, dt = 1e-4, spectral radius 1, -dynamics_energy, beta for zeta = 0.3 at the bending mode.
   The loads are not those of a rigid rotation of the consistent mass (none on the slopes), so the cable
   vibrates during the pulse; beta damps that, and what remains is a steady rotation with its
   centrifugal stretch. From t = 0.2 s on the energy it dissipates (least-squares trend of T + S - W) is
   below 3e-12 of T and T + S - W varies by less than 1e-11 of T. The same run with -stiffness_damping
   initial (beta K0 of the start frame; one rank, to t = 0.1 s) loses its kinetic energy (checked
   > 1e-2 of T): the test fails if the option is ignored. With -dynamics_scheme energy_momentum (one
   rank; beta in the step force) the steady rotation keeps T + S - W to 3e-12 of T.
2. Bending decay. The cable as a cantilever (clamp x, y, slope_y at node 1), a tip load of 0.01 N from
   rest (linear: 3.3e-4 m), beta = 2 zeta / w1 with zeta = 0.02, w1 = 3.516 sqrt(EI / rhoA) / L^2,
   dt = T1/200, 5 periods: the tip deflection after the first period fitted by
   u_s + exp(-s t) (a cos w t + b sin w t); the damping ratio s / sqrt(s^2 + w^2) against
   beta sqrt(s^2 + w^2) / 2 (tolerance 1e-2).
MEASURED (2026-11-27, 16 .. 61 s on a loaded machine): from 0.15 to 0.25 s T + S - W varies by 5.9e-12 of T
(2.109 J), trend -5.9e-12 (a gain: round-off of the trapezoidal rule on the rotating cable, of either sign;
the undamped run varies by 1.7e-9, the midpoint rule's trend 4.4e-13), S by 2.1e-15 of T; energy_momentum:
varies by 4.8e-13, trend -8.4e-15 (undamped energy_momentum: 7.6e-13, keeping its vibration); initial: kinetic
energy 3.7e-8 J at 0.1 s (lost 1.00); cantilever w = 35.149 rad/s, zeta 0.019986 against beta w / 2
0.019994: -3.7e-4 (fit rms 6.6e-5)."""
import math

import numpy as np
from scipy.optimize import least_squares

import sinewtest as st
from ancf_scenes import text

L, EA, EI, rhoA = 1.0, 1e5, 10.0, 0.1
n_el = 4
xs = [-0.5 + L * k / n_el for k in range(n_el + 1)]
w_bend = 22.373 * math.sqrt(EI / rhoA) / L ** 2  # free-free lowest bending mode

T, w_end = 0.05, 20.0
a0 = 2 * w_end / T
alpha = f"(t < {T} ? {a0}*(sin(pi*t/{T}))^2 : 0)"
phi = f"({a0}*(t^2/4 - {T ** 2 / (8 * math.pi ** 2)!r}*(1 - cos(2*pi*t/{T}))))"
TEND, TEND_K0, STEADY = 0.25, 0.1, 0.15


def cable_set():
    return {"elems": list(range(1, n_el + 1)), "type": "ancf_cable2d", "physicsMassPerLength": rhoA,
            "physicsBendingStiffness": EI, "physicsAxialStiffness": EA}


def dyn(tend, dt, beta, every):
    return {"calccompl": False, "calcfreq": False,
            "dynamics": {"tend": tend, "dt": dt, "spectral_radius": 1.0, "output_every": every,
                         "stiffness_proportional_damping": float(beta)}}


def spinning(beta, tend):
    nprops = {}
    le = L / n_el
    for i, x in enumerate(xs):
        m = rhoA * le * (0.5 if i in (0, n_el) else 1.0)
        fx = f"{m!r}*{alpha}*(-({x!r})*sin{phi})"
        fy = f"{m!r}*{alpha}*(({x!r})*cos{phi})"
        nprops[i + 1] = {"force": [fx, fy]}
    return {"title": "free ANCF cable spun up about z", "nodes": [[x, 0.0] for x in xs],
            "elements": [[k + 1, k + 2] for k in range(n_el)], "nprops": nprops, "eprops": [cable_set()],
            "opt": dyn(tend, 2e-4, beta, 25)}


def energies(name, scene, extra=(), np_=2):
    h, _ = st.run(name, text(scene), args=["-dynamics_energy"] + list(extra), np_=np_)
    with st.h5(h) as f:
        return f["time"][:], f["energy/kinetic"][:], f["energy/strain"][:], f["energy/external_work"][:]


beta = 2 * 0.3 / w_bend
t, Tk, S, W = energies("ancfdamp_spin", spinning(beta, TEND))
late = t >= STEADY - 1e-12
Tm = Tk[late].mean()
E_ = (Tk + S - W)[late] / Tm
dE = np.ptp(E_)
tl = t[late] - t[late][0]
lost = -np.polyfit(tl, E_, 1)[0] * tl[-1]
print(f"  free ANCF cable, corotated beta = {beta:.3e} s: from t = {STEADY} to {TEND} s T + S - W varies by {dE:.2e} "
      f"of T, its trend loses {lost:.2e} of T (T = {Tm:.6g} J, S = {S[late].mean():.3e} J varies by "
      f"{np.ptp(S[late]) / Tm:.1e} of T)")
st.check(abs(lost) < 1e-11, f"steady rotation dissipates {lost:.2e} of T with corotated damping (expected |.| < 1e-11)")
st.check(dE < 2e-11, f"T + S - W varies by {dE:.2e} of T in steady rotation (expected < 2e-11)")
# the same with the energy-momentum scheme (beta in the step force as beta EA (eps1 - eps0)/h, ...; one rank)
te, Te, Se, We = energies("ancfdamp_spin_em", spinning(beta, TEND), ["-dynamics_scheme", "energy_momentum"], np_=1)
late_e = te >= STEADY - 1e-12
Ee = (Te + Se - We)[late_e] / Te[late_e].mean()
tle = te[late_e] - te[late_e][0]
lost_e = -np.polyfit(tle, Ee, 1)[0] * tle[-1]
print(f"  energy_momentum with corotated beta: T + S - W varies by {np.ptp(Ee):.2e} of T, its trend loses {lost_e:.2e}")
st.check(abs(lost_e) < 3e-12 and np.ptp(Ee) < 3e-12,
         f"energy_momentum: steady rotation loses {lost_e:.2e} of T, varies by {np.ptp(Ee):.2e} (expected < 3e-12)")
t0, T0, S0, W0 = energies("ancfdamp_spin_k0", spinning(beta, TEND_K0), ["-stiffness_damping", "initial"], np_=1)
lost0 = 1 - T0[-1] / Tm
print(f"  -stiffness_damping initial: kinetic energy at t = {TEND_K0} s {T0[-1]:.3e} J, lost {lost0:.2e} of the "
      f"corotated run's T")
st.check(lost0 > 1e-2, f"-stiffness_damping initial: expected the rotation damped, lost {lost0:.2e}")

# ---------------------------------------------------------------- 2. bending decay of a cantilever
zeta = 0.02
w1 = 3.516 * math.sqrt(EI / rhoA) / L ** 2
beta1 = 2 * zeta / w1
T1 = 2 * math.pi / w1
cant = {"title": "ANCF cantilever, bending decay", "nodes": [[0.0, 0.0], [L, 0.0]], "elements": [[1, 2]],
        "nprops": {1: {"fix_coords": [1, 1, 0, 1]}, 2: {"force": [0.0, -0.01]}},
        "eprops": [dict(cable_set(), elems=[1], nbeams=8)], "opt": dyn(4 * T1, T1 / 100, beta1, 1)}
h, _ = st.run("ancfdamp_decay", text(cant))
with st.h5(h) as f:
    tt = f["time"][:]
    u = f["node/p"][:, 1, 1] - f["node/p0"][1, 1]
keep = tt >= T1
tt, u = tt[keep] - T1, u[keep]
us = u[-1]
U = u / us


def model(p):
    return p[0] + np.exp(-p[1] * tt) * (p[2] * np.cos(p[3] * tt) + p[4] * np.sin(p[3] * tt))


m = U.mean()
p = least_squares(lambda x: model(x) - U, [m, zeta * w1, U[0] - m, w1, 0.0]).x
rms = np.sqrt(np.mean((model(p) - U) ** 2))
wn = math.hypot(p[1], p[3])
zm, zp = p[1] / wn, beta1 * wn / 2
print(f"  cantilever: beta = {beta1:.4e} s, w = {wn:.6g} rad/s (Euler-Bernoulli {w1:.6g}), zeta measured {zm:.6f} "
      f"against beta w / 2 = {zp:.6f}: {zm / zp - 1:.2e} (fit rms {rms:.1e})")
st.check(abs(zm / zp - 1) < 1e-2, f"cantilever: damping ratio {zm:.5f} against beta w / 2 = {zp:.5f}")
st.done()
