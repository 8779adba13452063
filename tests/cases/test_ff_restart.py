"""Form finding, then what the load analysis starts from: elastic_restart_method FORCE,
DISPLACEMENT and NONE on the C1 cable patch under an in-plane point load (closed-form answers below);
the normal shape change stopping form finding of the sail (in-plane mesh drift ignored).
2 ranks."""
import os
import sys

import numpy as np
from scipy.optimize import brentq

sys.path.insert(0, os.path.dirname(__file__))
from sinewtest import run, h5, close, check, done, WORK  # noqa: E402
from ffscenes import sail_scene, to_yaml  # noqa: E402

os.makedirs(WORK, exist_ok=True)

# --- restart methods. C1 patch: corners (0,0) (2,0) (2,1) (0,1) fixed, node 5 starts at (1,0,0) and
# is form-found to (1, 0.5, 0) by four cables (prestress N0 = 1, EA = 100). Then a load P = 2 in -y
# on node 5; by symmetry it moves along y only, to y = y5. Cable lengths l_b = |(1, y5)| (bottom
# corners), l_t = |(1, 1 - y5)| (top), N = max(N0' + EA (l/L - 1), 0), y equilibrium
#   2 N_t (1 - y5)/l_t - 2 N_b y5/l_b = P.
#   FORCE:        L = sqrt(1.25) (found lengths), N0' = 1
#   DISPLACEMENT: L = sqrt(1.25), N0' = 0 (found shape stress-free)
#   NONE:         L_b = 1, L_t = sqrt(2) (initial lengths), N0' = 0
EA, P = 100.0, 2.0


def y5(Lb, Lt, N0):
    def g(y):
        lb, lt = np.hypot(1, y), np.hypot(1, 1 - y)
        Nb, Nt = max(N0 + EA * (lb / Lb - 1), 0), max(N0 + EA * (lt / Lt - 1), 0)
        return 2 * Nt * (1 - y) / lt - 2 * Nb * y / lb - P
    return brentq(g, -0.9, 0.9, xtol=1e-15)


expected = {"FORCE": y5(np.sqrt(1.25), np.sqrt(1.25), 1.0), "DISPLACEMENT": y5(np.sqrt(1.25), np.sqrt(1.25), 0.0),
            "NONE": y5(1.0, np.sqrt(2.0), 0.0)}
ys = {}
for method in ("FORCE", "DISPLACEMENT", "NONE"):
    sc = {"nodes": [[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0], [1, 0, 0]], "elements": [[1, 5], [2, 5], [3, 5], [4, 5]],
          "nprops": {"1": {"fix": True}, "2": {"fix": True}, "3": {"fix": True}, "4": {"fix": True},
                     "5": {"force": [0, -P, 0]}},
          "eprops": [{"elems": [1, 2, 3, 4], "type": "cable", "area": 1, "emod": EA, "prestress": 1.0}],
          "formfinding": {"formfinding_step": 40, "equilibrium_accuracy": 1e-12, "formfinding_tolerance": 1e-13,
                          "elastic_restart_method": method},
          "opt": {"loadsteps": 2}}
    out, log = run(f"ff_restart_{method}", to_yaml(sc))
    with h5(out) as f:
        nff = len(f["formfinding/residual"])
        p = f["node/p"]
        close(p[nff - 1, 4], [1, 0.5, 0], atol=1e-10, what=f"{method}: found node 5")
        close(p[-1, 4], [1, expected[method], 0], atol=1e-9, what=f"{method}: node 5 under P")
        ys[method] = p[-1, 4, 1]
        if method == "DISPLACEMENT":  # bottom cables shortened without prestress: slack, no reaction
            close(f["node/Freac"][-1, :2], np.zeros((2, 3)), atol=1e-12, what="DISPLACEMENT: bottom corners carry nothing")
        if method == "NONE":  # node 5 below the bottom corners: all four cables are taut and pull it up
            R = f["node/Freac"][-1, :4, 1]
            check(np.all(R > 0), f"NONE: every corner reaction points up ({R})")
            close(R.sum(), P, rtol=1e-10, what="NONE: sum of the corner reactions = P")
print(f"  node 5 y under P = {P}: FORCE {ys['FORCE']:.9f}, DISPLACEMENT {ys['DISPLACEMENT']:.9f}, "
      f"NONE {ys['NONE']:.9f}")
check(ys["FORCE"] > ys["DISPLACEMENT"], "prestress (FORCE) stiffens the patch against DISPLACEMENT")

# --- convergence measure: the sail stops on the normal shape change while the mesh still drifts
sc, idx = sail_scene(n=8, steps=60)
sc["formfinding"]["formfinding_tolerance"] = 1e-7
out, log = run("ff_sail_normal", to_yaml(sc))
with h5(out) as f:
    sn = f["formfinding/shape_change_normal"][:]
    st = f["formfinding/shape_change"][:]
    r = f["formfinding/residual"][:]
print(f"  sail: {len(sn)} steps, last total shape change {st[-1]:.3e}, normal {sn[-1]:.3e}, residual {r[-1]:.3e}")
check(len(sn) < 60 and sn[-1] < 1e-7, "sail stops on the normal shape change before formfinding_step")
check(st[-1] > 10 * sn[-1], "the total change (in-plane drift) is far above the normal change at the stop")
check(np.all(sn <= st * (1 + 1e-12)), "normal change <= total change")
done()
