# ctest-labels: smoke
"""Bad input through the executable (design.md: errors name the field path): every case below runs
build/sinew on 2 ranks and must exit with code 2, print its one-line message exactly once (rank 0
only, not once per rank) naming the field path and the fault, and leave no result file behind
(neither name.h5 nor name.h5.part). No case may crash (a signal or an MPI abort gives another
exit code)."""
import copy
import os
import subprocess

import yaml

import sinewtest as st

BASE = {"title": "bad input", "nodes": [[0, 0, 0], [0.5, 0, 0], [1, 0, 0]], "elements": [[1, 2], [2, 3]],
        "nprops": {1: {"fix": True}, 3: {"force": [0, 0, -10]}},
        "eprops": [{"elems": [1, 2], "flex": [1, 2, 3, 4, 5, 6], "emod": 210e9, "smod": 80e9, "cshape": "rect",
                    "dim": [0.02, 0.01], "orien": [0, 0, 1]}],
        "opt": {"loadsteps": 2, "calccompl": False}}


def scene(change):
    s = copy.deepcopy(BASE)
    change(s)
    return yaml.safe_dump(s, default_flow_style=None, sort_keys=False)


def setitem(path, value):
    def f(s):
        d = s
        for k in path[:-1]:
            d = d[k]
        d[path[-1]] = value
    return f


def two_sets(s):
    s["eprops"].append({"elems": [2], "flex": [1], "emod": 1e9, "cshape": "rect", "dim": [0.02, 0.01]})


def three_node(s):
    s["nodes"].append([0.5, 0.5, 0])
    s["elements"].append([1, 2, 4])
    s["eprops"][0]["elems"] = [1, 2, 3]


def no_emod(s):
    del s["eprops"][0]["emod"]


# (name, scene text or None for a missing file, extra flags, [fragments the message must contain])
CASES = [
    ("unknown_key", scene(setitem(["opt", "loadstep"], 3)), [], ["opt.loadstep", "unknown key", "did you mean 'loadsteps'"]),
    ("vector_length", scene(setitem(["nprops", 3, "force"], [0, -10])), [], ["nprops(3).force", "expected 3 numbers", "got 2"]),
    ("element_node_range", scene(setitem(["elements"], [[1, 2], [2, 7]])), [], ["elements(2,2)", "node 7 does not exist"]),
    ("nprops_node_range", scene(setitem(["nprops", 9], {"fix": True})), [], ["nprops(9)", "node 9 does not exist"]),
    ("zero_length", scene(setitem(["nodes"], [[0, 0, 0], [0.5, 0, 0], [0.5, 0, 0]])), [], ["elements(2)", "zero length"]),
    ("missing_emod", scene(no_emod), [], ["eprops(1).emod", "missing"]),
    ("dim_length", scene(setitem(["eprops", 0, "dim"], [0.02])), [], ["eprops(1).dim", "expected 2 numbers", "rect"]),
    ("override_value", scene(lambda s: None), ["-loadsteps", "abc"], ["opt.loadsteps", "-loadsteps abc", "expected an integer"]),
    ("missing_file", None, [], ["cannot open scene file", "no_such_scene.yaml"]),
    ("two_sets", scene(two_sets), [], ["eprops(2).elems", "already in eprops(1)"]),
    ("three_node_beam", scene(three_node), [], ["elements(3)", "has 3 nodes", "eprops(1)"]),
    ("load_on_fixed", scene(setitem(["nprops", 1], {"fix": True, "force": [1, 0, 0]})), [], ["nprops(1).force", "fix"]),
]

for name, text, flags, fragments in CASES:
    if text is None:  # st.run would write a scene: call mpirun directly on a path that does not exist
        path = os.path.join(st.WORK, "no_such_scene.yaml")
        out = os.path.join(st.WORK, "bad_" + name + ".h5")
        for stale in (path, out, out + ".part"):
            if os.path.exists(stale):
                os.remove(stale)
        p = subprocess.run([st.MPIEXEC, "-n", "2", st.BIN, path, "-o", out] + flags, env=st.ENV, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True, timeout=300)
        log = p.stdout
        st.check(p.returncode == 2, f"{name}: exit code {p.returncode}, expected 2")
    else:
        out, log = st.run("bad_" + name, st.scene_file("bad_" + name, text), args=flags, expect_exit=2)
    lines = [ln for ln in log.splitlines() if ln.startswith("error:")]
    msg = lines[0] if lines else ""
    print(f"{name}: {len(lines)} error line(s): {msg}")
    st.check(len(lines) == 1, f"{name}: the message is printed {len(lines)} times, expected once")
    for frag in fragments:
        st.check(frag in msg, f"{name}: message lacks '{frag}'")
    for leftover in (out, out + ".part"):
        st.check(not os.path.exists(leftover), f"{name}: {os.path.basename(leftover)} left behind")
    st.check("Segmentation" not in log and "MPI_ABORT" not in log and "signal" not in log.lower(),
             f"{name}: crash output")
st.done()
