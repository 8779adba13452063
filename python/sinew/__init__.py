"""Sinew from Python: scenes, runs and SPACAR Light's `out` structure.

    import sinew
    out = sinew.load("out/crosshinge.h5")          # a result file of a command-line run
    sim = sinew.Scene.from_yaml("runs/crosshinge.yaml"); sim.opt["loadsteps"] = 5; out = sim.run()
    out = sinew.spacarlight(nodes, elements, nprops, eprops, opt)   # SPACAR Light's call
    scene = sinew.from_spacar("crosshinge.m")       # a SPACAR Light script as a Sinew scene

Node and step numbers are 1-based, as in SPACAR Light (out.node[3].p, out.step[2].node[3].p).
Runs go through the compiled module sinew._core in this process (docs/python.md); it is found beside
this file (installed), in the build tree of $SINEW_BIN (<build>/python/sinew), or in build/ of the
source tree."""
import os as _os


def _core_dirs():
    here = _os.path.dirname(_os.path.abspath(__file__))
    dirs = []
    if _os.environ.get("SINEW_BIN"):
        dirs.append(_os.path.join(_os.path.dirname(_os.path.abspath(_os.environ["SINEW_BIN"])), "python", "sinew"))
    dirs.append(_os.path.normpath(_os.path.join(here, "..", "..", "build", "python", "sinew")))
    return [d for d in dirs if _os.path.isdir(d)]


__path__.extend(d for d in _core_dirs() if d not in __path__)  # sinew._core of a build tree

from .results import Results, load
from .scene import Scene, SinewError, core
from .spacar import SpacarError
from .spacarlight import spacarlight

__all__ = ["Results", "Scene", "SinewError", "SpacarError", "core", "from_spacar", "load", "spacarlight"]


def from_spacar(path):
    """A SPACAR Light MATLAB script (nodes, elements, nprops, eprops, opt assignments) as a Scene."""
    return Scene.from_spacar(path)
