#!/usr/bin/python3
"""Pictures of a Sinew result file without ParaView: the deformed shape over the undeformed one,
mode shapes, and animations (PNG / animated GIF; matplotlib Agg and Pillow, no display).

usage: scripts/plot_results.py result.h5 [-o out.png] [--step K] [--mode N | --mode buck:N]
                               [--animate path | --animate mode:N | --animate buck:N]
                               [--scale auto|S] [--view auto|3d|xy|xz|yz] [--labels auto|on|off]

- default: the deformed shape of step K (1-based like the run summary; default the last written
  step) over the undeformed one (/mesh/p0 when present, else /mesh/p - /mesh/u, /node/p0 without
  a mesh; for the load steps after form finding: the found shape, the last form-finding row), the
  load factor or time and the scene title in the title;
- --mode N: natural mode N (/mesh/mode_freq_N) of step K with its frequency (/freq) in Hz;
  --mode buck:N the buckling mode (/mesh/mode_buck_N) with its load multiplier (/buck);
- --animate path: a GIF of the deformed shape over all written steps (the load path or the time
  history); --animate mode:N (or buck:N): a GIF of mode N oscillating about the shape of step K.
Displacements are drawn true to scale when they are visible (at least 2 % of the model size);
smaller ones, and mode shapes (normalized), are scaled to 10 % of the model size and the factor
is in the title (--scale S sets it). Node numbers (scene numbering) are drawn up to 200 nodes.
With SPACAR Light's element look in the scene (eprops color, opacity, hide: /mesh/<kind>_color,
_opacity, _visible) the deformed shape is drawn in the element colours and opacities, and hidden
elements are drawn in neither shape.
Positions are in m (Sinew's scenes are SI). Prints the file written and its title; the PNG also
carries the title in its metadata ("Title")."""
import argparse
import os
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.animation import PillowWriter  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection  # noqa: E402

LABEL_LIMIT = 200       # node numbers drawn up to this many nodes (--labels auto)
VISIBLE = 0.02          # displacements below this fraction of the model size are magnified
SHOWN = 0.10            # ... to this fraction (also the amplitude of mode shapes)
MODE_FRAMES = 24        # frames of one period of a mode animation


class Result:
    """What the pictures need from a result file, read once."""

    def __init__(self, path):
        with h5py.File(path, "r") as f:
            if "node/p" not in f:
                sys.exit(f"{path}: no /node/p (not a Sinew result file?)")
            self.node_p = f["node/p"][()]
            self.node_p0 = f["node/p0"][()] if "node/p0" in f else self.node_p[0]
            self.mesh_p = f["mesh/p"][()] if "mesh/p" in f else self.node_p
            if "mesh/p0" in f:
                self.mesh_p0 = np.array(np.broadcast_to(f["mesh/p0"][()], self.mesh_p.shape))
            elif "mesh/u" in f:
                self.mesh_p0 = self.mesh_p - f["mesh/u"][()]
            else:
                self.mesh_p0 = np.array(np.broadcast_to(self.node_p0 if "mesh/p" not in f else self.mesh_p[0],
                                                        self.mesh_p.shape))
            # rows after form finding deform the found shape (the last form-finding row, design.md)
            self.nff = len(f["formfinding/residual"]) if "formfinding/residual" in f else 0
            self.cells = []
            self.colors = None  # per drawn cell (r, g, b, opacity) when the scene gives the element look
            self.hidden = 0
            for kind in ("lines", "triangles", "quads"):
                if f"mesh/{kind}" in f and "mesh/p" in f:
                    conn = [np.asarray(c) for c in f[f"mesh/{kind}"][()]]
                    if f"mesh/{kind}_color" in f:
                        rgb, alpha = f[f"mesh/{kind}_color"][()], f[f"mesh/{kind}_opacity"][()]
                        shown = f[f"mesh/{kind}_visible"][()] > 0
                        self.colors = (self.colors or []) + [(*c, a) for c, a, v in zip(rgb, alpha, shown) if v]
                        self.hidden += int(np.count_nonzero(~shown))
                        conn = [c for c, v in zip(conn, shown) if v]
                    self.cells += conn
            self.stepname = "time" if "time" in f else "load_factor" if "load_factor" in f else None
            self.stepvalue = f[self.stepname][()] if self.stepname else None
            self.freq = f["freq"][()] if "freq" in f else None
            self.buck = f["buck"][()] if "buck" in f else None
            # [ns, k]; files of Sinew before issue 24 wrote k = 1 as [ns]
            self.freq = None if self.freq is None else self.freq.reshape(len(self.freq), -1)
            self.buck = None if self.buck is None else self.buck.reshape(len(self.buck), -1)
            self.modes = {}
            if "mesh" in f:
                for name in f["mesh"]:
                    # mode_freq_N, mode_buck_N: translations (mode_*_N_rot: rotation vectors, not drawn)
                    if (name.startswith("mode_freq_") or name.startswith("mode_buck_")) and name[10:].isdigit():
                        self.modes[(name[5:9], int(name[10:]))] = f["mesh/" + name]
                self.modes = {k: v[()] for k, v in self.modes.items()}
            scene = f.attrs.get("scene", "")
            scene = scene.decode("utf-8", "replace") if isinstance(scene, bytes) else str(scene)
        self.path = path
        self.title = ""
        for line in scene.splitlines():
            if line.startswith("title:"):
                self.title = line.split(":", 1)[1].strip().strip("'\"")
                break
        self.title = self.title or os.path.basename(path)
        nn = len(self.node_p0)
        # scene nodes are the first rows of the FE mesh (nbeams splits append nodes): modes can move them
        self.scene_rows = nn <= self.mesh_p.shape[1] and np.allclose(self.mesh_p0[0][:nn], self.node_p0, atol=1e-12)
        self.node_ref = np.array([self.mesh_p0[k][:nn] if self.scene_rows else self.node_p0
                                  for k in range(len(self.mesh_p0))])
        if 0 < self.nff < len(self.mesh_p):
            self.mesh_p0[self.nff:] = self.mesh_p[self.nff - 1]
            self.node_ref[self.nff:] = self.node_p[self.nff - 1]
        written = np.all(np.isfinite(self.node_p.reshape(len(self.node_p), -1)), axis=1)
        self.steps = [k + 1 for k in range(len(self.node_p)) if written[k]]  # 1-based, as in the summary
        if not self.steps:
            sys.exit(f"{path}: no step written")

    def row(self, step):
        if step is None:
            return self.steps[-1] - 1
        if step not in self.steps:
            sys.exit(f"{self.path}: step {step} not written (steps 1..{len(self.node_p)}, written: "
                     f"{self.steps[0]}..{self.steps[-1]})")
        return step - 1

    def state(self, k):
        """'load factor 0.75' or 'time 0.01 s' of row k."""
        if self.stepname is None:
            return f"step {k + 1}"
        v = self.stepvalue[k]
        return f"step {k + 1} of {len(self.node_p)}, " + (f"time {v:.6g} s" if self.stepname == "time" else f"load factor {v:.6g}")

    def ref_nodes(self, k):
        """Scene-node positions of the undeformed shape of row k (the found shape after form finding)."""
        return self.node_ref[k]

    def ref_name(self, k):
        return "found shape" if 0 < self.nff <= k else "undeformed"

    def mode_nodes(self, k, shape):
        """Scene-node positions displaced by a mode shape (mesh rows), or the step's positions."""
        return self.node_p[k] + (shape[:len(self.node_p0)] if self.scene_rows else 0.0)

    def size(self):
        pts = np.concatenate([self.mesh_p0[self.steps[-1] - 1], self.node_p0])
        return max(float(np.linalg.norm(np.ptp(pts, axis=0))), 1e-300)


def choose_view(arg, clouds):
    if arg != "auto":
        return arg
    pts = np.concatenate(clouds)
    ext = np.ptp(pts, axis=0)
    flat = ext < 1e-9 * max(ext.max(), 1e-300)
    if flat[2]:
        return "xy"
    if flat[1]:
        return "xz"
    if flat[0]:
        return "yz"
    return "3d"


class Canvas:
    """One figure with fixed axes limits (so that animation frames do not jump)."""

    def __init__(self, view, clouds):
        self.view = view
        self.fig = plt.figure(figsize=(8, 6.5))
        pts = np.concatenate(clouds)
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        centre, half = (lo + hi) / 2, max(np.max(hi - lo) / 2 * 1.08, 1e-12)
        if view == "3d":
            self.ax = self.fig.add_subplot(projection="3d")
            self.idx = (0, 1, 2)
            for setlim, c in zip((self.ax.set_xlim, self.ax.set_ylim, self.ax.set_zlim), centre):
                setlim(c - half, c + half)
            self.ax.set_box_aspect((1, 1, 1))
            self.ax.set_xlabel("x [m]"), self.ax.set_ylabel("y [m]"), self.ax.set_zlabel("z [m]")
        else:
            self.ax = self.fig.add_subplot()
            self.idx = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}[view]
            i, j = self.idx
            self.ax.set_xlim(centre[i] - half, centre[i] + half)
            self.ax.set_ylim(centre[j] - half, centre[j] + half)
            self.ax.set_aspect("equal")
            self.ax.set_xlabel(f"{'xyz'[i]} [m]"), self.ax.set_ylabel(f"{'xyz'[j]} [m]")
            self.ax.grid(True, alpha=0.3)
        self.artists = []

    def clear(self):
        for a in self.artists:
            a.remove()
        self.artists = []

    def shape(self, mesh_pts, cells, node_pts, colors=None, **style):
        """colors: (r, g, b, opacity) per cell (the scene's element look) instead of style's colour."""
        node_style = dict(color=style.get("color"), alpha=style.get("alpha", 1.0))
        segs, segcolors = [], []
        for i, c in enumerate(cells):
            ring = np.append(c, c[0]) if len(c) > 2 else c
            segs += [mesh_pts[ring[m:m + 2]][:, self.idx] for m in range(len(ring) - 1)]
            if colors is not None:
                segcolors += [colors[i]] * (len(ring) - 1)
        if segs:
            if colors is not None:
                style = {k: v for k, v in style.items() if k not in ("color", "alpha")}
                style["colors"] = segcolors
            coll = Line3DCollection(segs, **style) if self.view == "3d" else LineCollection(segs, **style)
            self.artists.append(self.ax.add_collection(coll))
        pts = node_pts[:, self.idx]
        self.artists.append(self.ax.scatter(*pts.T, s=10, color=node_style["color"], alpha=node_style["alpha"],
                                            zorder=3))

    def labels(self, node_pts):
        for n, p in enumerate(node_pts, start=1):
            self.artists.append(self.ax.text(*p[list(self.idx)], f" {n}", fontsize=8, color="black"))

    def axis_labels(self):
        labels = [self.ax.get_xlabel(), self.ax.get_ylabel()] + ([self.ax.get_zlabel()] if self.view == "3d" else [])
        return ", ".join(labels)

    def title(self, text):
        self.ax.set_title(text, fontsize=10)  # replaces the previous title


def magnification(arg, disp, size, always):
    """Scale factor of displacements: given, or 1 when visible, else so that the largest is SHOWN * size."""
    if arg != "auto":
        return float(arg)
    dmax = float(np.max(np.linalg.norm(disp.reshape(-1, 3), axis=1))) if disp.size else 0.0
    if dmax == 0.0 or (not always and dmax >= VISIBLE * size):
        return 1.0
    s = SHOWN * size / dmax
    return float(f"{s:.2g}")  # a round factor for the title


def scaled(s):
    return "" if s == 1.0 else f" (displacements x {s:g})"


def mode_info(res, kind, n, k):
    key = ("freq", n) if kind == "freq" else ("buck", n)
    if key not in res.modes:
        have = sorted(f"{'' if kk == 'freq' else 'buck:'}{nn}" for kk, nn in res.modes)
        sys.exit(f"{res.path}: no /mesh/mode_{kind}_{n} (modes in the file: {', '.join(have) or 'none'}; "
                 "calcfreq/calcbuck in the scene)")
    shape = res.modes[key][k]
    table = res.freq if kind == "freq" else res.buck
    value = table[k, n - 1] if table is not None and n - 1 < table.shape[1] else float("nan")
    what = f"mode {n}: f = {value:.6g} Hz" if kind == "freq" else f"buckling mode {n}: load multiplier {value:.6g}"
    return shape, what


def parse_mode(text):
    kind, _, n = text.rpartition(":")
    kind = kind or "freq"
    if kind not in ("freq", "mode", "buck") or not n.isdigit() or int(n) < 1:
        sys.exit(f"mode '{text}': expected N, mode:N or buck:N with N >= 1")
    return ("freq" if kind in ("freq", "mode") else "buck"), int(n)


def save_png(canvas, out, title):
    canvas.fig.tight_layout()
    canvas.fig.savefig(out, dpi=110, metadata={"Title": title})
    print(f"wrote {out}")
    print(f"axes: {canvas.axis_labels()}")
    print(f"title: {title}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("h5")
    ap.add_argument("-o", "--output", help="image file (default: <result>_step<K>.png, _mode<N>.png, _<what>.gif)")
    ap.add_argument("--step", type=int, default=None, help="step K, 1-based as in the run summary (default: last)")
    ap.add_argument("--mode", default=None, help="N (natural mode N) or buck:N (buckling mode N)")
    ap.add_argument("--animate", default=None, help="path, mode:N or buck:N: write an animated GIF")
    ap.add_argument("--scale", default="auto", help="displacement scale factor (default auto)")
    ap.add_argument("--view", default="auto", choices=["auto", "3d", "xy", "xz", "yz"])
    ap.add_argument("--labels", default="auto", choices=["auto", "on", "off"],
                    help=f"node numbers (auto: up to {LABEL_LIMIT} nodes)")
    ap.add_argument("--fps", type=float, default=8.0, help="frames per second of a GIF")
    a = ap.parse_args()
    if a.mode and a.animate:
        sys.exit("--mode and --animate: give one of them (--animate mode:N animates a mode)")
    if a.scale != "auto":
        try:
            float(a.scale)
        except ValueError:
            sys.exit(f"--scale '{a.scale}': expected auto or a number")

    res = Result(a.h5)
    k = res.row(a.step)
    size = res.size()
    labels = a.labels == "on" or (a.labels == "auto" and len(res.node_p0) <= LABEL_LIMIT)
    print(f"node numbers: {'drawn' if labels else 'not drawn'} ({len(res.node_p0)} nodes)")
    if res.colors is not None:
        print(f"element look from the scene (color, opacity, hide): {res.hidden} hidden cell(s) not drawn")
    base = os.path.splitext(a.h5)[0]
    grey = dict(color="0.6", lw=1.0, alpha=0.8)
    blue = dict(color="tab:blue", lw=1.6)

    if a.animate == "path":
        rows = [s - 1 for s in res.steps]
        s = magnification(a.scale, np.stack([res.mesh_p[r] - res.mesh_p0[r] for r in rows]), size, False)
        frames = [(res.mesh_p0[r] + s * (res.mesh_p[r] - res.mesh_p0[r]),
                   res.ref_nodes(r) + s * (res.node_p[r] - res.ref_nodes(r)), r) for r in rows]
        canvas = Canvas(choose_view(a.view, [res.mesh_p0[rows[-1]]] + [f[0] for f in frames]),
                        [res.mesh_p0[rows[-1]]] + [f[0] for f in frames])
        out = a.output or base + "_path.gif"
        titles = [f"{res.title}\ndeformed shape, {res.state(r)}{scaled(s)}" for _, _, r in frames]
        write_gif(canvas, out, a.fps, frames, res, grey, blue, labels, titles, k_ref=rows[-1])
        return 0
    if a.animate:
        kind, n = parse_mode(a.animate)
        shape, what = mode_info(res, kind, n, k)
        s = magnification(a.scale, shape, size, True)
        ref, ref_nodes = res.mesh_p[k], res.node_p[k]
        phases = np.sin(2 * np.pi * np.arange(MODE_FRAMES) / MODE_FRAMES)
        frames = [(ref + c * s * shape, res.mode_nodes(k, c * s * shape), k) for c in phases]
        canvas = Canvas(choose_view(a.view, [ref + s * shape, ref - s * shape]), [ref + s * shape, ref - s * shape])
        out = a.output or base + f"_{'mode' if kind == 'freq' else 'buck'}{n}.gif"
        title = f"{res.title}\n{what} ({res.state(k)}; shape x {s:g})"
        write_gif(canvas, out, a.fps, frames, res, grey, blue, labels, [title] * len(frames), k_ref=k, ref=(ref, ref_nodes))
        return 0
    if a.mode:
        kind, n = parse_mode(a.mode)
        shape, what = mode_info(res, kind, n, k)
        s = magnification(a.scale, shape, size, True)
        ref, ref_nodes = res.mesh_p[k], res.node_p[k]
        moved = ref + s * shape
        canvas = Canvas(choose_view(a.view, [ref, moved]), [ref, moved])
        canvas.shape(ref, res.cells, ref_nodes, **grey)
        moved_nodes = res.mode_nodes(k, s * shape)
        canvas.shape(moved, res.cells, moved_nodes, colors=res.colors, **blue)
        if labels:
            canvas.labels(moved_nodes)
        title = f"{res.title}\n{what} ({res.state(k)}; shape x {s:g})"
        canvas.title(title)
        save_png(canvas, a.output or base + f"_{'mode' if kind == 'freq' else 'buck'}{n}.png", title)
        return 0
    s = magnification(a.scale, res.mesh_p[k] - res.mesh_p0[k], size, False)
    deformed = res.mesh_p0[k] + s * (res.mesh_p[k] - res.mesh_p0[k])
    deformed_nodes = res.ref_nodes(k) + s * (res.node_p[k] - res.ref_nodes(k))
    canvas = Canvas(choose_view(a.view, [res.mesh_p0[k], deformed]), [res.mesh_p0[k], deformed])
    canvas.shape(res.mesh_p0[k], res.cells, res.ref_nodes(k), **grey)
    canvas.shape(deformed, res.cells, deformed_nodes, colors=res.colors, **blue)
    if labels:
        canvas.labels(deformed_nodes)
    drawn = "scene colours" if res.colors is not None else "blue"
    title = f"{res.title}\ndeformed ({drawn}) and {res.ref_name(k)} (grey), {res.state(k)}{scaled(s)}"
    canvas.title(title)
    save_png(canvas, a.output or base + f"_step{k + 1}.png", title)
    return 0


def write_gif(canvas, out, fps, frames, res, grey, blue, labels, titles, k_ref, ref=None):
    """frames: (mesh positions, node positions, row); the undeformed (or reference) shape stays in grey."""
    base_mesh, base_nodes = ref if ref is not None else (res.mesh_p0[k_ref], res.ref_nodes(k_ref))
    canvas.shape(base_mesh, res.cells, base_nodes, **grey)
    fixed = canvas.artists
    canvas.artists = []
    writer = PillowWriter(fps=fps)
    with writer.saving(canvas.fig, out, dpi=90):
        for (mesh_pts, node_pts, _), title in zip(frames, titles):
            canvas.clear()
            canvas.shape(mesh_pts, res.cells, node_pts, colors=res.colors, **blue)
            if labels:
                canvas.labels(node_pts)
            canvas.title(title)
            if not hasattr(canvas, "laid_out"):
                canvas.fig.tight_layout()
                canvas.laid_out = True
            writer.grab_frame()
    del fixed
    print(f"wrote {out} ({len(frames)} frames)")
    print(f"axes: {canvas.axis_labels()}")
    print(f"title: {titles[-1]}")


if __name__ == "__main__":
    sys.exit(main())
