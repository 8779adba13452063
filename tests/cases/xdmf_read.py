"""A small XDMF reader for tests, with h5py: resolves the grids of a Sinew XDMF file the way
ParaView's XDMF Reader does (temporal collection of uniform grids or spatial collections of them;
Topology, Geometry and Attribute DataItems: plain HDF, HyperSlab over HDF, or XML values), so that
the ParaView convention (docs/results.md, "Opening the XDMF in ParaView") can be checked on any
machine. Every HDF DataItem must name an existing dataset of exactly its declared dimensions,
except that a step-indexed dataset may have more steps than declared (the XDMF is rewritten less
often than the HDF5 file grows: it then lists a prefix of the steps)."""
import os
import xml.etree.ElementTree as ET

import h5py
import numpy as np


class XdmfError(Exception):
    pass


def _dims(text):
    return tuple(int(x) for x in text.split())


def _values(item, directory, files):
    """The array of a DataItem element."""
    kind = item.get("ItemType", "Uniform")
    if kind == "HyperSlab":
        sel, data = list(item.findall("DataItem"))
        start, stride, count = _values(sel, directory, files).astype(int).reshape(3, -1)
        full = _values(data, directory, files)
        index = tuple(slice(b, b + s * c, s) for b, s, c in zip(start, stride, count))
        out = full[index]
        if out.shape != tuple(count):
            raise XdmfError(f"HyperSlab {start} {stride} {count} outside {full.shape}")
        return out.reshape(_dims(item.get("Dimensions")))
    dims = _dims(item.get("Dimensions"))
    fmt = item.get("Format", "XML")
    text = item.text.strip()
    if fmt == "XML":
        a = np.array([float(x) for x in text.split()])
        if a.size != int(np.prod(dims)):
            raise XdmfError(f"XML DataItem with {a.size} values for dimensions {dims}")
        return a.reshape(dims)
    if fmt != "HDF":
        raise XdmfError(f"DataItem format {fmt}")
    name, _, path = text.partition(":")
    h5path = os.path.join(directory, name)
    if h5path not in files:
        files[h5path] = h5py.File(h5path, "r")
    f = files[h5path]
    if path not in f:
        raise XdmfError(f"DataItem {text}: no dataset {path} in {h5path}")
    d = f[path]
    # a step-indexed dataset may hold more steps than the XDMF lists (a prefix); nothing else differs
    if d.shape != dims and not (len(d.shape) == len(dims) and d.shape[1:] == dims[1:] and d.shape[0] > dims[0]
                                and d.maxshape[0] is None):
        raise XdmfError(f"DataItem {text}: declared dimensions {dims}, dataset {d.shape}")
    return d[()]


def _grid(g, directory, files):
    topo = g.find("Topology")
    geom = g.find("Geometry")
    if geom is None or geom.get("GeometryType") != "XYZ":
        raise XdmfError(f"grid {g.get('Name')}: no XYZ geometry")
    out = {"name": g.get("Name"), "topology": topo.get("TopologyType"),
           "cells": None, "points": _values(geom.find("DataItem"), directory, files),
           "geometry_text": geom.find("DataItem").text.strip(),
           "point": {}, "cell": {}, "field": {}}
    if topo.find("DataItem") is not None:
        out["cells"] = _values(topo.find("DataItem"), directory, files)
        if out["cells"].shape[0] != int(topo.get("NumberOfElements")):
            raise XdmfError(f"grid {g.get('Name')}: NumberOfElements differs from the cell list")
    for a in g.findall("Attribute"):
        center = {"Node": "point", "Cell": "cell", "Grid": "field"}[a.get("Center")]
        v = _values(a.find("DataItem"), directory, files)
        if center != "field" and v.ndim >= 2 and v.shape[0] == 1:
            v = v[0]  # one row of a step-indexed dataset [1, rows, ...]
        rows = {"point": len(out["points"]), "cell": None if out["cells"] is None else len(out["cells"]), "field": 1}
        if center != "field" and v.shape[0] != rows[center]:
            raise XdmfError(f"grid {g.get('Name')}: attribute {a.get('Name')} has {v.shape[0]} rows, expected "
                            f"{rows[center]}")
        out[center][a.get("Name")] = v
    return out


def read(xdmf_path):
    """Returns a list of steps, each {"time": t, "grids": [grid, ...]}: grid = {"name", "topology",
    "cells", "points", "geometry_text", "point": {name: array}, "cell": {...}, "field": {...}}."""
    directory = os.path.dirname(os.path.abspath(xdmf_path))
    root = ET.parse(xdmf_path).getroot()
    temporal = root.find("Domain/Grid")
    if temporal is None or temporal.get("CollectionType") != "Temporal":
        raise XdmfError("no temporal collection")
    files = {}
    steps = []
    try:
        for g in temporal.findall("Grid"):
            t = g.find("Time")
            if t is None:
                raise XdmfError(f"grid {g.get('Name')} has no Time")
            if g.get("GridType") == "Collection":
                grids = [_grid(c, directory, files) for c in g.findall("Grid")]
            else:
                grids = [_grid(g, directory, files)]
            steps.append({"time": float(t.get("Value")), "grids": grids})
    finally:
        for f in files.values():
            f.close()
    return steps
