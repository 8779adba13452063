#include "app/interrupt.hpp"

#include <climits>
#include <csignal>

namespace sinew {

namespace {
volatile std::sig_atomic_t received = 0;

extern "C" void recordSignal(int sig) {
  if (!received) received = sig;
}
}  // namespace

void installInterruptHandlers() {
  struct sigaction sa {};
  sa.sa_handler = recordSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;  // system calls (MPI progress, file I/O) go on
  for (int sig : {SIGTERM, SIGINT, SIGUSR1}) sigaction(sig, &sa, nullptr);
  std::signal(SIGXFSZ, SIG_IGN);
}

int agreedInterrupt(MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int mine[2] = {received ? -rank : INT_MIN, static_cast<int>(received)}, first[2];
  MPI_Allreduce(mine, first, 1, MPI_2INT, MPI_MAXLOC, comm);
  return first[0] == INT_MIN ? 0 : first[1];  // MAXLOC carries the signal of that rank
}

const char* signalName(int sig) {
  switch (sig) {
    case SIGTERM: return "SIGTERM";
    case SIGINT: return "SIGINT";
    case SIGUSR1: return "SIGUSR1";
    default: return "a signal";
  }
}

}  // namespace sinew
