#!/usr/bin/python3
"""Issue 11 item 1: path following with ANCF cables (ancf_cable2d), 2 ranks. The shallow clamped arch
of test_continuation_flexures.py (L = 0.1 m, section 5 x 0.5 mm, E = 210 GPa, stress-free cosine shape
w0 = h/2 (1 - cos 2 pi x/L), h = 0.75 mm, mid-span load F = 1 N as the reference load), here as 40
ANCF cable elements: nodes on w0 with the exact reference slopes [1, w0'(x)] (nprops `slope`),
strainIsRelativeToReference = 1 (the arch is stress-free), both ends `fix` (x, y and slope held).
The arc length runs in the ANCF unknowns (positions in m and slope vectors, dimensionless).
Checked:
  (1) the path passes the snap-through limit point: the limit load and the mid-span position there
      vs shallow-arch (Marguerre) theory (tests/cases/shallow_beam.py; its error is of the order of
      the squared slopes, 0.1..0.5% here); measured 1.86926 N (+0.22%; 80 elements: 1.86719 N; the
      beam elements approach from below: 1.85716 N at 40, 0.14% low at 80; the two kinds'
      second-order extrapolations, about 1.8665 and 1.8645 N, differ by 0.1%);
  (2) negative eigenvalues of the tangent: 0 before the limit point, 1 after it; SLEPc's lowest
      eigenvalue (-continuation_lowest_eigenvalue) negative exactly where the count is one;
  (3) 1 and 2 ranks identical to 1e-9 along the whole path (load factors, positions, slopes)."""
import numpy as np

import ancf_scenes as asc
import sinewtest as st
from shallow_beam import Shallow

L, t, wd, E, n = 0.1, 0.5e-3, 5e-3, 210e9, 40
EI, EA = E * wd * t ** 3 / 12, E * wd * t
h = 0.75e-3
w0 = lambda x: h / 2 * (1 - np.cos(2 * np.pi * x / L))
dw0 = lambda x: h / 2 * 2 * np.pi / L * np.sin(2 * np.pi * x / L)
x = np.linspace(0, L, n + 1)
c = n // 2 + 1
nprops = {i + 1: {"slope": [1.0, float(dw0(xi))]} for i, xi in enumerate(x)}
nprops[1] = nprops[n + 1] = {"fix": True}
nprops[c] = {"force": [0, -1], "slope": [1.0, 0.0]}
scene = asc.text({"title": "ANCF shallow clamped arch", "nodes": [[float(a), float(w0(a))] for a in x],
                  "elements": [[i + 1, i + 2] for i in range(n)], "nprops": nprops,
                  "eprops": [{"elems": list(range(1, n + 1)), "type": "ancf_cable2d", "physicsMassPerLength": 0.0,
                              "physicsBendingStiffness": EI, "physicsAxialStiffness": EA, "strainIsRelativeToReference": 1}],
                  "opt": {"calccompl": False,
                          "continuation": {"method": "arclength", "ds": 0.002, "ds_max": 0.004, "node": c,
                                           "direction": "y", "max_steps": 24}}})

ref = Shallow(L, EI, EA, w0, 0.0)
Flim, wlim = ref.extreme(0.0, 0.999 * ref.P2, 1, 1)
print(f"  shallow-arch theory: limit load {Flim:.6f} N at mid-span w = {wlim * 1e3:.6f} mm")

runs = {}
for np_ in (2, 1):
    h5, out = st.run(f"continuation_ancf_{np_}", scene, np_=np_, args=["-continuation_lowest_eigenvalue"])
    with st.h5(h5) as f:
        runs[np_] = dict(lam=f["load_factor"][:], p=f["node/p"][:], slope=f["node/slope"][:],
                         neg=f["path/negative_eigenvalues"][:], crit=f["path/critical_points"][:],
                         low=f["path/lowest_eigenvalue"][:], y0=f["node/p"][0, c - 1, 1] - f["path/control_displacement"][0],
                         conv=int(f.attrs["converged"]))
r = runs[2]
print("  load factors", np.array2string(r["lam"], precision=4))
print("  negative eigenvalues", r["neg"].astype(int))
st.check(r["conv"] == 1 and len(r["lam"]) == 24, f"path converged, 24 points ({len(r['lam'])})")
crit = r["crit"]
if st.check(len(crit) == 1 and crit[0, 0] == 1, f"one limit point located ({crit})"):
    st.close(crit[0, 2], Flim, rtol=5e-3, what="limit load [N] vs shallow-arch theory (measured +0.21%)")
    st.close(r["y0"] + crit[0, 3], wlim, rtol=1e-2, what="mid-span position at the limit point [m]")
    k = int(crit[0, 1])
    st.check(np.all(r["neg"][:k] == 0) and np.all(r["neg"][k:] == 1), "0 negative eigenvalues before the limit point, 1 after")
    st.check(r["lam"][k - 1] > r["lam"][-1] + 0.1, "the path goes down past the limit point (snap-through branch)")
st.check(np.array_equal(r["low"] < 0, r["neg"] > 0), "SLEPc's lowest eigenvalue < 0 exactly where the inertia counts one")
r1 = runs[1]
if st.check(len(r1["lam"]) == len(r["lam"]), "1 and 2 ranks: same number of path points"):
    st.close(r1["lam"], r["lam"], atol=1e-9 * Flim, what="1 vs 2 ranks: load factors [N]")
    st.close(r1["p"], r["p"], atol=1e-9 * L, what="1 vs 2 ranks: positions [m]")
    st.close(r1["slope"], r["slope"], atol=1e-9, what="1 vs 2 ranks: slopes")
    st.check(np.array_equal(r1["neg"], r["neg"]), "1 vs 2 ranks: negative eigenvalue counts")
st.done()
