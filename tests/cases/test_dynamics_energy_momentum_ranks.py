"""Energy-momentum scheme on 2 ranks (-dynamics_scheme energy_momentum; docs/dynamics.md,
"Energy-momentum scheme"; issue 27): the free steel beam of test_dynamics_energy_momentum.py with its
torsion rigid (index-3 multipliers, the constraints holding at the step ends), 50 steps after the
pulse: T + S and the angular momentum exact on 2 ranks, positions equal on 1 and 2 ranks.
Measured: T + S to 2.7e-15, H to 1.0e-14, 1 vs 2 ranks 1.1e-15 m."""
import sinewtest as st
from energy_momentum_scenes import em, load, scene

# 2 ranks with rigid torsion (multipliers): energy and momenta exact, 1 vs 2 ranks
rigid = scene(4, 0.5, 5, flex=(1, 3, 4, 5, 6))
r2, _ = load("em_rigid_2", rigid, em, np_=2)
r1, _ = load("em_rigid_1", rigid, em, np_=1)
print(f"  energy_momentum, torsion rigid, 2 ranks: T + S drift {r2['dE']:.2e}, H {r2['dH']:.2e}")
st.check(r2["dE"] < 1e-11 and r2["dH"] < 1e-11, "energy_momentum with rigid modes on 2 ranks: energy and momentum exact")
st.close(r1["node/p"], r2["node/p"], atol=1e-9, what="energy_momentum: 1 vs 2 ranks, positions")
st.done()
