"""Progress lines (issue 9, item 1): one line per converged load step, printed and flushed while
the run goes (read here line by line with arrival times), with the elapsed wall time; -silent
silences them."""
import re

from batchrun import CROSSHINGE, Run, remove_outputs, work
from sinewtest import check, done

# enough steps that the run lasts over a second (about 9 ms per step without the step analyses,
# which the progress lines do not depend on: 1.8 s on a 2-core machine)
N = 200
out = work("batch_progress.h5")
remove_outputs(out)
run = Run(CROSSHINGE, out, ["-loadsteps", str(N), "-calcbuck", "false", "-calccompl", "false", "-calcfreq", "false"])
code = run.wait(timeout=600)
end = run.lines[-1][0] if run.lines else 0.0
steps = [(t, l) for t, l in run.lines if re.match(r"\s+load step \d+/%d\s" % N, l)]
for t, l in steps:
    print(f"  {t:7.3f} s  {l.strip()}")
check(code == 0, f"exit {code}")
check([int(re.search(r"load step (\d+)/", l).group(1)) for _, l in steps] == list(range(1, N + 1)),
      "not one progress line per load step, in order")
check(all("elapsed" in l and "load factor" in l and "Newton" in l for _, l in steps), "a line without elapsed time")
if len(steps) == N:
    times = [t for t, _ in steps]
    spread = times[-1] - times[0]
    # printed as the steps converge: the first line arrives well before the last (all at once at
    # the end would give a spread of milliseconds), and arrival times follow the steps
    print(f"  first line at {times[0]:.3f} s, last at {times[-1]:.3f} s, output ends at {end:.3f} s")
    check(spread > 0.3, f"progress lines arrived together (spread {spread:.3f} s)")
    check(times[0] < end - 0.3, "the first progress line arrived only at the end of the run")
    # each line arrives when its step ends: arrival time minus the elapsed time it prints stays
    # constant up to the 0.1 s print resolution (buffered output would make it shrink step by step)
    unit = {"s": 1.0, "min": 60.0, "h": 3600.0}
    printed = [re.search(r"elapsed ([0-9.]+) (s|min|h)\b", l) for _, l in steps]
    lag = [t - float(m.group(1)) * unit[m.group(2)] for (t, _), m in zip(steps, printed)]
    print(f"  arrival minus printed elapsed: {min(lag):.3f} .. {max(lag):.3f} s")
    # the print resolution is 0.1 s below 100 s, 0.1 min above
    resolution = 0.3 if times[-1] < 90 else 6.5
    check(max(lag) - min(lag) < resolution, f"progress lines lag their steps by {min(lag):.3f} .. {max(lag):.3f} s")

remove_outputs(out)
quiet = Run(CROSSHINGE, out, ["-loadsteps", "3", "-silent", "true"])
check(quiet.wait(timeout=300) == 0, "silent run failed")
check(not any("load step" in l for _, l in quiet.lines), "-silent printed progress lines")
done()
