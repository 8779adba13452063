"""The test's side of inprocess_worker.py: one `mpirun -n N python3 inprocess_worker.py` per test and
rank count, started at the test's first in-process run and ended when the test ends. Requests go
through two named pipes in the work directory; the worker's own output goes to a log file there,
printed when the worker dies."""
import atexit
import errno
import fcntl
import json
import os
import select
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


class WorkerDied(RuntimeError):
    pass


class InProcessWorker:
    def __init__(self, mpiexec, nranks, env, work):
        tag = f"inprocess_{os.getpid()}_{nranks}"
        self.requests_path = os.path.join(work, tag + ".requests")
        self.replies_path = os.path.join(work, tag + ".replies")
        self.log_path = os.path.join(work, tag + ".log")
        for p in (self.requests_path, self.replies_path):
            if os.path.exists(p):
                os.remove(p)
            os.mkfifo(p)
        self.log = open(self.log_path, "w")
        self.proc = subprocess.Popen([mpiexec, "-n", str(nranks), sys.executable, os.path.join(HERE, "inprocess_worker.py"),
                                      self.requests_path, self.replies_path], env=env, stdout=self.log,
                                     stderr=subprocess.STDOUT)
        # replies: opened read-write, so that opening does not wait for the worker and reading never
        # sees end of file; a dead worker is noticed by polling its process
        self.replies = os.open(self.replies_path, os.O_RDWR | os.O_NONBLOCK)
        self.requests = self._open_requests()
        self.buffer = b""
        atexit.register(self.close)

    def _open_requests(self):
        while True:  # ENXIO until the worker's rank 0 has opened its end
            try:
                fd = os.open(self.requests_path, os.O_WRONLY | os.O_NONBLOCK)
            except OSError as e:
                if e.errno != errno.ENXIO:
                    raise
                self._check_alive()
                time.sleep(0.005)
                continue
            fcntl.fcntl(fd, fcntl.F_SETFL, fcntl.fcntl(fd, fcntl.F_GETFL) & ~os.O_NONBLOCK)
            return fd

    def _check_alive(self):
        if self.proc.poll() is not None:
            self.log.flush()
            with open(self.log_path) as f:
                text = f.read()
            raise WorkerDied(f"the in-process worker ended with exit code {self.proc.returncode}:\n{text}")

    def run(self, scene, args, timeout=900):
        """Runs the scene file with the command-line words args; returns (exit code, printed text)."""
        self._check_alive()
        os.write(self.requests, (json.dumps({"scene": scene, "args": list(args)}) + "\n").encode())
        end = time.monotonic() + timeout
        while b"\n" not in self.buffer:
            ready, _, _ = select.select([self.replies], [], [], 0.2)
            if ready:
                self.buffer += os.read(self.replies, 1 << 20)
            else:
                self._check_alive()
                if time.monotonic() > end:
                    self.proc.kill()
                    raise WorkerDied(f"the in-process run of {scene} took more than {timeout} s")
        line, self.buffer = self.buffer.split(b"\n", 1)
        reply = json.loads(line)
        return reply["exit"], reply["output"]

    def close(self):
        if self.proc.poll() is None:
            try:
                os.write(self.requests, b"\n")
                self.proc.wait(timeout=60)
            except (OSError, subprocess.TimeoutExpired):
                self.proc.kill()
                self.proc.wait()
        for fd in (self.requests, self.replies):
            try:
                os.close(fd)
            except OSError:
                pass
        self.log.close()
        if os.path.getsize(self.log_path) == 0:
            os.remove(self.log_path)
        for p in (self.requests_path, self.replies_path):
            if os.path.exists(p):
                os.remove(p)
