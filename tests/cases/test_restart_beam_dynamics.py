"""Checkpoint and restart of beam dynamics (docs/dynamics.md): the free rigid body of
test_beam_dynamics_spin (nodal mass and anisotropic mominertia on a stiff massless beam, a constant
moment, rho = 1, dt = 0.02), whose state includes the absorbed reference rotations R_ref and the
spatial angular velocities and accelerations. A run stopped after 21 rows (t = 0.4) on 1 rank,
continued on 2 ranks to t = 1, equals the uninterrupted 2-rank run (every dataset, norm-wise
relative difference <= 1e-12; derived ones within twice the rank-count round-off floor). The same
for the cross-flexure hinge of runs/crosshinge.yaml in motion (rigid top body: Lagrange multipliers
in U, masked rates; moment 0.5 N m from t = 0, rho = 0.9, dt = 5e-4 to 0.05 s, every 10th step
written), stopped after 6 rows on 2 ranks and continued on 1."""
import os

import beamtools as bt
import sinewtest as st
from restartutil import compare, restarted, stopped

os.makedirs(st.WORK, exist_ok=True)
scene = {"title": "spin", "nodes": [[0, 0, 0], [0.2, 0, 0]], "elements": [[1, 2]],
         "nprops": {1: {"mass": 1.0, "mominertia": [0.01, 0, 0, 0.02, 0, 0.03], "moment": [0.05, 0.03, 0.02]},
                    2: {"mass": 1.0, "mominertia": [0.01, 0, 0, 0.02, 0, 0.03]}},
         "eprops": [bt.beam_set([1], 0.02, 0.02)],
         "opt": {"calcfreq": False, "calccompl": False, "dynamics": {"tend": 1.0, "dt": 0.02, "spectral_radius": 1.0}}}
text = bt.yaml_text(scene)
ref2, _ = st.run("rs_beamdyn_ref2", text, np_=2)
ref1, _ = st.run("rs_beamdyn_ref1", text, np_=1)
part = stopped("rs_beamdyn_part1", text, 1, 21)
rest, out = restarted("rs_beamdyn_rest2", text, 2, part)
st.check("50 of 50 steps" in out, "beam dynamics restart: steps to 50 of 50")
compare(ref2, rest, "beam dynamics 1 -> 2 (stopped at t = 0.4)", other_ranks=ref1)

with open(os.path.join(os.environ["SINEW_SOURCE_DIR"], "runs", "crosshinge.yaml")) as f:
    hinge = f.read().split("\nopt:")[0] + """
opt:
  calcfreq: false
  calccompl: false
  dynamics: {tend: 0.05, dt: 0.0005, spectral_radius: 0.9, output_every: 10}
"""
href2, _ = st.run("rs_hinge_ref2", hinge, np_=2)
href1, _ = st.run("rs_hinge_ref1", hinge, np_=1)
with st.h5(href2) as f:
    st.check(abs(f["node/r_axang"][-1, 4, 0]) > 0.3, "crosshinge dynamics: the top body turns by more than 0.3 rad")
hpart = stopped("rs_hinge_part2", hinge, 2, 6)
hrest, out = restarted("rs_hinge_rest1", hinge, 1, hpart)
compare(href2, hrest, "crosshinge dynamics 2 -> 1 (stopped at t = 0.025)", other_ranks=href1)
st.done()
