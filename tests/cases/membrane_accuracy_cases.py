"""The -target_error membrane scene (docs/accuracy.md "Membranes"): a square membrane L x L held on its
edge, prestressed n0 = sigma t in every direction, mass m = rho t per area, on a mesh of n x n squares
each cut into two linear triangles along alternating diagonals (or kept as bilinear quads). Its first frequency is analytic:
f11 = sqrt(n0 / m) sqrt(2) / (2 L)."""
import numpy as np

L, T, SIGMA, RHO = 1.0, 1e-3, 1e6, 1000.0
F11 = np.sqrt(SIGMA * T / (RHO * T)) * np.sqrt(2) / (2 * L)


def drum(n, opt=None, quads=False):
    nodes = [[L * i / n, L * j / n, 0] for j in range(n + 1) for i in range(n + 1)]
    num = lambda i, j: j * (n + 1) + i + 1  # 1-based
    elements = []
    for j in range(n):
        for i in range(n):
            a, b, c, d = num(i, j), num(i + 1, j), num(i + 1, j + 1), num(i, j + 1)
            if quads:
                elements.append([a, b, c, d])
            else:
                elements += [[a, b, c], [a, c, d]] if (i + j) % 2 == 0 else [[a, b, d], [b, c, d]]
    edge = {num(i, j): {"fix": True} for j in range(n + 1) for i in range(n + 1) if i in (0, n) or j in (0, n)}
    o = {"loadsteps": 1, "nfreq": 1}
    o.update(opt or {})
    return {"title": "accuracy: prestressed square membrane", "nodes": nodes, "elements": elements, "nprops": edge,
            "eprops": [{"elems": list(range(1, len(elements) + 1)), "type": "membrane", "thickness": T, "emod": 1e9,
                        "nu": 0.3, "dens": RHO, "prestress": [SIGMA, SIGMA, 0]}],
            "opt": o}
