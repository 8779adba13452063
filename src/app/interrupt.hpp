// SIGTERM, SIGINT and SIGUSR1 (a batch system's walltime, Ctrl-C, a user's request) end a run
// cleanly: the handler only records the signal; the step loops agree on it at step boundaries
// (one allreduce per step), write the step, close the result file and exit with code 5.
#pragma once
#include <mpi.h>

namespace sinew {

/// Replaces PETSc's handlers for SIGTERM, SIGINT and SIGUSR1 (which abort) by one that records the
/// signal, and ignores SIGXFSZ so that a file-size limit (ulimit -f) becomes a write error.
void installInterruptHandlers();
/// Collective: the signal received by the lowest rank that received one, or 0.
int agreedInterrupt(MPI_Comm comm);
/// "SIGTERM", "SIGINT", "SIGUSR1".
const char* signalName(int sig);

}  // namespace sinew
