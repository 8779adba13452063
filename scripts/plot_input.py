#!/usr/bin/python3
"""Draws the input geometry of a Sinew result file (e.g. from `showinputonly: true`): scene nodes
and elements with their 1-based numbers, as in SPACAR Light's input check.

usage: scripts/plot_input.py result.h5 [-o input.png] [--step K] [--view 3d|xy|xz|yz]
Elements come from /mesh/lines (+ triangles, quads) labelled by /mesh/<kind>_element; positions
from /node/p0 and /mesh/p0 (the input geometry), or /node/p and /mesh/p of step K (1-based,
as in the run summary: --step 1 is the first written step). When the scene gives SPACAR Light's
element look (eprops color, opacity, hide: /mesh/<kind>_color, _opacity, _visible), each element is
drawn in its colour and opacity and hidden elements are not drawn; otherwise all in blue. Rigid
elements (beams in no eprops set: rigid and massless, as in SPACAR Light) are drawn in the seed's grey
198/255.

A scene file (scene.yaml) is drawn too: the script runs the sinew executable on it as SPACAR Light's
input check (`sinew scene.yaml -showinputonly true -o <temporary>.h5`, one process) and draws that
file; the executable is $SINEW_BIN, else build/sinew of this repository (bin/sinew of an installed
prefix), else `sinew` on the PATH. A scene error is printed as Sinew says it (exit 2); a file that is
neither a result file nor a scene is a one-line error (exit 2)."""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np
import yaml

from plot_results import BLUE, RIGID_GREY, load_matplotlib, open_result, parse_scene, rigid_elements, scene_text

HERE = os.path.dirname(os.path.abspath(__file__))


def sinew_executable():
    """$SINEW_BIN, build/sinew of this repository, bin/sinew of an installed prefix, or sinew on the PATH."""
    for path in (os.environ.get("SINEW_BIN"), os.path.join(HERE, "..", "build", "sinew"),
                 os.path.join(HERE, "..", "..", "..", "bin", "sinew")):
        if path and os.path.isfile(path) and os.access(path, os.X_OK):
            return os.path.normpath(path)
    return shutil.which("sinew")


def looks_like_scene(path):
    """A YAML mapping with nodes or a mesh (the first keys of every scene)."""
    try:
        with open(path, encoding="utf-8") as f:
            scene = yaml.safe_load(f)
    except (OSError, UnicodeDecodeError, yaml.YAMLError):
        return False
    return isinstance(scene, dict) and ("nodes" in scene or "mesh" in scene)


def input_check(scene, tmp):
    """Runs sinew's input check on the scene into tmp; returns the result file (exit 2 on a scene error)."""
    exe = sinew_executable()
    if exe is None:
        sys.exit(f"{scene}: a scene; drawing it needs the sinew executable (set SINEW_BIN, build it with "
                 "scripts/setup, or put sinew on the PATH)")
    out = os.path.join(tmp, "input.h5")
    p = subprocess.run([exe, scene, "-showinputonly", "true", "-o", out], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0 or not os.path.isfile(out):
        msg = [ln for ln in p.stdout.splitlines() if ln.strip()]
        print("\n".join(ln for ln in msg if ln.startswith("error")) or "\n".join(msg[-3:]), file=sys.stderr)
        sys.exit(2 if p.returncode in (0, 2) else p.returncode)
    print(f"input check: {exe} {scene} -showinputonly true")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("h5", help="result file, or a scene file (drawn through sinew's input check)")
    ap.add_argument("-o", "--output", help="PNG file (default: <result or scene>_input.png)")
    ap.add_argument("--step", type=int, default=None,
                    help="draw the state of step K (1-based, as in the run summary) instead of the input")
    ap.add_argument("--view", default=None, choices=["3d", "xy", "xz", "yz"],
                    help="projection (default: xy for 2D models and flat models, else 3d)")
    a = ap.parse_args()
    if not os.path.isfile(a.h5):
        sys.exit(f"{a.h5}: no such file")
    if h5py.is_hdf5(a.h5):
        return draw(a, a.h5)
    if not looks_like_scene(a.h5):
        print(f"{a.h5}: neither a Sinew result file (HDF5) nor a scene (YAML with nodes or mesh)", file=sys.stderr)
        return 2
    if a.step is not None:
        sys.exit(f"{a.h5}: a scene has no steps: draw a result file with --step")
    with tempfile.TemporaryDirectory(prefix="sinew_input_") as tmp:
        return draw(a, input_check(a.h5, tmp), name=os.path.basename(a.h5))


def draw(a, path, name=None):
    """Draws the result file path (name: what the title calls it, default the file's name)."""
    out = a.output or os.path.splitext(a.h5)[0] + "_input.png"
    with open_result(path) as f:
        if "node/p0" not in f and "node/p" not in f:
            sys.exit(f"{path}: no /node/p0 (not a Sinew result file?)")
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
        rigid = rigid_elements(parse_scene(scene_text(f)))
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
                    styles = [(*BLUE, 1.0)] * len(conn)
                # rigid elements (in no eprops set) in the seed's grey
                styles = [(*RIGID_GREY, st[3]) if st is not None and kind == "lines" and e in rigid else st
                          for st, e in zip(styles, owner)]
                cells += [(c, int(e), st) for c, e, st in zip(conn, owner, styles)]
        title = scene_text(f)
    flat = np.ptp(nodes[:, 2]) < 1e-12 * max(np.ptp(nodes), 1e-300) if len(nodes) else True
    view = a.view or ("xy" if flat else "3d")
    axes = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}
    plt = load_matplotlib()  # after the input was read: bad files fail fast
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
        ax.plot(*proj(pts), color=st[:3], alpha=st[3], lw=3.0 if e in rigid and len(conn) == 2 else 1.5)  # rigid: bars
        centres.setdefault(e, ([], st))[0].append(mp[conn].mean(axis=0))
    hidden -= set(centres)
    if look:
        print(f"element look from the scene (color, opacity, hide): {len(hidden)} hidden element(s) not drawn"
              + (f" ({', '.join(map(str, sorted(hidden)))})" if hidden else ""))
    for e, (cs, st) in sorted(centres.items()):
        c = np.mean(cs, axis=0)
        ink = tuple(0.55 * x for x in st[:3]) if min(st[:3]) > 0.6 else st[:3]  # light colours: darker numbers
        ax.text(*proj(c), f"{e}", color=ink, fontsize=9, ha="center", va="bottom",
                bbox=dict(boxstyle="round,pad=0.15", fc="white", ec=ink, lw=0.5))
    ax.scatter(*proj(nodes), color="black", s=14, zorder=3)
    for n, p in enumerate(nodes, start=1):
        ax.text(*proj(p), f" {n}", color="black", fontsize=9, ha="left", va="top")
    if view == "3d":
        ax.set_xlabel("x [m]"), ax.set_ylabel("y [m]"), ax.set_zlabel("z [m]")
    else:
        ax.set_xlabel("xyz"[axes[view][0]] + " [m]"), ax.set_ylabel("xyz"[axes[view][1]] + " [m]")
    first = title.splitlines()[0] if isinstance(title, str) and title else ""
    nrigid = len(rigid & set(centres))
    if nrigid:
        print(f"rigid elements (in no eprops set): {nrigid} drawn grey")
    ax.set_title(f"{name or os.path.basename(path)}: {len(nodes)} nodes (black), {len(centres)} elements"
                 + (" (scene colours)" if look else " (blue)") + (f", {nrigid} rigid (grey)" if nrigid else "")
                 + (f"\n{first}" if first.startswith("title") else ""))
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
