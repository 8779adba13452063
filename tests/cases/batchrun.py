"""Helpers for the batch-run tests: start sinew under mpirun in the background, read its stdout
line by line with arrival times, find the rank processes, and open a (possibly partial) result."""
import os
import subprocess
import threading
import time

import h5py

from sinewtest import BIN, ENV, MPIEXEC, SOURCE, WORK

CROSSHINGE = os.path.join(SOURCE, "runs", "crosshinge.yaml")


class Run:
    """sinew on `scene` with `np_` ranks in the background; .lines holds (seconds since start, line)."""

    def __init__(self, scene, out, args=(), np_=2, env=None):
        self.out = out
        self.cmd = [MPIEXEC, "-n", str(np_), BIN, scene, "-o", out] + list(args)
        self.start = time.monotonic()
        self.proc = subprocess.Popen(self.cmd, env=env or ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                     text=True, bufsize=1)
        self.lines = []
        self.rank_pids = []
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        for line in self.proc.stdout:
            self.lines.append((time.monotonic() - self.start, line.rstrip("\n")))

    def steps_printed(self, word="load step"):
        return sum(1 for _, l in self.lines if l.lstrip().startswith(word + " "))

    def wait_for_steps(self, n, timeout=300, word="load step"):
        end = time.monotonic() + timeout
        while time.monotonic() < end and self.proc.poll() is None:
            if self.steps_printed(word) >= n:
                return True
            time.sleep(0.05)
        return self.steps_printed(word) >= n

    def ranks(self):
        """Pids of the sinew processes started by this mpirun."""
        out = subprocess.run(["pgrep", "-P", str(self.proc.pid)], stdout=subprocess.PIPE, text=True).stdout
        self.rank_pids = [int(p) for p in out.split()]
        return self.rank_pids

    def wait(self, timeout=600):
        """mpirun's exit code, once the rank processes asked for by ranks() have exited too: a rank killed
        together with mpirun is left to the kernel and holds its files (and the result's lock) until it has
        died, which on a loaded machine can come after mpirun's own end."""
        end = time.monotonic() + timeout
        code = self.proc.wait(timeout=timeout)
        self.reader.join(timeout=10)
        while time.monotonic() < end and not all(_exited(pid) for pid in self.rank_pids):
            time.sleep(0.02)
        return code

    def text(self):
        return "\n".join(l for _, l in self.lines)


def _exited(pid):
    """Whether the process has ended: gone, or a zombie (its files, and so its locks, released)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] in ("Z", "X")
    except (FileNotFoundError, ProcessLookupError, IndexError):
        return True


def remove_outputs(out):
    for suffix in ("", ".part", ".part2", ".lock"):
        if os.path.exists(out + suffix):
            os.remove(out + suffix)
    xdmf = os.path.splitext(out)[0] + ".xdmf"
    if os.path.exists(xdmf):
        os.remove(xdmf)


def read_result(path):
    """(converged attribute, number of steps) of a result file; raises if h5py cannot open it."""
    with h5py.File(path, "r") as f:
        steps = f["load_factor"].shape[0] if "load_factor" in f else (f["time"].shape[0] if "time" in f else 0)
        return int(f.attrs["converged"]), steps


def work(name):
    os.makedirs(WORK, exist_ok=True)
    return os.path.join(WORK, name)
