#!/usr/bin/python3
"""Pictures of a Sinew result file without ParaView: the deformed shape over the undeformed one,
mode shapes, and animations (PNG / animated GIF; matplotlib Agg and Pillow, no display).

usage: scripts/plot_results.py result.h5 [-o out.png] [--step K] [--mode N | --mode buck:N]
                               [--animate path | --animate mode:N | --animate buck:N]
                               [--scale auto|S] [--view auto|3d|xy|xz|yz] [--labels auto|on|off]
                               [--stress n1|vonmises|off]

- default: the deformed shape of step K (1-based like the run summary; default the last written
  step) over the undeformed one (/mesh/p0 when present, else /mesh/p - /mesh/u, /node/p0 without
  a mesh; for the load steps after form finding: the found shape, the last form-finding row), the
  load factor or time and the scene title in the title;
- --mode N: natural mode N (/mesh/mode_freq_N) of step K with its frequency (/freq) in Hz;
  --mode buck:N the buckling mode (/mesh/mode_buck_N) with its load multiplier (/buck);
- --animate path: a GIF of the deformed shape over all written steps (the load path or the time
  history); --animate mode:N (or buck:N): a GIF of mode N oscillating about the shape of step K.
Displacements are drawn true to scale when they are visible (at least 2 % of the model size; for
--animate path: the path's largest displacement at least 10 %, so that a shallow arch's snap shows);
smaller ones, and mode shapes (normalized), are scaled to 10 % of the model size and the factor
is in the title (--scale S sets it). Node numbers (scene numbering) are drawn up to 200 nodes.
Stress colours (the deformed shape of a step and --animate path; one scale per quantity with its
colour bar, fixed over a GIF): membranes (triangles, quads) are filled and coloured by the first
principal stress resultant n1 of /cell/<kind>/membrane_n11, _n22, _n12 in N/m (--stress vonmises:
the Von Mises resultant sqrt(n11^2 + n22^2 - n11 n22 + 3 n12^2); --stress off: none), cables by
/cell/lines/axial_force in N; beams are blue, rigid elements (beams in no eprops set) wide bars in
the seed's grey 198/255. Mode shapes have no stresses: drawn in the element colours.
With SPACAR Light's element look in the scene (eprops color, opacity, hide: /mesh/<kind>_color,
_opacity, _visible) the deformed shape is drawn in the element colours (they win over stress
colours) and opacities, and hidden elements are drawn in neither shape. A missing file or one that
is not a result file is a one-line error (exit 1).
Positions are in m (Sinew's scenes are SI). Prints the file written and its title; the PNG also
carries the title in its metadata ("Title")."""
import argparse
import os
import sys

import h5py
import numpy as np
import yaml

# matplotlib's names, bound by load_matplotlib() once the input was read
matplotlib = plt = PillowWriter = LineCollection = PolyCollection = Line3DCollection = Poly3DCollection = None


def load_matplotlib():
    """Imports matplotlib (Agg backend, no display) into this module's names and returns pyplot. The
    scripts call it after reading their input, so a missing or wrong file is reported without the
    second that importing matplotlib takes."""
    global matplotlib, plt, PillowWriter, LineCollection, PolyCollection, Line3DCollection, Poly3DCollection
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.animation import PillowWriter
    from matplotlib.collections import LineCollection, PolyCollection
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection
    return plt

LABEL_LIMIT = 200       # node numbers drawn up to this many nodes (--labels auto)
NODE_DOT_LIMIT = 200    # node dots drawn up to this many nodes
VISIBLE = 0.02          # displacements below this fraction of the model size are magnified
SHOWN = 0.10            # ... to this fraction (also the amplitude of mode shapes)
MODE_FRAMES = 24        # frames of one period of a mode animation


BLUE = (0.0, 0.447, 0.741)     # the seed's blue, Sinew's default element colour
RIGID_GREY = (198 / 255,) * 3  # the seed's grey: rigid elements (beams in no eprops set), docs/scene.md
MIN_SPAN = 0.02                # narrowest colour scale, relative to its largest value
SURFACE_ALPHA = 0.35           # membranes without stress colour: blue faces at this opacity
MEASURES = {  # membrane stress measure of the resultants n11, n22, n12 (N/m) -> (name for the colour bar, formula)
    "n1": ("first principal resultant n1",
           lambda a, b, c: 0.5 * (a + b) + np.sqrt(0.25 * (a - b) ** 2 + c ** 2)),
    "vonmises": ("Von Mises resultant sqrt(n11^2 + n22^2 - n11 n22 + 3 n12^2)",
                 lambda a, b, c: np.sqrt(a ** 2 + b ** 2 - a * b + 3 * c ** 2)),
}


def open_result(path):
    """The result file opened with h5py, or a one-line error (exit 1) when it is missing or not HDF5."""
    if not os.path.isfile(path):
        sys.exit(f"{path}: no such file")
    if not h5py.is_hdf5(path):
        sys.exit(f"{path}: not an HDF5 result file (Sinew writes one with `sinew scene.yaml -o result.h5`)")
    try:
        return h5py.File(path, "r")
    except OSError as e:
        sys.exit(f"{path}: cannot open ({str(e).splitlines()[0]})")


def scene_text(f):
    scene = f.attrs.get("scene", "")
    return scene.decode("utf-8", "replace") if isinstance(scene, bytes) else str(scene)


def parse_scene(text):
    """The scene stored in the result file as a dict ({} when it is not YAML)."""
    try:
        scene = yaml.safe_load(text) if text else {}
    except yaml.YAMLError:
        return {}
    return scene if isinstance(scene, dict) else {}


def listed(v):
    return [v] if isinstance(v, int) else [e for e in v if isinstance(e, int)] if isinstance(v, list) else []


def rigid_elements(scene):
    """Scene elements (1-based) in no eprops set: rigid and massless beams, as in SPACAR Light. Elements
    read from a mesh file (numbered after the scene's `elements`) belong to their physical group's set."""
    sets = scene.get("eprops") or []
    sets = sets if isinstance(sets, list) else []
    in_set = {e for s in sets if isinstance(s, dict) for e in listed(s.get("elems"))}
    elements = scene.get("elements") or []
    return {e for e in range(1, len(elements) + 1) if e not in in_set} if isinstance(elements, list) else set()


def coloured_elements(scene):
    """Scene elements whose eprops set gives a colour (the scene's look wins over stress colours there)."""
    sets = scene.get("eprops") or []
    return {e for s in (sets if isinstance(sets, list) else []) if isinstance(s, dict) and "color" in s
            for e in listed(s.get("elems"))}


def table_2d(f, name):
    """/freq or /buck as [ns, k] (a file with one value per row may hold it as (ns,))."""
    if name not in f:
        return None
    t = f[name][()]
    return t.reshape(len(t), -1)


class CellSet:
    """The drawn cells of /mesh/lines, triangles, quads (hidden ones left out) with their fixed colour
    (the scene's colour, or grey for rigid elements; None: stress colour or blue), opacity, and the
    per-row values painted on them: membrane measure [ns, ncells] (N/m) and cable axial force (N)."""

    @classmethod
    def empty(cls, ns):
        c = cls.__new__(cls)
        c.conn, c.surface, c.fixed, c.alpha, c.is_rigid = [], np.zeros(0, bool), [], np.zeros(0), []
        c.values = {"membrane": np.full((ns, 0), np.nan), "cable": np.full((ns, 0), np.nan)}
        c.hidden, c.look, c.rigid, c.measure = 0, False, 0, "n1"
        return c

    def __init__(self, f, scene, measure):
        ns = len(f["mesh/p"])
        rigid, coloured = rigid_elements(scene), coloured_elements(scene)
        self.measure, self.hidden, self.look = measure, 0, False
        conn, surface, fixed, alpha, membrane, cable, is_rigid = [], [], [], [], [], [], []
        for kind in ("lines", "triangles", "quads"):
            if f"mesh/{kind}" not in f:
                continue
            cells = [np.asarray(c) for c in f[f"mesh/{kind}"][()]]
            n = len(cells)
            owner = f[f"mesh/{kind}_element"][()] if f"mesh/{kind}_element" in f else np.zeros(n, int)
            shown = np.ones(n, bool)
            rgb, opacity = [None] * n, np.ones(n)
            if f"mesh/{kind}_color" in f:  # SPACAR Light's element look
                self.look = True
                shown = f[f"mesh/{kind}_visible"][()] > 0
                opacity = f[f"mesh/{kind}_opacity"][()]
                # a colour given by the cell's set (or, for mesh-file sets, any colour but the default blue)
                rgb = [tuple(c) if e in coloured or (e not in rigid and not np.allclose(c, BLUE, atol=1e-6)) else None
                       for c, e in zip(f[f"mesh/{kind}_color"][()], owner)]
            rgb = [RIGID_GREY if kind == "lines" and e in rigid else c for c, e in zip(rgb, owner)]
            if kind == "lines":
                force = f["cell/lines/axial_force"][()] if "cell/lines/axial_force" in f else np.full((ns, n), np.nan)
                cable.append(force[:, shown]), membrane.append(np.full((ns, int(shown.sum())), np.nan))
            else:
                g = f"cell/{kind}/membrane_"
                if g + "n11" in f:
                    n11, n22, n12 = (f[g + c][()] for c in ("n11", "n22", "n12"))
                    membrane.append(MEASURES[measure][1](n11, n22, n12)[:, shown])
                else:
                    membrane.append(np.full((ns, int(shown.sum())), np.nan))
                cable.append(np.full((ns, int(shown.sum())), np.nan))
            self.hidden += int(np.count_nonzero(~shown))
            conn += [c for c, v in zip(cells, shown) if v]
            surface += [kind != "lines"] * int(shown.sum())
            fixed += [c for c, v in zip(rgb, shown) if v]
            alpha += [a for a, v in zip(opacity, shown) if v]
            is_rigid += [kind == "lines" and e in rigid for e, v in zip(owner, shown) if v]
        self.conn, self.surface, self.fixed, self.alpha = conn, np.array(surface, bool), fixed, np.array(alpha)
        self.is_rigid, self.rigid = is_rigid, sum(is_rigid)
        self.values = {"membrane": np.concatenate(membrane, axis=1) if membrane else np.full((ns, 0), np.nan),
                       "cable": np.concatenate(cable, axis=1) if cable else np.full((ns, 0), np.nan)}
        for v in self.values.values():  # values on cells with the scene's colour are not painted
            v[:, [c is not None for c in self.fixed]] = np.nan


class Paint:
    """Colour scales of the membrane measure and the cable force over the rows drawn (fixed for a GIF)."""

    def __init__(self, cells, rows):
        self.scales = {}
        for what, cmap, label in (("membrane", "viridis", f"membrane {MEASURES[cells.measure][0]} [N/m]"),
                                  ("cable", "plasma", "cable axial force [N]")):
            v = cells.values[what][rows]
            v = v[np.isfinite(v)]
            if v.size:
                lo, hi = float(v.min()), float(v.max())
                # a scale at least 2 % of the largest value wide: a uniform stress is one colour, not round-off
                pad = max(0.0, 0.5 * (MIN_SPAN * max(abs(lo), abs(hi), 1e-300) - (hi - lo)))
                self.scales[what] = (matplotlib.colors.Normalize(lo - pad, hi + pad),
                                     matplotlib.colormaps[cmap], label, lo, hi)

    def colours(self, cells, row):
        """(r, g, b, a) per cell: the fixed colour, else the painted value of the row, else blue."""
        out = []
        for i, fixed in enumerate(cells.fixed):
            c = fixed
            if c is None and row is not None:
                for what, (norm, cmap, *_) in self.scales.items():
                    v = cells.values[what][row, i]
                    if np.isfinite(v):
                        c = cmap(norm(v))[:3]
            painted = c is not None and fixed is None
            if c is None:
                c = BLUE
            a = cells.alpha[i] * (SURFACE_ALPHA if cells.surface[i] and not painted and fixed is None else 1.0)
            out.append((*c[:3], a))
        return out

    def describe(self):
        return ", ".join(f"{label} {lo:.4g} .. {hi:.4g}" for _, _, label, lo, hi in self.scales.values())


class Result:
    """What the pictures need from a result file, read once."""

    def __init__(self, path, measure="n1"):
        with open_result(path) as f:
            if "node/p" not in f:
                what = ("an input-only run (showinputonly): draw it with scripts/plot_input.py"
                        if f.attrs.get("showinputonly", 0) else "not a Sinew result file?")
                sys.exit(f"{path}: no /node/p ({what})")
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
            scene = scene_text(f)
            self.cells = CellSet(f, parse_scene(scene), measure) if "mesh/p" in f else CellSet.empty(len(self.mesh_p))
            self.stepname = "time" if "time" in f else "load_factor" if "load_factor" in f else None
            self.stepvalue = f[self.stepname][()] if self.stepname else None
            # step analyses (frequencies, buckling, modes) at some rows only (opt.step_analyses): their
            # datasets have one row per analysed step, /step_analysis_rows the step row of each
            self.analysis_rows = list(f["step_analysis_rows"][()]) if "step_analysis_rows" in f else None
            self.freq = table_2d(f, "freq")
            self.buck = table_2d(f, "buck")
            self.modes = {}
            if "mesh" in f:
                for name in f["mesh"]:
                    # mode_freq_N, mode_buck_N: translations (mode_*_N_rot: rotation vectors, not drawn)
                    if (name.startswith("mode_freq_") or name.startswith("mode_buck_")) and name[10:].isdigit():
                        self.modes[(name[5:9], int(name[10:]))] = f["mesh/" + name]
                self.modes = {k: v[()] for k, v in self.modes.items()}
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

    def analysis_row(self, k):
        """Row of the step-analysis datasets (/freq, /buck, /mesh/mode_*) of step row k."""
        if self.analysis_rows is None:
            return k
        if k not in self.analysis_rows:
            steps = ", ".join(str(r + 1) for r in self.analysis_rows)
            sys.exit(f"{self.path}: step {k + 1} has no step analyses (steps with them: {steps or 'none'}; "
                     "-step_analyses all computes them at every step)")
        return self.analysis_rows.index(k)

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

    def shape(self, mesh_pts, cells, node_pts, rgba=None, **style):
        """cells: a CellSet. rgba None: a wireframe in style's colour (the reference shape); else one
        (r, g, b, opacity) per cell: lines in it, membranes filled with it (thin dark edges)."""
        segs, segcolors, widths, polys, facecolors = [], [], [], [], []
        for i, c in enumerate(cells.conn):
            if rgba is not None and cells.surface[i]:
                polys.append(mesh_pts[c][:, self.idx])
                facecolors.append(rgba[i])
                continue
            ring = np.append(c, c[0]) if len(c) > 2 else c
            segs += [mesh_pts[ring[m:m + 2]][:, self.idx] for m in range(len(ring) - 1)]
            if rgba is not None:
                segcolors += [rgba[i]] * (len(ring) - 1)
                # rigid bodies drawn as wide grey bars (told apart from the thin grey reference shape)
                widths += [style.get("lw", 1.0) * (2.0 if cells.is_rigid[i] else 1.0)] * (len(ring) - 1)
        if polys:
            edges = [(0.15, 0.15, 0.15, 0.5 * fc[3]) for fc in facecolors]
            make = Poly3DCollection if self.view == "3d" else PolyCollection
            self.artists.append(self.ax.add_collection(make(polys, facecolors=facecolors, edgecolors=edges, lw=0.4)))
        if segs:
            line_style = dict(style)
            if rgba is not None:
                line_style = {k: v for k, v in style.items() if k not in ("color", "alpha")}
                line_style["colors"], line_style["linewidths"] = segcolors, widths
                line_style.pop("lw", None)
            make = Line3DCollection if self.view == "3d" else LineCollection
            self.artists.append(self.ax.add_collection(make(segs, **line_style)))
        if len(node_pts) <= NODE_DOT_LIMIT:  # above: the dots would hide the cells and their colours
            pts = node_pts[:, self.idx]
            self.artists.append(self.ax.scatter(*pts.T, s=10, color=style.get("color", "black"),
                                                alpha=style.get("alpha", 1.0), zorder=3))

    def colorbars(self, paint):
        for norm, cmap, label, *_ in paint.scales.values():
            self.fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), ax=self.ax, label=label,
                              shrink=0.7, pad=0.04 if self.view == "3d" else 0.03)

    def labels(self, node_pts):
        for n, p in enumerate(node_pts, start=1):
            self.artists.append(self.ax.text(*p[list(self.idx)], f" {n}", fontsize=8, color="black"))

    def axis_labels(self):
        labels = [self.ax.get_xlabel(), self.ax.get_ylabel()] + ([self.ax.get_zlabel()] if self.view == "3d" else [])
        return ", ".join(labels)

    def title(self, text):
        self.fig.suptitle(text, fontsize=10)  # replaces the previous title; centred on the figure (colour bars)


def magnification(arg, disp, size, below):
    """Scale factor of displacements: given, or 1 when the largest is at least below * size, else the
    factor that makes the largest SHOWN * size."""
    if arg != "auto":
        return float(arg)
    dmax = float(np.max(np.linalg.norm(disp.reshape(-1, 3), axis=1))) if disp.size else 0.0
    if dmax == 0.0 or dmax >= below * size:
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
    j = res.analysis_row(k)
    shape = res.modes[key][j]
    table = res.freq if kind == "freq" else res.buck
    value = table[j, n - 1] if table is not None and n - 1 < table.shape[1] else float("nan")
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
    ap.add_argument("--stress", default="n1", choices=["n1", "vonmises", "off"],
                    help="membrane colour: first principal resultant n1 (default) or the Von Mises resultant, "
                         "both in N/m; off: no stress colours (membranes and cables in blue)")
    ap.add_argument("--fps", type=float, default=8.0, help="frames per second of a GIF")
    a = ap.parse_args()
    if a.mode and a.animate:
        sys.exit("--mode and --animate: give one of them (--animate mode:N animates a mode)")
    if a.scale != "auto":
        try:
            float(a.scale)
        except ValueError:
            sys.exit(f"--scale '{a.scale}': expected auto or a number")

    res = Result(a.h5, "n1" if a.stress == "off" else a.stress)
    load_matplotlib()
    k = res.row(a.step)
    size = res.size()
    labels = a.labels == "on" or (a.labels == "auto" and len(res.node_p0) <= LABEL_LIMIT)
    print(f"node numbers: {'drawn' if labels else 'not drawn'} ({len(res.node_p0)} nodes)")
    if res.cells.look:
        print(f"element look from the scene (color, opacity, hide): {res.cells.hidden} hidden cell(s) not drawn")
    if res.cells.rigid:
        print(f"rigid elements (in no eprops set): {res.cells.rigid} cell(s) drawn grey")
    base = os.path.splitext(a.h5)[0]
    grey = dict(color="0.6", lw=1.0, alpha=0.8)
    blue = dict(color="tab:blue", lw=1.6)

    def painted(rows):
        paint = Paint(res.cells, rows if a.stress != "off" else [])
        if paint.scales:
            print(f"colours: {paint.describe()}")
        return paint

    if a.animate == "path":
        # one rule for the whole path: magnified when its largest displacement is below SHOWN of the model size
        rows = [s - 1 for s in res.steps]
        s = magnification(a.scale, np.stack([res.mesh_p[r] - res.mesh_p0[r] for r in rows]), size, SHOWN)
        frames = [(res.mesh_p0[r] + s * (res.mesh_p[r] - res.mesh_p0[r]),
                   res.ref_nodes(r) + s * (res.node_p[r] - res.ref_nodes(r)), r) for r in rows]
        canvas = Canvas(choose_view(a.view, [res.mesh_p0[rows[-1]]] + [f[0] for f in frames]),
                        [res.mesh_p0[rows[-1]]] + [f[0] for f in frames])
        out = a.output or base + "_path.gif"
        titles = [f"{res.title}\ndeformed shape, {res.state(r)}{scaled(s)}" for _, _, r in frames]
        write_gif(canvas, out, a.fps, frames, res, grey, blue, labels, titles, painted(rows), k_ref=rows[-1])
        return 0
    if a.animate:
        kind, n = parse_mode(a.animate)
        shape, what = mode_info(res, kind, n, k)
        s = magnification(a.scale, shape, size, np.inf)
        ref, ref_nodes = res.mesh_p[k], res.node_p[k]
        phases = np.sin(2 * np.pi * np.arange(MODE_FRAMES) / MODE_FRAMES)
        frames = [(ref + c * s * shape, res.mode_nodes(k, c * s * shape), None) for c in phases]
        canvas = Canvas(choose_view(a.view, [ref + s * shape, ref - s * shape]), [ref + s * shape, ref - s * shape])
        out = a.output or base + f"_{'mode' if kind == 'freq' else 'buck'}{n}.gif"
        title = f"{res.title}\n{what} ({res.state(k)}; shape x {s:g})"
        write_gif(canvas, out, a.fps, frames, res, grey, blue, labels, [title] * len(frames), Paint(res.cells, []),
                  k_ref=k, ref=(ref, ref_nodes))
        return 0
    if a.mode:  # a mode shape has no stresses: drawn in the element colours
        kind, n = parse_mode(a.mode)
        shape, what = mode_info(res, kind, n, k)
        s = magnification(a.scale, shape, size, np.inf)
        ref, ref_nodes = res.mesh_p[k], res.node_p[k]
        moved = ref + s * shape
        canvas = Canvas(choose_view(a.view, [ref, moved]), [ref, moved])
        canvas.shape(ref, res.cells, ref_nodes, **grey)
        moved_nodes = res.mode_nodes(k, s * shape)
        canvas.shape(moved, res.cells, moved_nodes, Paint(res.cells, []).colours(res.cells, None), **blue)
        if labels:
            canvas.labels(moved_nodes)
        title = f"{res.title}\n{what} ({res.state(k)}; shape x {s:g})"
        canvas.title(title)
        save_png(canvas, a.output or base + f"_{'mode' if kind == 'freq' else 'buck'}{n}.png", title)
        return 0
    s = magnification(a.scale, res.mesh_p[k] - res.mesh_p0[k], size, VISIBLE)
    deformed = res.mesh_p0[k] + s * (res.mesh_p[k] - res.mesh_p0[k])
    deformed_nodes = res.ref_nodes(k) + s * (res.node_p[k] - res.ref_nodes(k))
    canvas = Canvas(choose_view(a.view, [res.mesh_p0[k], deformed]), [res.mesh_p0[k], deformed])
    paint = painted([k])
    canvas.shape(res.mesh_p0[k], res.cells, res.ref_nodes(k), **grey)
    canvas.shape(deformed, res.cells, deformed_nodes, paint.colours(res.cells, k), **blue)
    canvas.colorbars(paint)
    if labels:
        canvas.labels(deformed_nodes)
    drawn = "scene colours" if res.cells.look else "blue"
    if paint.scales:
        drawn = "coloured by " + " and ".join({"membrane": "membrane stress", "cable": "cable force"}[w]
                                               for w in paint.scales)
    if res.cells.rigid:
        drawn += "; rigid elements wide light grey"
    title = f"{res.title}\ndeformed ({drawn}) and {res.ref_name(k)} (grey),"
    title += "\n" if len(title) - len(res.title) > 60 else " "
    title += f"{res.state(k)}{scaled(s)}"
    canvas.title(title)
    save_png(canvas, a.output or base + f"_step{k + 1}.png", title)
    return 0


def write_gif(canvas, out, fps, frames, res, grey, blue, labels, titles, paint, k_ref, ref=None):
    """frames: (mesh positions, node positions, row whose values colour it or None); the undeformed
    (or reference) shape stays in grey, the colour scales are those of the whole animation."""
    base_mesh, base_nodes = ref if ref is not None else (res.mesh_p0[k_ref], res.ref_nodes(k_ref))
    canvas.shape(base_mesh, res.cells, base_nodes, **grey)
    canvas.colorbars(paint)
    fixed = canvas.artists
    canvas.artists = []
    writer = PillowWriter(fps=fps)
    with writer.saving(canvas.fig, out, dpi=90):
        for (mesh_pts, node_pts, row), title in zip(frames, titles):
            canvas.clear()
            canvas.shape(mesh_pts, res.cells, node_pts, paint.colours(res.cells, row), **blue)
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
