"""Loads and prescribed motions as functions of time in beam dynamics (docs/dynamics.md, "Loads and
motions as functions of time"; 2 ranks). One scene, three 1 m beams (20 x 20 mm, linear: 1e-3
amplitudes), each reduced by supports to one degree of freedom with a closed-form response
x'' + w0^2 x = B sin(w t) from rest, x = B / (w0^2 - w^2) (sin w t - (w / w0) sin w0 t):
- A, prescribed motion: node 1 moves by displ_x = A sin(w t), node 2 slides along the axis (dens
  7800, so the beam's consistent axial mass rhoA L [1/3 1/6; 1/6 1/3] couples the prescribed
  acceleration): m22 x'' + k x = k f - m21 f''. Without the prescribed acceleration's term the
  response differs by 15 % (computed below), so ignoring it fails.
- B, time-dependent load: a massless beam, node 4 with mass 2 kg and force_x = F0 sin(w t).
- C, prescribed rotation: node 5 turns by rot = [phi0 sin(w t), 1, 0, 0] (fixed axis x), node 6
  (mominertia 1e-4 kg m^2) twists through the beam's torsion (rho Ip L/6 couples the prescribed
  angular acceleration).
w0 = 2 pi 5 rad/s (moduli chosen for it), w = 2 pi 3 rad/s, rho_inf = 1, dt = 2e-3, 0.4 s.
Measured max error / amplitude: A 1.6e-3, B 9.0e-4, C 1.6e-3 (dt = 1e-3: 4.1e-4, 2.2e-4, 4.1e-4:
second order, the trapezoidal rule's phase error). The reaction at node 1 (dynamic: with M qdd)
equals m11 f'' + m12 x'' + k (f - x) of the closed form to 2.3e-3 of its amplitude (1e-3 step:
5.8e-4). 1 vs 2 ranks: identical to 1e-9 (measured below). A run stopped after 11 written rows
(t = 0.2) on 2 ranks and continued on 1 equals the uninterrupted run (the time functions continue).
Field validation: an expression with a syntax error or a force-law argument exits 2 naming the field."""
import math

import numpy as np

import beamtools as bt
import sinewtest as st
from restartutil import compare, restarted, stopped

a, L, rho = 0.02, 1.0, 7800.0
A = a * a
m = rho * A * L
m22, m21 = m / 3, m / 6
w0, w = 2 * math.pi * 5, 2 * math.pi * 3
k = w0 ** 2 * m22
E = k * L / A
Ip, It, J = a ** 4 / 6, bt.rect_torsion_constant(a, a), 1e-4
Jt = J + rho * Ip * L / 3
kt = w0 ** 2 * Jt
G = kt * L / It
Am, F0, phi0, mB = 1e-3, 1.0, 1e-3, 2.0
dt, tend = 2e-3, 0.4


def scene(nprops_extra=None):
    nprops = {1: {"fix_y": True, "fix_z": True, "fix_orien": True, "displ_x": f"{Am}*sin({w}*t)"},
              2: {"fix_y": True, "fix_z": True, "fix_orien": True},
              3: {"fix": True},
              4: {"fix_y": True, "fix_z": True, "fix_orien": True, "mass": mB, "force": [f"{F0}*sin({w}*t)", 0, 0]},
              5: {"fix_pos": True, "rot": [f"{phi0}*sin({w}*t)", 1, 0, 0]},
              6: {"fix_pos": True, "mominertia": [J, 0, 0, J, 0, J]}}
    for n, p in (nprops_extra or {}).items():
        nprops[n].update(p)
    return bt.yaml_text({
        "title": "time functions",
        "nodes": [[0, 0, 0], [L, 0, 0], [0, 1, 0], [L, 1, 0], [0, 2, 0], [L, 2, 0]],
        "elements": [[1, 2], [3, 4], [5, 6]],
        "nprops": nprops,
        "eprops": [dict(bt.beam_set([1], a, a), emod=E, smod=1e12, dens=rho),
                   dict(bt.beam_set([2], a, a), emod=E, smod=1e12),
                   dict(bt.beam_set([3], a, a), emod=1e12, smod=G, dens=rho)],
        "opt": {"calcfreq": False, "calccompl": False,
                "dynamics": {"tend": tend, "dt": dt, "spectral_radius": 1.0, "output_every": 10}}})


def resp(B, W0, t):
    return B / (W0 ** 2 - w ** 2) * (np.sin(w * t) - w / W0 * np.sin(W0 * t))


text = scene()
h2, out = st.run("tfun2", text, np_=2)
h1, _ = st.run("tfun1", text, np_=1)
with st.h5(h2) as f, st.h5(h1) as g:
    t, p, ax, Fr = f["time"][:], f["node/p"][:], f["node/r_axang"][:], f["node/Freac"][:]
    st.check(len(t) == 21, "time functions: 21 written rows")
    d12 = max(np.abs(f["node/p"][:] - g["node/p"][:]).max(), np.abs(f["node/r_quat"][:] - g["node/r_quat"][:]).max())
    print(f"  1 vs 2 ranks: max difference of positions/quaternions {d12:.2e}")
    st.check(d12 < 1e-9, "time functions: 1 vs 2 ranks to 1e-9")
refA = resp((k * Am + m21 * Am * w ** 2) / m22, w0, t)
refB = resp(F0 / mB, math.sqrt(k / mB), t)
refC = resp((kt * phi0 + rho * Ip * L / 6 * phi0 * w ** 2) / Jt, w0, t)
uncoupledA = resp(k * Am / m22, w0, t)
uncoupledC = resp(kt * phi0 / Jt, w0, t)
print(f"  without the prescribed accelerations' inertia A would differ by "
      f"{np.abs(uncoupledA - refA).max() / np.abs(refA).max():.3f}, C by {np.abs(uncoupledC - refC).max() / np.abs(refC).max():.3f}")
st.close(p[:, 0, 0], Am * np.sin(w * t), atol=1e-15, what="A: prescribed node 1 follows displ_x(t)")
st.close(p[:, 1, 0] - L, refA, rtol=2.5e-3, what="A: node 2 (prescribed base motion, consistent mass)")
st.close(p[:, 3, 0] - L, refB, rtol=1.5e-3, what="B: node 4 (force F0 sin(w t))")
st.close(ax[:, 4, 0] * ax[:, 4, 1], phi0 * np.sin(w * t), atol=1e-15, what="C: prescribed node 5 follows rot(t)")
st.close(ax[:, 5, 0] * ax[:, 5, 1], refC, rtol=2.5e-3, what="C: node 6 twist (prescribed hub rotation)")
# dynamic reaction at node 1: R = f_int - f_ext + M qdd = m11 f'' + m12 x2'' + k (f - x2)
f_ = Am * np.sin(w * t)
x2dd = (k * Am + m21 * Am * w ** 2) / m22 / (w0 ** 2 - w ** 2) * (-w ** 2 * np.sin(w * t) + w * w0 * np.sin(w0 * t))
R1 = m22 * (-w ** 2 * f_) + m21 * x2dd + k * (f_ - refA)
st.close(Fr[:, 0, 0], R1, rtol=3e-3, what="A: dynamic reaction at the prescribed node 1")

# restart: stopped on 2 ranks after 11 rows (t = 0.2), continued on 1
part = stopped("tfun_part2", text, 2, 11)
rest, _ = restarted("tfun_rest1", text, 1, part)
compare(h2, rest, "time functions 2 -> 1 (stopped at t = 0.2)", other_ranks=h1)

# validation: the field is named, exit 2
_, o = st.run("tfun_bad_syntax", scene({4: {"force": ["sin(2*pi*t", 0, 0]}}), expect_exit=2)
st.check("nprops(4).force(1)" in o, "a syntax error names nprops(4).force(1)")
_, o = st.run("tfun_bad_var", scene({1: {"displ_x": "0.001*axialStrain"}}), expect_exit=2)
st.check("nprops(1).displ_x" in o and "only use t" in o, "a force-law argument in a function of time names nprops(1).displ_x")
_, o = st.run("tfun_bad_rot", scene({5: {"rot": ["0.1*t", 0, 0]}}), expect_exit=2)
st.check("nprops(5).rot(1)" in o and "fixed axis" in o, "a rotation vector with a function names the entry")
st.done()
