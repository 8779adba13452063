"""Helpers for Sinew's system tests: run the sinew executable on a scene under mpirun and read
the HDF5 result with h5py. Each test_*.py file is one ctest case; it exits non-zero on failure
and prints the measured errors it compared."""
import json
import os
import subprocess
import sys

import h5py
import numpy as np

SOURCE = os.environ.get("SINEW_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.environ.get("SINEW_BIN", os.path.join(SOURCE, "build", "sinew"))
MPIEXEC = os.environ.get("SINEW_MPIEXEC", "mpirun")
WORK = os.environ.get("SINEW_WORK_DIR", os.path.join(SOURCE, "build", "tests", "work"))
# Open MPI as ctest sets it (tests/CMakeLists.txt SINEW_MPI_ENV) when a case runs by hand: shared
# memory only (no network transport probing at start) and no 1-2 s wait of mpirun after a non-zero exit
ENV = dict(dict(OMPI_MCA_pml="ob1", OMPI_MCA_btl="self,vader", OMPI_MCA_odls_base_sigkill_timeout="0"), **os.environ)
ENV.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")

_failures = []


def launcher(np_):
    """The command prefix that starts sinew on np_ ranks: `mpirun -n np_`, and for one rank the
    executable alone, as `sinew scene.yaml` starts without a launcher (an MPI singleton: the same
    arithmetic, without mpirun's 0.3 s start-up, which hundreds of one-rank runs of the suite would pay).
    SINEW_TEST_MPIRUN1=1 starts one-rank runs under mpirun too."""
    if np_ == 1 and os.environ.get("SINEW_TEST_MPIRUN1") != "1":
        return [BIN]
    return [MPIEXEC, "-n", str(np_), BIN]


def scene_file(name, scene):
    """Writes a scene (dict -> JSON, which is YAML) or text to WORK/name.yaml; returns the path."""
    os.makedirs(WORK, exist_ok=True)
    path = os.path.join(WORK, name + ".yaml")
    with open(path, "w") as f:
        f.write(scene if isinstance(scene, str) else json.dumps(scene, indent=1))
    return path


def run(name, scene, np_=2, args=(), expect_exit=0):
    """Runs sinew on the scene (dict, text, or an existing .yaml path) with np_ ranks.
    Returns (result .h5 path, stdout+stderr). Fails the test on an unexpected exit code."""
    path = scene if isinstance(scene, str) and scene.endswith(".yaml") and os.path.exists(scene) \
        else scene_file(name, scene)
    out = os.path.join(WORK, name + ".h5")
    for stale in (out, out + ".part"):
        if os.path.exists(stale):
            os.remove(stale)
    cmd = launcher(np_) + [path, "-o", out] + list(args)
    if in_process_eligible(path, np_, args, expect_exit):
        words = ["-o", out] + _environment_flags(args) + [str(a) for a in args]
        code, text = _worker(np_).run(path, words) if np_ > 1 else _run_here(path, words)
        cmd = ["(in process)"] + cmd
    else:
        p = subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=900)
        code, text = p.returncode, p.stdout
    if code != expect_exit:
        print(text)
        fail(f"{name}: exit code {code}, expected {expect_exit} ({' '.join(cmd)})")
    return out, text


# In-process runs (DEVELOPERS.md, "Build and test"): a test's runs that are expected to succeed go
# through sinew._core (the same SceneRun and result file as the command line): on 2 ranks in one
# worker process per rank (inprocess_worker.py) instead of one mpirun each, which costs 0.25 s before
# any work; on 1 rank in this process (an MPI singleton once, instead of once per run). Runs expected
# to fail (their exit codes, messages and no-hang guarantees are the command line's) and runs with
# the flags below stay processes; PETSC_OPTIONS in ENV become flags of the run. A test sets
# IN_PROCESS = False to run everything as processes; SINEW_TEST_IN_PROCESS=0 does it for the whole suite.
IN_PROCESS = os.environ.get("SINEW_TEST_IN_PROCESS", "1") != "0"
# handled by the command line before a scene runs (help, version, options files, PETSc's log at
# exit) or by its refinement driver (-target_error)
PROCESS_FLAGS = ("-help", "-help_dev", "-help_petsc", "-version", "-options_file", "-log_view", "-target_error")
_workers = {}


def _core_built():
    d = os.path.join(os.path.dirname(os.path.abspath(BIN)), "python", "sinew")
    return os.path.isdir(d) and any(f.startswith("_core") for f in os.listdir(d))


def in_process_eligible(path, np_, args, expect_exit):
    if not IN_PROCESS or expect_exit != 0 or not _core_built():
        return False
    if ENV.get("PETSC_OPTIONS_YAML"):  # read by each process's PetscInitialize
        return False
    if any(str(a).split("=")[0] in PROCESS_FLAGS for a in args):
        return False
    with open(path) as f:
        return "target_error" not in f.read()


def _environment_flags(args):
    """ENV's PETSC_OPTIONS as flags of an in-process run (a process's PetscInitialize reads them; the
    in-process runs start PETSc once, without them), those the run's own words give left out (the
    command line overrides PETSC_OPTIONS)."""
    words, given, out = ENV.get("PETSC_OPTIONS", "").split(), {str(a) for a in args if str(a).startswith("-")}, []
    for i, w in enumerate(words):
        if not w.startswith("-") or w[1:2].isdigit() or w[1:2] == ".":
            continue  # a value
        value = [words[i + 1]] if i + 1 < len(words) and not (words[i + 1].startswith("-") and not words[i + 1][1:2].isdigit()) else []
        if w not in given:
            out += [w] + value
    return out


_core = None


def _run_here(path, words):
    """A one-rank run in this process (sinew._core on MPI_COMM_WORLD of this singleton)."""
    global _core
    if _core is None:
        import atexit
        import glob
        import importlib.util
        core = sys.modules.get("sinew._core")
        if core is None:  # the compiled module alone, as sinew._core (the package, if imported later, uses it)
            so = glob.glob(os.path.join(os.path.dirname(os.path.abspath(BIN)), "python", "sinew", "_core*"))[0]
            spec = importlib.util.spec_from_file_location("sinew._core", so)
            core = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(core)
            sys.modules["sinew._core"] = core
        core.initialize([])
        atexit.register(core.finalize)
        _core = core
    run = _core.run(path, flags=words, echo=False)
    text = run["output"] or ""
    if run["exit_code"] != 0 and run["message"] and run["message"] not in text:
        text += run["message"] + "\n"
    return run["exit_code"], text


def _worker(np_):
    if np_ not in _workers:
        from inprocess_client import InProcessWorker
        env = {k: v for k, v in ENV.items() if k != "PETSC_OPTIONS"}  # passed as flags per run (_environment_flags)
        _workers[np_] = InProcessWorker(MPIEXEC, np_, env, WORK)
    return _workers[np_]


def script(name, *args, cwd=None):
    """Runs scripts/<name> with the arguments as `/usr/bin/python3 scripts/<name> args` would, but in
    this process (the file run as __main__ with sys.argv set, stdout and stderr captured): the
    interpreter start and the matplotlib import (about a second) are paid once per test, not per
    call. Returns an object with returncode, stdout, stderr (exit code as the interpreter would give
    it: SystemExit's code, 1 for an uncaught exception, whose traceback goes to stderr). Tests of
    what the command line itself prints (one line, no traceback) start the script as a process."""
    import contextlib
    import io
    import runpy
    import traceback
    import types
    scripts = os.path.join(SOURCE, "scripts")
    path = os.path.join(scripts, name)
    out, err = io.StringIO(), io.StringIO()
    argv, here, code = sys.argv, os.getcwd(), 0
    sys.path.insert(0, scripts)
    try:
        sys.argv = [path] + [str(a) for a in args]
        if cwd:
            os.chdir(cwd)
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                runpy.run_path(path, run_name="__main__")
            except SystemExit as e:
                if isinstance(e.code, str):
                    print(e.code, file=sys.stderr)
                code = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
            except Exception:  # noqa: BLE001 (an uncaught exception: the interpreter's exit 1)
                traceback.print_exc()
                code = 1
    finally:
        sys.argv = argv
        os.chdir(here)
        sys.path.remove(scripts)
        if "matplotlib.pyplot" in sys.modules:
            sys.modules["matplotlib.pyplot"].close("all")
    return types.SimpleNamespace(returncode=code, stdout=out.getvalue(), stderr=err.getvalue())


def h5(path):
    return h5py.File(path, "r")


def fail(msg):
    print("FAIL:", msg)
    _failures.append(msg)


def check(cond, msg):
    if not cond:
        fail(msg)
    return cond


def close(measured, expected, rtol=0.0, atol=0.0, what="value"):
    """Compares arrays/scalars; prints the measured relative and absolute errors."""
    m = np.asarray(measured, dtype=float)
    e = np.asarray(expected, dtype=float)
    err = np.max(np.abs(m - e)) if m.size else 0.0
    scale = np.max(np.abs(e)) if e.size else 0.0
    rel = err / scale if scale > 0 else err
    ok = np.all(np.isfinite(m)) and err <= atol + rtol * scale
    print(f"  {what}: measured {np.array2string(m.ravel()[:6], precision=12)} expected "
          f"{np.array2string(e.ravel()[:6], precision=12)} abs err {err:.3e} rel err {rel:.3e} "
          f"({'ok' if ok else 'FAIL'})")
    if not ok:
        fail(f"{what}: abs err {err:.3e}, rel err {rel:.3e} (rtol {rtol}, atol {atol})")
    return ok


def done():
    """Ends the test: prints the verdict, exits 1 if any check failed."""
    if _failures:
        print(f"{len(_failures)} check(s) failed")
        sys.exit(1)
    print("all checks passed")
    sys.exit(0)
