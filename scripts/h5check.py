#!/usr/bin/python3
"""List every group, dataset (shape, dtype) and attribute of a Sinew result file.

    h5check.py result.h5 [--values] [--max-attr-chars N]

Also checks the result-file contract of docs design.md section 3 (root attributes, one step
dataset, step-indexed datasets with one row per step, the step analyses' datasets (attribute
rows = step_analysis_rows) one row per /step_analysis_rows entry); exit status 0 when it holds, 2 when not,
1 when the file cannot be read. Needs python3-h5py.
"""
import argparse
import sys

try:
    import h5py
    import numpy as np
except ImportError as e:  # pragma: no cover
    sys.exit(f"h5check.py needs python3-h5py and numpy: {e}")

ROOT_ATTRS = ("version", "ndof", "nranks", "scene", "converged")
# Datasets of the contract whose first axis is the step axis.
STEP_PREFIXES = ("node/", "element/", "mesh/", "cell/", "sensors/")
STEP_NAMES = ("freq", "buck", "stressmax", "formfinding/step")
NOT_STEP = ("node/p0", "mesh/p0", "mesh/lines", "mesh/triangles", "mesh/quads",
            "mesh/lines_element", "mesh/triangles_element", "mesh/quads_element")


def show_value(v, limit):
    if isinstance(v, bytes):
        v = v.decode("utf-8", "replace")
    text = repr(v.tolist()) if isinstance(v, np.ndarray) else repr(v)
    return text if len(text) <= limit else text[:limit] + f"... ({len(text)} chars)"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("file")
    ap.add_argument("--values", action="store_true", help="print the values of small datasets")
    ap.add_argument("--max-attr-chars", type=int, default=80)
    a = ap.parse_args()
    try:
        f = h5py.File(a.file, "r")
    except OSError as e:
        print(f"h5check.py: cannot open {a.file}: {e}", file=sys.stderr)
        return 1
    problems = []
    with f:
        print(f"{a.file}")
        for k, v in f.attrs.items():
            print(f"  @{k} = {show_value(v, a.max_attr_chars)}")
        datasets = {}

        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                datasets[name] = obj
                print(f"  /{name}  shape {obj.shape}  {obj.dtype}"
                      + (f"  chunks {obj.chunks}" if obj.chunks else ""))
                if a.values and obj.size <= 64:
                    print(f"      {show_value(obj[()], 2000)}")
            else:
                print(f"  /{name}/")
            for k, v in obj.attrs.items():
                print(f"      @{k} = {show_value(v, a.max_attr_chars)}")

        f.visititems(visit)

        for k in ROOT_ATTRS:
            if k not in f.attrs:
                problems.append(f"root attribute '{k}' missing")
        steps = [n for n in ("load_factor", "time") if n in datasets]
        if len(steps) != 1:
            problems.append(f"expected one of /load_factor, /time, found {steps or 'none'}")
        else:
            ns = datasets[steps[0]].shape[0]
            print(f"  {ns} steps in /{steps[0]}")
            # step analyses at some rows only (opt.step_analyses): one row per analysed step
            rows = datasets["step_analysis_rows"][()] if "step_analysis_rows" in datasets else None
            if rows is not None:
                print(f"  step analyses at {len(rows)} of the {ns} steps (/step_analysis_rows)")
                if len(rows) and (np.any(np.diff(rows) <= 0) or rows[0] < 0 or rows[-1] >= ns):
                    problems.append(f"/step_analysis_rows {rows.tolist()} is not an increasing list of step rows")
            for name, d in datasets.items():
                stepwise = name in STEP_NAMES or (name.startswith(STEP_PREFIXES) and name not in NOT_STEP)
                analysed = d.attrs.get("rows") in ("step_analysis_rows", b"step_analysis_rows")
                want = len(rows) if analysed and rows is not None else ns
                if stepwise and (len(d.shape) == 0 or d.shape[0] != want):
                    problems.append(f"/{name} has shape {d.shape}, expected {want} rows (one per "
                                    f"{'analysed step' if want != ns else 'step'})")
    for p in problems:
        print(f"problem: {p}")
    return 2 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
