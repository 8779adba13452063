"""Sinew from Python: scenes, runs and SPACAR Light's `out` structure.

    import sinew
    out = sinew.load("out/crosshinge.h5")          # a result file of a command-line run
    sim = sinew.Scene.from_yaml("runs/crosshinge.yaml"); sim.opt["loadsteps"] = 5; out = sim.run()
    out = sinew.spacarlight(nodes, elements, nprops, eprops, opt)   # SPACAR Light's call
    scene = sinew.from_spacar("crosshinge.m")       # a SPACAR Light script as a Sinew scene

Node and step numbers are 1-based, as in SPACAR Light (out.node[3].p, out.step[2].node[3].p)."""
from .results import Results, load
from .scene import Scene, SinewError
from .spacar import SpacarError
from .spacarlight import spacarlight

__all__ = ["Results", "Scene", "SinewError", "SpacarError", "from_spacar", "load", "spacarlight"]


def from_spacar(path):
    """A SPACAR Light MATLAB script (nodes, elements, nprops, eprops, opt assignments) as a Scene."""
    return Scene.from_spacar(path)
