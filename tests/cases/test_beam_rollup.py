"""Cantilever roll-up (reference B1, Krenk 2009): an end moment M = 2 pi EI / L closes the beam into
a full circle, M = 4 pi EI / L into a double circle. At load factor lambda the exact tip is
x = L sin(theta)/theta, y = L (1 - cos(theta))/theta with theta = lambda M L / EI; every node at
arc length s is rotated by theta s / L about z. Checked at every load step: the tip (within 1e-3 L
at the closed circles), the node rotations through the result quaternions (rotations pass 2 pi
and 4 pi: the incremental rotation update must carry them)."""
import numpy as np

import beamtools as bt
import sinewtest as st

L, w, t = 1.0, 0.02, 0.01
EI = bt.rect_section(w, t)["EIy"]


def quat_err(q, theta):
    """Distance of quaternion rows q from the rotation theta about z (either sign)."""
    qe = np.stack([np.cos(theta / 2), 0 * theta, 0 * theta, np.sin(theta / 2)], axis=-1)
    return np.minimum(np.linalg.norm(q - qe, axis=-1), np.linalg.norm(q + qe, axis=-1))


# The element's bending modes are l0 sin(.) measures: an element bent by theta_e carries
# M = EI sin(theta_e) / l0, so the closed circle has an O(theta_e^2) angle deficit (measured with 32
# elements: 0.041 rad at 2 pi); 256 / 512 elements bring the tip within 1e-3 L.
for turns, nel, steps in ((1, 256, 20), (2, 512, 40)):
    M = 2 * np.pi * turns * EI / L
    nodes, elems = bt.chain([0, 0, 0], [L, 0, 0], nel)
    scene = {"title": f"roll-up {turns}", "nodes": nodes, "elements": elems,
             "nprops": {"1": {"fix": True}, str(nel + 1): {"moment": [0, 0, M]}},
             "eprops": [bt.beam_set(range(1, nel + 1), w, t)],
             "opt": {"loadsteps": steps, "calccompl": False}}
    out, log = st.run(f"beam_rollup{turns}", bt.yaml_text(scene))
    with st.h5(out) as f:
        lam = f["load_factor"][:]
        p = f["node/p"][:]
        q = f["node/r_quat"][:]
        conv = f.attrs["converged"]
    st.check(len(lam) == steps and conv == 1, f"roll-up {turns}: {len(lam)} converged steps of {steps}")
    th = lam * M * L / EI
    # SPACAR Light's step 1 is the unloaded beam (theta = 0): x = L sinc, y = L (1 - cos) / theta -> 0
    ths = np.where(th == 0, 1.0, th)
    exact = np.stack([L * np.sinc(th / np.pi), np.where(th == 0, 0.0, L * (1 - np.cos(th)) / ths), 0 * th], axis=1)
    err = np.linalg.norm(p[:, -1] - exact, axis=1)
    print(f"roll-up to {turns} circle(s), {nel} elements, {steps} steps: max tip error over steps "
          f"{err.max():.3e} L; at the end tip {p[-1, -1]} (root at 0)")
    st.close(p[-1, -1], [0, 0, 0], atol=1e-3 * L, what=f"{turns} circle(s): tip back at the root")
    st.check(err.max() < 2e-3 * L, f"tip path error {err.max():.3e} over the steps")
    s = np.linspace(0, L, nel + 1)
    qerr = quat_err(q, th[:, None] * s[None, :] / L)
    print(f"  node rotations vs theta s/L about z: max quaternion error {qerr.max():.3e}; "
          f"tip angle at the end {th[-1]:.6f} rad")
    st.check(qerr.max() < 2e-3, f"node rotations: quaternion error {qerr.max():.3e}")
    # the tip rotation passes 2 pi (and 4 pi) continuously: quaternion sign follows cos(theta/2)
    st.close(np.abs(q[-1, -1]), [1, 0, 0, 0], atol=1e-3, what=f"tip rotation at {2 * turns} pi is the identity")
st.done()
