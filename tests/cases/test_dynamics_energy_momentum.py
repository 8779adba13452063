# ctest-processors: 1
"""Energy-momentum scheme (-dynamics_scheme energy_momentum; docs/dynamics.md, "Energy-momentum scheme";
issue 27): a stiff steel beam in free flight keeps its total energy and momenta over 10,000 steps; with
-dynamics_energy_decay its energy decreases monotonically.

Scene: a free steel beam 1 m, 20 x 10 mm, 4 elements, -beam_mass lumped, no supports; at node 1 a force
(0, 4, 1) N and a moment (0.2, -0.4, 1.2) N m in a 0.1 s sin^2 pulse, then free flight. dt = 0.01 s:
the highest axial mode has omega h ~ 2 c / l_e h = 415 (c = sqrt(E / rho) = 5189 m/s, l_e = 0.25 m).
References (balance laws): after the pulse no load acts, so T + S, the linear momentum p and the angular
momentum H about the origin are constant.
Measured (1 rank, 10,000 steps to t = 100 s, 6.0 Newton iterations per step): T + S constant to 1.2e-12,
H to 4.3e-10 (the round-off of the update test at this stiffness accumulates over the run; the midpoint
rule shows 1.8e-10 on the same run), p to 3.5e-11. The implicit midpoint rule on the same scene: T + S
varies by 4.7e-2 within 1000 steps (feature off: the check must exceed 1e-3); 8 elements at dt = 0.005
(omega h ~ 400) it grew 8800-fold before Newton failed at t = 0.76 s (docs/dynamics.md). Energy decay
xi = 0.1: T + S lower at every written row (2000 steps, every 10th written; 9.2e-5 lost), H constant to
8.6e-12 (the decay acts on strain changes only, never on rigid motion). 2 ranks (50 steps, torsion rigid:
index-3 multipliers, constraints at the step ends): T + S to 2.7e-15, H to 1.0e-14, 1 vs 2 ranks 1.1e-15 m,
in test_dynamics_energy_momentum_ranks.py. The runs here are on one rank (one ctest slot): on 2 ranks 200
steps took 47 s of wall time on the shared machine (MUMPS per solve, polling ranks) against 0.3 s on one.
The whole case: 37 s wall, 12 s CPU (shared 2 cores)."""
import numpy as np

import sinewtest as st
from energy_momentum_scenes import em, load, scene

long, out = load("em_free_flight", scene(4, 100.0, 100), em)
st.check("energy-momentum scheme" in out, "energy_momentum: the summary names the scheme")
st.check(len(long["time"]) == 101, "energy_momentum: 10,000 steps, 101 written rows")
print(f"  energy_momentum, 10,000 steps: T + S drift {long['dE']:.2e}, H {long['dH']:.2e}, p {long['dp']:.2e}")
st.check(long["dE"] < 1e-9, "energy_momentum: T + S constant to 1e-9 over 10,000 steps")
st.check(long["dH"] < 1e-9, "energy_momentum: angular momentum constant to 1e-9 over 10,000 steps")
st.check(long["dp"] < 1e-9, "energy_momentum: linear momentum constant to 1e-9 over 10,000 steps")

# the scheme flag matters: the implicit midpoint rule (momentum exact, energy not) drifts on this scene
mid, _ = load("em_free_flight_midpoint", scene(4, 10.0, 10), ["-dynamics_scheme", "midpoint"])
print(f"  midpoint, 1000 steps: T + S drift {mid['dE']:.2e}, H {mid['dH']:.2e}")
st.check(mid["dE"] > 1e-3, "midpoint drifts in energy on the stiff beam (the energy check is sensitive to the scheme)")

# energy decay: T + S decreases at every written row of the free flight
dec, out = load("em_free_flight_decay", scene(4, 20.0, 10), em + ["-dynamics_energy_decay", "0.1"])
st.check("with energy decay" in out, "energy decay: the summary says so")
steps = np.diff(dec["E"])
print(f"  energy decay 0.1, 2000 steps: T + S lost {1 - dec['E'][-1] / dec['E'][0]:.2e}, "
      f"largest row-to-row change {steps.max():.2e}, H {dec['dH']:.2e}")
st.check((steps < 0).all(), "energy decay: T + S lower at every written row after the pulse")
st.check(dec["dH"] < 1e-9, "energy decay: angular momentum constant to 1e-9")

# an explicit -beam_mass consistent is taken (its inertia at q_{n+1}, not energy-exact: on this stiff free
# beam T + S grows 150-fold within 1.6 s, docs/dynamics.md; test_dynamics_spinup runs it) with a warning
# naming the exact masses; without -beam_mass the scheme takes the linear mass (test_dynamics_energy_momentum_linear)
_, out = st.run("em_consistent", scene(4, 0.1, 1), np_=1, args=em + ["-beam_mass", "consistent"])
st.check("energy-momentum scheme" in out, "energy_momentum with the consistent beam mass: accepted")
st.check("warning: -dynamics_scheme energy_momentum with the consistent beam mass" in out and
         "-beam_mass linear (its default) or lumped" in out,
         "energy_momentum with the consistent beam mass: the run warns that its energy is not exact, naming linear and lumped")
st.done()
