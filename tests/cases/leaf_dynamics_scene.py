"""The steel leaf cantilever (1 m x 20 mm x 2 mm) of the accuracy studies in time, shared by
test_accuracy_time_reuse and scripts/study_accuracy_time_reuse.py: generalized-alpha rho = 0.9 to half
the first period T1 from dt = T1 / 40 (20 steps), written every other step."""
import numpy as np

import beamtools as bt

L, W, T = 1.0, 0.02, 0.002
SEC = bt.rect_section(W, T)
T1 = 2 * np.pi / (1.875104068711961 ** 2 * np.sqrt(SEC["EIy"] / (7800 * SEC["A"] * L ** 4)))
STEPS0 = 20  # time steps of level 0


def leaf(title, force, nbeams):
    dyn = {"tend": T1 / 2, "dt": T1 / 40, "spectral_radius": 0.9, "output_every": 2}
    return bt.yaml_text({"title": title, "nodes": [[0, 0, 0], [L, 0, 0]], "elements": [[1, 2]],
                         "nprops": {1: {"fix": True}, 2: {"force": [0, force, 0]}},
                         "eprops": [bt.beam_set([1], W, T, dens=7800, nbeams=nbeams)],
                         "opt": {"calccompl": False, "calcfreq": False, "dynamics": dyn}})


def smooth_large(nbeams=4):
    """A tip force rising smoothly over T1 / 2 to 0.3 x 3 EI / L^3: large motion, the tip turns by 0.4 rad."""
    F = 0.3 * 3 * SEC["EIy"] / L ** 3
    return leaf("leaf, smooth tip load", f"{F!r} * smoothstep(t, 0, {T1 / 2!r}, 0, 1)", nbeams)


def step_response(nbeams=1):
    """test_accuracy_dynamics's step response: a tip force 1e-5 x 3 EI / L^3 from t = 0 (linear range)."""
    return leaf("leaf step response", 1e-5 * 3 * SEC["EIy"] / L ** 3, nbeams)
