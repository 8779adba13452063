#!/usr/bin/python3
"""Work-precision of beam dynamics (issue 14, docs/accuracy_dynamics.md; not a ctest).

Model: a steel leaf cantilever (L = 1 m, rect 20 mm x 2 mm, E = 210e9, G = 80e9, dens 7800, clamped
at x = 0, straight along x) released at rest under gravity g = 9.81 m/s^2 along -y, its thin
direction: the static tip deflection under its weight is q L^4 / (8 EI) = 0.137 m (14 % of L), so
the swing is geometrically nonlinear. Lie-group generalized alpha, spectral radius 0.6. Measured:
the tip position at t = 0.3 s (near the first extreme of the swing; T1 = 0.597 s) and the wall time.
- error vs step size: n = 16 elements, dt = 0.3 / N for N = 12 .. 768, against N = 6144 (same n);
- error vs elements: dt = 0.3 / 768, n = 2 .. 64, against n = 256 (same dt);
each with the time of the `dynamics` phase of Sinew's summary (one process, started without
mpirun). With --exudyn DIR (main/ of an Exudyn source tree built in place), Exudyn's geometrically
exact beam (ObjectBeamGeometricallyExact on NodeRigidBodyRotVecLG nodes: Simo-Reissner rod, linear
interpolation, Lie-group generalized alpha, same spectral radius, same section stiffnesses, the
same lumped gravity forces rhoA g l/2 on the nodes, mass per length rhoA and rotary inertia
rho diag(Iy + Iz, Iz, Iy) per length) runs the same cases; its errors are against its own finest
run, and the difference of the two codes' converged tips is printed.

usage: scripts/study_beam_dynamics.py [--exudyn DIR] [--doc] [--quick]"""
import argparse
import json
import os
import sys
import time

import numpy as np

import doc_tables
from bench_dynamics import run_sinew_dynamics, run_timed

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
BUILD = os.path.join(SOURCE, "build")
WORK = os.path.join(BUILD, "study", "beam_dynamics")
L, W, T, E, G, RHO, GRAV = 1.0, 0.02, 0.002, 210e9, 80e9, 7800.0, 9.81
TEND, RHOINF = 0.3, 0.6


def section():
    """Section values as Sinew computes them for a rect (beamtools: torsion constant, Cowper)."""
    sys.path.insert(0, os.path.join(SOURCE, "tests", "cases"))
    import beamtools as bt
    s = bt.rect_section(W, T, E, G)
    s["Iy_thin"] = W * T ** 3 / 12   # bending in the thin direction (global y)
    s["Iz_wide"] = T * W ** 3 / 12
    return s


def sinew_scene(n, steps):
    return f"""title: leaf cantilever released under gravity, {n} elements
nodes: [[0, 0, 0], [{L}, 0, 0]]
elements: [[1, 2]]
nprops:
  1: {{fix: true}}
eprops:
  - {{elems: [1], flex: [1, 2, 3, 4, 5, 6], emod: {E}, smod: {G}, dens: {RHO}, cshape: rect,
     dim: [{W}, {T}], orien: [0, 0, 1], nbeams: {n}}}
opt:
  gravity: [0, {-GRAV}, 0]
  calccompl: false
  calcfreq: false
  dynamics: {{tend: {TEND}, dt: {TEND / steps!r}, spectral_radius: {RHOINF}, output_every: {steps}}}
"""


def sinew(n, steps):
    r = run_sinew_dynamics(WORK, f"leaf_{n}_{steps}", sinew_scene(n, steps), 1)
    import h5py
    with h5py.File(r["h5"], "r") as f:
        tip = f["node/p"][-1, -1, :] - f["node/p0"][-1, :]
        t = f["time"][-1]
    assert abs(t - TEND) < 1e-12, t
    return {"tip": tip, "time": r["integration"], "process": r["process"]}


EXUDYN_SCRIPT = r'''
import sys, time, json
import numpy as np
import exudyn as exu
from exudyn.itemInterface import *
n, steps = int(sys.argv[1]), int(sys.argv[2])
p = json.loads(sys.argv[3])
SC = exu.SystemContainer(); mbs = SC.AddSystem()
sec = exu.BeamSection()
# local axes of the node frames = global axes: y (thin direction) bends with E Iy_thin about z
sec.stiffnessMatrix = np.diag([p["EA"], p["kGA"], p["kGA"], p["GIt"], p["E"] * p["Iz_wide"], p["E"] * p["Iy_thin"]])
sec.massPerLength = p["rhoA"]
sec.inertia = p["rho"] * np.diag([p["Iy_thin"] + p["Iz_wide"], p["Iz_wide"], p["Iy_thin"]])
le = p["L"] / n
nodes = [mbs.AddNode(NodeRigidBodyRotVecLG(referenceCoordinates=[le * i, 0, 0, 0, 0, 0])) for i in range(n + 1)]
for i in range(n):
    mbs.AddObject(ObjectBeamGeometricallyExact(nodeNumbers=[nodes[i], nodes[i + 1]], physicsLength=le, sectionData=sec))
for i in range(n + 1):  # lumped gravity, as Sinew's: rhoA g l/2 per element end
    w = (0.5 if i in (0, n) else 1.0) * p["rhoA"] * p["g"] * le
    mbs.AddLoad(Force(markerNumber=mbs.AddMarker(MarkerNodePosition(nodeNumber=nodes[i])), loadVector=[0, -w, 0]))
nG = mbs.AddNode(NodePointGround(referenceCoordinates=[0, 0, 0]))
mbs.AddObject(GenericJoint(markerNumbers=[mbs.AddMarker(MarkerNodeRigid(nodeNumber=nG)),
                                          mbs.AddMarker(MarkerNodeRigid(nodeNumber=nodes[0]))]))
mbs.Assemble()
s = exu.SimulationSettings()
s.solutionSettings.writeSolutionToFile = False
s.timeIntegration.numberOfSteps = steps
s.timeIntegration.endTime = p["tend"]
s.timeIntegration.verboseMode = 0
s.timeIntegration.generalizedAlpha.spectralRadius = p["rhoinf"]
s.timeIntegration.newton.relativeTolerance = 1e-6
s.timeIntegration.newton.useModifiedNewton = True
if n > 8:
    s.linearSolverType = exu.LinearSolverType.EigenSparse
t1 = time.perf_counter()
mbs.SolveDynamic(s)
t2 = time.perf_counter()
u = mbs.GetNodeOutput(nodes[-1], exu.OutputVariableType.Displacement)
print(json.dumps({"time": t2 - t1, "tip": list(u)}))
'''


def exudyn(exudyn_dir, n, steps, sec, timeout=900):
    p = {"EA": sec["EA"], "kGA": sec["kGA"], "GIt": sec["GIt"], "E": E, "Iy_thin": sec["Iy_thin"],
         "Iz_wide": sec["Iz_wide"], "rhoA": RHO * W * T, "rho": RHO, "L": L, "g": GRAV, "tend": TEND, "rhoinf": RHOINF}
    env = dict(os.environ, PYTHONPATH=os.path.join(exudyn_dir, "pythonDev"))
    out, wall, _, _ = run_timed(["/usr/bin/python3", "-c", EXUDYN_SCRIPT, str(n), str(steps), json.dumps(p)], env=env,
                             timeout=timeout)
    r = json.loads(out.strip().splitlines()[-1])
    return {"tip": np.array(r["tip"]), "time": r["time"], "process": wall}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exudyn", help="Exudyn main/ directory (built in place)")
    ap.add_argument("--doc", action="store_true")
    ap.add_argument("--quick", action="store_true")
    a = ap.parse_args()
    sec = section()
    t0, load0 = time.time(), os.getloadavg()[0]
    n0, nsteps = 16, [12, 24, 48, 96, 192, 384, 768]
    steps_ref, n_ref, nel = 6144, 256, [2, 4, 8, 16, 32, 64]
    if a.quick:
        nsteps, steps_ref, nel, n_ref = [12, 24, 48], 192, [2, 4, 8], 32
    # Exudyn's GE beam (numerically differentiated Jacobian) costs minutes per run here: it runs the
    # step study at n = 16 only, up to 48 steps, against its own 192-step run
    codes = {"Sinew": (lambda n, s: sinew(n, s), nsteps, steps_ref, True)}
    if a.exudyn:
        codes["Exudyn GE beam"] = (lambda n, s: exudyn(a.exudyn, n, s, sec), [12, 24, 48], 192, False)
    rows_dt, rows_n, limits, same = [], [], {}, {}
    for code, (run, code_steps, code_ref, with_n) in codes.items():
        ref = run(n0, code_ref)
        same[code] = run(n0, 192)["tip"] if code_ref != 192 else ref["tip"]
        print(f"{code}: reference n = {n0}, {code_ref} steps: tip {ref['tip']} ({ref['time']:.2f} s)", flush=True)
        for s in code_steps:
            r = run(n0, s)
            e = np.linalg.norm(r["tip"] - ref["tip"])
            rows_dt.append([code, str(s), f"{TEND / s:.3g}", f"{e:.2e}", f"{e / np.linalg.norm(ref['tip']):.1e}",
                            f"{r['time']:.3f}"])
            print(" | ".join(rows_dt[-1]), flush=True)
        if not with_n:
            continue
        s = nsteps[-1]
        refn = run(n_ref, s)
        limits[code] = refn["tip"]
        print(f"{code}: reference n = {n_ref}, {s} steps: tip {refn['tip']} ({refn['time']:.2f} s)", flush=True)
        for n in nel:
            r = run(n, s)
            e = np.linalg.norm(r["tip"] - refn["tip"])
            rows_n.append([code, str(n), str(6 * n), f"{e:.2e}", f"{e / np.linalg.norm(refn['tip']):.1e}",
                           f"{r['time']:.3f}"])
            print(" | ".join(rows_n[-1]), flush=True)
    lines = [f"Generated by `scripts/study_beam_dynamics.py{' --exudyn DIR' if a.exudyn else ''}` "
             f"({time.time() - t0:.0f} s; load average {load0:.1f} at the start, 2 cores shared: times are "
             "side by side in one run, each code on one process). Error: |tip(t = 0.3 s) - reference| "
             "(displacement vector, m) against the same code's finest run. Exudyn: Newton relativeTolerance 1e-6, modified Newton.", "",
             f"Error vs step size (n = {n0} elements; reference: the same code with {steps_ref} steps, Exudyn with 192):", "",
             "| code | steps | dt [s] | error [m] | relative | integration [s] |", "|---|---|---|---|---|---|"]
    lines += ["| " + " | ".join(r) + " |" for r in rows_dt]
    lines += ["", f"Error vs elements (dt = {TEND / nsteps[-1]:.3g} s; reference n = {n_ref}):", "",
              "| code | elements | unknowns | error [m] | relative | integration [s] |", "|---|---|---|---|---|---|"]
    lines += ["| " + " | ".join(r) + " |" for r in rows_n]
    for code, tip in limits.items():
        lines += ["", f"{code}, n = {n_ref}, dt = {TEND / nsteps[-1]:.3g} s: tip displacement "
                  f"[{tip[0]:.6e}, {tip[1]:.6e}, {tip[2]:.3e}] m."]
    if len(same) == 2:
        a_, b_ = same.values()
        lines += [f"Same model, n = {n0}, 192 steps: Sinew tip [{a_[0]:.6e}, {a_[1]:.6e}] m, Exudyn GE beam "
                  f"[{b_[0]:.6e}, {b_[1]:.6e}] m, difference {np.linalg.norm(a_ - b_):.2e} m "
                  f"({np.linalg.norm(a_ - b_) / np.linalg.norm(a_):.1e} relative)."]
    print("\n".join(lines))
    if a.doc:
        doc_tables.write_block("accuracy_dynamics.md", "study_beam_dynamics", "\n".join(lines))


if __name__ == "__main__":
    sys.exit(main())
