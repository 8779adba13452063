"""Issue 11: Williams' toggle frame under arc-length continuation (beams, 2 ranks).
Geometry and material as commonly quoted for Williams' toggle (F. W. Williams 1964, Q. J. Mech. Appl.
Math. 17, 451: two straight members rigidly joined at the apex, clamped at both supports): half span
a = 12.943 in, rise h = 0.386 in, E = 10.3e6 psi, section 0.753 x 0.243 in (A = 0.183 in^2,
I = 9.0e-4 in^4), apex load P (lb); 10 beam elements per member, in-plane (every node fix_z).
Reference: Williams' published limit load (his 1964 analysis and experiment; also plotted by Wood &
Zienkiewicz 1977 and in Crisfield's book) is still not at hand: a search of the stored public material
(web pages, documentation, GitHub code and issues, November 2026: "Williams toggle" with limit load,
experiment, 0.386 in, 12.943 in, 10.3e6 psi, Wood & Zienkiewicz, Oran & Kassimali 1976) found the frame
named in benchmark lists (e.g. a Rust corotational validation suite whose toggle test only checks that
the solver runs) but no number and no digitized curve; a third search (strings 12.943, 0.386, 0.753,
10.3e6, Williams toggle, williams_toggle; Oran & Kassimali, Kassimali 1983, Crisfield, Wood & Zienkiewicz)
found only a Rust solver test asserting 34.0392 lb as an unsourced "external" limit (Sinew -0.56 %) and a
C++ code's own beam-column formula. So the test compares with shallow-beam
(Marguerre) theory for the same frame (tests/cases/shallow_beam.py: w0 the
kinked stress-free shape, clamped ends, uniform axial force; exact to the order of the squared slopes,
(h/a)^2 = 1e-3), traced through its fold: limit load 33.900 lb at an apex deflection of 0.2321 in,
then a minimum of 31.306 lb at 0.3915 in (the load rises again after it). Tolerances 0.5% on the
loads, 1% on the deflections. Measured (2 ranks): 33.849 and 31.246 lb (-0.15%, -0.19%) at 0.23200 and
0.39175 in (-0.05%, +0.08%).
Checks: both limit points located (kind 1) and compared; the negative-eigenvalue count 0 -> 1 -> 0,
changing at the two limit points only; SLEPc's lowest eigenvalue of the tangent negative exactly where
the count is 1."""
import numpy as np

import beamtools as bt
import sinewtest as st
from shallow_beam import Shallow

a, h, E, b, t, n = 12.943, 0.386, 10.3e6, 0.753, 0.243, 10
L, EI, EA = 2 * a, E * b * t ** 3 / 12, E * b * t


def w0(x):
    return h * (1 - np.abs(2 * x / L - 1))


ref = Shallow(L, EI, EA, w0, 0.0, N=800)
F, w = ref.trace(3000)
i = int(np.nonzero(np.diff(F) < 0)[0][0])  # the first maximum
j = i + int(np.argmin(F[i:]))              # the minimum after it
Fmax, dmax, Fmin, dmin = F[i], h - w[i], F[j], h - w[j]
print(f"  shallow theory: limit loads {Fmax:.4f} lb at {dmax:.4f} in and {Fmin:.4f} lb at {dmin:.4f} in")

x = np.linspace(0, L, 2 * n + 1)
nprops = {k + 1: {"fix_z": True} for k in range(2 * n + 1)}
nprops[1] = {"fix": True}
nprops[2 * n + 1] = {"fix": True}
nprops[n + 1] = {"fix_z": True, "force": [0, -1, 0]}
scene = bt.yaml_text({"title": "Williams toggle frame", "nodes": [[float(p), float(q), 0.0] for p, q in zip(x, w0(x))],
                      "elements": [[k + 1, k + 2] for k in range(2 * n)], "nprops": nprops,
                      "eprops": [{"elems": list(range(1, 2 * n + 1)), "flex": [1, 2, 3, 4, 5, 6], "emod": E, "smod": E / 2.6,
                                  "cshape": "rect", "dim": [b, t], "orien": [0, 0, 1]}],
                      "opt": {"calccompl": False,
                              "continuation": {"method": "arclength", "ds": 0.02, "ds_max": 0.04, "node": n + 1,
                                               "direction": "y", "stop_displacement": -0.45, "max_steps": 60}}})
h5, out = st.run("continuation_toggle", scene, args=["-continuation_lowest_eigenvalue"])
with st.h5(h5) as f:
    lam, neg, crit = f["load_factor"][:], f["path/negative_eigenvalues"][:], f["path/critical_points"][:]
    low, conv = f["path/lowest_eigenvalue"][:], int(f.attrs["converged"])
print("  load factors", np.array2string(lam, precision=4))
print("  negative eigenvalues", neg.astype(int))
st.check(conv == 1, "path converged")
if st.check(crit.shape == (2, 4) and np.all(crit[:, 0] == 1), f"two limit points ({crit})"):
    st.close(crit[:, 2], [Fmax, Fmin], rtol=5e-3, what="limit loads [lb] vs shallow-beam theory")
    st.close(-crit[:, 3], [dmax, dmin], rtol=1e-2, what="apex deflection at the limit points [in]")
    k1, k2 = int(crit[0, 1]), int(crit[1, 1])
    st.check(np.all(neg[:k1] == 0) and np.all(neg[k1:k2] == 1) and np.all(neg[k2:] == 0),
             "0 negative eigenvalues before the first limit point, 1 between, 0 after the second")
st.check(np.array_equal(low < 0, neg == 1), "SLEPc's lowest eigenvalue < 0 exactly where the inertia counts 1")
st.done()
