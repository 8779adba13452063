#!/usr/bin/python3
"""Draws the input geometry of a Sinew result file (e.g. from `showinputonly: true`): scene nodes
and elements with their 1-based numbers, as in SPACAR Light's input check.

usage: scripts/plot_input.py result.h5 [-o input.png] [--step K] [--view 3d|xy|xz|yz]
Elements come from /mesh/lines (+ triangles, quads) labelled by /mesh/<kind>_element; positions
from /node/p0 and /mesh/p0 (the input geometry), or /node/p and /mesh/p of step K (1-based,
as in the run summary: --step 1 is the first written step). When the scene gives SPACAR Light's
element look (eprops color, opacity, hide: /mesh/<kind>_color, _opacity, _visible), each element is
drawn in its colour and opacity and hidden elements are not drawn; otherwise all in blue."""
import argparse
import os

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

BLUE = (0.0, 0.447, 0.741, 1.0)  # "blue", the first colour of the seed's table (Sinew's default element colour)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("h5")
    ap.add_argument("-o", "--output", help="PNG file (default: <result>_input.png)")
    ap.add_argument("--step", type=int, default=None,
                    help="draw the state of step K (1-based, as in the run summary) instead of the input")
    ap.add_argument("--view", default=None, choices=["3d", "xy", "xz", "yz"],
                    help="projection (default: xy for 2D models and flat models, else 3d)")
    a = ap.parse_args()
    out = a.output or os.path.splitext(a.h5)[0] + "_input.png"
    with h5py.File(a.h5, "r") as f:
        if a.step is None:  # the input geometry: initial positions
            nodes = f["node/p0"][()] if "node/p0" in f else f["node/p"][0]
            mp = (f["mesh/p0"][()] if "mesh/p0" in f else
                  f["mesh/p"][0] - f["mesh/u"][0] if "mesh/u" in f else nodes)
        else:
            if "node/p" not in f:
                raise SystemExit(f"{a.h5}: no step written (an input-only run, opt.showinputonly): draw it without --step")
            ns = f["node/p"].shape[0]
            if not 1 <= a.step <= ns:
                raise SystemExit(f"{a.h5}: --step {a.step} outside 1..{ns} (steps count from 1, as in the summary)")
            nodes = f["node/p"][a.step - 1]
            mp = f["mesh/p"][a.step - 1] if "mesh/p" in f else nodes
            lam = f["time"] if "time" in f else f["load_factor"] if "load_factor" in f else None
            state = f"step {a.step} of {ns}" + (f", {'time' if 'time' in f else 'load factor'} {lam[a.step - 1]:.6g}"
                                                   if lam is not None else "")
            print(f"positions of {state}")
        cells = []  # (connectivity, scene element, (r, g, b, opacity) or None when hidden)
        look = False
        for kind in ("lines", "triangles", "quads"):
            if f"mesh/{kind}" in f:
                conn = f[f"mesh/{kind}"][()]
                owner = f[f"mesh/{kind}_element"][()]
                if f"mesh/{kind}_color" in f:  # SPACAR Light's element look
                    look = True
                    rgb, alpha = f[f"mesh/{kind}_color"][()], f[f"mesh/{kind}_opacity"][()]
                    shown = f[f"mesh/{kind}_visible"][()] > 0
                    styles = [(*c, a) if v else None for c, a, v in zip(rgb, alpha, shown)]
                else:
                    styles = [BLUE] * len(conn)
                cells += [(c, int(e), st) for c, e, st in zip(conn, owner, styles)]
        title = f.attrs.get("scene", "")
    flat = np.ptp(nodes[:, 2]) < 1e-12 * max(np.ptp(nodes), 1e-300) if len(nodes) else True
    view = a.view or ("xy" if flat else "3d")
    axes = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}
    fig = plt.figure(figsize=(8, 6))
    if view == "3d":
        ax = fig.add_subplot(projection="3d")
        proj = lambda p: (p[..., 0], p[..., 1], p[..., 2])  # noqa: E731
    else:
        ax = fig.add_subplot()
        i, j = axes[view]
        proj = lambda p: (p[..., i], p[..., j])  # noqa: E731
        ax.set_aspect("equal")
    centres, hidden = {}, set()
    for conn, e, st in cells:
        if st is None:
            hidden.add(e)
            continue
        pts = mp[np.append(conn, conn[0]) if len(conn) > 2 else conn]
        ax.plot(*proj(pts), color=st[:3], alpha=st[3], lw=1.5)
        centres.setdefault(e, ([], st))[0].append(mp[conn].mean(axis=0))
    hidden -= set(centres)
    if look:
        print(f"element look from the scene (color, opacity, hide): {len(hidden)} hidden element(s) not drawn"
              + (f" ({', '.join(map(str, sorted(hidden)))})" if hidden else ""))
    for e, (cs, st) in sorted(centres.items()):
        c = np.mean(cs, axis=0)
        ax.text(*proj(c), f"{e}", color=st[:3], fontsize=9, ha="center", va="bottom",
                bbox=dict(boxstyle="round,pad=0.15", fc="white", ec=st[:3], lw=0.5))
    ax.scatter(*proj(nodes), color="black", s=14, zorder=3)
    for n, p in enumerate(nodes, start=1):
        ax.text(*proj(p), f" {n}", color="black", fontsize=9, ha="left", va="top")
    if view == "3d":
        ax.set_xlabel("x [m]"), ax.set_ylabel("y [m]"), ax.set_zlabel("z [m]")
    else:
        ax.set_xlabel("xyz"[axes[view][0]] + " [m]"), ax.set_ylabel("xyz"[axes[view][1]] + " [m]")
    first = title.splitlines()[0] if isinstance(title, str) and title else ""
    ax.set_title(f"{os.path.basename(a.h5)}: {len(nodes)} nodes (black), {len(centres)} elements"
                 + (" (scene colours)" if look else " (blue)")
                 + (f"\n{first}" if first.startswith("title") else ""))
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
