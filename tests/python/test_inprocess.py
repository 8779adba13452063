"""Runs in this process (sinew._core, issue 25), on the ranks pytest runs on (ctest: python_api on 1
rank, python_inprocess_errors_2ranks under mpiexec -n 2): Scene.run and spacarlight run in-process
by default and every rank gets the whole results; errors raise SinewError with Sinew's message and
exit code and the interpreter goes on (a scene error naming the field, an unknown flag, a Newton
failure, a PETSc error); a result file is written only when asked; on one rank, the process run
(Scene.run(process=True)) gives the same `out` bit for bit. The datasets of every runs/ scene
against the command line's file: inprocess_compare.py."""
import os

import numpy as np
import pytest

import sinew

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
HINGE = os.path.join(SOURCE, "runs", "crosshinge.yaml")


def world():
    from mpi4py import MPI
    return MPI.COMM_WORLD


def hinge(**opt):
    sim = sinew.Scene.from_yaml(HINGE)
    sim.opt.update(opt)
    return sim


def test_module_is_built():
    assert sinew.core() is not None, "sinew._core not found (build it: cmake --build build)"


def test_every_rank_gets_the_whole_results():
    out = hinge(loadsteps=3).run()
    assert out.converged and out.ns == 3 and len(out.node) == 5 and out.node[5].CMglob.shape == (3, 6, 6)
    assert out.attrs["nranks"] == world().Get_size()
    rows = world().allgather(out.data["node/p"])
    for r in rows:
        np.testing.assert_array_equal(r, rows[0])


def test_scene_error_names_the_field():
    sim = hinge()
    sim.data["eprops"][0]["dim"] = [0.05]
    with pytest.raises(sinew.SinewError) as e:
        sim.run(process=False)
    assert e.value.exit_code == 2 and "eprops(1).dim" in e.value.message
    assert hinge(loadsteps=1).run().converged  # the interpreter goes on


def test_unknown_flag_and_bad_value():
    with pytest.raises(sinew.SinewError, match="did you mean -loadsteps") as e:
        hinge().run(flags=["-loadstep", "3"], process=False)
    assert e.value.exit_code == 2
    with pytest.raises(sinew.SinewError) as e:
        hinge().run(flags={"max_cuts": "many"}, process=False)
    assert e.value.exit_code == 2 and "max_cuts" in e.value.message


def test_flags_as_list_or_dict():
    a = hinge(calcbuck=False).run(flags=["-loadsteps", "2", "-gravity", "0,-9.81,0"])
    b = hinge(calcbuck=False).run(flags={"loadsteps": 2, "gravity": [0, -9.81, 0]})
    assert a.ns == b.ns == 2
    np.testing.assert_array_equal(a.data["node/p"], b.data["node/p"])
    c = hinge(calcbuck=False, loadsteps=2).run()
    assert not np.array_equal(a.data["node/p"], c.data["node/p"])  # gravity acted, and held for its run only


def test_newton_failure_returns_converged_steps_or_raises():
    flags = ["-snes_max_it", "2", "-max_cuts", "0", "-calccompl", "false", "-calcbuck", "false"]
    out = hinge().run(flags=flags)
    assert not out.converged and out.ns >= 1 and out.attrs["converged"] == 0
    with pytest.raises(sinew.SinewError) as e:
        hinge().run(flags=flags, check=True)
    assert e.value.exit_code == 3 and "step" in e.value.message


def test_petsc_error_raises_and_the_interpreter_goes_on():
    with pytest.raises(sinew.SinewError) as e:
        hinge(loadsteps=1).run(flags=["-pc_type", "no_such_pc"])
    assert e.value.exit_code == 4 and "no_such_pc" in e.value.output + e.value.message
    assert hinge(loadsteps=1).run().converged


def test_file_only_when_asked(tmp_path):
    path = world().bcast(str(tmp_path / "hinge.h5"))  # rank 0's path on every rank
    before = set(os.listdir(os.getcwd()))
    mem = hinge(loadsteps=2).run()
    assert set(os.listdir(os.getcwd())) == before
    out = hinge(loadsteps=2).run(output=path)
    assert os.path.exists(path) and os.path.exists(path[:-3] + ".xdmf")
    assert sorted(out.data) == sorted(mem.data)
    for k in mem.data:
        np.testing.assert_array_equal(out.data[k], mem.data[k])


def test_process_run_gives_the_same_out():
    if world().Get_size() > 1:
        pytest.skip("a process run from inside an MPI job: one rank only")
    sim = hinge(loadsteps=3)
    mem, proc = sim.run(), sim.run(process=True)
    assert sorted(mem.data) == sorted(proc.data)
    for k in mem.data:
        np.testing.assert_array_equal(mem.data[k], proc.data[k])
    # the scene text differs: the process run reads PyYAML's text of the dict, the in-process one yaml-cpp's
    assert {k: v for k, v in mem.attrs.items() if k != "scene"} == {k: v for k, v in proc.attrs.items() if k != "scene"}


def test_target_error_in_process(tmp_path):
    """opt.target_error through spacarlight (docs/accuracy.md, "From the library and Python"): a
    cantilever's bending frequencies from one element (t / L = 1e-4, so Euler-Bernoulli's values are
    the limit): the answer is the finest level's (more nodes than the scene's two), out.accuracy holds
    the study, its estimates within a factor 3 of the true errors and the true errors within the target;
    with output=... the same in the file, /accuracy included."""
    L, w, t, E, rho = 1.0, 0.01, 1e-4, 210e9, 7800.0
    beta = np.array([1.875104068711961, 4.694091132974175, 7.854757438237613])
    ref = beta ** 2 * np.sqrt(E * w * t ** 3 / 12 / (rho * w * t * L ** 4)) / (2 * np.pi)
    eprops = [{"elems": [1], "flex": [1, 2, 3, 4, 5, 6], "emod": E, "smod": 80e9, "dens": rho, "cshape": "rect",
               "dim": [w, t], "orien": [0, 0, 1], "nbeams": 1}]
    args = ([[0, 0, 0], [L, 0, 0]], [[1, 2]], {1: {"fix": True}}, eprops)
    opt = {"nfreq": 3, "calccompl": False, "target_error": 1e-5}
    out = sinew.spacarlight(*args, opt=opt)
    acc = out.accuracy
    assert acc is not None and acc["met"] == 1 and acc["target"] == 1e-5 and acc["refinement"] == "elements / 2^level"
    assert out.data["mesh/p"].shape[1] == int(acc["nbeams_factor"][-1]) + 1 > 8, "the answer is the finest level's mesh"
    true = np.abs(out.freq[-1][:3] / ref - 1)
    est = acc["error"][-1][[acc["quantities"].index(f"freq {k + 1}") for k in range(3)]]
    assert true.max() <= 1e-5
    checked = true > 1e-7  # below target / 100 the model's shear terms are of the error's size
    assert np.all(((est / true > 1 / 3) & (est / true < 3))[checked]), (est, true)
    path = world().bcast(str(tmp_path / "accuracy.h5"))  # rank 0's path on every rank
    filed = sinew.spacarlight(*args, opt=opt, flags={"o": path})
    np.testing.assert_array_equal(filed.freq, out.freq)
    np.testing.assert_array_equal(filed.accuracy["error"], acc["error"])
    assert filed.accuracy["quantities"] == acc["quantities"] and filed.accuracy["met"] == 1
