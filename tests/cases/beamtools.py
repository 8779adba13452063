"""Shared pieces of the beam system tests (test_beam_*.py, test_core_*.py): section constants
computed independently of the C++ code (references B5, B6 of ../shared/references), scene
builders, rotation helpers."""
import math

import numpy as np

E = 210e9
G = 80e9


def rect_torsion_constant(s1, s2):
    """Reference B6: I_t of a rectangle with sides s1, s2."""
    a, b = 0.5 * min(s1, s2), 0.5 * max(s1, s2)
    s = sum(math.tanh(n * math.pi * b / (2 * a)) / n ** 5 for n in range(1, 400, 2))
    return (1 / 3) * (2 * a) ** 3 * (2 * b) * (1 - 192 / math.pi ** 5 * (a / b) * s)


def cowper_rect(E_=E, G_=G):
    """Cowper's (1966, J. Appl. Mech. 33) shear coefficient of a rectangle as SPACAR Light uses it:
    10 (1 + nu) / (12 + 11 nu), nu = E / (2 G) - 1 (0.8497 for 210/80 GPa, not 5/6)."""
    nu = E_ / (2 * G_) - 1
    return 10 * (1 + nu) / (12 + 11 * nu)


def rect_section(w, t, E_=E, G_=G):
    """Stiffnesses of a rect section dim [w, t] (w along local y = orien, t along local z)."""
    A = w * t
    return dict(EA=E_ * A, EIy=E_ * w * t ** 3 / 12, EIz=E_ * t * w ** 3 / 12,
                GIt=G_ * rect_torsion_constant(w, t), kGA=G_ * cowper_rect(E_, G_) * A, A=A)


def beam_set(elems, w, t, flex=(1, 2, 3, 4, 5, 6), nbeams=1, orien=(0, 0, 1), **extra):
    s = {"elems": list(elems), "flex": list(flex), "emod": E, "smod": G, "cshape": "rect",
         "dim": [w, t], "orien": list(orien), "nbeams": nbeams}
    s.update(extra)
    return s


def chain(x0, x1, n, first=1):
    """n equal elements from x0 to x1: (nodes, elements) with 1-based numbers starting at first."""
    x0, x1 = np.asarray(x0, float), np.asarray(x1, float)
    nodes = [list(x0 + (x1 - x0) * i / n) for i in range(n + 1)]
    elems = [[first + i, first + i + 1] for i in range(n)]
    return nodes, elems


def rotvec_matrix(v):
    """exp(skew(v)) (Rodrigues)."""
    v = np.asarray(v, float)
    th = np.linalg.norm(v)
    if th == 0:
        return np.eye(3)
    k = v / th
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(th) * K + (1 - math.cos(th)) * K @ K


def rotation_vector(Rm):
    """The rotation vector of a rotation matrix (inverse of rotvec_matrix, angles below pi)."""
    a = np.arccos(np.clip((np.trace(Rm) - 1) / 2, -1, 1))
    vv = np.array([Rm[2, 1] - Rm[1, 2], Rm[0, 2] - Rm[2, 0], Rm[1, 0] - Rm[0, 1]])
    return vv / 2 if a < 1e-12 else a / (2 * np.sin(a)) * vv


def max_relative(a, b):
    """max |a - b| / max |b|."""
    return np.max(np.abs(a - b)) / np.max(np.abs(b))


def quat_matrix(q):
    """Rotation matrix of a unit quaternion [w, x, y, z]."""
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def _plain(v):
    if isinstance(v, dict):
        return {(int(k) if isinstance(k, str) and k.isdigit() else k): _plain(x) for k, x in v.items()}
    if isinstance(v, (list, tuple, np.ndarray)):
        return [_plain(x) for x in v]
    if isinstance(v, (np.floating, np.integer)):
        return v.item()
    return v


def yaml_text(scene):
    """Scene dict -> YAML text (node numbers as integer keys, numpy values as plain numbers)."""
    import yaml
    return yaml.safe_dump(_plain(scene), default_flow_style=None, sort_keys=False)


def leaf_pulse_scene(dynamics, title="leaf, tip force pulse then free vibration"):
    """The steel leaf (1 m x 20 mm x 2 mm, 4 elements) clamped at node 1 and struck at its tip by
    40 sin^2(pi t / 0.005) N for 5 ms (test_dynamics_adaptive, test_restart_dynamics_damping);
    `dynamics` is the body of opt.dynamics (e.g. "tend: 0.3, dt: 1e-3, spectral_radius: 0.6")."""
    return f"""title: {title}
nodes: [[0, 0, 0], [1, 0, 0]]
elements: [[1, 2]]
nprops:
  1: {{fix: true}}
  2: {{force: [0, "40*sin(pi*t/0.005)^2*step(0.005 - t)", 0]}}
eprops:
  - {{elems: [1], flex: [1, 2, 3, 4, 5, 6], emod: 210e9, smod: 80e9, dens: 7800, cshape: rect,
     dim: [0.02, 0.002], orien: [0, 0, 1], nbeams: 4}}
opt:
  calccompl: false
  calcfreq: false
  dynamics: {{{dynamics}}}
"""
