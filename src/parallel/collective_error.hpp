// Errors found on some ranks only, made known to every rank.
// - agreeOnFailure: at a phase boundary every rank passes what it found (exit code 0: nothing);
//   every rank gets the failure of the lowest failing rank.
// - raiseCollective: an error every rank has agreed on, turned into a PETSc error that all ranks
//   return together (so PETSc objects and the result file are released collectively), with the
//   exit code and message the run ends with.
// - SolverErrorGuard: a PETSc error handler for errors PETSc/SLEPc/MUMPS raise on their own. It names
//   the current phase (PhaseScope); when only some ranks fail while the others wait inside a
//   collective, those cannot be reached any more: after a short wait the failing rank prints the
//   message and ends the job with MPI_Abort(4).
// - SinewCallThrow: in constructors of analyses (no PetscErrorCode to return), a failing PETSc call
//   throws SolverCallError; runFromCommandLine catches it and reports the recorded failure.
#pragma once
#include <mpi.h>
#include <petscsys.h>

#include <stdexcept>
#include <string>

#include "sinew/petsc_compat.hpp"

namespace sinew {

/// Exit code of an internal solver error (a PETSc/SLEPc/MUMPS error caught collectively).
inline constexpr int kExitSolverError = 4;

struct RunFailure {
  int exitCode = 0;     ///< 0: no failure
  std::string message;  ///< full message, starting with "error: "
  explicit operator bool() const { return exitCode != 0; }
};

/// Collective: every rank passes its local failure (exitCode 0 when none). Returns, on every rank,
/// the failure with the lowest key (e.g. the global element index, so that the message does not
/// depend on the partition; ties and key < 0: the lowest failing rank), exitCode 0 when no rank failed.
RunFailure agreeOnFailure(MPI_Comm comm, const RunFailure& local, long key = -1);

/// Collective, with `f` the same on every rank (after agreeOnFailure): records f as the failure the
/// run ends with and returns a PETSc error code for every rank to propagate (PetscCall).
PetscErrorCode raiseCollective(MPI_Comm comm, const RunFailure& f);

/// The failure recorded by raiseCollective or by the solver error handler (exitCode 0: none).
const RunFailure& recordedFailure();
void clearRecordedFailure();

/// Name of the phase that runs ("set-up", "statics", "frequencies", ...), for solver error messages.
const char* currentPhase();
class PhaseScope {
 public:
  explicit PhaseScope(const char* phase);
  ~PhaseScope();
  PhaseScope(const PhaseScope&) = delete;
  PhaseScope& operator=(const PhaseScope&) = delete;

 private:
  const char* previous_;
};

/// A failing PETSc call where no error code can be returned (constructors): the error is recorded
/// by the solver error handler; this carries PETSc's code up to runFromCommandLine.
class SolverCallError : public std::runtime_error {
 public:
  explicit SolverCallError(PetscErrorCode code)
      : std::runtime_error("PETSc error " + std::to_string(static_cast<int>(code))), code_(code) {}
  PetscErrorCode code() const { return code_; }

 private:
  PetscErrorCode code_;
};

/// Like PetscCallAbort(comm, call), but throws SolverCallError instead of MPI_Abort (comm unused: the
/// error handler decides whether the other ranks can still be reached).
#define SinewCallThrow(comm, ...)                                                                             \
  do {                                                                                                        \
    (void)(comm);                                                                                             \
    const PetscErrorCode sinew_ierr_ = __VA_ARGS__;                                                           \
    if (PetscUnlikely(sinew_ierr_)) {                                                                         \
      PetscError(PETSC_COMM_SELF, __LINE__, PETSC_FUNCTION_NAME, __FILE__, sinew_ierr_, PETSC_ERROR_REPEAT, " "); \
      throw ::sinew::SolverCallError(sinew_ierr_);                                                            \
    }                                                                                                         \
  } while (0)

/// Installs the solver error handler for its lifetime (PetscPushErrorHandler / PetscPopErrorHandler).
/// waitSeconds: how long a failing rank waits for the other ranks to fail too before it aborts.
class SolverErrorGuard {
 public:
  SolverErrorGuard(MPI_Comm comm, double waitSeconds);
  ~SolverErrorGuard();
  SolverErrorGuard(const SolverErrorGuard&) = delete;
  SolverErrorGuard& operator=(const SolverErrorGuard&) = delete;
};

}  // namespace sinew
