"""A form-finding failure in the first step (issue 9): exit 3 with Sinew's message naming the step,
no HDF5 error or abort, and a result file h5py opens (converged = 0, empty form-finding history)."""
import os
import re

import h5py

from sinewtest import SOURCE, check, done, run

sail = open(os.path.join(SOURCE, "runs", "sail.yaml")).read()
sail = sail.replace("mesh: ../meshes/", "mesh: " + os.path.join(SOURCE, "meshes") + "/")
cases = {
    "max_shape_change": sail.replace("  formfinding_tolerance: 1e-5", "  formfinding_tolerance: 1e-5\n  max_shape_change: 1e-3"),
}
for name, text in cases.items():
    check(text != sail, f"{name}: scene edit did not apply")
    out, log = run(f"batch_ff_{name}", text, expect_exit=3)
    print("  " + "\n  ".join(l for l in log.splitlines() if "error" in l.lower())[:600])
    check(re.search(r"error: formfinding step 1 of \d+", log) is not None, f"{name}: no Sinew message for step 1")
    check("HDF5" not in log and not re.search(r"SIGABRT|on signal|core dumped", log), f"{name}: HDF5 error or abort")
    with h5py.File(out, "r") as f:
        check(int(f.attrs["converged"]) == 0, f"{name}: converged = {f.attrs['converged']}")
        check(f["formfinding/residual"].shape == (0,), f"{name}: /formfinding/residual {f['formfinding/residual'].shape}")
    check(not os.path.exists(out + ".part"), f"{name}: .part left")
# homotopy_curve [1] (the elastic problem on the flat start mesh) is singular before step 1: since the
# constraint check also runs on the form-finding problem, it ends as a model error (exit 2), no abort
text = sail.replace("  formfinding_tolerance: 1e-5", "  formfinding_tolerance: 1e-5\n  homotopy_curve: [1]")
out, log = run("batch_ff_homotopy_curve", text, expect_exit=2)
check("mechanism" in log and "form-finding problem" in log, "homotopy_curve [1]: the mechanism message names the form-finding problem")
check("HDF5" not in log and not re.search(r"SIGABRT|on signal|core dumped", log), "homotopy_curve: HDF5 error or abort")
done()
