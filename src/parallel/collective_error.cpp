#include "parallel/collective_error.hpp"

#include <chrono>
#include <climits>
#include <cstdio>
#include <thread>

namespace sinew {
namespace {

RunFailure gFailure;
const char* gPhase = "set-up";

struct HandlerState {
  MPI_Comm comm = MPI_COMM_NULL;  // private duplicate: the failing ranks' barrier matches nothing else
  int size = 1;
  double waitSeconds = 5.0;
};
HandlerState gHandler;

std::string trimmed(const char* s) {
  std::string t = s ? s : "";
  while (!t.empty() && (t.back() == '\n' || t.back() == ' ')) t.pop_back();
  while (!t.empty() && t.front() == ' ') t.erase(t.begin());
  return t;
}

/// True when every rank of the run reaches this point within the wait (each failed too).
bool allRanksFailed() {
  MPI_Request req;
  if (MPI_Ibarrier(gHandler.comm, &req) != MPI_SUCCESS) return false;
  const auto t0 = std::chrono::steady_clock::now();
  for (;;) {
    int done = 0;
    MPI_Test(&req, &done, MPI_STATUS_IGNORE);
    if (done) return true;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > gHandler.waitSeconds) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

// PETSc calls this at the origin of every error (PETSC_ERROR_INITIAL) and again in every frame the
// error passes (PETSC_ERROR_REPEAT). Only the first error of the run is recorded; nothing is
// printed here (the runner prints the message once on rank 0).
PetscErrorCode solverErrorHandler(MPI_Comm, int, const char* fun, const char*, PetscErrorCode n, PetscErrorType p,
                                  const char* mess, void*) {
  if (p != PETSC_ERROR_INITIAL || gFailure) return n;
  std::string text = trimmed(mess);
  if (text.empty()) {
    const char* generic = nullptr;
    PetscErrorMessage(n, &generic, nullptr);
    text = trimmed(generic);
  }
  gFailure.exitCode = kExitSolverError;
  gFailure.message = std::string("error: internal solver error in ") + gPhase + ": " + text + " (PETSc error " +
                     std::to_string(static_cast<int>(n)) + " in " + (fun ? fun : "?") +
                     "); check the PETSc/SLEPc solver flags given (-ksp_*, -pc_*, -snes_*, -eps_*, -st_*)";
  if (gHandler.size == 1 || gHandler.comm == MPI_COMM_NULL || allRanksFailed()) return n;
  // The other ranks wait inside a collective operation for this one: no message can reach them.
  std::printf("%s\n", gFailure.message.c_str());
  std::fflush(stdout);
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, kExitSolverError);
  return n;
}

}  // namespace

RunFailure agreeOnFailure(MPI_Comm comm, const RunFailure& local, long key) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  if (key < 0) key = rank;
  long k = local ? key : LONG_MAX;
  MPI_Allreduce(MPI_IN_PLACE, &k, 1, MPI_LONG, MPI_MIN, comm);
  if (k == LONG_MAX) return {};
  int lowest = local && key == k ? rank : size;
  MPI_Allreduce(MPI_IN_PLACE, &lowest, 1, MPI_INT, MPI_MIN, comm);
  RunFailure f = local;
  long len = static_cast<long>(local.message.size());
  MPI_Bcast(&f.exitCode, 1, MPI_INT, lowest, comm);
  MPI_Bcast(&len, 1, MPI_LONG, lowest, comm);
  f.message.resize(static_cast<size_t>(len));
  if (len > 0) MPI_Bcast(f.message.data(), static_cast<int>(len), MPI_CHAR, lowest, comm);
  return f;
}

PetscErrorCode raiseCollective(MPI_Comm comm, const RunFailure& f) {
  gFailure = f;  // recorded first: the handler then leaves this error alone
  return PetscError(comm, __LINE__, PETSC_FUNCTION_NAME, __FILE__, PETSC_ERR_USER, PETSC_ERROR_INITIAL, "%s",
                    f.message.c_str());
}

const RunFailure& recordedFailure() { return gFailure; }
void clearRecordedFailure() { gFailure = RunFailure{}; }

const char* currentPhase() { return gPhase; }
PhaseScope::PhaseScope(const char* phase) : previous_(gPhase) { gPhase = phase; }
PhaseScope::~PhaseScope() { gPhase = previous_; }

SolverErrorGuard::SolverErrorGuard(MPI_Comm comm, double waitSeconds) {
  MPI_Comm_dup(comm, &gHandler.comm);
  MPI_Comm_size(comm, &gHandler.size);
  gHandler.waitSeconds = waitSeconds;
  clearRecordedFailure();
  PetscPushErrorHandler(solverErrorHandler, nullptr);
}

SolverErrorGuard::~SolverErrorGuard() {
  PetscPopErrorHandler();
  MPI_Comm_free(&gHandler.comm);
  gHandler = HandlerState{};
}

}  // namespace sinew
