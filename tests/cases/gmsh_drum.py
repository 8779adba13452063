"""A coarse unstructured Gmsh 4.1 mesh of the prestressed square drum of membrane_accuracy_cases
(L = 1 m, n0 = 1000 N/m, 1 kg/m^2, f11 = 22.360680 Hz): `n` boundary intervals per side and
interior nodes on a jittered grid (fixed seed), Delaunay triangles; physical surface "membrane" and
physical curve "edge" (its line elements name the held boundary nodes: a node group for nprops)."""
import numpy as np
from scipy.spatial import Delaunay

import membrane_accuracy_cases as mc


def points(n=4, seed=3):
    rng = np.random.default_rng(seed)
    edge = [[mc.L * i / n, 0] for i in range(n)] + [[mc.L, mc.L * i / n] for i in range(n)] + \
           [[mc.L * (n - i) / n, mc.L] for i in range(n)] + [[0, mc.L * (n - i) / n] for i in range(n)]
    inner = [[mc.L * (i + 0.5 + 0.3 * rng.uniform(-1, 1)) / n, mc.L * (j + 0.5 + 0.3 * rng.uniform(-1, 1)) / n]
             for j in range(n) for i in range(n)]
    return np.array(edge), np.array(inner)


def write_msh(path, n=4):
    """Writes the mesh; returns (nodes, triangles) as written (0-based)."""
    edge, inner = points(n)
    xy = np.vstack([edge, inner])
    tris = Delaunay(xy).simplices
    # counter-clockwise: normals +z like the structured drum
    for t in tris:
        a, b, c = xy[t]
        if (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) < 0:
            t[1], t[2] = t[2], t[1]
    ne = len(edge)
    lines = [[k, (k + 1) % ne] for k in range(ne)]
    nn = len(xy)
    with open(path, "w") as f:
        f.write("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n")
        f.write('$PhysicalNames\n2\n1 2 "edge"\n2 1 "membrane"\n$EndPhysicalNames\n')
        f.write(f"$Entities\n0 1 1 0\n1 0 0 0 {mc.L} {mc.L} 0 1 2 0\n1 0 0 0 {mc.L} {mc.L} 0 1 1 1 1\n$EndEntities\n")
        f.write(f"$Nodes\n1 {nn} 1 {nn}\n2 1 0 {nn}\n")
        f.write("".join(f"{i + 1}\n" for i in range(nn)))
        f.write("".join(f"{x!r} {y!r} 0\n" for x, y in xy))
        f.write("$EndNodes\n")
        f.write(f"$Elements\n2 {len(lines) + len(tris)} 1 {len(lines) + len(tris)}\n")
        f.write(f"1 1 1 {len(lines)}\n" + "".join(f"{k + 1} {a + 1} {b + 1}\n" for k, (a, b) in enumerate(lines)))
        f.write(f"2 1 2 {len(tris)}\n" +
                "".join(f"{len(lines) + k + 1} {a + 1} {b + 1} {c + 1}\n" for k, (a, b, c) in enumerate(tris)))
        f.write("$EndElements\n")
    return xy, tris


def scene(msh, opt=None):
    o = {"loadsteps": 1, "nfreq": 1}
    o.update(opt or {})
    return {"title": "accuracy: prestressed drum from a coarse Gmsh mesh", "mesh": msh, "nprops": {"edge": {"fix": True}},
            "eprops": [{"physical": "membrane", "type": "membrane", "thickness": mc.T, "emod": 1e9, "nu": 0.3,
                        "dens": mc.RHO, "prestress": [mc.SIGMA, mc.SIGMA, 0]}],
            "opt": o}
