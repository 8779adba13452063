"""Scene generators shared by the core system tests: a 3D braced tower of beams (a few hundred
DOFs) with supports, nodal forces/moments, initial loads and rigid members."""
import numpy as np

import beamtools as bt


def tower(nx=2, ny=2, nz=4, bay=0.5, storey=0.6, nbeams=2, loadsteps=6, load=1.0):
    """(scene dict, list of loaded node numbers). Columns, beams and one diagonal per bay face;
    base nodes fixed (one only fix_pos); top floor loaded sideways, twisted and pressed down."""
    idx = {}
    nodes = []
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                idx[i, j, k] = len(nodes) + 1
                nodes.append([i * bay, j * bay, k * storey])
    elems, rigid = [], []
    for (i, j, k), a in idx.items():
        if k < nz:
            elems.append([a, idx[i, j, k + 1]])                      # column
        if k > 0:
            if i < nx:
                elems.append([a, idx[i + 1, j, k]])                  # beam x
            if j < ny:
                elems.append([a, idx[i, j + 1, k]])                  # beam y
        if k < nz and i < nx and j == 0:
            elems.append([a, idx[i + 1, j, k + 1]])                  # diagonal, front face
        if k < nz and j < ny and i == nx:
            elems.append([a, idx[i, j + 1, k + 1]])                  # diagonal, side face
    # top-floor beams in x rigid (no eprops set)
    flex = []
    for e, (a, b) in enumerate(elems, start=1):
        za, zb = nodes[a - 1][2], nodes[b - 1][2]
        (rigid if za == zb == nz * storey and nodes[a - 1][1] == nodes[b - 1][1] else flex).append(e)
    nprops = {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            nprops[str(idx[i, j, 0])] = {"fix": True}
    nprops[str(idx[nx, ny, 0])] = {"fix_pos": True}
    top = [idx[i, j, nz] for j in range(ny + 1) for i in range(nx + 1)]
    loaded = []
    for c, a in enumerate(top):
        nprops[str(a)] = {"force": [load * 300.0, load * 150.0 * (c % 2), -load * 400.0],
                          "moment": [0, 0, load * 40.0], "force_initial": [0, 0, -50.0]}
        loaded.append(a)
    scene = {"title": "braced tower", "nodes": nodes, "elements": elems, "nprops": nprops,
             "eprops": [bt.beam_set(flex, 0.04, 0.03, nbeams=nbeams, orien=[0.3, 0.2, 1.0])],
             "opt": {"loadsteps": loadsteps, "calccompl": False}}
    return scene, loaded
