#!/usr/bin/python3
"""Plot the load path of one node from a Sinew result file: load factor (or time) against the
displacement of node N, u = p[step] - p0, with p from /node/p and p0 from /node/p0 (the initial
positions; the first row of /node/p when /node/p0 is missing).

    plot_loadpath.py result.h5 --node N --dir x|y|z|abs [-o out.png]

N is 1-based as in the scene file. Needs python3-h5py and matplotlib (Agg backend, no display).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import h5py  # noqa: E402
import numpy as np  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description="Load factor against the displacement of one node.")
    ap.add_argument("file", help="result file (HDF5)")
    ap.add_argument("--node", type=int, required=True, help="node number, 1-based")
    ap.add_argument("--dir", choices=("x", "y", "z", "abs"), default="abs",
                    help="displacement component, or abs for its length")
    ap.add_argument("-o", "--output", help="image file (default: <file>_node<N>_<dir>.png)")
    a = ap.parse_args()

    with h5py.File(a.file, "r") as f:
        step_name = "load_factor" if "load_factor" in f else "time" if "time" in f else None
        if step_name is None or "node/p" not in f:
            sys.exit(f"{a.file}: needs /load_factor or /time, and /node/p")
        p = f["node/p"]
        nn = p.shape[1]
        if not 1 <= a.node <= nn:
            sys.exit(f"{a.file}: node {a.node} outside 1..{nn}")
        i = a.node - 1
        lam = f[step_name][:]
        pos = p[:, i, :]
        has_p0 = "node/p0" in f
        p0 = f["node/p0"][i, :] if has_p0 else pos[0]
        scene_title = ""
        if "scene" in f.attrs:
            scene = f.attrs["scene"]
            scene = scene.decode("utf-8", "replace") if isinstance(scene, bytes) else str(scene)
            for line in scene.splitlines():
                if line.startswith("title:"):
                    scene_title = line.split(":", 1)[1].strip()
                    break

    u = pos - p0
    x = np.linalg.norm(u, axis=1) if a.dir == "abs" else u[:, "xyz".index(a.dir)]
    ok = np.isfinite(x) & np.isfinite(lam)  # rows never written are NaN
    xs, ys = x[ok], lam[ok]
    # p0 is the unloaded state: start the path there when the first load factor is above zero.
    if step_name == "load_factor" and has_p0 and len(ys) and ys[0] > 0:
        xs, ys = np.concatenate(([0.0], xs)), np.concatenate(([0.0], ys))

    out = a.output or f"{os.path.splitext(a.file)[0]}_node{a.node}_{a.dir}.png"
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(xs, ys, "o-", ms=3)
    label = "|u|" if a.dir == "abs" else f"u_{a.dir}"
    ax.set_xlabel(f"{label} of node {a.node} [m]")
    ax.set_ylabel("load factor [-]" if step_name == "load_factor" else "time [s]")
    ax.set_title(scene_title or os.path.basename(a.file))
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
