#include "app/run_context.hpp"

namespace sinew {

PetscErrorCode runFormFinding(RunContext& ctx) {
  PetscFunctionBeginUser;
  ctx.converged = false;
  ctx.failure = "formfinding: form finding is unavailable in this build";
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
