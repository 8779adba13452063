"""-target_error on ANCF cables (docs/accuracy.md, "ANCF cables"), from nbeams 1, 2 ranks: the cubic
Hermite cable's nodal positions and rotations converge as h^4 (nodal superconvergence of a C1 cubic,
2(k + 1 - m) with k = 3, m = 2), its frequencies as h^4; with that order (ElementKind::nodalOrder)
the estimates are trusted ("converging") instead of "resolved" or "erratic" under the beams' h^2.
Statics: reference A2 (Exudyn ANCFCable2DBendingTest, tip force 3 EI / L^2, 10 load steps), true error
|tip - A2(256 elements)| / |A2(256)| (A2(256) is within about 1e-11 of the limit). Frequencies: the
unloaded A1 cantilever, f1..f3 against Euler-Bernoulli. Targets 1e-3, 1e-5, 1e-7: the true error is
within the target, the estimate within a factor 3 of it."""
import numpy as np

import sinewtest as st

A2_TIP = np.array([-0.5085373043209689, -1.2072398545457785])
BETA_L = np.array([1.875104068711961, 4.694091132974175, 7.854757438237613])


def cantilever(props, nprops, opt):
    p = {"elems": [1], "type": "ancf_cable2d", "nbeams": 1, "useReducedOrderIntegration": 0}
    p.update(props)
    n = {1: {"fix_coords": [1, 1, 0, 1]}}
    n.update(nprops)
    return {"title": "ANCF cantilever", "nodes": [[0, 0], [2, 0]], "elements": [[1, 2]], "nprops": n, "eprops": [p],
            "opt": opt}


def statics(target):
    return cantilever({"physicsMassPerLength": 78, "physicsBendingStiffness": 1.725e6, "physicsAxialStiffness": 2.07e9},
                      {2: {"force": [0, -3 * 1.725e6 / 4]}}, {"loadsteps": 10, "calcfreq": False, "target_error": target})


def frequencies(target):
    return cantilever({"physicsMassPerLength": 78, "physicsBendingStiffness": 833.3333333333333,
                       "physicsAxialStiffness": 1e6}, {}, {"calcfreq": True, "nfreq": 3, "target_error": target})


FREQ_REF = BETA_L ** 2 / 2.0 ** 2 * np.sqrt(833.3333333333333 / 78) / (2 * np.pi)


def accuracy(f, name):
    g = f["accuracy"]
    names = [n for n in g.attrs["quantities"].split("\n") if n]
    k = names.index(name)
    return (float(g["error"][-1][k]), int(g["status"][-1][k]), float(g["order"][-1][k]), int(g.attrs["met"]),
            ", ".join(str(int(x)) for x in g["nbeams_factor"][:]), int(g["unknowns"][-1]), float(np.sum(g["wall_time"][:])))


for target in (1e-3, 1e-5, 1e-7):
    path, _ = st.run(f"accuracy_ancf_statics_{target:g}", statics(target))
    with st.h5(path) as f:
        tip = f["node/p"][-1, 1, :2] - f["node/p0"][1, :2]
        est, status, order, met, nbeams, unknowns, wall = accuracy(f, "node 2 p")
    true = np.linalg.norm(tip - A2_TIP) / np.linalg.norm(A2_TIP)
    print(f"  A2 tip, target {target:g}: levels of nbeams {nbeams}, {unknowns} unknowns, {wall:.2f} s; "
          f"true error {true:.2e}, estimate {est:.2e} (ratio {est / true:.2f}), order {order:.2f}")
    st.check(met == 1 and status == 0, f"A2 {target:g}: met, tip position converging (status {status}) under h^4")
    st.check(true <= target, f"A2 {target:g}: true error {true:.2e} above the target")
    st.check(1 / 3 <= est / true <= 3, f"A2 {target:g}: estimate {est:.2e} vs true {true:.2e} outside a factor 3")

for target in (1e-3, 1e-5, 1e-7):
    path, _ = st.run(f"accuracy_ancf_freq_{target:g}", frequencies(target))
    with st.h5(path) as f:
        true = np.abs(f["freq"][-1][:3] / FREQ_REF - 1)
        figures = [accuracy(f, f"freq {k + 1}") for k in range(3)]
    est = np.array([x[0] for x in figures])
    _, _, _, met, nbeams, unknowns, wall = figures[0]
    print(f"  A1 f1..f3, target {target:g}: levels of nbeams {nbeams}, {unknowns} unknowns, "
          f"{wall:.2f} s; true errors {np.array2string(true, precision=2)}, estimates {np.array2string(est, precision=2)}")
    st.check(met == 1 and true.max() <= target, f"A1 {target:g}: met, true error {true.max():.2e} within the target")
    for k in range(3):
        if true[k] > target / 100 or k == int(np.argmax(true)):
            st.check(1 / 3 <= est[k] / true[k] <= 3, f"A1 {target:g}: freq {k + 1}: estimate {est[k]:.2e} vs true "
                                                     f"{true[k]:.2e} outside a factor 3")
st.done()
