"""The right-angle cantilever of Simo & Vu-Quoc 1988 (docstring of test_dynamics_right_angle.py) and the
published curve it is compared with; shared by that test and scripts/study_right_angle.py."""
import numpy as np

L = 10.0  # leg length; leg 1 along y from the clamp at the origin to the elbow, leg 2 along x to the tip

# The tip's out-of-plane displacement of Simo & Vu-Quoc 1988 (their figure) as digitized in
# FinEtoolsFlexStructures.jl, examples/beams/nonlin_transient/simo_vuquoc_examples.jl (array Aus, 45
# points; repository PetrKryslUCSD/FinEtoolsFlexStructures.jl, commit 2040cdace8418aa3f79321686c4a3a37921604ee):
# columns t, w_tip.
SIMO_VUQUOC_TIP = np.array([
    [0, 0], [0.94612, 0.025692], [1.5375, 0.92688], [2.3259, 2.3913], [3.0355, 3.6680], [3.8633, 5.0949],
    [4.5729, 6.3715], [5.1643, 7.2352], [5.8739, 8.0237], [6.5834, 8.3241], [7.4507, 8.0237], [8.2786, 6.7846],
    [8.8305, 5.6957], [9.2641, 4.4190], [9.8949, 2.6917], [10.329, 1.1522], [10.723, -0.53755], [11.275, -3.4664],
    [11.787, -5.5692], [12.260, -7.0711], [12.970, -7.9723], [13.758, -8.5356], [14.428, -9.2115], [15.059, -9.2115],
    [15.966, -8.4229], [16.873, -6.6581], [17.740, -4.3300], [18.568, -1.8893], [18.962, -0.086957], [19.632, 2.5791],
    [20.302, 4.4565], [20.894, 5.5079], [21.879, 6.5217], [22.746, 6.7846], [23.693, 6.2964], [24.481, 6.1462],
    [25.191, 6.6719], [25.821, 7.4980], [26.413, 6.9348], [26.965, 5.4704], [27.438, 4.1561], [27.792, 2.8419],
    [28.423, 1.2648], [29.409, 0.81423], [29.961, 0.73913]])

# Le, Battini & Hjiaj 2012, Fig. 3, extrema as read in a public verification code: tip maximum and
# minimum, elbow minimum and maximum (the latter the maximum over 0 .. 30 s).
LE_EXTREMA = {"tip maximum": 8.2, "tip minimum": -9.7, "elbow minimum": -4.0, "elbow maximum": 6.2}


def digitized_fit(t, tip, step):
    """The tip history (t, tip) against SIMO_VUQUOC_TIP at its points: the RMS difference as computed,
    the time shift in 0 .. 2 s (in steps of `step`) that fits best (the digitized axis leads), its RMS."""
    sv = SIMO_VUQUOC_TIP
    rms = {s: float(np.sqrt(np.mean((np.interp(sv[:, 0], t - s, tip) - sv[:, 1]) ** 2)))
           for s in np.round(np.arange(0.0, 2.0 + step / 2, step), 6)}
    best = min(rms, key=rms.get)
    return rms[0.0], float(best), rms[best]


def scene(n=10, dt=0.1, tend=30.0, output_steps="every:2"):
    """n beam elements per leg, generalized alpha with rho_inf = 1; node n + 1 is the elbow, 2 n + 1 the tip."""
    h = L / n
    d = np.sqrt(16e-3)
    inertia = np.pi * d ** 4 / 64
    E = 1e3 / inertia
    J1, J2 = np.diag([10.0, 20.0, 10.0]), np.diag([20.0, 10.0, 10.0])  # leg 1 along y, leg 2 along x

    def sym(J):
        return [float(J[0, 0]), 0.0, 0.0, float(J[1, 1]), 0.0, float(J[2, 2])]

    nodes = [[0.0, L * i / n, 0.0] for i in range(n + 1)] + [[L * i / n, L, 0.0] for i in range(1, n + 1)]
    nprops = {1: {"fix": True}}
    for k in range(2, 2 * n + 2):
        if k <= n:
            m, J = h, h * J1
        elif k == n + 1:
            m, J = h, h / 2 * (J1 + J2)
        elif k < 2 * n + 1:
            m, J = h, h * J2
        else:
            m, J = h / 2, h / 2 * J2
        nprops[k] = {"mass": float(m), "mominertia": sym(J)}
    nprops[n + 1]["force"] = [0, 0, "t < 1 ? 50*t : (t < 2 ? 50*(2 - t) : 0)"]
    return {"title": "right-angle cantilever (Simo & Vu-Quoc 1988)", "nodes": nodes,
            "elements": [[i + 1, i + 2] for i in range(2 * n)], "nprops": nprops,
            "eprops": [{"elems": list(range(1, 2 * n + 1)), "flex": [1, 2, 3, 4, 5, 6], "emod": float(E),
                        "smod": float(E / 2), "cshape": "circ", "dim": [float(d)]}],
            "opt": {"calcfreq": False, "calccompl": False, "output_steps": output_steps,
                    "dynamics": {"tend": tend, "dt": dt, "spectral_radius": 1.0}}}
