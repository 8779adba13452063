"""Natural frequencies of a prestressed membrane after form finding (issue 5, item 4): a flat square
membrane (side a = 1, thickness 1 mm, density 1000, isotropic prestress s0 = 1 MPa) fixed on its
edges, form-found (it stays flat) and restarted with FORCE, so the frequency analysis sees the
prestress as initial stress. Transverse modes of a prestressed membrane:
f_mn = (c / 2a) sqrt(m^2 + n^2), c = sqrt(s0 / rho). Checks f_11 and f_12 (double) on 16x16 and
32x32 quads (second-order convergence) and that doubling the prestress scales them by sqrt(2)."""
import math

import numpy as np

import ancf_scenes as A
import sinewtest as st


def membrane(n, s0):
    nodes, idx = [], {}
    for j in range(n + 1):
        for i in range(n + 1):
            idx[i, j] = len(nodes) + 1
            nodes.append([i / n, j / n, 0.0])
    elems = [[idx[i, j], idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]] for j in range(n) for i in range(n)]
    nprops = {k: {"fix": True} for (i, j), k in idx.items() if i in (0, n) or j in (0, n)}
    return {"title": "prestressed square membrane", "nodes": nodes, "elements": elems, "nprops": nprops,
            "eprops": [{"elems": list(range(1, len(elems) + 1)), "type": "membrane", "thickness": 1e-3,
                        "emod": 1e9, "nu": 0.3, "dens": 1000, "prestress": [s0, s0, 0]}],
            "formfinding": {"formfinding_step": 3, "formfinding_elements": [1], "elastic_restart_method": "FORCE"},
            "opt": {"loadsteps": 1, "nfreq": 4}}


c = math.sqrt(1e6 / 1000)
exact = np.array([c / 2 * math.sqrt(2), c / 2 * math.sqrt(5), c / 2 * math.sqrt(5)])
err = {}
for n in (16, 32):
    h5, _ = st.run(f"ff_membrane_freq_{n}", A.text(membrane(n, 1e6)))
    with st.h5(h5) as f:
        fr = f["freq"][-1][:3]
    err[n] = np.abs(fr - exact) / exact
    st.close(fr, exact, rtol=6e-3 if n == 16 else 1.5e-3, what=f"{n}x{n}: f11, f12, f21 [Hz]")  # measured 5.5e-3, 1.4e-3
st.check(err[16][0] / err[32][0] > 3.5, f"second-order convergence of f11: error ratio {err[16][0] / err[32][0]:.2f}")
h5, _ = st.run("ff_membrane_freq_2s0", A.text(membrane(16, 2e6)))
with st.h5(h5) as f2, st.h5(st.os.path.join(st.WORK, "ff_membrane_freq_16.h5")) as f1:
    st.close(f2["freq"][-1][:3] / f1["freq"][-1][:3], [math.sqrt(2)] * 3, rtol=1e-6,
             what="doubling the prestress scales the frequencies by sqrt(2)")
st.done()
