#include "app/run_context.hpp"

namespace sinew {

PetscErrorCode addStepAnalyses(RunContext& /*ctx*/) {
  PetscFunctionBeginUser;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
