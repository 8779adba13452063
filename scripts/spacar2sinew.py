#!/usr/bin/python3
"""A SPACAR Light MATLAB script as a Sinew scene (YAML).

usage: scripts/spacar2sinew.py script.m [-o scene.yaml] [--run] [-n RANKS]

Reads the assignments of SPACAR Light's inputs (nodes, elements, nprops(i).field, eprops(i).field,
opt.field, opt.rls(i).def), plain variables, arithmetic and for-loops (python/sinew/spacar.py says
which MATLAB it reads), and writes the scene (default: script name with .yaml). --run also runs it
and prints the summary. A line it cannot read is an error naming the line (exit 2)."""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# the package in the source tree (python/) or installed beside share/ (lib/python3/dist-packages)
for cand in (os.path.join(HERE, "..", "python"), os.path.join(HERE, "..", "..", "..", "lib", "python3", "dist-packages")):
    if os.path.isdir(os.path.join(cand, "sinew")):
        sys.path.insert(0, os.path.normpath(cand))
        break

import sinew  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0], epilog=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("script")
    ap.add_argument("-o", "--output", help="scene file (default: <script>.yaml)")
    ap.add_argument("--run", action="store_true", help="run the scene after writing it")
    ap.add_argument("-n", type=int, default=1, help="MPI ranks of --run")
    a = ap.parse_args()
    try:
        scene = sinew.from_spacar(a.script)
    except (sinew.SpacarError, OSError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    out = a.output or os.path.splitext(a.script)[0] + ".yaml"
    scene.write(out)
    print(f"wrote {out}")
    if a.run:
        try:
            res = scene.run(np=a.n, quiet=False)
        except sinew.SinewError as e:
            print(f"error: {e.message}", file=sys.stderr)
            return e.exit_code
        print(res)
    return 0


if __name__ == "__main__":
    sys.exit(main())
