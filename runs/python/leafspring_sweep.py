#!/usr/bin/python3
"""Parameter sweep from Python (docs/python.md): a parallel leaf spring (two leaves of length L, width
w, thickness t, joined by a rigid stage of mass m) for leaf thicknesses t; per design the first natural
frequency and the buckling load multiplier of a downward load P on the stage, built with SPACAR
Light's call (sinew.spacarlight) and read from SPACAR Light's `out`.

Closed forms beside them: lateral stiffness k = 24 E I / L^3 (two clamped-guided leaves, I = w t^3 / 12),
f1 = sqrt(k / m) / (2 pi) without the leaves' own mass (2 x 1.6 .. 4.7 g against m = 0.1 kg: Sinew's
f1, which has it, is 0.6 .. 1.7 % lower), and the buckling load of the two leaves in sway,
P_cr = 2 pi^2 E I / L^2 (Sinew: the multiplier of P at the last load step times P).
Measured 2026-11-26, 1 rank: f1 11.6018 .. 59.5829 Hz (closed form 11.6694 .. 60.6362), P_cr
22.107 .. 596.559 N (closed form 22.108 .. 596.914, within 6e-4); 5 designs in 8.6 s.

usage: PYTHONPATH=python runs/python/leafspring_sweep.py [-o sweep.png] [-n RANKS]"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import sinew  # noqa: E402

L, W, D = 0.05, 0.02, 0.03      # leaf length, width, spacing [m]
E, G, RHO = 210e9, 80e9, 7800   # steel
M, P = 0.1, 10.0                # stage mass [kg], downward load on the stage [N]


def design(t, ranks=1):
    nodes = [[0, 0, 0], [0, L, 0], [D, 0, 0], [D, L, 0], [D / 2, L, 0]]
    elements = [[1, 2], [3, 4], [2, 5], [4, 5]]
    nprops = [{"fix": True}, None, {"fix": True}, None,
              {"force": [0, -P, 0], "mass": M, "mominertia": [1e-6, 0, 0, 1e-6, 0, 1e-6]}]
    eprops = [{"elems": [1, 2], "emod": E, "smod": G, "dens": RHO, "cshape": "rect", "dim": [W, t],
               "orien": [0, 0, 1], "nbeams": 8, "flex": [1, 2, 3, 4, 5, 6]}]
    opt = {"loadsteps": 2, "calcbuck": True, "calccompl": False, "nfreq": 1, "nbuck": 1, "filename": "leafspring"}
    out = sinew.spacarlight(nodes, elements, nprops, eprops, opt, np_ranks=ranks, check=True)
    # step 1: unloaded (frequencies about the undeformed state); buckling of the full load at the last step
    return out.step[1].freq[0], out.buck[-1, 0] * P


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-o", "--output", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "leafspring_sweep.png"))
    ap.add_argument("-n", type=int, default=1, help="MPI ranks per run")
    a = ap.parse_args()
    ts = np.array([0.2, 0.3, 0.4, 0.5, 0.6]) * 1e-3
    rows = []
    print(" t [mm]   f1 [Hz]  closed form   P_cr [N]  closed form")
    for t in ts:
        f1, pcr = design(t, a.n)
        I = W * t**3 / 12
        f1_cf = math.sqrt(24 * E * I / L**3 / M) / (2 * math.pi)
        pcr_cf = 2 * math.pi**2 * E * I / L**2
        rows.append((t, f1, f1_cf, pcr, pcr_cf))
        print(f" {t * 1e3:5.2f}  {f1:9.4f}  {f1_cf:11.4f}  {pcr:9.3f}  {pcr_cf:11.3f}")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    r = np.array(rows)
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.6))
    ax[0].plot(r[:, 0] * 1e3, r[:, 1], "o-", label="Sinew")
    ax[0].plot(r[:, 0] * 1e3, r[:, 2], "k--", label="sqrt(24EI/L^3/m)/2pi")
    ax[0].set_xlabel("leaf thickness t [mm]"), ax[0].set_ylabel("f1 [Hz]"), ax[0].legend(fontsize=8)
    ax[1].plot(r[:, 0] * 1e3, r[:, 3], "o-", label="Sinew")
    ax[1].plot(r[:, 0] * 1e3, r[:, 4], "k--", label="2 pi^2 EI / L^2")
    ax[1].set_xlabel("leaf thickness t [mm]"), ax[1].set_ylabel("buckling load [N]"), ax[1].legend(fontsize=8)
    for x in ax:
        x.grid(True, alpha=0.3)
    fig.suptitle("Parallel leaf spring: thickness sweep (sinew.spacarlight)", fontsize=10)
    fig.tight_layout()
    fig.savefig(a.output, dpi=100)
    print(f"wrote {a.output}")


if __name__ == "__main__":
    main()
