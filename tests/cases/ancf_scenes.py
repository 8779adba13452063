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
