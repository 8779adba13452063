"""sinew.from_spacar: the MATLAB subset of SPACAR Light scripts (issue 25). Each check fails when the
construct is read wrongly or not at all."""
import numpy as np
import pytest

from sinew.spacar import Interpreter, SpacarError, convert

MODEL = "nodes = [0 0 0; 1 0 0]; elements = [1 2];\n"


def run(text):
    it = Interpreter("t")
    it.run(text)
    return it.vars


def test_matrix_whitespace_signs_and_rows():
    v = run("a = [1 -2, 3 - 4, 5-6, 7 +8];\nb = [1 2\n 3 4];\nc = [1, 2, ...\n 3];")
    assert v["a"].tolist() == [[1, -2, -1, -1, 7, 8]]
    assert v["b"].tolist() == [[1, 2], [3, 4]]
    assert v["c"].tolist() == [[1, 2, 3]]


def test_ranges_indexing_transpose_functions():
    v = run("r = 0:0.5:2; s = 1:3; b = [1 2; 3 4]'; c = b(2, :); d = b(end); e = sqrt(16)*2^2; f = -2^2;"
            "g = [s' s']; h = numel(s); k = size(b, 1); m = deg2rad(180); n = atan2(1, 1)")
    assert v["r"].tolist() == [[0, 0.5, 1, 1.5, 2]]
    assert v["b"].tolist() == [[1, 3], [2, 4]] and v["c"].tolist() == [[2, 4]] and v["d"] == 4
    assert v["e"] == 16 and v["f"] == -4 and v["g"].shape == (3, 2) and v["h"] == 3 and v["k"] == 2
    assert v["m"] == pytest.approx(np.pi) and v["n"] == pytest.approx(np.pi / 4)


def test_comments_strings_and_transpose_quotes():
    v = run("x = 'it''s % not a comment'; % a comment\ny = [1 2]'; z = \"dq\"")
    assert v["x"] == "it's % not a comment" and v["y"].tolist() == [[1], [2]] and v["z"] == "dq"


def test_loops_and_matrix_growth():
    v = run("n = zeros(2, 3);\nfor k = 1:3\n  n(k, :) = [k 2*k 0];\n  for j = 1:2\n    m(j, k) = j*k;\n  end\nend")
    assert v["n"].tolist() == [[1, 2, 0], [2, 4, 0], [3, 6, 0]]
    assert v["m"].tolist() == [[1, 2, 3], [2, 4, 6]]


def test_struct_arrays_to_scene():
    s = convert(MODEL + "nprops(1).fix = 1; nprops(2).force = [0 1 0]; nprops(2).moment_initial = [0 0 -0.025];\n"
                "eprops(1).elems = 1; eprops(1).dim = 5e-3; eprops(1).cw = 0; eprops(1).cshape = 'circ';\n"
                "eprops(1).flex = 1:6;\n"
                "opt.rls(1).def = [2 3]; opt.transfer = {true, 0.02}; opt.calcbuck = 1; opt.filename = 'x';\n"
                "out = spacarlight(nodes, elements, nprops, eprops, opt);")
    assert s["nprops"] == {1: {"fix": True}, 2: {"force": [0, 1, 0], "moment_initial": [0, 0, -0.025]}}
    assert s["eprops"] == [{"elems": [1], "dim": [0.005], "cw": False, "cshape": "circ", "flex": [1, 2, 3, 4, 5, 6]}]
    assert s["opt"] == {"rls": {1: [2, 3]}, "transfer": [True, 0.02], "calcbuck": True, "filename": "x"}
    assert s["title"] == "x" and s["nodes"] == [[0, 0, 0], [1, 0, 0]] and s["elements"] == [[1, 2]]


def test_call_names_the_model_variables():
    s = convert("p = [0 0 0; 1 0 0]; e = [1 2]; np(1).fix = true; ep(1).elems = 1; o.loadsteps = 3;\n"
                "res = spacarlight(p, e, np, ep, o);")
    assert s["nodes"] == [[0, 0, 0], [1, 0, 0]] and s["opt"] == {"loadsteps": 3} and s["nprops"] == {1: {"fix": True}}


@pytest.mark.parametrize("text, where", [
    ("x = [1 2", "line 1"),
    ("\n\ny = undefined_thing + 1", "line 3: unknown variable or function 'undefined_thing'"),
    ("if x > 1\n end", "line 1: 'if' is not read"),
    ("a = [1 2; 3]", "matrix rows of different lengths"),
    ("v = [1 2 3]; w = v(4)", "index [4.0] outside 1..3"),
])
def test_errors_name_the_line(text, where):
    with pytest.raises(SpacarError, match=where.replace("[", r"\[").replace("]", r"\]").replace("(", r"\(").replace(")", r"\)")):
        convert(text)


def test_missing_model_is_an_error():
    with pytest.raises(SpacarError, match="no 'nodes' assigned"):
        convert("elements = [1 2];")
