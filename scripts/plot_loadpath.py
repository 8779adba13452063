#!/usr/bin/python3
"""Plot the load path of one or more nodes from a Sinew result file: load factor (or time) against the
displacement of each node, u = p[step] - p0, with p from /node/p and p0 from /node/p0 (the initial
positions; the first row of /node/p when /node/p0 is missing).

    plot_loadpath.py result.h5 --node N [N ...] --dir x|y|z|abs [-o out.png]

N is 1-based as in the scene file. A path-following result (opt.continuation: /path/negative_eigenvalues,
/path/critical_points) is drawn in segments: stable (no negative eigenvalue of the tangent) solid,
unstable dashed and red; limit points are marked with triangles, bifurcation points with diamonds, and
the counts are printed ("segments: stable S, unstable U; limit points L, bifurcation points B").
The left axis is the load factor; a time history (a dynamics result: /time) is drawn over time, time
along the horizontal axis. When the scene (stored in the result file) ramps exactly one load,
a `force` or a `moment` of one node, the right axis is that load itself: load factor x its
component when it acts along one axis ("load F_y [N]"), else x its magnitude ("load |F| [N]"); the
script prints what it used ("load axis: ..."). Needs python3-h5py and matplotlib (Agg, no display).
"""
import argparse
import os
import sys

import numpy as np

from plot_results import load_matplotlib, open_result, parse_scene, scene_text

# ramped loads of a scene (docs/scene.md): the load axis is drawn when exactly one of them is given
NODE_RAMPED = ("force", "moment", "displ_x", "displ_y", "displ_z", "rot")
SET_RAMPED = ("pressure", "massProportionalLoad")


def segments(stable):
    """[(start, end)] index ranges (end inclusive) of runs of equal stability; neighbours share a point."""
    out, s = [], 0
    for i in range(1, len(stable) + 1):
        if i == len(stable) or stable[i] != stable[s]:
            out.append((s, min(i, len(stable) - 1), bool(stable[s])))
            s = i
    return out


def ramped_load(scene):
    """(label, unit, factor, source) of the one ramped force or moment of the scene, or (None, reason)."""
    nprops = scene.get("nprops") or {}
    loads = [(node, key, props[key]) for node, props in (nprops.items() if isinstance(nprops, dict) else [])
             if isinstance(props, dict) for key in NODE_RAMPED if key in props]
    sets = scene.get("eprops") or []
    loads += [("eprops", key, s[key]) for s in (sets if isinstance(sets, list) else []) if isinstance(s, dict)
              for key in SET_RAMPED if key in s]
    opt = scene.get("opt") or {}
    if isinstance(opt, dict) and opt.get("gravity") is not None:
        loads.append(("opt", "gravity", opt["gravity"]))
    if len(loads) != 1:
        return None, f"the scene ramps {len(loads)} loads" if loads else "no ramped load in the scene"
    node, key, value = loads[0]
    if key not in ("force", "moment") or not isinstance(node, int):
        return None, f"the ramped load is {key} of {node}, not a force or moment of one node"
    if not isinstance(value, list) or not all(isinstance(v, (int, float)) for v in value) or len(value) not in (2, 3):
        return None, f"nprops({node}).{key} is not a list of numbers"
    v = np.array(value, float)
    symbol, unit = ("F", "N") if key == "force" else ("M", "N m")
    nonzero = np.nonzero(v)[0]
    if not nonzero.size:
        return None, f"nprops({node}).{key} is zero"
    if len(nonzero) == 1:
        i = int(nonzero[0])
        return (f"load {symbol}_{'xyz'[i]}", unit, float(v[i]), f"nprops({node}).{key} = {value}"), ""
    return (f"load |{symbol}|", unit, float(np.linalg.norm(v)), f"nprops({node}).{key} = {value}"), ""


def main():
    ap = argparse.ArgumentParser(description="Load factor against the displacement of nodes.")
    ap.add_argument("file", help="result file (HDF5)")
    ap.add_argument("--node", type=int, nargs="+", required=True, help="node number(s), 1-based")
    ap.add_argument("--dir", choices=("x", "y", "z", "abs"), default="abs",
                    help="displacement component, or abs for its length")
    ap.add_argument("-o", "--output", help="image file (default: <file>_node<N>_<dir>.png)")
    a = ap.parse_args()

    with open_result(a.file) as f:
        step_name = "load_factor" if "load_factor" in f else "time" if "time" in f else None
        if step_name is None or "node/p" not in f:
            sys.exit(f"{a.file}: needs /load_factor or /time, and /node/p")
        p = f["node/p"]
        nn = p.shape[1]
        for node in a.node:
            if not 1 <= node <= nn:
                sys.exit(f"{a.file}: node {node} outside 1..{nn}")
        lam = f[step_name][:]
        pos = {node: p[:, node - 1, :] for node in a.node}
        has_p0 = "node/p0" in f
        p0 = {node: (f["node/p0"][node - 1, :] if has_p0 else pos[node][0]) for node in a.node}
        neg = f["path/negative_eigenvalues"][:] if "path/negative_eigenvalues" in f else None
        crit = f["path/critical_points"][:] if "path/critical_points" in f else np.zeros((0, 4))
        scene = parse_scene(scene_text(f))
        scene_title = str(scene.get("title") or "")

    out = a.output or f"{os.path.splitext(a.file)[0]}_node{'-'.join(map(str, a.node))}_{a.dir}.png"
    plt = load_matplotlib()  # after the input was read: bad files fail fast
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    label = "|u|" if a.dir == "abs" else f"u_{a.dir}"
    counts = {"stable": 0, "unstable": 0, "limit": 0, "bifurcation": 0}
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for j, node in enumerate(a.node):
        u = pos[node] - p0[node]
        x = np.linalg.norm(u, axis=1) if a.dir == "abs" else u[:, "xyz".index(a.dir)]
        ok = np.isfinite(x) & np.isfinite(lam)  # rows never written are NaN
        color = colors[j % len(colors)]
        name = f"node {node}"
        if neg is not None and len(neg) == len(lam):
            # path following: the state before the first point is the unloaded one (stable by convention)
            xs = np.concatenate(([0.0], x[ok])) if has_p0 else x[ok]
            ys = np.concatenate(([0.0], lam[ok])) if has_p0 else lam[ok]
            ng = np.concatenate(([neg[ok][0]], neg[ok])) if has_p0 else neg[ok]
            for s, e, st in segments(ng == 0):
                lo = max(s - 1, 0) if s > 0 else 0  # join to the previous segment's last point
                seg = slice(lo, e + 1)
                ax.plot(xs[seg], ys[seg], "-" if st else "--", color=color if st else "tab:red", lw=1.6,
                        marker="o", ms=2.5, label=f"{name}, stable" if st and counts["stable"] == 0 and j == 0 else
                        (f"{name}, unstable (negative eigenvalues)" if not st and counts["unstable"] == 0 and j == 0 else None))
                counts["stable" if st else "unstable"] += j == 0
            rows = np.nonzero(ok)[0]
            for kind, k, lc, _ in crit:
                r = int(k) - 1  # path point k is row k - 1; the critical point lies between rows r and r + 1
                if r + 1 >= len(x) or r < 0:
                    continue
                xc = 0.5 * (x[r] + x[r + 1])
                t = (lc - lam[r]) / (lam[r + 1] - lam[r]) if kind == 2 and lam[r + 1] != lam[r] else 0.5
                if kind == 2:
                    xc = x[r] + np.clip(t, 0, 1) * (x[r + 1] - x[r])
                first = (kind == 1 and counts["limit"] == 0) or (kind == 2 and counts["bifurcation"] == 0)
                ax.plot([xc], [lc], "^" if kind == 1 else "D", color="k", ms=8, mfc="none" if kind == 1 else "gold",
                        label=("limit point" if kind == 1 else "bifurcation point") if first and j == 0 else None)
                if j == 0:
                    counts["limit" if kind == 1 else "bifurcation"] += 1
            del rows
        else:
            xs, ys = x[ok], lam[ok]
            # p0 is the unloaded state: start the path there when the first load factor is above zero.
            if step_name == "load_factor" and has_p0 and len(ys) and ys[0] > 0:
                xs, ys = np.concatenate(([0.0], xs)), np.concatenate(([0.0], ys))
            if step_name == "time":  # a time history: time along the horizontal axis
                xs, ys = ys, xs
            ax.plot(xs, ys, "o-", ms=3, color=color, label=name)
    if step_name == "time" and neg is None:
        ax.set_xlabel("time [s]")
        ax.set_ylabel(f"{label} [m]")
    else:
        ax.set_xlabel(f"{label} [m]")
        ax.set_ylabel("load factor [-] (applied loads x factor)" if step_name == "load_factor" else "time [s]")
    if step_name == "load_factor":
        load, why = ramped_load(scene)
        if load is None:
            print(f"load axis: load factor only ({why})")
        else:
            label, unit, factor, source = load
            second = ax.secondary_yaxis("right", functions=(lambda x: x * factor, lambda y: y / factor))
            second.set_ylabel(f"{label} [{unit}]")
            print(f"load axis: {label} [{unit}] = load factor x {factor:g} ({source})")
    ax.set_title(scene_title or os.path.basename(a.file))
    ax.grid(True, alpha=0.3)
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.legend(fontsize=8, loc="best")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    if neg is not None:
        print(f"segments: stable {counts['stable']}, unstable {counts['unstable']}; "
              f"limit points {counts['limit']}, bifurcation points {counts['bifurcation']}")
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
