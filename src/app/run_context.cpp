#include "app/run_context.hpp"

namespace sinew {

PetscErrorCode RunContext::writeStep(double stepValue, Vec Ustate, const LoadState& ls) {
  PetscFunctionBeginUser;
  const double tOut = MPI_Wtime();
  file.beginStep(nextStep++, stepValue);
  PetscCall(results.write(file, Ustate, ls));
  times.output += MPI_Wtime() - tOut;
  for (auto& a : stepAnalyses) {
    const double ta = MPI_Wtime();
    bool ok = true;
    PetscCall(a->atStep(Ustate, ls, file, &ok));
    times.analyses += MPI_Wtime() - ta;
    if (!ok && converged) {
      converged = false;
      failure = a->failure();
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
