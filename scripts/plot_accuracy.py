#!/usr/bin/python3
"""What accuracy cost: the estimated relative discretization error of each watched quantity against
the wall time of the levels of a -target_error run (docs/accuracy.md), from the /accuracy group of
its result file (PNG; matplotlib Agg, no display).

usage: scripts/plot_accuracy.py result.h5 [-o out.png]

One line per quantity (estimates exist from the third level on), the target as a dashed line, the
cumulative wall time of the levels on the x axis (each level's time added to those before it: what
the answer at that level cost). Quantities whose observed order was erratic at a level are drawn
with an open marker there. A missing file, a text file or a file without /accuracy prints one line
and exits 1."""
import argparse
import os
import sys

import numpy as np


def load_matplotlib():
    """Imports matplotlib (Agg backend) only after the input was read: a bad file is reported at once."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def read(path):
    try:
        import h5py
        with h5py.File(path, "r") as f:
            if "accuracy" not in f:
                raise KeyError("no /accuracy group (a run without -target_error)")
            g = f["accuracy"]
            names = [n for n in g.attrs["quantities"].split("\n") if n]
            return dict(names=names, time=g["wall_time"][:], error=g["error"][:], status=g["status"][:],
                        unknowns=g["unknowns"][:], target=float(g.attrs["target"]), met=int(g.attrs["met"]))
    except (OSError, KeyError) as e:
        print(f"plot_accuracy.py: {path}: {e}")
        sys.exit(1)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("h5")
    ap.add_argument("-o", "--output", help="PNG file (default: <result>_accuracy.png)")
    a = ap.parse_args()
    d = read(a.h5)
    out = a.output or os.path.splitext(a.h5)[0] + "_accuracy.png"
    plt = load_matplotlib()
    cumulative = np.cumsum(d["time"])
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for q, name in enumerate(d["names"]):
        e = d["error"][:, q]
        ok = np.isfinite(e) & (e > 0)
        if not ok.any():
            continue
        line, = ax.loglog(cumulative[ok], e[ok], "-", label=name)
        erratic = ok & (d["status"][:, q] == 2)
        trusted = ok & ~erratic
        ax.loglog(cumulative[trusted], e[trusted], "o", color=line.get_color())
        ax.loglog(cumulative[erratic], e[erratic], "o", mfc="none", color=line.get_color())
    ax.axhline(d["target"], color="k", ls="--", lw=1, label=f"target {d['target']:g}")
    ax.set_xlabel("wall time of the levels so far [s]")
    ax.set_ylabel("estimated relative error")
    ax.set_title(("target met" if d["met"] else "target not met") + f", finest level {len(d['time']) - 1}"
                 f" ({int(d['unknowns'][-1])} unknowns); open markers: erratic order", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"{out}: {len(d['names'])} quantities over {len(d['time'])} levels")


if __name__ == "__main__":
    main()
