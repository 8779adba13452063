"""opt.output_steps (issue 9, item 4): the load steps at which results are written and the step
analyses run: all (default), last, every:k, a list; the last step is always written. Checked on the
rows of /load_factor, /freq and /node/CMglob, and on the number of eigen/compliance runs."""
import re

import h5py
import numpy as np

from batchrun import CROSSHINGE
from sinewtest import check, done, run

N = 6
cases = {
    "all": np.arange(1, N + 1),
    "last": np.array([N]),
    "every:4": np.array([4, 6]),
    "1,3": np.array([1, 3, 6]),
}
for value, written in cases.items():
    args = ["-loadsteps", str(N), "-calcbuck", "true"] + ([] if value == "all" else ["-output_steps", value])
    out, log = run("batch_output_steps_" + re.sub(r"\W", "_", value), CROSSHINGE, args=args)
    with h5py.File(out, "r") as f:
        lf = f["load_factor"][:]
        rows = {k: f[k].shape[0] for k in ("freq", "buck", "node/CMglob", "node/p", "stressmax")}
    print(f"  output_steps {value}: load factors {lf}, rows {rows}")
    expected = (written - 1) / (N - 1)  # SPACAR Light's steps: step 1 = initial loads alone (load factor 0)
    check(np.allclose(lf, expected), f"{value}: load factors {lf}, expected {expected}")
    check(all(r == len(written) for r in rows.values()), f"{value}: rows {rows}")
    m = re.search(r"(\d+) factorizations?", log)
    check(m is not None and int(m.group(1)) == len(written), f"{value}: compliance ran {m.group(1) if m else '?'} times")
    check(len(re.findall(r"^\s+load step \d+/", log, re.M)) == N, f"{value}: not one progress line per load step")
for bad in ("every:0", "some", "every:x"):
    _, log = run("batch_output_steps_bad", CROSSHINGE, args=["-output_steps", bad], expect_exit=2)
    check("opt.output_steps" in log, f"-output_steps {bad}: no message naming opt.output_steps")
done()
