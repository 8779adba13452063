"""Patch tests: uniform axial force, torque and bending moment states on an oblique cantilever with
irregular element lengths. Every node must reproduce the exact field (u = N s/EA, phi = T s/GIt,
theta = M s/EI, w: circular arc of curvature M/EI), whatever the mesh.
Load level: axial strain and twist 1e-5; bending end rotation 3e-4. Measured on this mesh, the
bending displacements carry a round-off floor growing like 1/load^2 (2e-4 relative at an end
rotation of 1e-6, 2e-6 at 1e-5, 8e-9 at 1e-4: the stiff axial rows' residual noise eps EA) and an
O(theta^2) element arc error (7.6e-9 at 1e-3), so bending is checked to 1e-8 at 3e-4, the
uniform axial and torsion states to 1e-10."""
import numpy as np

import beamtools as bt
import sinewtest as st

L, w, t = 1.3, 0.02, 0.01
sec = bt.rect_section(w, t)
d = np.array([1.0, 2.0, 2.0]) / 3.0                      # beam axis
o = np.array([0.0, 0.0, 1.0])                             # orien
ey = o - o.dot(d) * d
ey /= np.linalg.norm(ey)
ez = np.cross(d, ey)
frac = np.array([0, 0.07, 0.3, 0.38, 0.61, 0.9, 1.0])    # irregular node positions along the axis
s = frac * L
kappa = 3e-4 / L                                          # curvature M / EI of the bending cases


def arc(s, n):
    """Displacements of the exact circular arc of curvature kappa bending towards n (the
    second-order shortening is 1e-6 of the deflection: a patch test at this level needs it)."""
    return np.outer(np.sin(kappa * s) / kappa - s, d) + np.outer((1 - np.cos(kappa * s)) / kappa, n)


cases = {  # name: (tip nprops, expected displacement(s), expected rotation vector(s))
    "axial": ({"force": list(1e-5 * sec["EA"] / L * d)},
              lambda s: np.outer(1e-5 * s / L, d), lambda s: np.zeros((len(s), 3))),
    "torsion": ({"moment": list(1e-5 * sec["GIt"] / L * d)},
                lambda s: np.zeros((len(s), 3)), lambda s: np.outer(1e-5 * s / L, d)),
    "bending y": ({"moment": list(kappa * sec["EIy"] * ey)},
                  lambda s: arc(s, -ez), lambda s: np.outer(kappa * s, ey)),
    "bending z": ({"moment": list(kappa * sec["EIz"] * ez)},
                  lambda s: arc(s, ey), lambda s: np.outer(kappa * s, ez)),
}
# one run per case: a residual floor set by the stiff axial case (eps EA ~ 4e-8 N) would otherwise
# limit the relative accuracy of the much smaller bending loads of a shared solve
for name, (load, ue, re) in cases.items():
    nodes = [list(si * d) for si in s]
    elems = [[i + 1, i + 2] for i in range(len(s) - 1)]
    scene = {"title": "beam patch test: " + name, "nodes": nodes, "elements": elems,
             "nprops": {"1": {"fix": True}, str(len(nodes)): load},
             "eprops": [bt.beam_set(range(1, len(elems) + 1), w, t, orien=list(o))],
             "opt": {"loadsteps": 1, "calccompl": False}}
    out, log = st.run("beam_patch_" + name.replace(" ", "_"), bt.yaml_text(scene))
    with st.h5(out) as f:
        u = f["node/p"][-1] - f["node/p0"][:]
        q = f["node/r_quat"][-1]
    rot = np.array([2 * np.arctan2(np.linalg.norm(qq[1:]), qq[0]) * qq[1:] / max(np.linalg.norm(qq[1:]), 1e-300)
                    for qq in q * np.sign(q[:, :1] + 1e-300)])
    tol = 1e-8 if name.startswith("bending") else 1e-10
    st.close(u, ue(s), atol=tol * np.abs(ue(s)).max(), what=f"{name}: node displacements (all nodes)")
    st.close(rot, re(s), atol=tol * max(np.abs(re(s)).max(), 1e-5), what=f"{name}: node rotation vectors (all nodes)")
st.done()
