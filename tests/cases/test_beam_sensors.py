# ctest-labels: smoke
"""Node sensors for beam (Frame6) nodes (sensors: [{node, variable, name}], Exudyn's SensorNode;
docs/dynamics.md "Sensors on beam nodes") on 2 ranks, in dynamics: a leaf cantilever (4 beams,
1 m x 20 mm x 2 mm, steel) under a tip force and a tip moment from t = 0 (tip turns by up to 0.1 rad),
rho = 1, every step written. References: the /node datasets of the same run (Position = /node/p,
Displacement = p - p0, Rotation = angle x axis of /node/r_axang), and for the rates the scheme's own
identities at rho = 1 (Newmark, gamma = 1/2, beta = 1/4, alpha_m = alpha_f = 1/2 so qdd = a):
x_{n+1} - x_n = h/2 (v_n + v_{n+1}), v_{n+1} - v_n = h/2 (a_n + a_{n+1}), and for rotations
log(R_{n+1} R_n^T) = h/2 (w_n + w_{n+1}) (spatial increments), w_{n+1} - w_n = h/2 (wd_n + wd_{n+1}).
MEASURED (2 ranks, 96 s at load ~9): Position and Displacement equal /node to 0, Rotation to 1.4e-17
rad (tip turns up to 0.078 rad); identities: position 8.0e-14, velocity 5.9e-15, rotation 8.2e-15,
angular velocity 8.6e-15 relative (tolerance 1e-8); a sensor ignoring its variable or reading
the wrong DOFs fails them."""
import numpy as np

import beamtools as bt
import sinewtest as st

L, w, t, nel = 1.0, 0.02, 0.002, 4
sec = bt.rect_section(w, t)
Mz = 0.05 * sec["EIy"] / L  # 0.05 rad of static tip rotation (0.1 rad peak in motion)
tip = nel + 1
nodes, elems = bt.chain([0, 0, 0], [L, 0, 0], nel)
variables = ["Position", "Displacement", "Rotation", "Velocity", "Acceleration", "AngularVelocity", "AngularAcceleration"]
dt = 0.002
scene = {"title": "leaf sensors", "nodes": nodes, "elements": elems,
         "nprops": {1: {"fix": True}, tip: {"force": [0, 0.5 * Mz / L, 0], "moment": [0, 0, 0]}},
         "eprops": [bt.beam_set(range(1, nel + 1), w, t, dens=7800)],
         "sensors": [{"node": tip, "variable": v, "name": v.lower()} for v in variables],
         "opt": {"calccompl": False, "calcfreq": False, "dynamics": {"tend": 0.2, "dt": dt, "spectral_radius": 1.0}}}
scene["nprops"][tip]["moment"] = [0, 0, Mz]
h5, _ = st.run("beam_sensors", bt.yaml_text(scene))
with st.h5(h5) as f:
    s = {v: f[f"sensors/{v.lower()}"][:] for v in variables}
    p, p0, ax = f["node/p"][:, tip - 1, :], f["node/p0"][tip - 1, :], f["node/r_axang"][:, tip - 1, :]
n = len(p)
st.check(all(s[v].shape == (n, 3) for v in variables), "sensors: [ns, 3] rows for every variable")
d = {"Position": np.max(np.abs(s["Position"] - p)), "Displacement": np.max(np.abs(s["Displacement"] - (p - p0))),
     "Rotation": np.max(np.abs(s["Rotation"] - ax[:, :1] * ax[:, 1:]))}
turn = np.max(np.linalg.norm(s["Rotation"], axis=1))
print(f"  tip turns up to {turn:.3f} rad; sensor vs /node: " + ", ".join(f"{k} {v:.1e}" for k, v in d.items()))
st.check(turn > 0.05, "sensors: the tip turns")
for k, v in d.items():
    st.check(v < 1e-12, f"sensors: {k} = /node data (to 1e-12)")


def rotm(v):
    return bt.rotvec_matrix(v)


e_x = bt.max_relative(np.diff(s["Position"], axis=0), dt / 2 * (s["Velocity"][1:] + s["Velocity"][:-1]))
e_v = bt.max_relative(np.diff(s["Velocity"], axis=0), dt / 2 * (s["Acceleration"][1:] + s["Acceleration"][:-1]))
inc = np.array([bt.rotation_vector(rotm(s["Rotation"][k + 1]) @ rotm(s["Rotation"][k]).T) for k in range(n - 1)])
e_r = bt.max_relative(inc, dt / 2 * (s["AngularVelocity"][1:] + s["AngularVelocity"][:-1]))
e_w = bt.max_relative(np.diff(s["AngularVelocity"], axis=0), dt / 2 * (s["AngularAcceleration"][1:] + s["AngularAcceleration"][:-1]))
print(f"  scheme identities: position {e_x:.1e}, velocity {e_v:.1e}, rotation {e_r:.1e}, angular velocity {e_w:.1e}")
for name, e in (("Velocity", e_x), ("Acceleration", e_v), ("AngularVelocity", e_r), ("AngularAcceleration", e_w)):
    st.check(e < 1e-8, f"sensors: {name} consistent with the scheme (to 1e-8)")
st.check(np.max(np.abs(s["AngularVelocity"][:, 2])) > 0.01, "sensors: the tip rotates about z")

# a node sensor names either a node or an element position: refused naming the field (exit 2)
bad = dict(scene, sensors=[{"node": tip, "element": 1, "variable": "Position", "name": "x"}])
_, out = st.run("beam_sensors_bad", bt.yaml_text(bad), expect_exit=2)
st.check("sensors(1).node" in out, "node and element together refused, naming sensors(1).node")
st.done()
