"""Rigid elements in beam dynamics (index 3: the Lagrange multipliers of the rigid deformation
modes are unknowns of the time step, without mass; docs/dynamics.md), 2 ranks: the steel leaf of
test_beam_dynamics (16 elements, dens 7800, clamped) with a rigid element from its tip to an
offset node (0.1, 0.05, 0.02) carrying mass 0.05 kg, mominertia diag(1e-4, 2e-4, 3e-4) kg m^2 and a
force (0, 0.5, 0.3) N, under gravity, from rest, rho = 0.9, dt = 0.005, 1 s (the tip swings by
0.31 m, bending and twisting). Checks:
- the rigid modes stay exact: the offset node's position and rotation in the frame of the leaf's
  tip node stay those of the start over the whole run (measured 6.0e-16 m and 4.4e-16);
- the same run with the rigid element replaced by a flexible steel-like link 10 times stiffer than
  steel and without mass (emod 2e12) gives the same motion to 1.7e-7 m (5.7e-7 of the largest
  displacement; 100 times steel: 3.3e-7 m): the multipliers' forces are the stiff link's forces;
- 1 vs 2 ranks identical (measured 5.2e-15 m);
- the offset node without any mass also integrates (the constraints carry it; measured 2.8e-14 m)."""
import numpy as np

import beamtools as bt
import sinewtest as st

L, w, t, nel = 1.0, 0.02, 0.002, 16
nodes, elems = bt.chain([0, 0, 0], [L, 0, 0], nel)
nodes.append([L + 0.1, 0.05, 0.02])
elems.append([nel + 1, nel + 2])
tip = {"force": [0, 0.5, 0.3], "mass": 0.05, "mominertia": [1e-4, 0, 0, 2e-4, 0, 3e-4]}


def scene(link=None, tipnode=tip):
    sets = [bt.beam_set(range(1, nel + 1), w, t, dens=7800)]
    if link:  # element nel + 1 flexible (otherwise in no set: rigid)
        sets.append(bt.beam_set([nel + 1], 0.02, 0.02, emod=link, smod=link / 2.6))
    return bt.yaml_text({"title": "leaf + rigid", "nodes": nodes, "elements": elems,
                         "nprops": {1: {"fix": True}, nel + 2: tipnode}, "eprops": sets,
                         "opt": {"calcfreq": False, "calccompl": False, "gravity": [0, -9.81, 0],
                                 "dynamics": {"tend": 1.0, "dt": 0.005, "spectral_radius": 0.9}}})


def rot(qq):
    w_, x, y, z = qq
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w_ * z), 2 * (x * z + w_ * y)],
                     [2 * (x * y + w_ * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w_ * x)],
                     [2 * (x * z - w_ * y), 2 * (y * z + w_ * x), 1 - 2 * (x * x + y * y)]])


def load(name, text, np_=2):
    h5, _ = st.run(name, text, np_=np_)
    with st.h5(h5) as f:
        return f["node/p"][:], f["node/r_quat"][:], f["node/p0"][:]


def constraint_error(p, q, p0):
    d0 = p0[nel + 1] - p0[nel]
    ep = max(np.linalg.norm(rot(q[k, nel]).T @ (p[k, nel + 1] - p[k, nel]) - d0) for k in range(len(p)))
    er = max(np.abs(rot(q[k, nel]).T @ rot(q[k, nel + 1]) - np.eye(3)).max() for k in range(len(p)))
    return ep, er


p2, q2, p0 = load("beamdyn_rigid_2", scene())
p1, q1, _ = load("beamdyn_rigid_1", scene(), np_=1)
st.check(len(p2) == 201, "rigid: 201 written steps")
ep, er = constraint_error(p2, q2, p0)
motion = np.abs(p2 - p2[0]).max()
print(f"  rigid element: offset position error {ep:.2e} m, relative rotation error {er:.2e}; tip motion {motion:.4f} m")
st.check(motion > 0.1, "rigid: the structure moves")
st.check(ep < 1e-13 and er < 1e-13, "rigid modes exact over the run (round-off)")
d = np.abs(p1 - p2).max()
print(f"  1 vs 2 ranks: {d:.2e} m")
st.check(d < 1e-9 * motion, "rigid: 1 and 2 ranks identical to 1e-9")
ps, _, _ = load("beamdyn_rigid_stiff", scene(link=2e12))
d = np.abs(ps - p2).max()
print(f"  rigid vs a flexible link 10 x stiffer than steel: {d:.2e} m ({d / motion:.1e} of the motion)")
st.check(d < 2e-6 * motion, "rigid element = very stiff flexible link (to 2e-6 of the motion)")
pm, qm, _ = load("beamdyn_rigid_massless", scene(tipnode={"force": [0, 0.5, 0.3]}))
ep, er = constraint_error(pm, qm, p0)
print(f"  massless offset node: constraint errors {ep:.2e} m, {er:.2e}")
st.check(ep < 1e-12 and er < 1e-12, "rigid element with a massless node: constraints exact")
st.done()
