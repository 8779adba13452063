// Sinew's default linear solver: a direct LU factorization with MUMPS (any -<prefix>ksp_type /
// -<prefix>pc_type given by the user overrides it when the KSP is set from options afterwards).
#pragma once
#include <petscksp.h>

#include <string>

#include "assembly/assembler.hpp"
#include "mesh/distributed_mesh.hpp"
#include "solvers/dense_lu.hpp"
#include "settings/settings.hpp"
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

/// PETSc's own sequential LU without pivoting: a zero pivot (a wild Newton iterate) is shifted
/// instead of failing the solve. For one-process models whose matrices need no pivoting (see below
/// and DynamicAnalysis::useDynamicsSolver). Ordering: nested dissection, or `ordering`.
inline PetscErrorCode usePetscLU(KSP ksp, MatOrderingType ordering = MATORDERINGND) {
  PetscFunctionBeginUser;
  PC pc;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERPETSC));
  PetscCall(PCFactorSetMatOrderingType(pc, ordering));
  PetscCall(PCFactorSetShiftType(pc, MAT_SHIFT_NONZERO));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// A chain of ANCF cable elements: every node an ANCF node, no multipliers (on every rank). Collective.
inline bool ancfChain(const DistributedMesh& mesh) {
  int chain = mesh.anyAncf;
  for (const LocalNode& n : mesh.nodes) chain = chain && n.kind == NodeKind::Ancf2D;
  for (const LocalElement& e : mesh.elements) chain = chain && e.firstMultiplier < 0;
  MPI_Allreduce(MPI_IN_PLACE, &chain, 1, MPI_INT, MPI_LAND, mesh.comm);
  return chain != 0;
}

/// The LU of an ANCF chain's time-step matrix (DynamicAnalysis): PETSc's LU (usePetscLU) in reverse
/// Cuthill-McKee order, which keeps a chain's band (A1g at 65536 elements, 262145 unknowns, one
/// process: factorization 35 ms and solve 4.2 ms against 61 ms and 6.6 ms in nested-dissection order).
/// On several processes every process factors the whole matrix (PCREDUNDANT; options prefix
/// redundant_): the chain's elimination tree is one path, which MUMPS neither orders nor
/// distributes well (A1g, 65537 unknowns, 2 ranks: factorization 100 ms and solve 30 ms with MUMPS,
/// whatever its ordering, ICNTL(7) = 0..6 or PT-Scotch / ParMETIS; 12 ms and 2 ms here). Each process
/// then holds the whole matrix and its factors (docs/performance.md, Dynamics).
inline PetscErrorCode useChainLU(KSP ksp, MPI_Comm comm) {
  PetscFunctionBeginUser;
  int size = 1;
  MPI_Comm_size(comm, &size);
  KSP lu = ksp;  // one process: this KSP; several: the redundant preconditioner's own
  PC pc;
  if (size > 1) {
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCSetType(pc, PCREDUNDANT));
    PetscCall(PCRedundantGetKSP(pc, &lu));
  }
  PetscCall(KSPSetType(lu, KSPPREONLY));
  PetscCall(KSPGetPC(lu, &pc));
  PetscCall(PCSetType(pc, PCLU));
  PetscCall(usePetscLU(lu, MATORDERINGRCM));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// The dense LU of a small matrix on every process of the KSP's communicator: PCREDUNDANT (options
/// prefix redundant_) gathers the whole matrix on each process, which factors it with PCDENSELU.
inline PetscErrorCode useRedundantDenseLU(KSP ksp) {
  PetscFunctionBeginUser;
  PC pc;
  KSP inner;
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCREDUNDANT));
  PetscCall(PCRedundantGetKSP(pc, &inner));
  PetscCall(useDenseLU(inner));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// Whether the small-model dense LU applies: one process and at most denseMaxUnknowns unknowns.
inline bool useDenseTangentLU(const DistributedMesh& mesh, int denseMaxUnknowns) {
  return mesh.size == 1 && mesh.numGlobalUnknowns <= static_cast<long>(denseMaxUnknowns);
}

/// The default direct solver for a model's tangent. An ANCF-only model on one process (chains of
/// cable elements, no multipliers, symmetric positive tangents in statics) is factored with PETSc's
/// own LU in nested-dissection order: the chain's elimination tree has thousands of tiny fronts,
/// where MUMPS spends its time in per-front overhead (A1 with 16384 elements, 65538 unknowns:
/// factorization 8 ms and solve 1 ms against 50 ms and 10 ms with MUMPS). PETSc's LU does not
/// pivot: zero pivots are shifted (the static solver wraps it in GMRES on the exact operator, and
/// the constraint check factors a diagonally shifted tangent). On several processes the same LU on
/// every process, in reverse Cuthill-McKee order (useChainLU: MUMPS orders and distributes a chain
/// badly). Everything else: MUMPS.
inline PetscErrorCode useDirectSolver(KSP ksp, const DistributedMesh& mesh) {
  PetscFunctionBeginUser;
  PetscCall(useDirectSolver(ksp));
  if (!ancfChain(mesh)) PetscFunctionReturn(PETSC_SUCCESS);
  int size = 1;
  MPI_Comm_size(mesh.comm, &size);
  if (size == 1) PetscCall(usePetscLU(ksp));
  else PetscCall(useChainLU(ksp, mesh.comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// The direct solver of a tangent solved many times in small designs (statics Newton, compliance,
/// constraint check): a model with at most `denseMaxUnknowns` unknowns (-dense_max_unknowns) is
/// factored dense with LAPACK (useDenseLU: getrf with partial pivoting, PC type denselu; on several
/// processes every process factors the whole matrix, useRedundantDenseLU; an ANCF chain keeps its
/// chain LU), where MUMPS's fixed cost per call dominates (66 unknowns: docs/performance.md,
/// "Designs from Python"); otherwise useDirectSolver(ksp, mesh). Collective.
inline PetscErrorCode useDirectSolver(KSP ksp, const DistributedMesh& mesh, int denseMaxUnknowns) {
  PetscFunctionBeginUser;
  if (useDenseTangentLU(mesh, denseMaxUnknowns)) PetscCall(useDenseLU(ksp));
  else if (mesh.numGlobalUnknowns <= static_cast<long>(denseMaxUnknowns) && !ancfChain(mesh)) PetscCall(useRedundantDenseLU(ksp));
  else PetscCall(useDirectSolver(ksp, mesh));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// -eigen_operator auto|elementwise|assembled: how the eigenvalue analyses apply the stiffness.
/// elementwise (auto: whenever the model allows it, Assembler::elementwiseTangentAvailable, and has no
/// multipliers of rigid elements or modes): the
/// element-wise rigid-motion-free products of Assembler::applyTangent(x, y, true), with inner GMRES
/// solves preconditioned by the LU of the assembled matrix (docs/modal.md, "Eigenvalues on fine
/// meshes"); assembled: the assembled matrix and its LU alone. Collective.
inline PetscErrorCode eigenOperator(Assembler& assembler, OperatorChoice c, bool* elementwise, bool withMultipliers = false) {
  PetscFunctionBeginUser;
  MPI_Comm comm = assembler.mesh().comm;
  const bool available = assembler.elementwiseTangentAvailable();
  if (c == OperatorChoice::Elementwise && !available)
    SETERRQ(comm, PETSC_ERR_ARG_INCOMP, "-eigen_operator elementwise: not available for models with cables or surface pressure");
  // auto with multipliers (rigid elements/modes): the frequency analysis (withMultipliers) uses the
  // element-wise operator once it is made symmetric as the assembled tangent (ModalAnalysis::Kskew_;
  // before, a loaded crosshinge's frequencies differed by 2e-6 between rank counts); the buckling
  // analysis keeps the assembled operator for them (not measured on such models)
  int multipliers = 0;
  for (const LocalElement& e : assembler.mesh().elements) multipliers |= e.firstMultiplier >= 0;
  MPI_Allreduce(MPI_IN_PLACE, &multipliers, 1, MPI_INT, MPI_LOR, comm);
  *elementwise = available && (c == OperatorChoice::Elementwise ||
                               (c == OperatorChoice::Auto && (withMultipliers || !multipliers)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// The inner solver of shift-and-invert with the element-wise operator: GMRES (right preconditioned,
/// so it measures the true residual) with the LU of the assembled shifted matrix (set by
/// STSetPreconditionerMat). It stops at rtol 1e-12 or where the residual stagnates at the round-off
/// of the element-wise products (less than halved in an iteration), never with a failure.
struct InnerSolveContext {
  void* defaultCtx = nullptr;  // KSPConvergedDefault's
  PetscReal previous = 0;
};

inline PetscErrorCode innerConverged(KSP ksp, PetscInt it, PetscReal rnorm, KSPConvergedReason* reason, void* ctx) {
  PetscFunctionBeginUser;
  auto* c = static_cast<InnerSolveContext*>(ctx);
  PetscCall(KSPConvergedDefault(ksp, it, rnorm, reason, c->defaultCtx));
  if (*reason == KSP_CONVERGED_ITERATING && it >= 2 && rnorm > 0.5 * c->previous) *reason = KSP_CONVERGED_STEP_LENGTH;
  PetscInt maxit;
  PetscCall(KSPGetTolerances(ksp, nullptr, nullptr, nullptr, &maxit));
  if (*reason == KSP_DIVERGED_ITS || (*reason == KSP_CONVERGED_ITERATING && it >= maxit)) *reason = KSP_CONVERGED_ITS;
  c->previous = rnorm;
  PetscFunctionReturn(PETSC_SUCCESS);
}

inline PetscErrorCode useAccurateInnerSolver(KSP ksp) {
  PetscFunctionBeginUser;
  PetscCall(KSPSetType(ksp, KSPGMRES));
  PetscCall(KSPSetPCSide(ksp, PC_RIGHT));
  PetscCall(KSPGMRESSetRestart(ksp, 50));
  PetscCall(KSPSetTolerances(ksp, 1e-12, 1e-300, PETSC_DEFAULT, 100));
  auto* c = new InnerSolveContext;
  PetscCall(KSPConvergedDefaultCreate(&c->defaultCtx));
  PetscCall(KSPSetConvergenceTest(ksp, innerConverged, c, [](void* p) -> PetscErrorCode {
    auto* c = static_cast<InnerSolveContext*>(p);
    PetscCall(KSPConvergedDefaultDestroy(c->defaultCtx));
    delete c;
    return PETSC_SUCCESS;
  }));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
