// Sinew's default linear solver: a direct LU factorization with MUMPS (any -<prefix>ksp_type /
// -<prefix>pc_type given by the user overrides it when the KSP is set from options afterwards).
#pragma once
#include <petscksp.h>

#include "mesh/distributed_mesh.hpp"
#include "sinew/petsc_compat.hpp"

namespace sinew {

/// Newton has converged on its update: the relative update below `tight`, or below `loose` and no
/// longer shrinking tenfold (round-off has ended quadratic convergence).
inline bool updateConverged(double rel, double relPrev, double tight, double loose) {
  return rel <= tight || (rel <= loose && rel > 0.1 * relPrev);
}

inline PetscErrorCode useDirectSolver(KSP ksp) {
  PetscFunctionBeginUser;
  PC pc;
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCLU));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// The default direct solver for a model's tangent. An ANCF-only model on one process (chains of
/// cable elements, no multipliers, symmetric positive tangents in statics) is factored with PETSc's
/// own LU in nested-dissection order: the chain's elimination tree has thousands of tiny fronts,
/// where MUMPS spends its time in per-front overhead (A1 with 16384 elements, 65538 unknowns:
/// factorization 8 ms and solve 1 ms against 50 ms and 10 ms with MUMPS). PETSc's LU does not
/// pivot: zero pivots are shifted (the static solver wraps it in GMRES on the exact operator, and
/// the constraint check factors a diagonally shifted tangent). Everything else: MUMPS.
inline PetscErrorCode useDirectSolver(KSP ksp, const DistributedMesh& mesh) {
  PetscFunctionBeginUser;
  PetscCall(useDirectSolver(ksp));
  int size = 1;
  MPI_Comm_size(mesh.comm, &size);
  int chain = size == 1 && mesh.anyAncf;
  for (const LocalNode& n : mesh.nodes) chain = chain && n.kind == NodeKind::Ancf2D;
  for (const LocalElement& e : mesh.elements) chain = chain && e.firstMultiplier < 0;
  if (!chain) PetscFunctionReturn(PETSC_SUCCESS);
  PC pc;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERPETSC));
  PetscCall(PCFactorSetMatOrderingType(pc, MATORDERINGND));
  // no pivoting: a zero pivot (a wild Newton iterate) is shifted instead of failing the solve
  PetscCall(PCFactorSetShiftType(pc, MAT_SHIFT_NONZERO));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
