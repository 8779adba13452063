"""The free steel beam of the energy-momentum tests (test_dynamics_energy_momentum*.py; docs/dynamics.md,
"Energy-momentum scheme"): 1 m, 20 x 10 mm, n elements, lumped mass, no supports, a 0.1 s sin^2 pulse
of force and moment at node 1, then free flight at dt = 0.01 s (omega h ~ 415 with 4 elements)."""
import numpy as np

import beamtools as bt
import sinewtest as st

tp = 0.1
pulse = f"(t < {tp} ? sin(pi*t/{tp})^2 : 0)"
F0, M0 = [0, 4, 1], [0.2, -0.4, 1.2]


def scene(n, tend, every, flex=(1, 2, 3, 4, 5, 6)):
    nodes, elems = bt.chain([0, 0, 0], [1, 0, 0], n)
    return bt.yaml_text({
        "title": "stiff steel free beam", "nodes": nodes, "elements": elems,
        "nprops": {1: {"force": [f"{f}*{pulse}" for f in F0], "moment": [f"{m}*{pulse}" for m in M0]}},
        "eprops": [bt.beam_set(list(range(1, n + 1)), 0.02, 0.01, flex=flex, dens=7800)],
        "opt": {"calcfreq": False, "calccompl": False,
                "dynamics": {"tend": tend, "dt": 0.01, "spectral_radius": 1.0, "output_every": every}}})


args = ["-dynamics_energy", "-beam_mass", "lumped"]
em = ["-dynamics_scheme", "energy_momentum"]


def load(name, text, extra, np_=1, mass="lumped"):
    """Runs the scene with -dynamics_energy and -beam_mass `mass` (None: not given) plus `extra`; the
    free flight's relative drifts dE (T + S), dH, dp."""
    given = ["-beam_mass", mass] if mass else []
    h5, out = st.run(name, text, np_=np_, args=["-dynamics_energy"] + given + extra)
    with st.h5(h5) as f:
        r = {k: f[k][:] for k in ("time", "node/p", "energy/kinetic", "energy/strain", "momentum/linear",
                                  "momentum/angular")}
    a = r["time"] >= tp - 1e-12  # free flight after the pulse
    r["E"] = (r["energy/kinetic"] + r["energy/strain"])[a]
    H, p = r["momentum/angular"][a], r["momentum/linear"][a]
    r["dE"] = np.abs(r["E"] - r["E"][0]).max() / r["E"][0]
    r["dH"] = np.abs(H - H[0]).max() / np.linalg.norm(H[0])
    r["dp"] = np.abs(p - p[0]).max() / np.linalg.norm(p[0])
    return r, out


