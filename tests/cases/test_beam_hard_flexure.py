"""Hard case of issue 3: very slender flexures (EA/EI = 12/t^2 > 1e8) with 1e-9-thick rigid links.
A cross-flexure hinge (runs/crosshinge.yaml geometry) whose leaves are t = 0.1 mm thick
(EA/EI = 1.2e9) and whose top body is a set of rigid links with a 1e-9-thick section.
Checks: (1) the statics converge, including a large rotation in 10 steps; (2) in the linear range
the rotation scales exactly with EI ~ t^3: the hinge with t = 0.5 mm under a 125x larger moment
rotates by the same angle (1e-3 relative, the small nonlinearity); (3) frequencies and buckling
multipliers are finite and positive; (4) reactions balance the applied moment."""
import numpy as np

import ancf_scenes as A
import sinewtest as st


def hinge(t, moment, steps):
    return {
        "title": f"cross hinge t = {t}",
        "nodes": [[-0.05, 0, 0], [0.05, 0, 0], [0.05, 0.1, 0], [-0.05, 0.1, 0], [0, 0.12, 0]],
        "elements": [[1, 3], [2, 4], [3, 4], [4, 5]],
        "nprops": {1: {"fix": True}, 2: {"fix": True}, 5: {"moment": [0, 0, moment], "mass": 0.01,
                                                           "mominertia": [1e-6, 0, 0, 1e-6, 0, 1e-6]}},
        "eprops": [{"elems": [1, 2], "flex": [1, 2, 3, 4, 5, 6], "emod": 210e9, "smod": 80e9, "dens": 7800,
                    "cshape": "rect", "dim": [0.05, t], "orien": [0, 0, 1], "nbeams": 8},
                   {"elems": [3, 4], "flex": [], "emod": 210e9, "smod": 80e9, "cshape": "rect",
                    "dim": [0.01, 1e-9], "orien": [0, 0, 1]}],
        "opt": {"loadsteps": steps, "calcbuck": True},
    }


def rotation_z(f):
    q = f["node/r_quat"][-1, 4]
    return 2 * np.arctan2(q[3], q[0])


M1 = 2e-5  # t = 0.1 mm: about 0.01 rad
h1, out1 = st.run("hard_flexure_thin", A.text(hinge(1e-4, M1, 2)))
h5_, out5 = st.run("hard_flexure_thick", A.text(hinge(5e-4, 125 * M1, 2)))
with st.h5(h1) as f1, st.h5(h5_) as f5:
    r1, r5 = rotation_z(f1), rotation_z(f5)
    print(f"  rotation t=0.1 mm: {r1:.9e} rad, t=0.5 mm with 125x moment: {r5:.9e} rad")
    st.close(r1, r5, rtol=1e-3, what="rotation ~ M / t^3 (linear range)")
    for name, f in (("thin", f1), ("thick", f5)):
        fr, bk = f["freq"][-1], f["buck"][-1]
        st.check(np.all(np.isfinite(fr)) and fr[0] > 0, f"{name}: frequencies finite and positive {fr[:3]}")
        st.check(np.all(np.isfinite(bk[bk < np.inf])), f"{name}: buckling multipliers finite or +inf {bk}")
        Mz = f["node/Mreac"][-1][:, 2].sum()
        p, Fr = f["node/p"][-1], f["node/Freac"][-1]
        Mz += np.sum(p[:, 0] * Fr[:, 1] - p[:, 1] * Fr[:, 0])  # moment of the reaction forces about 0
        M = M1 if name == "thin" else 125 * M1
        st.close((Mz + M) / M, 0.0, atol=1e-8, what=f"{name}: reaction moment balances the applied moment")
# large rotation of the thin hinge: 0.3 rad in 10 load steps
h, out = st.run("hard_flexure_large", A.text(hinge(1e-4, 4e-3, 10)))
with st.h5(h) as f:
    r = rotation_z(f)
    print(f"  large rotation: {r:.4f} rad in 10 steps")
    st.check(r > 0.2, "thin hinge rotates by more than 0.2 rad")
    st.check(int(f.attrs["converged"]) == 1, "large rotation converged")
st.done()
