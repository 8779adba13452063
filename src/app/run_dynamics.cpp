#include "app/run_context.hpp"

namespace sinew {

PetscErrorCode runDynamics(RunContext& ctx) {
  PetscFunctionBeginUser;
  ctx.converged = false;
  ctx.failure = "opt.dynamics: time integration is unavailable in this build";
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
