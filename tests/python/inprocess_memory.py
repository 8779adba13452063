#!/usr/bin/python3
"""Memory of many in-process runs (issue 25): `runs` runs of a small cross-flexure hinge in a loop in
one process (sinew.Scene.run through sinew._core, results in memory); the resident set size after
the last run must be within 5 % of the one after run `warm` (10 % of the runs). The hinge keeps its
statics, frequencies, buckling and compliance but with one load step, so that 1000 runs fit in a
test (a fresh Scene dict and a fresh results object each time, as a parameter study does).

    inprocess_memory.py [runs=1000]      (ctest: python_inprocess_memory)
"""
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "python"))

import sinew  # noqa: E402


def rss_kib():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("no VmRSS in /proc/self/status")


def main():
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    warm = max(1, runs // 10)
    base = sinew.Scene.from_yaml(os.path.join(SOURCE, "runs", "crosshinge.yaml"))
    base.opt["loadsteps"] = 1
    if sinew.core() is None:
        print("sinew._core is not built")
        return 1
    t0 = time.time()
    rss_warm, tip = None, None
    for i in range(1, runs + 1):
        sim = base.copy()
        sim.data["eprops"][0]["dim"] = [0.05, 0.0005 * (1 + 1e-3 * (i % 7))]  # a design variable, as a study changes it
        out = sim.run()
        if not out.converged or out.freq is None or out.buck is None or out.node[5].CMglob is None:
            print(f"run {i}: converged {out.converged}, freq/buck/compliance missing")
            return 1
        if i % 7 == 0:
            tip = tip if tip is not None else out.node[5].p[-1].copy()
            if not (out.node[5].p[-1] == tip).all():
                print(f"run {i}: the same design gave another result")
                return 1
        if i == warm:
            rss_warm, t_warm = rss_kib(), time.time()
    rss_end, t_end = rss_kib(), time.time()
    growth = (rss_end - rss_warm) / rss_warm
    print(f"{runs} runs of the hinge (1 load step, frequencies, buckling, compliance): {(t_end - t0) / runs * 1e3:.1f} ms "
          f"per run ({(t_end - t_warm) / (runs - warm) * 1e3:.1f} ms after run {warm}); RSS {rss_warm} KiB after run {warm}, "
          f"{rss_end} KiB after run {runs} ({100 * growth:+.2f} %)")
    return 0 if abs(growth) <= 0.05 else 1


if __name__ == "__main__":
    sys.exit(main())
