#!/usr/bin/python3
"""Each time scheme's energy error and cost per step, side by side (issue 27; docs/accuracy_dynamics.md,
block bench_dynamics_schemes; not a ctest).

Three hard cases, each run with every scheme that takes it (one process each, one rank, -dynamics_energy):
- stiff steel free beam (1 m, 20 x 10 mm, 4 elements, lumped mass: -beam_mass lumped for every scheme),
  a 0.1 s pulse of force and moment, then free flight at dt = 0.01 (highest axial omega h = 415) to
  t = 10 s (1000 steps): the energy error is max |T + S - (T + S)(0.1 s)| over the free flight, relative;
- slack cable pendulum: 8 cables (1 m, EA = 1e4 N, rhoA = 0.1 kg/m) and a 0.2 kg end mass released
  horizontal under gravity, dt = 2.5 ms to 1 s; energy error max |T + S - W - E(0)| / max T;
- membrane drum (4 x 4 quads, held edge, n0 = 1000 N/m, 1 kg/m^2) after a 5 ms centre force pulse,
  dt = 0.5 ms to 0.05 s; energy error of T + S after the pulse, relative.
Schemes: arnold_bruls (the default, Lie-group generalized alpha) at rho_inf = 1 and 0.6, midpoint,
energy_momentum, energy_momentum with -dynamics_energy_decay 0.1. Cost: the summary's `dynamics`
wall time per step and Newton iterations per step. A run that fails reports the time it reached.

usage: scripts/bench_dynamics_schemes.py [--doc]"""
import argparse
import os
import re
import subprocess
import sys
import time

import h5py
import numpy as np

import doc_tables

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
BUILD = os.path.join(SOURCE, "build")
WORK = os.path.join(BUILD, "study", "dynamics_schemes")
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_pml="ob1", OMPI_MCA_btl="self,vader")
SCHEMES = [("arnold_bruls, rho_inf 1", 1.0, []), ("arnold_bruls, rho_inf 0.6", 0.6, []),
           ("midpoint", 1.0, ["-dynamics_scheme", "midpoint"]),
           ("energy_momentum", 1.0, ["-dynamics_scheme", "energy_momentum"]),
           ("energy_momentum, decay 0.1", 1.0, ["-dynamics_scheme", "energy_momentum", "-dynamics_energy_decay", "0.1"])]


def yaml_of(scene):
    import json
    return json.dumps(scene, indent=1)


def free_beam(rho):
    n, tp = 4, 0.1
    pulse = f"(t < {tp} ? sin(pi*t/{tp})^2 : 0)"
    return {"title": "stiff steel free beam", "nodes": [[i / n, 0, 0] for i in range(n + 1)],
            "elements": [[i + 1, i + 2] for i in range(n)],
            "nprops": {1: {"force": [f"{f}*{pulse}" for f in (0, 4, 1)], "moment": [f"{m}*{pulse}" for m in (0.2, -0.4, 1.2)]}},
            "eprops": [{"elems": list(range(1, n + 1)), "flex": [1, 2, 3, 4, 5, 6], "emod": 210e9, "smod": 80e9, "dens": 7800,
                        "cshape": "rect", "dim": [0.02, 0.01], "orien": [0, 0, 1]}],
            "opt": {"calcfreq": False, "calccompl": False,
                    "dynamics": {"tend": 10.0, "dt": 0.01, "spectral_radius": rho, "output_every": 10}}}, tp


def cable_chain(rho):
    n = 8
    return {"title": "slack cable pendulum", "nodes": [[i / n, 0, 0] for i in range(n + 1)],
            "elements": [[i + 1, i + 2] for i in range(n)], "nprops": {1: {"fix": True}, n + 1: {"mass": 0.2}},
            "eprops": [{"elems": list(range(1, n + 1)), "type": "cable", "area": 1e-4, "emod": 1e8, "dens": 1000}],
            "opt": {"gravity": [0, 0, -9.81], "calcfreq": False,
                    "dynamics": {"tend": 1.0, "dt": 2.5e-3, "spectral_radius": rho, "output_every": 4}}}, None


def drum(rho):
    m, tp = 4, 0.005
    nodes = [[i / m, j / m, 0] for j in range(m + 1) for i in range(m + 1)]
    quads = [[j * (m + 1) + i + 1, j * (m + 1) + i + 2, (j + 1) * (m + 1) + i + 2, (j + 1) * (m + 1) + i + 1]
             for j in range(m) for i in range(m)]
    edge = [k + 1 for k, x in enumerate(nodes) if x[0] in (0, 1) or x[1] in (0, 1)]
    centre = (m // 2) * (m + 1) + m // 2 + 1
    return {"title": "drum, centre force pulse", "nodes": nodes, "elements": quads,
            "nprops": {**{k: {"fix": True} for k in edge}, centre: {"force": [0, 0, f"(t < {tp} ? 2*sin(pi*t/{tp})^2 : 0)"]}},
            "eprops": [{"elems": list(range(1, len(quads) + 1)), "type": "membrane", "thickness": 1e-3, "emod": 1e9,
                        "nu": 0.3, "dens": 1000, "prestress": [1e6, 1e6, 0]}],
            "opt": {"calcfreq": False, "dynamics": {"tend": 0.05, "dt": 5e-4, "spectral_radius": rho, "output_every": 2}}}, tp


CASES = [("stiff free beam (omega h 415), 1000 steps", free_beam, ["-beam_mass", "lumped"]),
         ("slack cable pendulum, 400 steps", cable_chain, []),
         ("membrane drum after a pulse, 100 steps", drum, [])]


def run(name, scene, flags):
    os.makedirs(WORK, exist_ok=True)
    path, h5 = os.path.join(WORK, name + ".yaml"), os.path.join(WORK, name + ".h5")
    with open(path, "w") as f:
        f.write(yaml_of(scene))
    p = subprocess.run([os.path.join(BUILD, "sinew"), path, "-o", h5, "-dynamics_energy"] + flags, env=ENV,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    m = re.search(r"dynamics ([0-9.]+) s \((\d+) Newton iterations\)", p.stdout)
    s = re.search(r"(\d+) of (\d+) steps", p.stdout)
    return p.returncode, float(m.group(1)) if m else float("nan"), int(m.group(2)) if m else 0, \
        int(s.group(1)) if s else 0, h5


def energy_error(h5, after, with_work):
    with h5py.File(h5, "r") as f:
        if "energy/kinetic" not in f:
            return float("nan"), float("nan")
        t, T, S, W = f["time"][:], f["energy/kinetic"][:], f["energy/strain"][:], f["energy/external_work"][:]
    if with_work:
        E = T + S - W
        return np.abs(E - E[0]).max() / T.max(), t[-1]
    a = t >= after - 1e-12
    E = (T + S)[a]
    return np.abs(E - E[0]).max() / E[0], t[-1]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--doc", action="store_true", help="write the table into docs/accuracy_dynamics.md")
    args = ap.parse_args()
    load = os.getloadavg()[0]
    t0 = time.perf_counter()
    lines = ["| case | scheme | energy error | steps done | Newton its/step | ms/step |", "|---|---|---|---|---|---|"]
    for title, build, extra in CASES:
        for label, rho, flags in SCHEMES:
            scene, after = build(rho)
            tag = re.sub(r"[^a-z0-9]+", "_", f"{title[:12]}_{label}".lower())
            code, secs, its, done, h5 = run(tag, scene, flags + extra)
            if done == 0 and code != 0:
                lines.append(f"| {title} | {label} | refused (exit {code}) | | | |")
                continue
            err, reached = energy_error(h5, after, after is None)
            total = round(scene["opt"]["dynamics"]["tend"] / scene["opt"]["dynamics"]["dt"])
            status = f"{done}" if code == 0 else f"{done} (failed at t = {reached:.3g})"
            lines.append(f"| {title} | {label} | {err:.1e} | {status} of {total} | {its / max(done, 1):.2f} | "
                         f"{1000 * secs / max(done, 1):.3f} |")
            print(lines[-1], flush=True)
    head = (f"Generated by `scripts/bench_dynamics_schemes.py` ({time.perf_counter() - t0:.0f} s; load average "
            f"{load:.1f} at the start, 2 cores shared: the times are side by side in one run, one process each). "
            "Energy error: free beam and drum max |T + S - (T + S)(end of pulse)| / (T + S), cable pendulum "
            "max |T + S - W - E(0)| / max T. ms/step: the summary's `dynamics` time over the steps done.\n")
    body = head + "\n" + "\n".join(lines)
    print(body)
    if args.doc:
        doc_tables.write_block("accuracy_dynamics.md", "bench_dynamics_schemes", body)


if __name__ == "__main__":
    sys.exit(main())
