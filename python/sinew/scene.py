"""A Sinew scene in Python: read (YAML or a SPACAR Light script), change, write, run.

    sim = sinew.Scene.from_yaml("runs/crosshinge.yaml")
    sim.opt["loadsteps"] = 5
    out = sim.run()                      # a sinew.Results (SPACAR Light's `out`)
    out = sim.run(np=2, flags=["-calcbuck", "true"])

run() starts the sinew executable (mpirun -n np when np > 1) on the scene and reads its result
file; a scene error or a failed run raises SinewError with Sinew's message and exit code; a run
that did not converge returns its converged steps with out.converged == False (raises with
check=True)."""
import copy
import os
import shutil
import subprocess
import tempfile

import yaml

from .results import load


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

    def run(self, np=1, flags=(), output=None, check=False, keep_files=False, quiet=True):
        """Runs the scene; returns a Results object. output: result file to keep (default: a
        temporary file, removed unless keep_files). flags: extra command-line flags."""
        work = tempfile.mkdtemp(prefix="sinew_")
        scene_path = os.path.join(self.base_dir if os.access(self.base_dir, os.W_OK) else work,
                                  f".sinew_scene_{os.getpid()}_{id(self)}.yaml")
        out = output or os.path.join(work, "result.h5")
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
