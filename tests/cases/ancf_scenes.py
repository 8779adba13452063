"""Scene builders for the ANCF cable system tests (Exudyn ObjectANCFCable2D references A1-A5 of
../shared/references/README.md)."""
import json
import re


def text(scene):
    """JSON text (valid YAML) with integer nprops keys."""
    s = json.dumps(scene)
    npj = json.dumps(scene["nprops"])
    return s.replace(npj, re.sub(r'"(\d+)":', r"\1:", npj))


def cantilever(n, L=2.0, EA=2.07e9, EI=1.725e6, rhoA=78.0, force=None, gravity=None, integration=0,
               dynamics=None, sensors=None, opt=None):
    """One scene element split into n ANCF elements (nbeams), clamp [1,1,0,1] at node 1, tip node 2."""
    nprops = {1: {"fix_coords": [1, 1, 0, 1]}}
    if force is not None:
        nprops[2] = {"force": [0, -force]}
    o = {"loadsteps": 1, "calcfreq": False}
    if gravity:
        o["gravity"] = gravity
    if dynamics:
        o["dynamics"] = dynamics
    o.update(opt or {})
    scene = {"title": "ANCF cantilever", "nodes": [[0, 0], [L, 0]], "elements": [[1, 2]], "nprops": nprops,
             "eprops": [{"elems": [1], "type": "ancf_cable2d", "physicsMassPerLength": rhoA,
                         "physicsBendingStiffness": EI, "physicsAxialStiffness": EA,
                         "useReducedOrderIntegration": integration, "nbeams": n}], "opt": o}
    if sensors:
        scene["sensors"] = sensors
    return scene


def tip_displacement(f):
    p, p0 = f["node/p"][-1], f["node/p0"][:]
    return p[1, :2] - p0[1, :2]

def elastica(alpha, n=1000):
    """Tip (x, y) / L of the inextensible cantilever under a fixed transverse tip load, alpha = P L^2 / EI
    (theta'' = -alpha cos theta, shooting with RK4 and bisection on theta'(0))."""
    import numpy as np
    def end(k0):
        u = np.array([0.0, k0, 0.0, 0.0])  # theta, theta', x, y over s in [0, 1]
        h = 1.0 / n
        f = lambda u: np.array([u[1], -alpha * np.cos(u[0]), np.cos(u[0]), np.sin(u[0])])
        for _ in range(n):
            k1 = f(u); k2 = f(u + h / 2 * k1); k3 = f(u + h / 2 * k2); k4 = f(u + h * k3)
            u = u + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        return u
    a, b = 0.0, alpha  # theta'(1) = 0: bisection on k0 = theta'(0)
    fa = end(a)[1]
    for _ in range(55):
        m = 0.5 * (a + b)
        fm = end(m)[1]
        if fa * fm <= 0:
            b = m
        else:
            a, fa = m, fm
    u = end(0.5 * (a + b))
    return u[2], u[3]
