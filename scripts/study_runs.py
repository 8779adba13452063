#!/usr/bin/python3
"""One run of a scene with this tree's build/sinew (on one rank, or by mpirun), the command line and the
figures of the study scripts (study_right_angle.py, study_spinup.py, study_accuracy_reuse.py,
study_accuracy_time_reuse.py)."""
import argparse
import json
import os
import subprocess
import sys
import time

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_pml="ob1", OMPI_MCA_btl="self,vader")


def doc_flag(usage):
    """The command line of a study script: whether --doc (write the table and the figure into docs/) is given."""
    ap = argparse.ArgumentParser(description=usage, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--doc", action="store_true", help="write the table and the figure into docs/")
    return ap.parse_args().doc


def run_scene(work, name, yaml_text, args=()):
    """Writes the scene to work/name.yaml and runs it into work/name.h5; returns that path and the wall
    seconds of the run. Exits with the end of the run's output when it fails."""
    os.makedirs(work, exist_ok=True)
    yml, h5 = os.path.join(work, name + ".yaml"), os.path.join(work, name + ".h5")
    with open(yml, "w") as f:
        f.write(yaml_text)
    t0 = time.perf_counter()
    r = subprocess.run([os.path.join(SOURCE, "build", "sinew"), yml, "-o", h5, *args], env=ENV,
                       capture_output=True, text=True)
    if r.returncode:
        sys.exit(f"{name}: exit {r.returncode}\n{r.stdout[-2000:]}{r.stderr[-2000:]}")
    return h5, time.perf_counter() - t0


def run_mpi(work, tag, scene, args, env, np_=2):
    """Writes the scene (YAML text, or a dict as JSON) to work/tag.yaml and runs it on np_ ranks into
    work/tag.h5; returns that path, the wall seconds of mpirun and the run's output. Exits with the end of
    the output when the run fails."""
    path = os.path.join(work, tag + ".yaml")
    with open(path, "w") as f:
        f.write(scene if isinstance(scene, str) else json.dumps(scene, indent=1))
    h5 = os.path.join(work, tag + ".h5")
    t0 = time.time()
    p = subprocess.run(["mpirun", "-n", str(np_), os.path.join(SOURCE, "build", "sinew"), path, "-o", h5] + list(args),
                       env=env, capture_output=True, text=True)
    wall = time.time() - t0
    if p.returncode != 0:
        print(p.stdout[-3000:], p.stderr[-2000:])
        sys.exit(f"{tag}: exit {p.returncode}")
    return h5, wall, p.stdout


def save_figure(fig, png):
    """Saves the figure as docs/png."""
    fig.tight_layout()
    fig.savefig(os.path.join(SOURCE, "docs", png), dpi=110)


def label_axes(ax, ylabel, xlabel=None, legend=None):
    """The axis labels, a legend at the given place (none when None) and a light grid."""
    ax.set_ylabel(ylabel)
    if xlabel:
        ax.set_xlabel(xlabel)
    if legend:
        ax.legend(fontsize=8, loc=legend)
    ax.grid(alpha=0.3)
