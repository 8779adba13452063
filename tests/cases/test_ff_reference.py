# ctest-labels: smoke
"""Form finding against the references of ../shared/references section C: C1 cable patch, C2
five-node membrane (anisotropic and isotropic), C3 force density (one free node, loaded chain),
C5 hypar net z = c x y. 2 ranks."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from sinewtest import run, h5, close, check, done, SOURCE, WORK  # noqa: E402
from ffscenes import c2_scene, to_yaml  # noqa: E402

os.makedirs(WORK, exist_ok=True)

# C1: runs/cable_patch.yaml, free node -> (1, 0.5, 0)
out, log = run("ff_c1", os.path.join(SOURCE, "runs", "cable_patch.yaml"))
with h5(out) as f:
    nff = len(f["formfinding/residual"])
    close(f["node/p"][nff - 1, 4], [1.0, 0.5, 0.0], atol=1e-10, what="C1 free node (found shape)")
    check(f["formfinding/shape_change"][-1] < 1e-9, "C1 stops on formfinding_tolerance")
    close(f["load_factor"][:nff], np.zeros(nff), atol=0, what="C1 form-finding rows have load factor 0")

# C2: node 5 uz after steps 1, 2, 3
out, log = run("ff_c2", to_yaml(c2_scene()))
with h5(out) as f:
    uz = f["node/p"][:3, 4, 2] - 5.0
    close(uz, [-35 / 19, -2.324760220, -2.453273210], atol=1e-8, what="C2 node 5 uz after steps 1-3")
    check(len(f["formfinding/residual"]) == 3, "C2 three form-finding rows")
# Kratos' membrane_test/test_formfinding setup (docs/formfinding.md, "C2 and Kratos' test"): its element
# node order [1,2,5], [1,5,3], [3,4,5], [2,4,5], E = 0 and one Newton iteration per step (max_iters 1):
# the same C2 values (the reference problem of a step is linear), not Kratos' stored -2.16216216216
kr = c2_scene()
kr["elements"] = [[1, 2, 5], [1, 5, 3], [3, 4, 5], [2, 4, 5]]
kr["eprops"][0]["emod"] = 0
kr["formfinding"]["max_iter_equilibrium"] = 1
out, log = run("ff_c2_kratos_setup", to_yaml(kr))
with h5(out) as f:
    close(f["node/p"][:3, 4] - 5.0, [[0, 0, u] for u in (-35 / 19, -2.324760220, -2.453273210)], atol=1e-8,
          what="C2 in Kratos' element order, E = 0, one iteration per step: node 5 displacement after steps 1-3")
    check(abs(f["node/p"][2, 4, 2] - 5.0 + 80 / 37) > 0.29, "not Kratos' -80/37 = -2.16216 after 3 steps")
# converged, anisotropic and isotropic
for name, ps in (("ff_c2_conv", (2, 1, 0)), ("ff_c2_iso", (1, 1, 0))):
    out, log = run(name, to_yaml(c2_scene(prestress=ps, steps=200, tol=1e-12)))
    with h5(out) as f:
        nff = len(f["formfinding/residual"])
        close(f["node/p"][nff - 1, 4, 2] - 5.0, -2.5, atol=1e-8, what=f"{name}: converged node 5 uz")

# C3a: one free node, three cables with different force densities q_j = N0_j / L_j, load p
X = np.array([[0.0, 0, 0], [3, 0, 0], [0, 2, 1], [0.5, 0.5, 0.2]])
N0 = [1.0, 2.0, 3.0]
p = np.array([0.3, -0.2, -1.0])
sc = {"nodes": X.tolist(), "elements": [[1, 4], [2, 4], [3, 4]],
      "nprops": {"1": {"fix": True}, "2": {"fix": True}, "3": {"fix": True}, "4": {"force_initial": p.tolist()}},
      "eprops": [{"elems": [j + 1], "type": "cable", "area": 1, "emod": 1e6, "prestress": N0[j]} for j in range(3)],
      "formfinding": {"formfinding_step": 1, "equilibrium_accuracy": 1e-13, "formfinding_tolerance": 0}, "opt": {"loadsteps": 1}}
q = np.array([N0[j] / np.linalg.norm(X[3] - X[j]) for j in range(3)])
xfd = (p + (q[:, None] * X[:3]).sum(0)) / q.sum()
out, log = run("ff_c3_node", to_yaml(sc))
with h5(out) as f:
    close(f["node/p"][0, 3], xfd, atol=1e-12, what="C3 one free node = (p + sum q x)/sum q")

# C3b: chain of n free nodes, spacing h, uniform q = N0/h, loads P down: z_i = -(P/2q) i (n+1-i)
n, h, qd, P = 9, 0.5, 4.0, 0.7
nodes = [[i * h, 0, 0] for i in range(n + 2)]
sc = {"nodes": nodes, "elements": [[i + 1, i + 2] for i in range(n + 1)],
      "nprops": dict({"1": {"fix": True}, str(n + 2): {"fix": True}},
                     **{str(i + 1): {"force_initial": [0, 0, -P]} for i in range(1, n + 1)}),
      "eprops": [{"elems": list(range(1, n + 2)), "type": "cable", "area": 1, "emod": 1e6, "prestress": qd * h}],
      "formfinding": {"formfinding_step": 1, "equilibrium_accuracy": 1e-13, "formfinding_tolerance": 0}, "opt": {"loadsteps": 1}}
out, log = run("ff_c3_chain", to_yaml(sc))
i = np.arange(1, n + 1)
with h5(out) as f:
    close(f["node/p"][0, 1:n + 1, 2], -(P / (2 * qd)) * i * (n + 1 - i), atol=1e-12, what="C3 loaded chain parabola")
    close(f["node/p"][0, 1:n + 1, 0], i * h, atol=1e-12, what="C3 chain x unchanged")

# C5: square net, uniform force density, boundary on z = c x y: interior reproduces z = c x y
m, c = 8, 0.3
xs = np.linspace(-1, 1, m + 1)
nid = lambda i, j: j * (m + 1) + i
nodes = [[xs[i], xs[j], 0.0] for j in range(m + 1) for i in range(m + 1)]
els = [[nid(i, j) + 1, nid(i + 1, j) + 1] for j in range(m + 1) for i in range(m)] + \
      [[nid(i, j) + 1, nid(i, j + 1) + 1] for j in range(m) for i in range(m + 1)]
nprops = {}
for j in range(m + 1):
    for i in range(m + 1):
        if i in (0, m) or j in (0, m):
            nprops[str(nid(i, j) + 1)] = {"fix": True, "displ_initial_z": c * xs[i] * xs[j]}
sc = {"nodes": nodes, "elements": els, "nprops": nprops,
      "eprops": [{"elems": list(range(1, len(els) + 1)), "type": "cable", "area": 1, "emod": 0,
                  "prestress": 2.0 * (xs[1] - xs[0])}],
      "formfinding": {"formfinding_step": 1, "equilibrium_accuracy": 1e-13, "formfinding_tolerance": 0}, "opt": {"loadsteps": 1}}
out, log = run("ff_c5", to_yaml(sc))
with h5(out) as f:
    pz = f["node/p"][0, :, :]
    close(pz[:, 2], c * pz[:, 0] * pz[:, 1], atol=1e-12, what="C5 net z = c x y")
done()
