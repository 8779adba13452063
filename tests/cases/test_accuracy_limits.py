"""-target_error's limits (docs/accuracy.md): a target that needs more than -accuracy_max_unknowns
stops with the best level reached in the result file, its estimate in /accuracy (met = 0) and
exit 3; a scene -target_error cannot refine yet (a membrane with trailing unconnected nodes) is refused with exit 2 before any run,
and so is a quantity of opt.accuracy_quantities that names no scene node;
without target_error there is no /accuracy; scripts/plot_accuracy.py draws the estimates."""
import os
import subprocess

import accuracy_cases as ac
import sinewtest as st

# the cap: 1e-5 needs 192 unknowns (level 5 from nbeams 1); 60 allows levels 0..3 (48 unknowns)
path, out = st.run("accuracy_cap", ac.cantilever(1), args=["-target_error", "1e-5", "-accuracy_max_unknowns", "60"],
                   expect_exit=3)
with st.h5(path) as f:
    g = f["accuracy"]
    print(f"  cap: levels {list(g['level'][:])}, unknowns {list(g['unknowns'][:])}, met {g.attrs['met']}, "
          f"worst estimate {g['worst_error'][-1]:.2e}")
    st.check(int(g.attrs["met"]) == 0, "/accuracy met = 0")
    st.check(int(g["unknowns"][-1]) <= 60 and len(g["level"]) == 4, "stopped at the last level within the cap")
    st.check(f["mesh/p"].shape[1] == 9, "the file holds the best level (nbeams x8)")
    st.check(g["worst_error"][-1] > 1e-5, "its estimate is above the target")
st.check("-target_error 1e-05 not reached" in out and "-accuracy_max_unknowns 60" in out, "the message names the cap")

# plot_accuracy.py on that file
png = os.path.join(st.WORK, "accuracy_cap.png")
p = subprocess.run(["/usr/bin/python3", os.path.join(st.SOURCE, "scripts", "plot_accuracy.py"), path, "-o", png],
                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
print("  plot_accuracy.py:", p.stdout.strip())
st.check(p.returncode == 0 and os.path.getsize(png) > 10000, "plot_accuracy.py wrote the picture")

# without target_error: the scene as given, no /accuracy
path, out = st.run("accuracy_off", ac.cantilever(4))
with st.h5(path) as f:
    st.check("accuracy" not in f and f["mesh/p"].shape[1] == 5, "no /accuracy, the scene's mesh")
p = subprocess.run(["/usr/bin/python3", os.path.join(st.SOURCE, "scripts", "plot_accuracy.py"), path],
                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
st.check(p.returncode == 1 and "no /accuracy" in p.stdout, f"plot_accuracy.py on a file without /accuracy: {p.stdout}")

# membranes are split by numbering new nodes after the scene's: trailing unconnected nodes are refused
# (exit 2) before any level runs
membrane = ("nodes: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [2, 2, 0]]\nelements: [[1, 2, 3]]\n"
            "nprops: {1: {fix: true}, 2: {fix: true}, 3: {fix: true}}\n"
            "eprops: [{elems: [1], type: membrane, thickness: 0.001, emod: 1e9, nu: 0.3, prestress: [1e3, 1e3, 0]}]\n"
            "opt: {target_error: 1e-3}\n")
path, out = st.run("accuracy_membrane", membrane, expect_exit=2)
st.check("error: opt.target_error: membranes are refined by splitting" in out and "trailing unconnected nodes" in out,
         f"the refusal names the membranes and the trailing nodes: {out[-300:]}")

# opt.accuracy_quantities names scene nodes: another number is a scene error with the field's path
path, out = st.run("accuracy_bad_quantity", ac.cantilever(1, {"target_error": 1e-3, "accuracy_quantities": ["node 7 p"]}),
                   expect_exit=2)
st.check("error: opt.accuracy_quantities(1): expected a node number 1..2 after 'node', got 'node 7 p'" in out,
         "the bad quantity is named with its path")
st.done()
