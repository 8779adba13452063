"""The spin-up of a flexible beam by a prescribed hub rotation (Kane, Ryan & Banerjee 1987; Simo & Vu-Quoc
1988, Example 5.1; docstring of test_dynamics_spinup.py), the published curves it is compared with and the
4-mode reference model; shared by test_dynamics_spinup.py, test_dynamics_spinup_newton.py and
scripts/study_spinup.py."""
import math

import numpy as np

import beamtools as bt

L, EA, EI, rhoA = 10.0, 2.8e7, 1.4e4, 1.2
Om, Ts = 6.0, 15.0
a = math.sqrt(12 * EI / EA)  # the square section that gives EA and EI with E = 4.67e9 Pa, rho = 200 kg/m^3
A = a * a
theta_expr = f"t < {Ts} ? ({Om}/{Ts})*(t^2/2 + ({Ts}/(2*pi))^2*(cos(2*pi*t/{Ts}) - 1)) : {Om}*(t - {Ts}/2)"

# Simo & Vu-Quoc 1988 (CMAME 66, 125-161), Example 5.1, their figures of the tip's displacement relative to
# the rigidly rotating beam, as digitized in the repository hortulanusT/dynLattice (tests/transient/
# ref_data/test1_ref_u2.csv at commit 68e0403816f268de146e6e42839e754858d9f014 and test1_ref_u1.csv at
# commit e410bac1ab694154be78b99d52e055ea0e4c83ed; tests/transient/test1.py there plots them as
# "Simo, Vu-Quoc 1988"): columns t [s] and the displacement [m], transverse (u2, along the rotating
# frame's y axis) and axial (u1, along the beam's rotated axis); read to 5 digits.
SIMO_VUQUOC_U2 = np.array([
    [-0.0093302, -9.5326e-05], [0.11136, 0.0001474], [0.25, -0.00021584], [0.5, -0.0023037], [0.7495, -0.0090267],
    [0.99417, -0.02402], [1.0549, -0.028116], [1.1845, -0.037274], [1.25, -0.044582], [1.5, -0.067548],
    [1.75, -0.089471], [2, -0.11139], [2.25, -0.1354], [2.5, -0.16098], [2.75, -0.19073], [2.9426, -0.21628],
    [3.1064, -0.23881], [3.25, -0.25963], [3.4968, -0.28742], [3.75, -0.32644], [3.9953, -0.35561], [4.133, -0.3761],
    [4.25, -0.39221], [4.5, -0.42248], [4.75, -0.45275], [5, -0.47885], [5.25, -0.49868], [5.5, -0.51591],
    [5.75, -0.53053], [6, -0.54618], [6.25, -0.56028], [6.5, -0.56967], [6.75, -0.57228], [7, -0.56863],
    [7.25, -0.56393], [7.5, -0.55819], [7.75, -0.55088], [8, -0.54149], [8.25, -0.52426], [8.5, -0.50286],
    [8.75, -0.47937], [9, -0.45588], [9.25, -0.43449], [9.5, -0.411], [9.7438, -0.38413], [9.9226, -0.36009],
    [10.146, -0.3333], [10.251, -0.32078], [10.5, -0.29617], [10.75, -0.26955], [11, -0.2424], [11.25, -0.21631],
    [11.5, -0.18864], [11.75, -0.16098], [12, -0.13958], [12.25, -0.12027], [12.5, -0.098866], [12.75, -0.077466],
    [13, -0.057109], [13.25, -0.043538], [13.5, -0.033621], [13.712, -0.024496], [13.893, -0.017625],
    [14.053, -0.0091176], [14.251, 0.00024373], [14.501, 0.0059645], [14.751, 0.0054633], [15, 0.00032691],
    [15.25, -0.0017609], [15.5, -0.00023664], [15.751, 0.0054425], [16.001, 0.0054425], [16.25, 0.0013916],
    [16.5, -0.0012182], [16.75, -0.001239], [17, 0.0033963], [17.251, 0.0064656], [17.5, 0.0049413],
    [17.75, 0.00032691], [18, -0.001239], [18.25, 0.0033963], [18.501, 0.0064864], [18.751, 0.0070084],
    [19, 0.0023732], [19.25, -0.0017193], [19.5, -0.0012182], [19.75, 0.0033963], [20, 0.0044818],
    [20.25, 0.0039598], [20.5, 0.00082807], [20.75, -0.0007378], [21, -0.00021584], [21.25, 0.0034379],
    [21.5, 0.0034379], [21.75, 0.0034379], [22, -0.00021584], [22.25, 0.00030611], [22.5, 0.0029159],
    [22.75, 0.0044818], [23, 0.0029159], [23.25, 0.00082807], [23.5, -0.0012598], [23.75, -0.0007378],
    [24, 0.0023939], [24.25, 0.0039598], [24.5, 0.0029159], [24.75, 0.00082807], [25, -0.0017817],
    [25.25, -0.00021584], [25.5, 0.0029159], [25.75, 0.0044818], [26, 0.0029159], [26.25, 0.00030611],
    [26.5, 0.00030611], [26.75, 0.0023939], [27, 0.0044818], [27.25, 0.0044818], [27.5, 0.00135],
    [27.75, -0.00021584], [28, 0.00082807], [28.25, 0.0044818], [28.5, 0.0050037], [28.75, 0.0044818],
    [29, 0.00030611], [29.25, -0.0007378], [29.5, 0.001872], [29.637, 0.0057811], [29.75, 0.0097013]
])
SIMO_VUQUOC_U1 = np.array([
    [0.0025667, -1.1715e-05], [0.5, -3.8696e-05], [1, -5.4472e-05], [1.4992, -0.00028501], [1.9977, -0.00074609],
    [2.4873, -0.0016102], [2.7551, -0.0023306], [3, -0.0032413], [3.5, -0.005024], [3.8957, -0.0068844],
    [4.1043, -0.0079437], [4.4087, -0.0096296], [4.5782, -0.010878], [4.8826, -0.012564], [5.1043, -0.013655],
    [5.5, -0.015389], [6, -0.017408], [6.4999, -0.018685], [7.0001, -0.018593], [7.5261, -0.017724], [8, -0.016477],
    [8.4348, -0.014394], [8.6304, -0.01326], [9, -0.011319], [9.3957, -0.0095348], [9.7258, -0.0079617],
    [10.117, -0.0060349], [10.487, -0.004519], [10.974, -0.0029076], [11.381, -0.0018354], [11.527, -0.0014865],
    [11.998, -0.00060919], [12.5, -5.6507e-05], [13.002, 0.00032772], [13.502, 0.00048447], [14, 0.00049769],
    [14.5, 0.00049566], [15, 0.00049566], [15.5, 0.00049668], [16, 0.00049769], [16.5, 0.00049769], [17, 0.00051042],
    [17.5, 0.00051042], [18, 0.00051042], [18.5, 0.00051042], [19, 0.00052721], [19.5, 0.00052925], [20, 0.00052721],
    [20.5, 0.00052721], [21, 0.00052925], [21.5, 0.00051347], [21.998, 0.00054145], [22.5, 0.00054502],
    [23, 0.00052925], [23.5, 0.00052925], [24, 0.00052925], [24.5, 0.00052925], [25, 0.00052925], [25.5, 0.00052925],
    [26, 0.00052925], [26.5, 0.00054502], [27, 0.0005608], [27.5, 0.0005608], [28, 0.00054502], [28.5, 0.0005608],
    [29, 0.00052925], [29.5, 0.0005608]
])


def scene(title, spectral_radius, tend=20.0, dt=0.02, nbeams=10, output_every=10):
    """The beam from the hub at the origin along x, 10 beams; node 2 is the tip."""
    return {"title": title, "nodes": [[0, 0, 0], [L, 0, 0]], "elements": [[1, 2]],
            "nprops": {1: {"fix_pos": True, "rot": [theta_expr, 0, 0, 1]}},
            "eprops": [dict(bt.beam_set([1], a, a, nbeams=nbeams), emod=EA / A, smod=EA / A / 2.6, dens=rhoA / A)],
            "opt": {"calcfreq": False, "calccompl": False,
                    "dynamics": {"tend": tend, "dt": dt, "spectral_radius": spectral_radius,
                                 "output_every": output_every}}}


def theta(tt):
    """The hub angle."""
    return np.where(tt < Ts, (Om / Ts) * (tt ** 2 / 2 + (Ts / (2 * np.pi)) ** 2 * (np.cos(2 * np.pi * tt / Ts) - 1)),
                    Om * (tt - Ts / 2))


def rotating_frame(t, tip):
    """The tip's displacement from the rigidly rotating beam: transverse v and axial u (tip: positions, rows t)."""
    c, s = np.cos(theta(t)), np.sin(theta(t))
    return -s * tip[:, 0] + c * tip[:, 1], c * tip[:, 0] + s * tip[:, 1] - L


def digitized_difference(t, x, curve):
    """The history x(t) against a digitized curve at its points within t: RMS and largest difference."""
    inside = (curve[:, 0] >= t[0]) & (curve[:, 0] <= t[-1])
    d = np.interp(curve[inside, 0], t, x) - curve[inside, 1]
    return float(np.sqrt(np.mean(d ** 2))), float(np.abs(d).max())


def kane_model(n, stiffening=True, t_end=20.0, h=1e-3):
    """Tip deflection of Kane's linearized theory: n cantilever modes in the rotating frame,
    rhoA (w'' + alpha x - Omega^2 w) + EI w'''' - (T w')' = 0, T = rhoA Omega^2 (L^2 - x^2)/2 (RK4, step h)."""
    bl = [1.8751040687, 4.6940911330, 7.8547574382, 10.9955407349][:n]
    x = np.linspace(0, L, 4001)
    ph, dph = [], []
    for b in bl:
        k = b / L
        sg = (math.cosh(b) + math.cos(b)) / (math.sinh(b) + math.sin(b))
        ph.append(np.cosh(k * x) - np.cos(k * x) - sg * (np.sinh(k * x) - np.sin(k * x)))
        dph.append(k * (np.sinh(k * x) + np.sin(k * x) - sg * (np.cosh(k * x) - np.cos(k * x))))
    ph, dph = np.array(ph), np.array(dph)
    M = np.array([[np.trapz(rhoA * ph[i] * ph[j], x) for j in range(n)] for i in range(n)])
    K = np.diag([(b / L) ** 4 * EI * np.trapz(ph[i] ** 2, x) for i, b in enumerate(bl)])
    KT = np.array([[np.trapz(rhoA * (L * L - x * x) / 2 * dph[i] * dph[j], x) for j in range(n)] for i in range(n)])
    fa = np.array([np.trapz(rhoA * x * ph[i], x) for i in range(n)])
    Mi = np.linalg.inv(M)

    def rhs(tt, y):
        w = (Om / Ts) * (tt - Ts / (2 * math.pi) * math.sin(2 * math.pi * tt / Ts)) if tt < Ts else Om
        al = (Om / Ts) * (1 - math.cos(2 * math.pi * tt / Ts)) if tt < Ts else 0.0
        Keff = K + w * w * ((KT if stiffening else 0.0) - M)
        return np.concatenate([y[n:], Mi @ (-Keff @ y[:n] - al * fa)])

    ts, y, wt = np.arange(0.0, t_end + 1e-12, h), np.zeros(2 * n), [0.0]
    for tt in ts[:-1]:
        k1 = rhs(tt, y)
        k2 = rhs(tt + h / 2, y + h / 2 * k1)
        k3 = rhs(tt + h / 2, y + h / 2 * k2)
        k4 = rhs(tt + h, y + h * k3)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        wt.append(ph[:, -1] @ y[:n])
        if abs(wt[-1]) > 1e3:
            break
    return ts[:len(wt)], np.array(wt)
