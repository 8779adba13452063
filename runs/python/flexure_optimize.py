#!/usr/bin/python3
"""Optimization loop from Python (docs/python.md): the leaf thickness t of a parallel leaf spring that
gives a target lateral stiffness k_target, found by scipy.optimize.brentq on Sinew runs. The lateral
stiffness of each design is its compliance: 1 / CMglob[0, 0] of the stage node (SPACAR Light's
compliance matrix), so one load step without loads is enough.

Closed form for the check: k = 24 E I / L^3 = 2 E w t^3 / L^3 (two clamped-guided leaves), so
t = (k L^3 / (2 E w))^(1/3). Measured 2026-11-26, 1 rank: t = 0.309922 mm for 2000 N/m in 12 runs
(11.2 s), closed form 0.309899 mm (+7.5e-5: the leaves' shear and axial compliance).

usage: PYTHONPATH=python runs/python/flexure_optimize.py [--target 2000] [-n RANKS]"""
import argparse
import os
import sys

from scipy.optimize import brentq

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import sinew  # noqa: E402

L, W, D, E, G = 0.05, 0.02, 0.03, 210e9, 80e9


def stiffness(t, ranks=1):
    nodes = [[0, 0, 0], [0, L, 0], [D, 0, 0], [D, L, 0], [D / 2, L, 0]]
    elements = [[1, 2], [3, 4], [2, 5], [4, 5]]
    nprops = {1: {"fix": True}, 3: {"fix": True}}
    eprops = [{"elems": [1, 2], "emod": E, "smod": G, "cshape": "rect", "dim": [W, t], "orien": [0, 0, 1],
               "nbeams": 8, "flex": [1, 2, 3, 4, 5, 6]}]
    opt = {"loadsteps": 1, "calccompl": True, "compliance_nodes": [5], "filename": "flexure"}
    out = sinew.spacarlight(nodes, elements, nprops, eprops, opt, np_ranks=ranks, check=True)
    return 1.0 / out.node[5].CMglob[-1, 0, 0]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--target", type=float, default=2000.0, help="lateral stiffness [N/m]")
    ap.add_argument("-n", type=int, default=1, help="MPI ranks per run")
    a = ap.parse_args()
    runs = []

    def residual(t):
        k = stiffness(t, a.n)
        runs.append((t, k))
        print(f"  t = {t * 1e3:.6f} mm: k = {k:.4f} N/m")
        return k - a.target

    t = brentq(residual, 0.1e-3, 1.0e-3, xtol=1e-12, rtol=1e-10)
    t_cf = (a.target * L**3 / (2 * E * W)) ** (1 / 3)
    print(f"t = {t * 1e3:.6f} mm for k = {a.target:g} N/m in {len(runs)} Sinew runs; closed form {t_cf * 1e3:.6f} mm "
          f"({(t / t_cf - 1):+.2e})")


if __name__ == "__main__":
    main()
