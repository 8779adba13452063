"""A dict given to sinew._core goes to the scene reader as the YAML tree its text would give, without
text (issue 25, python_scene.hpp): the tree must be YAML::Load of the dict's text node for node
(kinds, scalars, quoted "!" or plain "?" tags, key order, duplicate keys such as 1 and "1"), so that
the reader gives the same Model; the runs through the tree and through the text (as_text=True) must
give the same results bit for bit, the same errors (without the text's line numbers, naming the
field), and a result file the same scene text."""
import glob
import os
import re

import h5py
import numpy as np
import pytest

import sinew

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
RUNS = sorted(glob.glob(os.path.join(SOURCE, "runs", "*.yaml")))
# the scenes the system cases wrote (tests/cases/sinewtest.py scene_file: their dicts as JSON) when they ran
CASE_SCENES = sorted(glob.glob(os.path.join(os.environ.get("SINEW_WORK_DIR", os.path.join(SOURCE, "build", "tests", "work")),
                                            "*.yaml")))
ODD_STRINGS = ["null", "Null", "NULL", "~", "", "a: b", "- x", "-", "--", "---", "...", "x, y", "[1]", "{a}", "#c", "a #b",
               "a#b", "key:", "?", "!t", "&a", "*a", "%", "@", "`", "yes", "off", "True", "1", "-1", "+1", "1e3", ".5", "-.5",
               "0x1F", ".nan", ".inf", " lead", "trail ", "two\nlines", "tab\t", 'quote"', "back\\slash", "ü", "é: x",
               "\x01", "\u00a0", "a\u2028b", "a:b", "a,b"]
VALUES = [None, True, False, 0, -1, 2**70, 1.5, -0.0, 0.1, 1e-300, 5e-324, 1e300, 1e16, 100.0, float("nan"),
          float("inf"), -float("inf"), np.float32(0.1), np.float64(2.5), np.int64(3), np.bool_(True),
          np.array([[1.0, 2], [3, 4]]), np.arange(3), (1, 2.5), [], {}, {"k": []}]


def core():
    c = sinew.core()
    assert c is not None, "sinew._core not found (build it: cmake --build build)"
    return c


def scene_dicts():
    """Every runs/ scene and every case scene that is a map (dicts as JSON, texts as YAML)."""
    import json
    import yaml
    for path in RUNS:
        yield path, sinew.Scene.from_yaml(path).data
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    for path in CASE_SCENES:
        try:
            with open(path) as f:
                text = f.read()
            if "[" * 64 in text or "{" * 64 in text:  # the robustness case's deep nesting (libyaml's stack)
                continue
            data = json.loads(text) if text.startswith("{") else yaml.load(text, Loader=loader)
        except (ValueError, RecursionError, yaml.YAMLError):  # not UTF-8, not YAML (robustness cases)
            continue
        if isinstance(data, dict):
            yield path, data


def test_tree_is_the_text_tree_for_every_scene():
    checked, problems = 0, []
    for path, data in scene_dicts():
        d = core().scene_tree_check(data)
        checked += 1
        if d:
            problems.append(f"{os.path.relpath(path, SOURCE)}: {d}")
    assert checked >= len(RUNS) and not problems, "\n".join(problems)


def test_tree_is_the_text_tree_for_odd_strings_and_values():
    c = core()
    mixed = {"top": {s: s for s in ODD_STRINGS}, "list": ODD_STRINGS, "values": VALUES, 1: "one", "1": 2, 2.5: None,
             (1, "a b"): 3, "nested": [{s: [s, {s: s}]} for s in ODD_STRINGS], "tuple": tuple(VALUES)}
    assert c.scene_tree_check(mixed) == ""
    for s in ODD_STRINGS:
        for x in ({s: s}, [s], [{s: s}], {"a": {s: [s, (s,)]}}):
            assert c.scene_tree_check(x) == "", (s, x)
    # a lone string that would not read back (a document marker) is run as text
    assert c.scene_tree_check("...").startswith("no tree")


def test_text_is_the_dict():
    base = {"nodes": [[0, 0, 0], [1, 0, 0]], "opt": {"loadsteps": 5, "gravity": np.array([0, 0, -9.81])}}
    import yaml
    assert yaml.safe_load(core().scene_text(base)) == dict(base, opt={"loadsteps": 5, "gravity": [0, 0, -9.81]})


def run_both(data, flags, base_dir):
    c = core()
    tree = c.run(data, flags=flags, base_dir=base_dir)
    text = c.run(data, flags=flags, base_dir=base_dir, as_text=True)
    return tree, text


def untimed(output):
    """The printed text without its times (elapsed 0.1 s, the wall time line)."""
    return re.sub(r"[0-9.]+ (s|ms)\b", "(time)", output)


def same_run(tree, text, where):
    assert "scene_text" in tree and "scene_text" not in text, where
    for k in ("exit_code", "message", "file"):
        assert tree[k] == text[k], (where, k)
    assert untimed(tree["output"]) == untimed(text["output"]), where
    attrs = dict(text["attrs"])
    assert attrs.pop("scene", "") in ("", tree["scene_text"]()), where
    assert tree["attrs"] == attrs, where
    assert tree["group_attrs"] == text["group_attrs"], where
    if text["datasets"] is None:
        assert tree["datasets"] is None, where
        return
    assert sorted(tree["datasets"]) == sorted(text["datasets"]), where
    for name, a in text["datasets"].items():
        b = tree["datasets"][name]
        assert a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes(), (where, name)


@pytest.mark.parametrize("path", RUNS, ids=[os.path.basename(p)[:-5] for p in RUNS])
def test_every_runs_scene_reads_the_same(path):
    """Every runs/ scene read and set up through both paths (-showinputonly: the model, the mesh
    datasets, the printed summary), with an opt flag (a copy of the tree takes it)."""
    sim = sinew.Scene.from_yaml(path)
    for flags in ({"showinputonly": True}, {"showinputonly": True, "loadsteps": 2}):
        tree, text = run_both(sim.data, flags, sim.base_dir)
        same_run(tree, text, (path, flags))
    assert core().scene_tree_check(sim.data) == ""  # the flag went into a copy, not the dict's tree


@pytest.mark.parametrize("name", ["crosshinge", "lee_frame"])
def test_runs_give_the_same_results(name):
    sim = sinew.Scene.from_yaml(os.path.join(SOURCE, "runs", name + ".yaml"))
    tree, text = run_both(sim.data, [], sim.base_dir)
    assert tree["exit_code"] == 0
    same_run(tree, text, name)
    out = sinew.results.from_memory(tree)
    assert out.scene == core().scene_text(sim.data)


def without_line(message):
    return re.sub(r" \(line \d+\)", "", message)


BAD = [
    ({"nodes": [[0, 0, 0], [1, 0, 0]], "elements": [[1, 2]], "opt": {"loadsteps": "many"}}, "opt.loadsteps"),
    ({"nodes": [[0, 0, 0], [1, 0, 0]], "elements": [[1, 3]]}, "elements(1,2)"),
    ({"nodes": [[0, 0, 0], [1, 0]], "elements": [[1, 2]]}, "nodes(2)"),
    ({"nodes": [[0, 0, 0], [1, 0, 0]], "elements": [[1, 2]], "nprops": {1: {"fix": "yes please"}}}, "nprops(1).fix"),
    ({"nodes": [[0, 0, 0], [1, 0, 0]], "elements": [[1, 2]], "nprops": {1: {"fix": True}, "1": {"fix": True}}}, "nprops(1)"),
    ({"nodes": [[0, 0, 0], [1, 0, 0]], "elements": [[1, 2]], "eprops": [{"elems": [1], "emod": "stiff"}]}, "eprops(1).emod"),
    ({"nodes": [[0, 0, 0], [1, 0, 0]], "elements": [[1, 2]], "eprops": [{"elems": [1], "emodd": 1e9}]}, "eprops(1).emodd"),
    ({"nodes": [[0, 0, 0], [float("nan"), 0, 0]], "elements": [[1, 2]]}, "nodes(2,1)"),
    ({"nodes": [[0, 0, 0], [1, 0, 0]], "elements": [[1, 2]], "opt": {"gravity": [0, 0, None]}}, "opt.gravity"),
    ({"nodes": [[0, 0, 0], [1, 0, 0]], "elements": [[1, 2]], "tittle": "x"}, "tittle"),
    ({"nodes": None, "elements": [[1, 2]]}, "nodes"),
    ({}, "nodes"),
    (None, ""),
    ([1, 2], ""),
]


@pytest.mark.parametrize("data,field", BAD, ids=[str(i) for i in range(len(BAD))])
def test_errors_name_the_field(data, field):
    """A bad scene: the same exit code and message, where the text names a line the tree names the
    field (every message starts with the field's path)."""
    for flags in ({}, {"calcbuck": True}):  # with an opt flag: a copy of the tree takes it
        tree, text = run_both(data, flags, ".")
        assert tree["exit_code"] == text["exit_code"] != 0
        assert tree["message"] == without_line(text["message"]), (tree["message"], text["message"])
        assert field in tree["message"]


def test_result_file_holds_the_scene_text(tmp_path):
    """A run of the tree to a file: the text made for the file is the text path's (scene attribute)."""
    sim = sinew.Scene.from_yaml(os.path.join(SOURCE, "runs", "crosshinge.yaml"))
    files = []
    for as_text in (False, True):
        h5 = str(tmp_path / f"hinge_{as_text}.h5")
        run = core().run(sim.data, flags=["-o", h5, "-loadsteps", "2"], base_dir=sim.base_dir, as_text=as_text)
        assert run["exit_code"] == 0 and run["file"] == h5 and "scene_text" not in run
        files.append(h5)
    with h5py.File(files[0]) as a, h5py.File(files[1]) as b:
        assert a.attrs["scene"] == b.attrs["scene"] and len(a.attrs["scene"]) > 100
        assert np.array_equal(a["node/p"][()], b["node/p"][()])
