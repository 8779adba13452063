// StaticAnalysis, ContinuationAnalysis and a -target_error study's levels (analysis/statics_handover.hpp): the record of the
// converged states and the Newton start from a coarser level's state.
#include <cmath>

#include "analysis/static_analysis.hpp"
#include "sinew/rotation.hpp"

namespace sinew {

PetscErrorCode gatherLevelState(const Assembler& assembler, double lambda, LevelState* state) {
  PetscFunctionBeginUser;
  const DistributedMesh& mesh = assembler.mesh();
  LevelState& st = *state;
  st.loadFactor = lambda;
  st.nodes.assign(12 * static_cast<std::size_t>(mesh.numFeNodes), 0.0);
  for (int i = 0; i < mesh.numOwnedNodes; ++i) {  // every FE node is owned by one rank
    const double* s = assembler.nodeState(i);
    std::copy(s, s + 12, st.nodes.begin() + 12 * mesh.nodes[static_cast<std::size_t>(i)].gid);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, st.nodes.data(), static_cast<int>(st.nodes.size()), MPI_DOUBLE, MPI_SUM,
                             mesh.comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

LevelState displacedFrom(const LevelState& start, const LevelState& d) {
  LevelState g = d;
  for (std::size_t n = 0; 12 * n < g.nodes.size(); ++n)
    for (std::size_t k = 0; k < 3; ++k) g.nodes[12 * n + k] += start.nodes[12 * n + k];
  return g;
}

PetscErrorCode setUnknownsFromState(const Assembler& assembler, const LevelState& guess, Vec U) {
  PetscFunctionBeginUser;
  const DistributedMesh& mesh = assembler.mesh();
  const std::vector<Mat3> Rref = assembler.referenceRotations();
  PetscScalar* u;
  PetscCall(VecGetArray(U, &u));
  for (int i = 0; i < mesh.numOwnedNodes; ++i) {
    const LocalNode& n = mesh.nodes[static_cast<std::size_t>(i)];
    const double* g = &guess.nodes[12 * static_cast<std::size_t>(n.gid)];
    auto set = [&](int k, double value) {
      if (n.status[k] == DofStatus::Free && n.dof[k] >= 0) u[n.dof[k]] = value;
    };
    if (n.kind == NodeKind::Ancf2D) {  // positions and slopes as displacements from the reference
      set(0, g[0] - n.X0[0]), set(1, g[1] - n.X0[1]), set(2, g[2] - n.slope0[0]), set(3, g[3] - n.slope0[1]);
      continue;
    }
    for (int k = 0; k < 3; ++k) set(k, g[k] - n.X0[k]);
    if (n.kind != NodeKind::Frame6 || n.rotationPrescribed) continue;
    Mat3 R;
    std::copy(g + 3, g + 12, R.begin());
    const Vec3 theta = logSO3(R * transpose(Rref[static_cast<std::size_t>(i)]));  // R = exp(theta) R_ref
    for (int k = 0; k < 3; ++k) set(3 + k, theta[k]);
  }
  PetscCall(VecRestoreArray(U, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode StaticAnalysis::recordState(double lambda) {
  PetscFunctionBeginUser;
  LevelState st;
  PetscCall(gatherLevelState(asm_, lambda, &st));
  handover_->record.push_back(std::move(st));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode StaticAnalysis::startFromGuess(Vec U, double lambda, bool* used) {
  PetscFunctionBeginUser;
  *used = false;
  const LevelState* guess = nullptr;  // the guesses are the same on every rank
  for (const LevelState& g : handover_->guesses)
    if (std::abs(g.loadFactor - lambda) <= 1e-12 * std::max(1.0, std::abs(lambda))) guess = &g;
  if (!guess) PetscFunctionReturn(PETSC_SUCCESS);
  if (handover_->fromStart) {  // a displacement from the start state: this level's found shape plus it
    if (handover_->start.nodes.size() != guess->nodes.size()) PetscFunctionReturn(PETSC_SUCCESS);
    PetscCall(setUnknownsFromState(asm_, displacedFrom(handover_->start, *guess), U));
  } else {
    PetscCall(setUnknownsFromState(asm_, *guess, U));
  }
  ++handover_->guessesUsed;
  *used = true;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode StaticAnalysis::nearerStart(Vec U, Vec Ulast, Vec dU, double s, bool* guessed) {
  PetscFunctionBeginUser;
  // the coarser level's displacement carries its discretization error; where the load steps are nearly
  // linear (a prestressed sail under wind) the extrapolation of the last increment is nearer
  PetscReal fromGuess = 0, fromExtrapolation = 0;
  PetscCall(asm_.residual(U, ls_, F_));
  PetscCall(VecNorm(F_, NORM_2, &fromGuess));
  Vec W;
  PetscCall(VecDuplicate(U, &W));
  PetscCall(VecWAXPY(W, s, dU, Ulast));
  PetscCall(asm_.residual(W, ls_, F_));
  PetscCall(VecNorm(F_, NORM_2, &fromExtrapolation));
  PetscCall(VecDestroy(&W));
  if (fromExtrapolation < fromGuess) {  // the caller extrapolates from Ulast
    PetscCall(VecCopy(Ulast, U));
    --handover_->guessesUsed;
    *guessed = false;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
