"""Scene builders shared by the form-finding system tests (test_ff_*.py) and scripts."""
import numpy as np


def c2_scene(prestress=(2, 1, 0), steps=3, tol=0.0):
    """tol 0: exactly `steps` URS steps (the reference gives steps 1-3), no stop rule."""
    return {
        "title": "C2 five-node membrane",
        "nodes": [[0, 0, 0], [0, 10, 5], [10, 0, 5], [10, 10, 0], [5, 5, 5]],
        "elements": [[1, 3, 5], [3, 4, 5], [4, 2, 5], [2, 1, 5]],
        "nprops": {str(i): {"fix": True} for i in range(1, 5)},
        "eprops": [{"elems": [1, 2, 3, 4], "type": "membrane", "thickness": 1, "emod": 1000, "nu": 0,
                    "prestress": list(prestress)}],
        "formfinding": {"formfinding_step": steps, "max_iter_equilibrium": 20, "equilibrium_accuracy": 1e-12,
                        "formfinding_elements": [1], "formfinding_tolerance": tol},
        "opt": {"loadsteps": 1},
    }


def sail_scene(n=8, h=0.5, cable_prestress=4.0, mem_prestress=1.0, steps=10, adapt=False, distort=0.0,
               pressure=None, restart="FORCE", seed=1, tol=0.0):
    """Four-point sail on the unit square: corners (0,0) and (1,1) low, (1,0) and (0,1) lifted by h
    (displ_initial_z), edge cables on the boundary, n x n cells with 4 triangles each (centre node),
    symmetric under x <-> y and (x, y) -> (1 - x, 1 - y). distort > 0 moves interior nodes in plane
    by up to distort * cell size (seeded). tol: formfinding_tolerance (0: exactly `steps` steps, as the
    tests that compare fixed step counts need; a run that uses up formfinding_step before a positive
    tolerance ends with exit 3)."""
    nodes, idx = [], {}
    rng = np.random.default_rng(seed)
    for j in range(n + 1):
        for i in range(n + 1):
            idx[("v", i, j)] = len(nodes)
            nodes.append([i / n, j / n, 0.0])
    for j in range(n):
        for i in range(n):
            idx[("c", i, j)] = len(nodes)
            nodes.append([(i + 0.5) / n, (j + 0.5) / n, 0.0])
    if distort > 0:
        for k, x in enumerate(nodes):
            if 1e-12 < x[0] < 1 - 1e-12 and 1e-12 < x[1] < 1 - 1e-12:
                d = rng.uniform(-distort, distort, 2) / n
                x[0] += d[0]
                x[1] += d[1]
    tris, cables = [], []
    for j in range(n):
        for i in range(n):
            a, b = idx[("v", i, j)], idx[("v", i + 1, j)]
            c, d = idx[("v", i + 1, j + 1)], idx[("v", i, j + 1)]
            m = idx[("c", i, j)]
            tris += [[a, b, m], [b, c, m], [c, d, m], [d, a, m]]
    for k in range(n):
        cables += [[idx[("v", k, 0)], idx[("v", k + 1, 0)]], [idx[("v", n, k)], idx[("v", n, k + 1)]],
                   [idx[("v", k, n)], idx[("v", k + 1, n)]], [idx[("v", 0, k)], idx[("v", 0, k + 1)]]]
    elements = [[v + 1 for v in t] for t in tris] + [[v + 1 for v in c] for c in cables]
    nt = len(tris)
    corners = {idx[("v", 0, 0)]: 0.0, idx[("v", n, n)]: 0.0, idx[("v", n, 0)]: h, idx[("v", 0, n)]: h}
    nprops = {str(k + 1): {"fix": True, "displ_initial_z": z} if z else {"fix": True} for k, z in corners.items()}
    mem = {"elems": list(range(1, nt + 1)), "type": "membrane", "thickness": 1e-3, "emod": 1e7, "nu": 0.3,
           "prestress": [mem_prestress / 1e-3] * 2 + [0]}
    if pressure is not None:
        mem["pressure"] = pressure
    cab = {"elems": list(range(nt + 1, len(elements) + 1)), "type": "cable", "area": 1e-4, "emod": 1e8,
           "prestress": cable_prestress}
    ff = {"formfinding_step": steps, "max_iter_equilibrium": 30, "equilibrium_accuracy": 1e-10,
          "formfinding_elements": [1, 2], "elastic_restart_method": restart, "formfinding_tolerance": tol}
    if adapt:
        ff.update({"stress_adaption": [1], "lambda_max": 1.1})
    return {"title": "four-point sail", "nodes": nodes, "elements": elements, "nprops": nprops,
            "eprops": [mem, cab], "formfinding": ff, "opt": {"loadsteps": 1}}, idx


def catenoid_scene(R=1.0, halfh=0.5, nt=32, nz=16, steps=40, tol=1e-9, urs_x=False):
    """Cylinder of radius R between rings at z = -halfh, +halfh (fixed), isotropic prestress,
    triangles; form finding towards the catenoid r = a cosh(z/a), R = a cosh(halfh/a)."""
    nodes = []
    for k in range(nz + 1):
        z = -halfh + 2 * halfh * k / nz
        for i in range(nt):
            t = 2 * np.pi * (i + 0.5 * (k % 2)) / nt
            nodes.append([R * np.cos(t), R * np.sin(t), z])
    el = []
    for k in range(nz):
        for i in range(nt):
            a, b = k * nt + i, k * nt + (i + 1) % nt
            c, d = (k + 1) * nt + (i + 1) % nt, (k + 1) * nt + i
            if k % 2 == 0:
                el += [[a, b, d], [b, c, d]]
            else:
                el += [[a, b, c], [a, c, d]]
    nprops = {str(k * nt + i + 1): {"fix": True} for k in (0, nz) for i in range(nt)}
    ff = {"formfinding_step": steps, "max_iter_equilibrium": 30, "equilibrium_accuracy": 1e-10,
          "formfinding_elements": [1], "formfinding_tolerance": tol}
    if urs_x:
        ff.update({"x_urs": True, "x_urs_step": 1})
    return {"title": "catenoid", "nodes": nodes, "elements": [[v + 1 for v in e] for e in el], "nprops": nprops,
            "eprops": [{"elems": list(range(1, len(el) + 1)), "type": "membrane", "thickness": 1, "emod": 1000,
                        "nu": 0, "prestress": [1, 1, 0]}],
            "formfinding": ff, "opt": {"loadsteps": 1}}


def catenoid_a(R, halfh):
    """Neck radius a of the stable catenoid R = a cosh(halfh / a) (None beyond the limit)."""
    from math import cosh
    f = lambda a: a * cosh(halfh / a) - R
    # stable branch: the larger root; bracket between the minimum of f and R
    lo, hi = 0.05 * halfh, R
    grid = np.linspace(lo, hi, 20001)
    vals = [f(a) for a in grid]
    k = int(np.argmin(vals))
    if vals[k] > 0:
        return None
    lo, hi = grid[k], R
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) < 0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def to_yaml(scene):
    """Scene dict -> YAML text; nprops keys become integers (node numbers)."""
    import yaml
    s = dict(scene)
    if "nprops" in s:
        s["nprops"] = {int(k) if str(k).isdigit() else k: v for k, v in s["nprops"].items()}

    def clean(o):
        if isinstance(o, dict):
            return {k: clean(v) for k, v in o.items()}
        if isinstance(o, (list, tuple)):
            return [clean(v) for v in o]
        if isinstance(o, np.generic):
            return o.item()
        return o
    return yaml.safe_dump(clean(s), default_flow_style=None, sort_keys=False, width=200)


def catenary_scene(n=40, span=10.0, length=12.0, w=1.0, EA=1e7, N0=5.0, loadsteps=1):
    """C4 chain of n elastic cables (area 1, emod EA) between fixed ends (0,0,0), (span,0,0) under
    gravity w per unstretched length (ramped). Start: equal chords on a circular arc, each of length
    L = h / (1 - N0/EA) with prestress N0, so that every cable is taut and its stress-free length is
    h = length / n exactly; density 1 - N0/EA makes the weight rho A L = w h."""
    eps = N0 / EA
    S = length / (1 - eps)
    f = lambda th: np.sin(th / 2) / (n * np.sin(th / (2 * n))) - span / S
    lo, hi = 1e-9, 2 * np.pi - 1e-9
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) > 0 else (lo, mid)
    th = 0.5 * (lo + hi)
    R = span / (2 * np.sin(th / 2))
    ang = -np.pi / 2 - th / 2 + th * np.arange(n + 1) / n
    X = np.c_[span / 2 + R * np.cos(ang), np.zeros(n + 1), R * np.sin(ang) - R * np.sin(ang[0])]
    X[0], X[n] = [0, 0, 0], [span, 0, 0]
    return {"title": "C4 catenary", "nodes": X.tolist(), "elements": [[i + 1, i + 2] for i in range(n)],
            "nprops": {"1": {"fix": True}, str(n + 1): {"fix": True}},
            "eprops": [{"elems": list(range(1, n + 1)), "type": "cable", "area": 1.0, "emod": EA, "dens": w * (1 - eps),
                        "prestress": N0}],
            "opt": {"loadsteps": loadsteps, "gravity": [0, 0, -w]}}
