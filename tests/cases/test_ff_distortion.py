"""Form finding of a strongly distorted mesh with and without shape distortion control
(stress_adaption with distortion_max, docs/formfinding.md). Square [0,1]^2, 6 x 6 cells of two
triangles, boundary fixed on the hypar z = c (2x - 1)(2y - 1)/2 (straight edges), isotropic
prestress, interior nodes start at z = 0 and are moved in plane by up to 0.45 cells (seeded):
initial mesh quality 0.0020. Without control the URS keeps the distorted parametrisation (the
reference problem reproduces the reference mesh); with control the mesh is regularised. Checks:
both runs reach equilibrium and stop on the normal shape change, the found surfaces agree within
a measured tolerance, the mesh quality is better with control by a wide margin, no element
collapses, and the controlled run ends with anisotropic stress only where it regularised."""
import os
import re
import sys

import numpy as np
from scipy.interpolate import LinearNDInterpolator

sys.path.insert(0, os.path.dirname(__file__))
from sinewtest import run, h5, close, check, done, WORK  # noqa: E402
from ffscenes import to_yaml  # noqa: E402

os.makedirs(WORK, exist_ok=True)
C = 0.5  # hypar rise factor: boundary z in [-0.25, 0.25]


def scene(n=6, distort=0.45, adapt=None, steps=40, tol=1e-7, seed=3):
    rng = np.random.default_rng(seed)
    nodes, fix = [], []
    for j in range(n + 1):
        for i in range(n + 1):
            x, y = i / n, j / n
            bnd = i in (0, n) or j in (0, n)
            if not bnd and distort > 0:
                d = rng.uniform(-distort, distort, 2) / n
                x, y = x + d[0], y + d[1]
            nodes.append([x, y, C * (2 * x - 1) * (2 * y - 1) / 2 if bnd else 0.0])
            if bnd:
                fix.append(len(nodes))
    nid = lambda i, j: j * (n + 1) + i + 1
    el = []
    for j in range(n):
        for i in range(n):
            a, b, c, d = nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1)
            el += [[a, b, c], [a, c, d]] if (i + j) % 2 == 0 else [[a, b, d], [b, c, d]]
    ff = {"formfinding_step": steps, "max_iter_equilibrium": 20, "equilibrium_accuracy": 1e-10,
          "formfinding_tolerance": tol}
    if adapt:
        ff.update(adapt)
    return {"title": "distorted hypar patch", "nodes": nodes, "elements": el,
            "nprops": {str(k): {"fix": True} for k in fix},
            "eprops": [{"elems": list(range(1, len(el) + 1)), "type": "membrane", "thickness": 1, "emod": 1000,
                        "nu": 0, "prestress": [1, 1, 0]}],
            "formfinding": ff, "opt": {"loadsteps": 1}}


def result(name, sc, expect_exit=0):
    out, log = run(name, to_yaml(sc), expect_exit=expect_exit)
    m = re.search(r"membrane mesh quality: initial ([0-9.]+), found ([0-9.]+)", log)
    with h5(out) as f:
        nff = len(f["formfinding/residual"])
        r = dict(P=f["node/p"][nff - 1][:], P0=f["node/p"][0][:] - 0.0, steps=nff,
                 res=f["formfinding/residual"][:], normal=f["formfinding/shape_change_normal"][:],
                 force=f["element/force"][nff - 1][:] if "element/force" in f else None,
                 q0=float(m.group(1)), q=float(m.group(2)), converged=int(f.attrs["converged"]))
    return r, log


def areas(P, el):
    e = np.asarray(el) - 1
    return 0.5 * np.linalg.norm(np.cross(P[e[:, 1]] - P[e[:, 0]], P[e[:, 2]] - P[e[:, 0]]), axis=1)


plain_sc = scene()
ctrl_sc = scene(adapt={"stress_adaption": [1], "lambda_max": 1, "distortion_max": 1.1})
# issue 10 item 14: the uncontrolled mesh uses up formfinding_step (40) before formfinding_tolerance
# 1e-7: exit 3, converged = 0, and a message that says so (the 40 rows are still written)
plain, plain_log = result("ff_distort_plain", plain_sc, expect_exit=3)
check(plain["converged"] == 0, "without control: converged = 0 in the result file")
check("the shape is not converged after formfinding_step = 40 steps" in plain_log,
      "without control: message says the shape is not converged")
# a -restart of that run finds its 40 steps done: the same exit 3 and converged = 0 (the checkpoint's
# form-finding history is re-checked against formfinding_tolerance)
rs_out, rs_log = run("ff_distort_plain_rs", to_yaml(plain_sc), args=["-restart", os.path.join(WORK, "ff_distort_plain.h5")],
                     expect_exit=3)
with h5(rs_out) as f:
    check(int(f.attrs["converged"]) == 0 and len(f["formfinding/residual"]) == 40,
          "restart of the unconverged run: converged = 0, the 40 form-finding rows")
check("continuing the form finding" in rs_log and "the shape is not converged" in rs_log,
      "restart of the unconverged run: continues the form finding and reports the shape not converged")
ctrl, _ = result("ff_distort_ctrl", ctrl_sc)
for name, r in (("without control", plain), ("with distortion_max 1.1", ctrl)):
    print(f"  {name}: {r['steps']} steps, residual {r['res'][-1]:.2e}, normal change {r['normal'][-1]:.2e}, "
          f"mesh quality initial {r['q0']:.4f} found {r['q']:.4f}")
    check(r["res"][-1] < 1e-10, f"{name}: equilibrium at the found shape")
# without control the mesh drifts in the surface (the URS leaves it undetermined): normal change still
# 3.3e-5 after 40 steps; the controlled mesh is pinned and stops on the tolerance 1e-7 (measured: step 10)
check(plain["steps"] == 40 and plain["normal"][-1] < 1e-4, "without control: normal change below 1e-4 after 40 steps")
check(ctrl["steps"] < 20 and ctrl["normal"][-1] < 1e-7, "with control: stops on the normal shape change 1e-7")
check(plain["q0"] < 0.01, f"initial mesh strongly distorted (quality {plain['q0']:.4f})")
# measured: 0.0027 without, 0.7339 with control (the undistorted 6 x 6 mesh reaches 0.7298)
check(ctrl["q"] > plain["q"] + 0.5, f"mesh quality with control {ctrl['q']:.4f} vs without {plain['q']:.4f}")
check(plain["q"] < 0.01, "without control the URS keeps the distorted mesh")
# same surface: z of one found mesh against the piecewise-linear surface of the other (both ways);
# measured 7.4e-3 (3 % of the rise 0.25; the control modifies the stress of the regularised elements,
# its surface is within 2.7e-4 of the hypar, the 200-step undistorted mesh within 3.8e-3)
diff = 0.0
for A, B in ((plain["P"], ctrl["P"]), (ctrl["P"], plain["P"])):
    zi = LinearNDInterpolator(A[:, :2], A[:, 2])(B[:, :2])
    diff = max(diff, np.nanmax(np.abs(zi - B[:, 2])))
print(f"  found surfaces, max |z difference|: {diff:.3e}")
check(diff < 1e-2, f"both runs find the same surface within 1e-2 (measured {diff:.3e})")
# nothing collapses: every triangle keeps a sizeable area, interior nodes stay inside the square
for name, r in (("without", plain), ("with", ctrl)):
    a = areas(r["P"], plain_sc["elements"])
    print(f"  {name} control: smallest triangle area {a.min():.3e} (mean {a.mean():.3e})")
    check(a.min() > 1e-4 * a.mean(), f"{name} control: no element collapsed")
    check(np.all((r["P"][:, :2] > -1e-12) & (r["P"][:, :2] < 1 + 1e-12)), f"{name} control: nodes inside the square")
check(areas(ctrl["P"], plain_sc["elements"]).min() > 0.2 * areas(ctrl["P"], plain_sc["elements"]).mean(),
      "with control: no sliver triangles")
done()
