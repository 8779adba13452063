"""The linear beam mass under the energy-momentum scheme (-beam_mass linear, the default of
-dynamics_scheme energy_momentum; docs/dynamics.md, "Energy-momentum scheme"; issue 27): Simo and
Vu-Quoc's constant mass of linearly interpolated velocities on the translations (rhoA l/6 [2 I, I; I, 2 I])
with the section's rotary inertia lumped on the nodes. A constant mass with isotropic blocks makes the
step's inertia M (v_n+1 - v_n) / h exact for the energy and the angular momentum, so the stiff steel
free beam of test_dynamics_energy_momentum.py (4 elements, dt = 0.01: the highest axial mode of the
linear mass at omega h ~ 2 sqrt(3) c / l_e h = 720) keeps T + S and H after its pulse on 2 ranks.
Measured (2 ranks, 200 steps): T + S to 7e-15, H to 1e-13, p to 7e-14; by hand, 1 rank, 10,000 steps to
t = 100 s (5.1 s wall): T + S to 1.9e-12, H to 4.1e-10, p to 5.4e-11 (-beam_mass lumped: 1.2e-12,
4.3e-10, 3.5e-11). Feature off (-beam_mass consistent, the mass in the turning element frame): T + S
drifts by 2.3e-3 within 30 steps (the check needs > 1e-3) and grows 150-fold within 1.6 s (1 rank)."""
import numpy as np

import sinewtest as st
from energy_momentum_scenes import em, load, scene

# -beam_mass linear: T + S and the momenta exact over 200 steps on 2 ranks
lin, _ = load("em_linear", scene(4, 2.0, 10), em, np_=2, mass="linear")
print(f"  -beam_mass linear, 200 steps, 2 ranks: T + S drift {lin['dE']:.2e}, H {lin['dH']:.2e}, p {lin['dp']:.2e}")
st.check(lin["dE"] < 1e-9, "linear mass: T + S constant to 1e-9")
st.check(lin["dH"] < 1e-9, "linear mass: angular momentum constant to 1e-9")
st.check(lin["dp"] < 1e-9, "linear mass: linear momentum constant to 1e-9")

# no -beam_mass: energy_momentum takes the linear mass and says so (the same steps)
dft, out = load("em_default_mass", scene(4, 0.5, 10), em, np_=2, mass=None)
st.check("energy-momentum scheme (beams: the linear mass" in out, "no -beam_mass: the summary names the linear mass")
st.check("warning" not in out, "no -beam_mass: no warning")
st.close(dft["node/p"], lin["node/p"][:len(dft["node/p"])], atol=1e-12,
         what="no -beam_mass under energy_momentum = -beam_mass linear (positions)")

# feature off: the consistent mass drifts on the same beam within 30 steps
con, out = load("em_consistent_drift", scene(4, 0.3, 5), em, np_=2, mass="consistent")
print(f"  -beam_mass consistent, 30 steps, 2 ranks: T + S drift {con['dE']:.2e}, H {con['dH']:.2e}")
st.check(con["dE"] > 1e-3, "consistent mass: T + S drifts (the energy check tells the masses apart)")
st.check("-beam_mass linear (its default) or lumped" in out, "consistent mass: the warning names linear and lumped")
st.done()
