#!/usr/bin/python3
"""Time (or load-factor) plots of every /sensors/<name> dataset of a Sinew result file.
usage: scripts/plot_sensors.py result.h5 [-o sensors.png]"""
import argparse

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("h5")
ap.add_argument("-o", "--output", default="sensors.png")
a = ap.parse_args()
with h5py.File(a.h5, "r") as f:
    if "sensors" not in f:
        raise SystemExit(f"{a.h5}: no /sensors group (the scene has no sensors)")
    xname = "time" if "time" in f else "load_factor"
    x = f[xname][:]
    names = sorted(f["sensors"].keys())
    fig, axes = plt.subplots(len(names), 1, figsize=(7, 2.6 * len(names)), squeeze=False, sharex=True)
    for ax, name in zip(axes[:, 0], names):
        v = f["sensors/" + name][:]
        v = v.reshape(len(x), -1)
        for k in range(v.shape[1]):
            if v.shape[1] == 1 or abs(v[:, k]).max() > 0:
                ax.plot(x, v[:, k], label=f"{name}[{k}]")
        ax.set_ylabel(name)
        ax.legend(loc="best", fontsize=8)
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel(xname)
    fig.tight_layout()
    fig.savefig(a.output, dpi=120)
print("wrote", a.output)
