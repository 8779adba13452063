#!/usr/bin/python3
"""Opens a Sinew XDMF file with ParaView's XDMF reader and prints what it sees.
Run with ParaView's Python (Debian: paraview + python3-paraview): scripts/check_xdmf_paraview.py out/crosshinge.xdmf
(Debian's python3 imports paraview.simple from python3-paraview), or pvbatch3.11 scripts/check_xdmf_paraview.py ...
"""
import sys

from paraview.simple import XDMFReader

r = XDMFReader(FileNames=[sys.argv[1]])
r.UpdatePipelineInformation()
times = list(r.TimestepValues)
print("time steps", len(times), times[:3], "...")
r.UpdatePipeline(times[-1])
info = r.GetDataInformation()
print("points", info.GetNumberOfPoints(), "cells", info.GetNumberOfCells())
print("point arrays", [r.PointData[i].Name for i in range(len(r.PointData))])
if info.GetNumberOfPoints() == 0 or info.GetNumberOfCells() == 0:
    sys.exit("no geometry read")
