// Sinew's default linear solver: a direct LU factorization with MUMPS (any -<prefix>ksp_type /
// -<prefix>pc_type given by the user overrides it when the KSP is set from options afterwards).
#pragma once
#include <petscksp.h>

#include "sinew/petsc_compat.hpp"

namespace sinew {

inline PetscErrorCode useDirectSolver(KSP ksp) {
  PetscFunctionBeginUser;
  PC pc;
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCLU));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
