"""A Sinew scene in Python: read (YAML or a SPACAR Light script), change, write, run.

    sim = sinew.Scene.from_yaml("runs/crosshinge.yaml")
    sim.opt["loadsteps"] = 5
    out = sim.run()                      # a sinew.Results (SPACAR Light's `out`)
    out = sim.run(np=2, flags=["-calcbuck", "true"])

run() runs the scene in this process through Sinew's library (the module sinew._core: no process
start, no file), on the ranks of `comm` (an mpi4py communicator; default all ranks of the job, so
that `mpirun -n 2 python3 study.py` runs every scene on 2 ranks). run(process=True), or np > 1 asked
from a one-rank interpreter, starts the sinew executable instead (mpirun -n np) and reads its result
file. Either way a scene error or a failed run raises SinewError with Sinew's message and exit code;
a run that did not converge returns its converged steps with out.converged == False (raises with
check=True)."""
import atexit
import copy
import os
import shutil
import subprocess
import tempfile

import yaml

from .results import from_memory, load


class SinewError(RuntimeError):
    """Sinew refused the scene or the run failed: `message` is Sinew's error line(s), `exit_code` its
    documented exit status (2 scene or flag error, 3 not converged, 4 solver error, 5 interrupted)."""

    def __init__(self, message, exit_code, output=""):
        super().__init__(message)
        self.message, self.exit_code, self.output = message, exit_code, output


def find_binary():
    """The sinew executable: $SINEW_BIN, the build tree next to this package (python/sinew ->
    build/sinew), the installed prefix (<prefix>/bin/sinew), then PATH."""
    if os.environ.get("SINEW_BIN"):
        return os.environ["SINEW_BIN"]
    here = os.path.dirname(os.path.abspath(__file__))
    for cand in (os.path.join(here, "..", "..", "build", "sinew"),
                 os.path.join(here, "..", "..", "..", "..", "bin", "sinew")):
        if os.access(cand, os.X_OK):
            return os.path.normpath(cand)
    found = shutil.which("sinew")
    if not found:
        raise SinewError("no sinew executable found: set SINEW_BIN, build it (scripts/test) or install it", 127)
    return found


def core():
    """The in-process entry point sinew._core, or None when it was not built (python/sinew/__init__.py
    says where it is looked for). PETSc/SLEPc end at interpreter exit, before mpi4py ends MPI."""
    global _core_module
    if _core_module is None:
        try:
            from . import _core
        except ImportError:
            _core_module = False
        else:
            atexit.register(_core.finalize)
            _core_module = _core
    return _core_module or None


_core_module = None


def _comm_size(comm):
    if comm is not None:
        return comm.Get_size()
    for var in ("OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "SLURM_NTASKS"):
        if os.environ.get(var):
            return int(os.environ[var])
    return 1


def _raise_or_accept(message, code, output, check):
    """SinewError unless the run converged or (check False) it failed after converged steps."""
    if code not in (0, 3) or (code == 3 and check):
        errors = [ln[len("error: "):] if ln.startswith("error: ") else ln for ln in message.splitlines()]
        raise SinewError("\n".join(errors) or f"sinew ended with exit {code}", code, output)


def _yaml_text(data):
    def clean(o):
        if isinstance(o, dict):
            return {k: clean(v) for k, v in o.items()}
        if isinstance(o, (list, tuple)):
            return [clean(v) for v in o]
        if hasattr(o, "tolist"):
            return o.tolist()
        return o
    return yaml.safe_dump(clean(data), sort_keys=False, default_flow_style=None, width=110)


class Scene:
    """A scene as its YAML data (dict): nodes, elements, nprops (node number -> fields), eprops (a
    list of sets), opt, and the other blocks of docs/scene.md. `base_dir`: where relative paths in
    the scene (mesh:) are read from."""

    def __init__(self, data, base_dir="."):
        self.data = data
        self.base_dir = base_dir
        self.data.setdefault("opt", {})

    @classmethod
    def from_yaml(cls, path):
        with open(path) as f:
            data = yaml.safe_load(f)
        if not isinstance(data, dict):
            raise SinewError(f"{path}: not a scene (a YAML map with nodes, elements, ...)", 2)
        return cls(data, os.path.dirname(os.path.abspath(path)))

    @classmethod
    def from_spacar(cls, path):
        from .spacar import convert
        with open(path) as f:
            text = f.read()
        return cls(convert(text, os.path.splitext(os.path.basename(path))[0]), os.path.dirname(os.path.abspath(path)))

    @property
    def opt(self):
        return self.data["opt"]

    def copy(self):
        return Scene(copy.deepcopy(self.data), self.base_dir)

    def to_yaml(self):
        return _yaml_text(self.data)

    def write(self, path):
        with open(path, "w") as f:
            f.write(self.to_yaml())
        return path

    def run(self, np=1, flags=(), output=None, check=False, keep_files=False, quiet=True, process=None, comm=None):
        """Runs the scene; returns a Results object. flags: extra command-line flags (a list of words
        or a dict {flag: value}). output: result file to write (in-process: written only when given;
        process: default a temporary file, removed unless keep_files). quiet=False prints Sinew's
        output. process: True starts the sinew executable (np ranks); None (default) runs in this
        process on comm's ranks unless np > 1 is asked from a one-rank interpreter."""
        if process is None:
            process = core() is None or (np > 1 and _comm_size(comm) == 1)
        if not process:
            return self._run_in_process(flags, output, check, quiet, comm)
        if isinstance(flags, dict):
            flags = [w for k, v in flags.items() for w in (f"-{k.lstrip('-')}", _flag_word(v))]
        return self._run_process(np, flags, output, check, keep_files, quiet)

    def _run_in_process(self, flags, output, check, quiet, comm):
        if output:
            output = os.path.abspath(output)
            flags = dict(flags, o=output) if isinstance(flags, dict) else list(flags) + ["-o", output]
        run = core().run(self.data, flags=flags if isinstance(flags, dict) else [str(f) for f in flags], comm=comm,
                         echo=not quiet, base_dir=self.base_dir)
        if run["datasets"] is None and not run["file"]:  # no results: a scene, flag, model or solver error
            _raise_or_accept(run["message"], run["exit_code"], run["output"], True)
        _raise_or_accept(run["message"], run["exit_code"], run["output"], check)
        return load(run["file"]) if run["file"] else from_memory(run)

    def _run_process(self, np, flags, output, check, keep_files, quiet):
        work = tempfile.mkdtemp(prefix="sinew_")
        scene_path = os.path.join(self.base_dir if os.access(self.base_dir, os.W_OK) else work,
                                  f".sinew_scene_{os.getpid()}_{id(self)}.yaml")
        out = os.path.abspath(output) if output else os.path.join(work, "result.h5")
        try:
            self.write(scene_path)
            cmd = [find_binary(), scene_path, "-o", out] + [str(f) for f in flags]
            if np > 1:
                cmd = [os.environ.get("SINEW_MPIEXEC", "mpirun"), "-n", str(np)] + cmd
            env = dict(os.environ)
            env.setdefault("OMPI_MCA_pml", "ob1")
            env.setdefault("OMPI_MCA_btl", "self,vader")
            p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env,
                               cwd=self.base_dir)
            if not quiet:
                print(p.stdout, end="")
            errors = [ln[len("error: "):] if ln.startswith("error: ") else ln
                      for ln in p.stdout.splitlines() if ln.startswith("error")]
            if p.returncode not in (0, 3) or (p.returncode == 3 and check) or not os.path.exists(out):
                last = p.stdout.strip().splitlines()[-1:]
                message = "\n".join(errors) or (last[0] if last else f"sinew ended with exit {p.returncode}")
                raise SinewError(message, p.returncode, p.stdout)
            return load(out)
        finally:
            if os.path.exists(scene_path):
                os.remove(scene_path)
            if not keep_files:
                shutil.rmtree(work, ignore_errors=True)


def _flag_word(v):
    """A flag value as a command-line word: true/false, comma lists."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (list, tuple)) or hasattr(v, "tolist"):
        v = v.tolist() if hasattr(v, "tolist") else v
        return ",".join(_flag_word(x) for x in v)
    return str(v)
