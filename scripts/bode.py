#!/usr/bin/python3
"""Bode plot of every input/output pair of the state-space model in a Sinew result file
(/statespace/A, B, C, D written with opt.transfer):  H(i w) = C (i w I - A)^-1 B + D.

usage: scripts/bode.py result.h5 [-o out.png] [--points 800]
The picture goes beside the result file as <result>_bode.png unless -o names it."""
import argparse
import os
import sys

import numpy as np

from plot_results import load_matplotlib, open_result

IN_NAMES = ["force_x", "force_y", "force_z", "moment_x", "moment_y", "moment_z"]
OUT_NAMES = ["displ_x", "displ_y", "displ_z", "veloc_x", "veloc_y", "veloc_z"]
IN_UNITS = ["N", "N", "N", "(N m)", "(N m)", "(N m)"]
OUT_UNITS = ["m", "m", "m", "m/s", "m/s", "m/s"]


def frequency_response(A, B, C, D, w):
    """H[k, out, in] at the circular frequencies w."""
    n = A.shape[0]
    H = np.empty((len(w), C.shape[0], B.shape[1]), dtype=complex)
    for k, wk in enumerate(w):
        H[k] = C @ np.linalg.solve(1j * wk * np.eye(n) - A, B) + D
    return H


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("h5")
    ap.add_argument("-o", "--output", help="PNG file (default: <result>_bode.png beside the result file)")
    ap.add_argument("--points", type=int, default=800)
    a = ap.parse_args()
    out = a.output or os.path.splitext(a.h5)[0] + "_bode.png"
    with open_result(a.h5) as f:
        if "statespace" not in f:
            sys.exit(f"{a.h5} has no /statespace (run the scene with opt.transfer: true)")
        g = f["statespace"]
        A, B, C, D = (g[k][:] for k in "ABCD")
        ins, outs = g["inputs"][:].astype(int), g["outputs"][:].astype(int)
        hz = g["freq"][:]
    w_modes = 2 * np.pi * np.abs(hz[hz != 0])
    lo = 0.1 * (w_modes.min() if w_modes.size else 1.0)
    hi = 10 * (w_modes.max() if w_modes.size else 1.0)
    w = np.logspace(np.log10(lo), np.log10(hi), a.points)
    H = frequency_response(A, B, C, D, w)
    plt = load_matplotlib()  # after the input was read: bad files fail fast
    fig, ax = plt.subplots(2, 1, sharex=True, figsize=(8, 7))
    for o, (on, oc) in enumerate(outs):
        for i, (inn, ic) in enumerate(ins):
            label = (f"{OUT_NAMES[oc - 1]}({on}) / {IN_NAMES[ic - 1]}({inn}) "
                     f"[{OUT_UNITS[oc - 1]}/{IN_UNITS[ic - 1]}]")
            ax[0].loglog(w / (2 * np.pi), np.abs(H[:, o, i]), label=label)
            ax[1].semilogx(w / (2 * np.pi), np.degrees(np.unwrap(np.angle(H[:, o, i]))), label=label)
    ax[0].set_ylabel("magnitude |H| [output unit / input unit]")
    ax[1].set_ylabel("phase [deg]")
    ax[1].set_xlabel("frequency [Hz]")
    ax[0].legend(fontsize=8)
    for x in ax:
        x.grid(True, which="both", alpha=0.3)
    ax[0].set_title(f"Bode plot: {len(outs)} output(s) x {len(ins)} input(s), {A.shape[0]} states")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
