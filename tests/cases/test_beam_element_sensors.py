#!/usr/bin/python3
"""Sensors along beam elements (sensors: [{element, xi | x, variable, name}], Exudyn's SensorBody;
docs/dynamics.md "Sensors along beam elements") in statics on 2 ranks. Three small-load steel
cantilevers along x (L = 1 m, section 20 mm x 2 mm, orien z, so local y = global z and local
z = -global y), each of two scene elements (0..0.5 m with nbeams 1, 0.5..1 m with nbeams 3: the
sensor finds the FE element of the split), load factors 0, 0.5, 1 (loadsteps: 3):
  A: tip force F along global y (bending about local y, EIy = E w t^3 / 12): linear beam theory
     (Euler-Bernoulli plus the Timoshenko shear term of the element, F x / kGA) gives
     v(x) = F x^2 (3L - x) / (6 EIy) + F x / kGA, section rotation about z F x (2L - x) / (2 EIy),
     local moment My = F (L - x), local shear force Qz = -F (the load acts along local -z).
  B: tip axial force P and torque T: N = P, torsion moment T everywhere.
  C: as A with a rigid first element (no eprops set): its sensor's section forces come from the
     multipliers of its rigid modes (My = F (L - x), Qz = -F), it does not move.
Loads give deflections of 1e-5 L (geometric nonlinearity about 1e-5 relative: the shortening
u_x and the load's component F theta along the turned chord in N are checked against that size).
The interior field is the element's Timoshenko one (Phi = 12 EI / (kGA l0^2): 4.9e-5 on the
0.5 m elements, 4.4e-4 on the 1/6 m ones), so the reference keeps the shear term F x / kGA.
MEASURED (2 ranks): deflection 8.1e-11, section rotation 6.5e-11, My 4.9e-11, (Qy, Qz) 1.1e-10,
N (B) 6.6e-12, T (B) 1.3e-11 relative; in A, N = 1.4e-9 N = 1.7e-5 F (second order) and
u_x, u_z = 5.4e-11 m (5.9e-6 of v); xi = 0 and 1 equal the node sensors (Position, Displacement,
Rotation) to 4.2e-22 m and 3.4e-21 rad; load factor 0.5 gives half of 1 to 1.5e-5 (the second-order
N); C: My 2.5e-12, Qz 1.6e-16 relative, no displacement. With xi ignored (the FE element's first
node) the deflection check fails by 0.19 relative. Five bad sensors exit 2 naming the field."""
import numpy as np

import beamtools as bt
import sinewtest as st

L, w, t = 1.0, 0.02, 0.002
sec = bt.rect_section(w, t)
F = 1e-5 * 3 * sec["EIy"] / L ** 3
P, T = 1e-5 * sec["EA"], 1e-5 * sec["GIt"] / L
nodes = [[0, 0, 0], [0.5, 0, 0], [1, 0, 0], [0, 0.2, 0], [0.5, 0.2, 0], [1, 0.2, 0], [0, 0.4, 0], [0.5, 0.4, 0], [1, 0.4, 0]]
elems = [[1, 2], [2, 3], [4, 5], [5, 6], [7, 8], [8, 9]]  # element 5: rigid (no eprops set)
# (element, xi, x along the cantilever); the second one given as x (length) instead of xi
where = [(1, 0.5), (1, 0.3), (2, 0.5), (2, 0.9), (2, 0.2)]
sensors = []
for k, (e, xi) in enumerate(where):
    pos = {"x": xi * 0.5} if k == 1 else {"xi": xi}
    for v in ("Displacement", "Rotation", "TorqueLocal", "ForceLocal"):
        sensors.append(dict({"element": e, "variable": v, "name": f"A{k}_{v}"}, **pos))
    for v in ("TorqueLocal", "ForceLocal"):
        sensors.append(dict({"element": e + 2, "variable": v, "name": f"B{k}_{v}"}, **pos))
for v in ("Displacement", "TorqueLocal", "ForceLocal"):
    sensors.append({"element": 5, "xi": 0.5, "variable": v, "name": f"C_{v}"})
ends = [(1, 0.0, 1), (1, 1.0, 2), (2, 0.0, 2), (2, 1.0, 3)]  # (element, xi, node)
for k, (e, xi, nd) in enumerate(ends):
    for v in ("Position", "Displacement", "Rotation"):
        sensors.append({"element": e, "xi": xi, "variable": v, "name": f"end{k}_{v}"})
for nd in (1, 2, 3):
    for v in ("Position", "Displacement", "Rotation"):
        sensors.append({"node": nd, "variable": v, "name": f"node{nd}_{v}"})
scene = {"title": "beam element sensors", "nodes": nodes, "elements": elems,
         "nprops": {1: {"fix": True}, 4: {"fix": True}, 3: {"force": [0, F, 0]}, 6: {"force": [P, 0, 0], "moment": [T, 0, 0]},
                    7: {"fix": True}, 9: {"force": [0, F, 0]}},
         "eprops": [bt.beam_set([1, 3], w, t, nbeams=1), bt.beam_set([2, 4, 6], w, t, nbeams=3)],
         "sensors": sensors, "opt": {"loadsteps": 3, "calccompl": False}}
h5, _ = st.run("beam_element_sensors", bt.yaml_text(scene))
with st.h5(h5) as f:
    s = {k: f[f"sensors/{k}"][:] for k in f["sensors"].keys()}
    lf = f["load_factor"][:]
st.check(np.allclose(lf, [0, 0.5, 1]), "load factors 0, 0.5, 1")
st.check(all(v.shape == (3, 3) for v in s.values()), "sensors: [3 load steps, 3] rows each")

EI, kGA = sec["EIy"], sec["kGA"]
xs = np.array([(e - 1) * 0.5 + 0.5 * xi for e, xi in where])
u = np.array([s[f"A{k}_Displacement"][-1] for k in range(len(where))])
rot = np.array([s[f"A{k}_Rotation"][-1] for k in range(len(where))])
MA = np.array([s[f"A{k}_TorqueLocal"][-1] for k in range(len(where))])
FA = np.array([s[f"A{k}_ForceLocal"][-1] for k in range(len(where))])
MB = np.array([s[f"B{k}_TorqueLocal"][-1] for k in range(len(where))])
FB = np.array([s[f"B{k}_ForceLocal"][-1] for k in range(len(where))])
v_ref = F * xs ** 2 * (3 * L - xs) / (6 * EI) + F * xs / kGA
z = np.zeros_like(xs)
st.close(u[:, 1], v_ref, rtol=1e-8, what="A: Displacement y at x = " + ", ".join(f"{x:g}" for x in xs))
# x: the second-order shortening (about 1e-5 of v), z: nothing
st.close(u[:, [0, 2]], 0 * u[:, [0, 2]], atol=2e-5 * np.max(v_ref), what="A: Displacement x, z (second order only)")
st.close(rot, np.c_[z, z, F * xs * (2 * L - xs) / (2 * EI)], rtol=1e-8, what="A: Rotation (about z)")
st.close(MA, np.c_[z, F * (L - xs), z], rtol=1e-8, what="A: TorqueLocal (T, My, Mz)")
st.close(FA[:, 1:], np.c_[z, -F + z], rtol=1e-8, what="A: ForceLocal (Qy, Qz)")
# N: the load's component along the turned chord, F sin(theta) ~ 1e-5 F
st.close(FA[:, 0], z, atol=2e-5 * F, what="A: ForceLocal N (second order only)")
st.close(FB, np.c_[P + z, z, z], rtol=1e-8, what="B: ForceLocal (N, Qy, Qz)")
st.close(MB, np.c_[T + z, z, z], rtol=1e-8, what="B: TorqueLocal (T, My, Mz)")
# C: the rigid element 5 (0..0.5 m) carries the same moment and shear through its multipliers
st.close(s["C_TorqueLocal"][-1], [0, F * 0.75, 0], rtol=1e-8, what="C: rigid element, TorqueLocal at x = 0.25")
st.close(s["C_ForceLocal"][-1], [0, 0, -F], rtol=1e-8, what="C: rigid element, ForceLocal at x = 0.25")
st.close(s["C_Displacement"][-1], [0, 0, 0], atol=1e-15, what="C: rigid element fixed at node 7 does not move")
half = max(np.max(np.abs(v[1] - 0.5 * v[2])) / np.max(np.abs(v[2])) for k, v in s.items() if k[0] in "AB" and k[1].isdigit())
zero = max(np.max(np.abs(v[0])) for k, v in s.items() if k[0] in "AB" and k[1].isdigit())
print(f"  load factor 0.5 vs half of load factor 1: {half:.1e} relative; unloaded row: {zero:.1e}")
st.check(half < 1e-4, "sensors: one row per load step (load factor 0.5 gives half, up to the geometric nonlinearity)")
st.check(zero == 0.0, "sensors: the unloaded row is zero")

for k, (e, xi, nd) in enumerate(ends):
    for v in ("Position", "Displacement", "Rotation"):
        d = np.max(np.abs(s[f"end{k}_{v}"] - s[f"node{nd}_{v}"]))
        print(f"  element {e} xi = {xi:g} vs node {nd}: {v} differs by {d:.1e}")
        st.check(d < 1e-15, f"element {e} xi = {xi:g}: {v} = node {nd} sensor to round-off")

# errors name the field (exit 2)
bad_cases = [({"element": 7, "xi": 0.5, "variable": "Position", "name": "b"}, "sensors(1).element"),
             ({"element": 1, "xi": 1.5, "variable": "Position", "name": "b"}, "sensors(1).xi"),
             ({"element": 1, "xi": 0.5, "x": 0.2, "variable": "Position", "name": "b"}, "sensors(1).xi"),
             ({"element": 1, "xi": 0.5, "variable": "Director1", "name": "b"}, "sensors(1).variable"),
             ({"element": 1, "xi": 0.5, "variable": "Pressure", "name": "b"}, "sensors(1).variable")]
for k, (bad, field) in enumerate(bad_cases):
    _, out = st.run(f"beam_element_sensors_bad{k}", bt.yaml_text(dict(scene, sensors=[bad])), expect_exit=2)
    st.check(field in out, f"bad sensor {bad} refused naming {field}")
st.done()
