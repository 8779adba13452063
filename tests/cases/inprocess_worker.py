#!/usr/bin/python3
"""The system tests' in-process runner: `mpirun -n N python3 inprocess_worker.py REQUESTS REPLIES`
starts one Python process per rank that runs scenes through sinew._core (the library entry the
command line shares: the same SceneRun, the same result file) until told to stop. A test that runs
many scenes on 2 ranks pays mpirun's and PETSc's start once instead of once per scene
(sinewtest.run; DEVELOPERS.md, "Build and test").

REQUESTS and REPLIES are named pipes made by the test (sinewtest.InProcessWorker). Rank 0 reads one
JSON request per line, {"scene": path, "args": [words]}, every rank runs it, and rank 0 answers
{"exit": code, "output": text}: the exit code the command line would end with and the text it
would print. An empty line or end of file ends the worker."""
import json
import os
import sys
import time

from mpi4py import MPI

# the compiled module alone (<build>/python/sinew/_core of $SINEW_BIN): the package's numpy and h5py
# imports would double the worker's start
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(os.environ["SINEW_BIN"])), "python"))
from sinew import _core as core  # noqa: E402


def serve(requests, replies):
    comm = MPI.COMM_WORLD
    rank = comm.Get_rank()
    core.initialize([])
    while True:
        line = requests.readline() if rank == 0 else None
        # the other ranks wait for the next request asleep, not spinning in MPI_Bcast on a core the
        # test's own process needs meanwhile
        waiting = comm.Ibarrier()
        while not waiting.Test():
            time.sleep(0.0005)
        job = comm.bcast(json.loads(line) if line and line.strip() else None, root=0)
        if job is None:
            return
        run = core.run(job["scene"], flags=job["args"], echo=False)
        if rank == 0:
            text = run["output"] or ""
            if run["exit_code"] != 0 and run["message"] and run["message"] not in text:
                text += run["message"] + "\n"
            replies.write(json.dumps({"exit": run["exit_code"], "output": text}) + "\n")
            replies.flush()


def main():
    rank = MPI.COMM_WORLD.Get_rank()
    # opening a pipe blocks until the other end opens it: the test opens REQUESTS for writing first
    requests = open(sys.argv[1]) if rank == 0 else None
    replies = open(sys.argv[2], "w") if rank == 0 else None
    try:
        serve(requests, replies)
        core.finalize()  # PETSc/SLEPc end before mpi4py ends MPI
    finally:
        if rank == 0:
            requests.close()
            replies.close()


if __name__ == "__main__":
    main()
