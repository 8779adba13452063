"""Run by ParaView's Python (pvpython), not by the test runner: opens Sinew XDMF files the way a
user does and writes what ParaView shows as JSON, for tests/cases/test_paraview.py to compare with
the HDF5 file (paraview_scenes.check_view).

    pvpython paraview_probe.py out.json a.xdmf [b.xdmf ...]

Per file, with the "XDMF Reader" (ParaView's XDMF 2 reader, the one docs/results.md names): the
time steps; per step and block the reference points, the points warped by Warp By Vector
(Vectors = displacement, Scale Factor = 1), the largest |value| of every point and cell array, the
field data. With "Xdmf3ReaderS": the time steps and the arrays of the last step (documented as
incomplete in docs/results.md)."""
import json
import sys

import numpy as np
from paraview import servermanager as sm
from paraview import simple as pv
from vtkmodules.numpy_interface import dataset_adapter as dsa


def blocks(d):
    if d.IsA("vtkCompositeDataSet"):
        it = d.NewIterator()
        it.InitTraversal()
        while not it.IsDoneWithTraversal():
            yield it.GetCurrentDataObject()
            it.GoToNextItem()
    else:
        yield d


def maxabs(a):
    v = np.abs(np.asarray(a, dtype=float))
    v = v[np.isfinite(v)]
    return float(v.max()) if v.size else float("nan")


def arrays(attrs):
    return {attrs.GetArrayName(i): maxabs(dsa.vtkDataArrayToVTKArray(attrs.GetArray(i)))
            for i in range(attrs.GetNumberOfArrays())}


def describe(b, warped=None):
    fd = b.GetFieldData()
    return {"points": dsa.WrapDataObject(b).Points.tolist() if b.GetPoints() else [],
            "warped": dsa.WrapDataObject(warped).Points.tolist() if warped is not None else [],
            "point_type": b.GetPoints().GetData().GetDataTypeAsString() if b.GetPoints() else None,
            "cells": b.GetNumberOfCells(),
            "point_max": arrays(b.GetPointData()), "cell_max": arrays(b.GetCellData()),
            "field": {fd.GetArrayName(i): fd.GetArray(i).GetValue(0) for i in range(fd.GetNumberOfArrays())}}


def legacy(path):
    r = pv.XDMFReader(FileNames=[path])
    r.UpdatePipelineInformation()
    times = list(r.TimestepValues)
    w = pv.WarpByVector(Input=r, Vectors=["POINTS", "displacement"], ScaleFactor=1.0)
    steps = []
    for t in times:
        r.UpdatePipeline(t)
        w.UpdatePipeline(t)
        plain, warped = list(blocks(sm.Fetch(r))), list(blocks(sm.Fetch(w)))
        steps.append([describe(b, wb) for b, wb in zip(plain, warped)])
    pv.Delete(w)
    pv.Delete(r)
    return {"times": times, "steps": steps}


def xdmf3(path):
    r = pv.Xdmf3ReaderS(FileName=[path])
    r.UpdatePipelineInformation()
    times = list(r.TimestepValues)
    r.UpdatePipeline(times[-1] if times else 0.0)
    last = [describe(b) for b in blocks(sm.Fetch(r))]
    pv.Delete(r)
    return {"times": times, "last": last}


out = {}
for path in sys.argv[2:]:
    out[path] = {"XDMFReader": legacy(path), "Xdmf3ReaderS": xdmf3(path)}
with open(sys.argv[1], "w") as f:
    json.dump(out, f)
print("probed", len(sys.argv) - 2, "files")
