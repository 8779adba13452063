#!/usr/bin/python3
"""Opens a Sinew XDMF file with ParaView's XDMF Reader and prints what it sees.
Run with ParaView's Python (Debian: paraview + python3-paraview): scripts/check_xdmf_paraview.py out/crosshinge.xdmf
(Debian's python3 imports paraview.simple from python3-paraview), or pvpython scripts/check_xdmf_paraview.py ...
Prints the time steps, the points and cells, the point, cell and field arrays of the last step, and
the x range of the reference geometry and of the geometry warped by the displacement (Warp By
Vector, scale factor 1), which is the deformed shape /mesh/p of that step (docs/results.md,
"Opening the XDMF in ParaView").
"""
import os
import sys

from paraview import servermanager as sm
from paraview.simple import WarpByVector, XDMFReader


def blocks(d):
    if d.IsA("vtkCompositeDataSet"):
        it = d.NewIterator()
        it.InitTraversal()
        while not it.IsDoneWithTraversal():
            yield it.GetCurrentDataObject()
            it.GoToNextItem()
    else:
        yield d


def names(attrs):
    return sorted(attrs.GetArrayName(i) for i in range(attrs.GetNumberOfArrays()))


r = XDMFReader(FileNames=[os.path.abspath(sys.argv[1])])
r.UpdatePipelineInformation()
times = list(r.TimestepValues)
print("time steps", len(times), times[:3], "..." if len(times) > 3 else "")
if not times:
    sys.exit("no time steps read")
r.UpdatePipeline(times[-1])
info = r.GetDataInformation()
print("points", info.GetNumberOfPoints(), "cells", info.GetNumberOfCells())
data = list(blocks(sm.Fetch(r)))
print("point arrays", sorted(set(a for b in data for a in names(b.GetPointData()))))
print("cell arrays", sorted(set(a for b in data for a in names(b.GetCellData()))))
fd = data[0].GetFieldData()
print("field data", {fd.GetArrayName(i): fd.GetArray(i).GetValue(0) for i in range(fd.GetNumberOfArrays())})
print("reference x range", info.GetBounds()[:2])
w = WarpByVector(Input=r, Vectors=["POINTS", "displacement"], ScaleFactor=1.0)
w.UpdatePipeline(times[-1])
print("warped by displacement x range", w.GetDataInformation().GetBounds()[:2])
if info.GetNumberOfPoints() == 0 or info.GetNumberOfCells() == 0:
    sys.exit("no geometry read")
