"""Command-line flags (issue 13 item 7), on 1 and 2 ranks, every run under a timeout.
- A flag that is neither Sinew's (src/settings/flags.cpp: the settings fields and every scene opt field) nor a
  PETSc/SLEPc option is an error: exit 2, one message printed once (rank 0), with the nearest
  Sinew flag; from the command line, an -options_file or PETSC_OPTIONS alike.
- Every Sinew flag's value is checked before the scene is read: exit 2, a message naming the flag
  and the accepted values, no result file (neither the -o file, nor <filename>.h5, nor true.h5),
  and no MPI_Abort (-tangent_operator bogus used to end in exit 62).
- PETSc's and SLEPc's own flags, also under Sinew's solver prefixes, pass, and valid Sinew flags
  act (-loadsteps 3 gives 3 result rows).
- -version prints Sinew's version (the CMake project version, also the result file's `version`
  attribute), then one line per library (PETSc, SLEPc, MPI, HDF5, METIS, yaml-cpp) and no PETSc
  banner, and exits 0 without running the scene (issue 24 item 11)."""
import os
import re
import subprocess
from concurrent.futures import ThreadPoolExecutor

import h5py
import yaml

import sinewtest as st

TIMEOUT = 120
SCENE = {"title": "flags", "nodes": [[0, 0, 0], [0.5, 0, 0], [1, 0, 0]], "elements": [[1, 2], [2, 3]],
         "nprops": {1: {"fix": True}, 3: {"force": [0, 0, -10]}},
         "eprops": [{"elems": [1, 2], "flex": [1, 2, 3, 4, 5, 6], "emod": 210e9, "smod": 80e9, "cshape": "rect",
                     "dim": [0.02, 0.01], "orien": [0, 0, 1]}],
         "opt": {"loadsteps": 2, "calccompl": False}}


def project_version():
    with open(os.path.join(st.SOURCE, "CMakeLists.txt")) as f:
        return re.search(r"project\(Sinew VERSION ([0-9.]+)", f.read()).group(1)


SCENE_PATH = st.scene_file("flags", yaml.safe_dump(SCENE, default_flow_style=None, sort_keys=False))


def run(name, np_, args, out=True, env=None):
    """Runs sinew on the scene in its own directory WORK/flags_<name>_<np> (the cwd, so a result
    named by the scene or by -filename would land there); returns (exit code, output, directory).
    out=False leaves -o away."""
    cwd = os.path.join(st.WORK, f"flags_{name}_{np_}")
    os.makedirs(cwd, exist_ok=True)
    for stale in os.listdir(cwd):
        os.remove(os.path.join(cwd, stale))
    cmd = st.launcher(np_) + [SCENE_PATH] + (["-o", os.path.join(cwd, "out.h5")] if out else []) + \
        list(args)
    try:
        p = subprocess.run(cmd, env=dict(st.ENV, **(env or {})), cwd=cwd, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return None, f"no exit within {TIMEOUT} s (hang): {' '.join(cmd)}", cwd
    return p.returncode, p.stdout, cwd


def run_all(jobs):
    """jobs: {key: (name, np, args, out, env)}; runs them 3 at a time (start-up latency dominates)."""
    with ThreadPoolExecutor(max_workers=3) as pool:
        futures = {k: pool.submit(run, *job) for k, job in jobs.items()}
        return {k: f.result() for k, f in futures.items()}


def no_results(tag, cwd):
    written = [f for f in os.listdir(cwd) if f.endswith((".h5", ".part", ".xdmf"))]
    st.check(not written, f"{tag}: result files written: {written}")


# (name, flags, expected error lines (exactly these, each once), out: give -o)
ERRORS = [
    ("misspelt", ["-loadstep", "40"], ["error: unknown flag -loadstep; did you mean -loadsteps?"], True),
    ("misspelt_sinew_flag", ["-max_cut", "3"], ["error: unknown flag -max_cut; did you mean -max_cuts?"], True),
    ("unknown_far", ["-frobnicate", "1"],
     ["error: unknown flag -frobnicate (neither a Sinew flag nor a PETSc/SLEPc option; sinew -help lists them)"], True),
    ("solver_prefix", ["-coarse_snes_max_it", "3"],
     ["error: unknown flag -coarse_snes_max_it: max_it is not a PETSc/SLEPc option (options of the solver with prefix "
      "coarse_snes_ are -coarse_snes_<PETSc option>, e.g. -coarse_snes_ksp_view)"], True),
    ("force_rtol_nan", ["-force_rtol", "nan"], ["error: -force_rtol: expected a finite number in (0, 1), got nan"], True),
    ("force_rtol_negative", ["-force_rtol", "-1"], ["error: -force_rtol: expected a finite number in (0, 1), got -1"], True),
    ("max_cuts_negative", ["-max_cuts", "-1"], ["error: -max_cuts: expected an integer in 0..50, got -1"], True),
    ("max_cuts_real", ["-max_cuts", "2.5"], ["error: -max_cuts: expected an integer in 0..50, got 2.5"], True),
    ("coarse_ratio_negative", ["-ancf_coarse_ratio", "-3"],
     ["error: -ancf_coarse_ratio: expected an integer >= 0, got -3"], True),
    ("tangent_operator_bogus", ["-tangent_operator", "bogus"],
     ["error: -tangent_operator: expected one of auto, elementwise, assembled, got bogus"], True),
    ("compliance_method", ["-compliance_method", "Sparse"],
     ["error: -compliance_method: expected one of selinv, sparse, dense, got Sparse"], True),
    ("dynamics_scheme", ["-dynamics_scheme", "rk4"],
     ["error: -dynamics_scheme: expected one of arnold_bruls, tsalpha2, midpoint, energy_momentum, got rk4"], True),
    ("dt_grow_after", ["-dt_grow_after", "-1"], ["error: -dt_grow_after: expected an integer >= 0, got -1"], True),
    ("predictor_word", ["-predictor", "maybe"],
     ["error: -predictor: expected true or false (also yes/no, on/off, 1/0; the flag alone means true), got maybe"], True),
    ("check_tol_zero", ["-constraint_check_tol", "0"],
     ["error: -constraint_check_tol: expected a finite number in (0, 1), got 0"], True),
    ("shift_inf", ["-freq_shift_rel", "inf"], ["error: -freq_shift_rel: expected a finite number in (0, 1], got inf"], True),
    ("eps_nev_zero", ["-eps_nev", "0"], ["error: -eps_nev: expected an integer >= 1, got 0"], True),
    ("filename_empty", ["-filename", ""], ["error: -filename: expected a value (string), got no value"], True),
    ("filename_empty_no_o", ["-filename", ""], ["error: -filename: expected a value (string), got no value"], False),
    ("o_without_value", ["-o"], ["error: -o: expected a file name, got no value"], False),
    ("two_errors", ["-loadstep", "4", "-max_cuts", "x"],
     ["error: unknown flag -loadstep; did you mean -loadsteps?", "error: -max_cuts: expected an integer in 0..50, got x"],
     True),
    ("help_with_error", ["-help", "-loadstep", "4"], ["error: unknown flag -loadstep; did you mean -loadsteps?"], True),
    # opt fields: the scene reader checks their values (before any file exists)
    ("loadsteps_huge", ["-loadsteps", "1e9"],
     ["error: opt.loadsteps: expected at most 100000 load steps, got 1000000000 (the node positions alone would take 72 "
      "GB of results for 3 nodes) (from the command line: -loadsteps 1e9)"], True),
    ("loadsteps_missing_value", ["-loadsteps"], ["error: -loadsteps: expected a value (integer 1..100000), got no value"],
     True),
    ("calcbuck_word", ["-calcbuck", "maybe"],
     ["error: opt.calcbuck: expected true or false, got 'maybe' (from the command line: -calcbuck maybe)"], True),
]

OPTS = os.path.join(st.WORK, "flags_options.txt")
with open(OPTS, "w") as f:
    f.write("-loadsteps 3\n-max_cutz 4\n")
FROM_FILES = [("options_file", ["-options_file", OPTS], None, "max_cutz; did you mean -max_cuts?"),
              ("petsc_options_env", [], {"PETSC_OPTIONS": "-predictr false"}, "predictr; did you mean -predictor?")]
# PETSc's and SLEPc's flags pass, also under Sinew's solver prefixes; valid Sinew flags act
OK_FLAGS = ["-loadsteps", "3", "-max_cuts", "0", "-predictor", "no", "-force_rtol", "1e-10", "-tangent_operator",
            "assembled", "-constraint_check_tol", "1e-10", "-freq_shift_rel", "1e-6", "-calcbuck",
            "-snes_rtol", "1e-12", "-ksp_type", "preonly", "-buck_eps_tol", "1e-9", "-buck_st_ksp_type", "preonly",
            "-eps_nev", "2", "-ff_snes_max_it", "5", "-compl_ksp_type", "preonly", "-coarse_snes_snes_max_it", "3",
            "-fine_pc_type", "lu", "-constraint_check_ksp_type", "preonly", "-init_ksp_type", "preonly",
            "-mg_levels_1_pc_type", "jacobi", "-options_left", "no", "-malloc_debug", "no", "-log_view",
            ":" + os.path.join(st.WORK, "flags_log.txt")]

jobs = {}
for np_ in (1, 2):
    for name, flags, expected, out in ERRORS:
        jobs[(name, np_)] = (name, np_, flags, out, None)
    for name, flags, env, _ in FROM_FILES:
        jobs[(name, np_)] = (name, np_, flags, True, env)
    jobs[("petsc_flags", np_)] = ("petsc_flags", np_, OK_FLAGS, True, None)
    jobs[("version", np_)] = ("version", np_, ["-version"], True, None)
results = run_all(jobs)

for np_ in (1, 2):
    for name, flags, expected, out in ERRORS:
        tag = f"{name} on {np_} rank(s)"
        code, log, cwd = results[(name, np_)]
        if not st.check(code is not None, f"{tag}: {log}"):
            continue
        errors = [ln for ln in log.splitlines() if ln.startswith("error")]
        print(f"{tag}: exit {code}: {errors}")
        st.check(code == 2, f"{tag}: exit code {code}, expected 2\n{log}")
        st.check(errors == expected, f"{tag}: error lines {errors}, expected {expected} (each exactly once)")
        st.check("MPI_ABORT" not in log and "PETSC ERROR" not in log, f"{tag}: abort / PETSc error trace")
        no_results(tag, cwd)

    # the same unknown flag from an options file and from PETSC_OPTIONS
    for name, flags, env, want in FROM_FILES:
        tag = f"{name} on {np_} rank(s)"
        code, log, cwd = results[(name, np_)]
        if not st.check(code is not None, f"{tag}: {log}"):
            continue
        errors = [ln for ln in log.splitlines() if ln.startswith("error")]
        print(f"{tag}: exit {code}: {errors}")
        st.check(code == 2 and errors == ["error: unknown flag -" + want], f"{tag}: exit {code}, {errors}")
        no_results(tag, cwd)

    tag = f"petsc_flags on {np_} rank(s)"
    code, log, cwd = results[("petsc_flags", np_)]
    if st.check(code is not None, f"{tag}: {log}"):
        print(f"{tag}: exit {code}")
        st.check(code == 0, f"{tag}: exit {code}\n{log}")
        st.check("error" not in log, f"{tag}: an error message\n{log}")
        h5 = os.path.join(cwd, "out.h5")
        if st.check(os.path.exists(h5), f"{tag}: no result file"):
            with h5py.File(h5, "r") as f:
                rows = f["load_factor"].shape[0]
                st.check(rows == 3, f"{tag}: {rows} load steps written, -loadsteps 3 asked")
                st.check("buck" in f, f"{tag}: -calcbuck alone (true) did not act")
                version = f.attrs["version"]
                version = version.decode() if isinstance(version, bytes) else str(version)
                st.check(version == project_version(), f"result file version {version} != {project_version()}")

    # -version: Sinew's version once, PETSc's and SLEPc's; exit 0; the scene is not run
    tag = f"version on {np_} rank(s)"
    code, log, cwd = results[("version", np_)]
    if st.check(code is not None, f"{tag}: {log}"):
        lines = log.splitlines()
        print(f"{tag}: exit {code}: {lines}")
        st.check(code == 0, f"{tag}: exit {code}")
        # one line per library, Sinew's first; no PETSc/SLEPc banner
        expected = [rf"Sinew {re.escape(project_version())}", r"PETSc 3\.\d+\.\d+", r"SLEPc 3\.\d+\.\d+",
                    r"Open MPI v\d+\.\d+\.\d+", r"HDF5 1\.\d+\.\d+", r"METIS 5\.\d+\.\d+", r"yaml-cpp \d+\.\d+\.\d+"]
        st.check(len(lines) == len(expected) and all(re.fullmatch(e, ln) for e, ln in zip(expected, lines)),
                 f"{tag}: expected one line per library ({', '.join(expected)}), got {lines}")
        no_results(tag, cwd)

st.done()
