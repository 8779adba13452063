#!/usr/bin/python3
"""-target_error's reuse between levels (docs/accuracy.md, block accuracy_reuse): the cost of a study
with -accuracy_reuse 1 and 0 against the cost of its finest level run alone, side by side in one run
(2 MPI ranks each, one run after the other):

- the beam roll-up to a quarter circle (scripts/study_accuracy.py's scene, 4 load steps), target 1e-4;
- Lee's frame from 10 elements to v = -0.5 (tests/cases/test_accuracy_path.py's scene with ds 0.1), 1e-3.

Per case: the levels, the Newton iterations of all levels (/accuracy newton_iterations) and of the
finest level alone (the scene with that level's nbeams and max_steps, without target_error), the wall
time of each run (mpirun's start, every level, the file; the least of three interleaved runs), the
study's ratio to the finest level alone, and the largest relative change of a level's value (/accuracy
value, per quantity relative to its size on that level) between reuse and none.

Block accuracy_path_plan: Lee's frame at 1e-3 (the default quantities) and 1e-5 (the first limit load alone, as
docs/accuracy.md's table runs it) with the coarser level's steps as the plan (-accuracy_reuse 1), reuse without
the plan (-accuracy_path_plan 0) and no reuse (-accuracy_reuse 0): Newton iterations, path steps, rejected
steps and wall time of the study (the least of `repeats` runs at 1e-3, one run at 1e-5), the finest level's
first limit load and its estimate, and the change of the finest level's values against no reuse.

usage: scripts/study_accuracy_reuse.py [repeats] [--plan-only | --reuse-only]   (one block each; about 15 minutes on 2 cores; repeats default 3)"""
import copy
import json
import os
import subprocess
import sys
import time

import h5py
import numpy as np
import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import doc_tables  # noqa: E402
from study_accuracy import ENV, rollup  # noqa: E402

sys.path.insert(0, os.path.join(ROOT, "tests", "cases"))
import lee_frame_scene as lf  # noqa: E402

WORK = os.path.join(ROOT, "build", "study_accuracy_reuse")
REPEATS = int(sys.argv[1]) if len(sys.argv) > 1 and sys.argv[1].isdigit() else 3


def lee():
    return lf.lee("Lee's frame", 0.1)


def finest(scene, factor):
    """The scene as the study's level with nbeams x factor runs it (refinedModel: max_steps x factor too)."""
    s = copy.deepcopy(scene)
    for p in s["eprops"]:
        p["nbeams"] = p.get("nbeams", 1) * factor
    if "continuation" in s["opt"]:
        s["opt"]["continuation"]["max_steps"] *= factor
    return s


def run(tag, scene, args):
    path = os.path.join(WORK, tag + ".yaml")
    with open(path, "w") as f:
        f.write(scene if isinstance(scene, str) else json.dumps(scene, indent=1))
    h5 = os.path.join(WORK, tag + ".h5")
    t0 = time.time()
    p = subprocess.run(["mpirun", "-n", "2", os.path.join(ROOT, "build", "sinew"), path, "-o", h5] + args, env=ENV,
                       capture_output=True, text=True)
    wall = time.time() - t0
    if p.returncode != 0:
        print(p.stdout[-3000:], p.stderr[-2000:])
        sys.exit(f"{tag}: exit {p.returncode}")
    return h5, wall, p.stdout


def main():
    os.makedirs(WORK, exist_ok=True)
    rows = ["| case | target | levels | Newton iterations of the study, reuse / none | of the finest level alone | "
            f"wall time (s, least of {REPEATS}): study with reuse / without / finest level alone | "
            "study / finest alone, reuse / none | largest change of a level's value, reuse / none |",
            "|---|---|---|---|---|---|---|---|"]
    start = time.time()
    for name, scene, target in (("roll-up tip position, from nbeams 1", rollup(), 1e-4),
                                ("Lee's frame, from 10 elements", lee(), 1e-3)):
        tag = name.split()[0].strip("'s,").lower()
        its, values, walls = {}, {}, {1: [], 0: [], "alone": []}
        for _ in range(REPEATS):  # interleaved, so that a change of the machine's load hits all three alike
            for reuse in (1, 0):
                h5, wall, _ = run(f"{tag}_{reuse}", scene, ["-target_error", f"{target:g}", "-accuracy_reuse", str(reuse)])
                walls[reuse].append(wall)
                with h5py.File(h5, "r") as f:
                    g = f["accuracy"]
                    its[reuse] = int(sum(g["newton_iterations"][:]))
                    values[reuse] = np.nan_to_num(g["value"][:])
                    factors = [int(x) for x in g["nbeams_factor"][:]]
            alone = finest(yaml.safe_load(scene) if isinstance(scene, str) else scene, factors[-1])
            _, wall, out = run(f"{tag}_finest", alone, [])
            walls["alone"].append(wall)
            alone_its = sum(int(w.split("(")[1].split()[0]) for w in out.split(", ") if w.endswith("Newton iterations)"))
        w1, w0, wa = min(walls[1]), min(walls[0]), min(walls["alone"])
        size = np.maximum(np.linalg.norm(values[0], axis=2), 1e-300)
        change = float(np.max(np.linalg.norm(values[1] - values[0], axis=2) / size))
        row = (f"| {name} | {target:g} | x{factors[0]} .. x{factors[-1]} | {its[1]} / {its[0]} | {alone_its} | "
               f"{w1:.2f} / {w0:.2f} / {wa:.2f} | {w1 / wa:.2f} / {w0 / wa:.2f} | {change:.1e} |")
        print(row, flush=True)
        rows.append(row)
    load = os.getloadavg()[0]
    text = (f"Generated by `scripts/study_accuracy_reuse.py {REPEATS}` ({time.time() - start:.0f} s, 2 MPI ranks; load average "
            f"{load:.1f} on 2 cores shared with other jobs: times are indicative, the Newton iterations are not).\n\n"
            + "\n".join(rows) + "\n")
    doc_tables.write_block("accuracy.md", "accuracy_reuse", text)
    if "--reuse-only" not in sys.argv:
        path_plan()


MODES = (("plan", ["-accuracy_reuse", "1"]), ("reuse, no plan", ["-accuracy_reuse", "1", "-accuracy_path_plan", "0"]),
         ("no reuse", ["-accuracy_reuse", "0"]))


def path_plan():
    """Block accuracy_path_plan (module docstring)."""
    rows = ["| target | mode | levels | Newton iterations, study (finest level) | path steps per level | rejected steps | "
            "wall time (s) | finest level's limit 1, estimate | largest change of the finest level's values against no reuse |",
            "|---|---|---|---|---|---|---|---|---|"]
    start = time.time()
    for target, quantities, repeats in ((1e-3, None, REPEATS), (1e-5, ["limit"], 1)):
        scene = lf.lee("Lee's frame", 0.1, opt={"accuracy_quantities": quantities} if quantities else None)
        got = {}
        for _ in range(repeats):
            for mode, args in MODES:
                tag = f"lee_plan_{target:g}_{mode.split(',')[0].replace(' ', '_')}"
                h5, wall, _ = run(tag, scene, ["-target_error", f"{target:g}"] + args)
                with h5py.File(h5, "r") as f:
                    g = f["accuracy"]
                    names = [n for n in g.attrs["quantities"].split("\n") if n]
                    r = {k: g[k][:] for k in ("nbeams_factor", "newton_iterations", "path_steps", "rejected_steps", "value", "error")}
                r["limit"] = names.index("limit 1")
                r["wall"] = min(wall, got[mode]["wall"]) if mode in got else wall
                got[mode] = r
        none = got["no reuse"]
        for mode, _ in MODES:
            r = got[mode]
            vals, ref = np.nan_to_num(r["value"][-1]), np.nan_to_num(none["value"][-1])
            change = float(np.max(np.linalg.norm(vals - ref, axis=1) / np.maximum(np.linalg.norm(ref, axis=1), 1e-300)))
            f = [int(x) for x in r["nbeams_factor"]]
            row = (f"| {target:g} | {mode} | x{f[0]} .. x{f[-1]} | {int(r['newton_iterations'].sum())} "
                   f"({int(r['newton_iterations'][-1])}) | {', '.join(str(int(x)) for x in r['path_steps'])} | "
                   f"{int(r['rejected_steps'].sum())} | {r['wall']:.2f} | {r['value'][-1, r['limit'], 0]:.8f}, "
                   f"{r['error'][-1, r['limit']]:.2e} | {change:.1e} |")
            print(row, flush=True)
            rows.append(row)
    load = os.getloadavg()[0]
    text = (f"Generated by `scripts/study_accuracy_reuse.py {REPEATS}` ({time.time() - start:.0f} s for this table, 2 MPI ranks; "
            f"load average {load:.1f} on 2 cores shared with other jobs: times are indicative, the Newton iterations and steps "
            f"are not; wall time the least of {REPEATS} runs at 1e-3, one run at 1e-5).\n\n" + "\n".join(rows) + "\n")
    doc_tables.write_block("accuracy.md", "accuracy_path_plan", text)


if __name__ == "__main__":
    if "--plan-only" in sys.argv:
        os.makedirs(WORK, exist_ok=True)
        path_plan()
    else:
        main()
