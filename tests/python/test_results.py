"""sinew.load and Scene.run (issue 25): SPACAR Light's `out` from a result file equals the file's
datasets; 1-based node and step numbers; errors raise SinewError with Sinew's message and exit code;
a non-converged run returns its converged steps with converged False."""
import os

import h5py
import numpy as np
import pytest

import sinew

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
SCRIPTS = os.path.join(HERE, "spacar")


@pytest.fixture(scope="module")
def crosshinge(tmp_path_factory):
    path = str(tmp_path_factory.mktemp("res") / "crosshinge.h5")
    out = sinew.Scene.from_yaml(os.path.join(SOURCE, "runs", "crosshinge.yaml")).run(output=path, keep_files=True)
    return out, path


def test_out_structure_equals_the_file(crosshinge):
    out, path = crosshinge
    with h5py.File(path, "r") as f:
        p, cm, freq = f["node/p"][()], f["node/CMglob"][()], f["freq"][()]
        assert out.ndof == int(f.attrs["ndof"]) and out.converged == bool(f.attrs["converged"])
    assert out.ns == p.shape[0] == 10 and len(out.node) == p.shape[1] == 5
    np.testing.assert_array_equal(out.node[5].p, p[:, 4])
    np.testing.assert_array_equal(out.node[5].CMglob, cm[:, 4])
    np.testing.assert_array_equal(out.step[3].node[5].p, p[2, 4])
    np.testing.assert_array_equal(out.freq, freq)
    np.testing.assert_array_equal(out.step[3].freq, freq[2])
    assert out.node[5].r_eulzyx.shape == (10, 3) and out.node[5].r_quat.shape == (10, 4)
    with pytest.raises(IndexError, match="node 6: expected 1..5"):
        out.node[6]
    with pytest.raises(IndexError, match="step 0"):
        out.step[0]


def test_opt_changes_the_run():
    sim = sinew.Scene.from_yaml(os.path.join(SOURCE, "runs", "crosshinge.yaml"))
    sim.opt["loadsteps"] = 4
    sim.opt["calcbuck"] = False
    out = sim.run()
    assert out.ns == 4 and out.buck is None and out.load_factor[-1] == 1.0


def test_scene_error_raises_with_the_field():
    sim = sinew.Scene.from_yaml(os.path.join(SOURCE, "runs", "crosshinge.yaml"))
    sim.data["eprops"][0]["dim"] = [0.05]
    with pytest.raises(sinew.SinewError) as e:
        sim.run()
    assert e.value.exit_code == 2 and "eprops" in e.value.message and "dim" in e.value.message


def test_unknown_flag_raises():
    with pytest.raises(sinew.SinewError, match="did you mean -loadsteps"):
        sinew.Scene.from_yaml(os.path.join(SOURCE, "runs", "crosshinge.yaml")).run(flags=["-loadstep", "3"])


def test_not_converged_returns_steps_or_raises():
    sim = sinew.Scene.from_yaml(os.path.join(SOURCE, "runs", "crosshinge.yaml"))
    flags = ["-snes_max_it", "2", "-max_cuts", "0", "-calccompl", "false", "-calcbuck", "false"]
    out = sim.run(flags=flags)
    assert not out.converged and out.ns >= 1
    with pytest.raises(sinew.SinewError) as e:
        sim.run(flags=flags, check=True)
    assert e.value.exit_code == 3


def test_spacarlight_call_matches_the_scene():
    nodes = [[-0.05, 0, 0], [0.05, 0, 0], [0.05, 0.1, 0], [-0.05, 0.1, 0], [0, 0.12, 0]]
    elements = [[1, 3], [2, 4], [3, 4], [4, 5]]
    nprops = [{"fix": True}, {"fix": True}, None, None,
              {"force_initial": [0, -20, 0], "moment": [0, 0, 0.5], "mass": 0.2, "mominertia": [1e-4, 0, 0, 1e-4, 0, 1e-4]}]
    eprops = [{"elems": [1, 2], "flex": [1, 2, 3, 4, 5, 6], "emod": 210e9, "smod": 80e9, "dens": 7800, "cshape": "rect",
               "dim": [0.05, 0.0005], "orien": [0, 0, 1], "nbeams": 4, "cw": True}]
    opt = {"loadsteps": 10, "calcbuck": True, "stressperelement": True, "filename": "crosshinge"}
    out = sinew.spacarlight(nodes, elements, nprops, eprops, opt)
    ref = sinew.Scene.from_yaml(os.path.join(SCRIPTS, "crosshinge.yaml")).run()
    np.testing.assert_array_equal(out.node[5].p, ref.node[5].p)
    np.testing.assert_array_equal(out.buck, ref.buck)
