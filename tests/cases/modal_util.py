"""Scene builders shared by the eigenvalue system tests (frequencies, buckling, state-space)."""
import json
import re

import numpy as np

E, G, RHO = 210e9, 80e9, 7800.0
BETA_L = np.array([1.87510407, 4.69409113, 7.85475744, 10.99554073, 14.13716839])  # reference B3


def yaml_text(scene):
    """JSON is YAML; node numbers of nprops must stay integer keys ({1: ...}, not {"1": ...})."""
    return re.sub(r'"(\d+)":', r"\1:", json.dumps(scene, indent=1))


def beam_x(length, width, thick, nbeams, nprops, dens=RHO, flex=(1, 2, 3, 4, 5, 6), opt=None, extra_nodes=(),
           extra_elements=()):
    """A straight rect-section beam from (0,0,0) to (length,0,0); width along y, thickness along z
    (the compliant bending plane is x-z). Nodes 1, 2 are its ends; extra nodes/elements (rigid,
    massless) follow."""
    eset = {"elems": [1], "flex": list(flex), "emod": E, "smod": G, "cshape": "rect", "dim": [width, thick],
            "orien": [0, 1, 0], "nbeams": nbeams}
    if dens:
        eset["dens"] = dens
    o = {"loadsteps": 1, "calccompl": False}
    o.update(opt or {})
    return yaml_text({"title": "beam", "nodes": [[0, 0, 0], [length, 0, 0]] + list(extra_nodes),
                      "elements": [[1, 2]] + list(extra_elements), "nprops": nprops, "eprops": [eset], "opt": o})


def cantilever_hz(length, width, thick, n=5):
    """B3: f_n = (beta_n L)^2 sqrt(EI / (rho A L^4)) / (2 pi), bending in the compliant plane."""
    A, I = width * thick, width * thick**3 / 12
    return BETA_L[:n] ** 2 * np.sqrt(E * I / (RHO * A * length**4)) / (2 * np.pi)
