// ContinuationAnalysis on the levels of a -target_error study (docs/accuracy.md "Reuse between levels"):
// the record of the path's states, the coarser level's steps as the plan and the predictor from its path.
#include <algorithm>
#include <cmath>

#include "analysis/continuation_analysis.hpp"

namespace sinew {

PetscErrorCode ContinuationAnalysis::recordPoint(Vec U, double lambda) {
  PetscFunctionBeginUser;
  LoadState ls;  // the node states of (U, lambda): an evaluation there
  ls.loadFactor = ls.time = lambda;
  PetscCall(asm_.residual(U, ls, work_));
  LevelState st;
  PetscCall(gatherLevelState(asm_, lambda, &st));
  handover_->record.push_back(std::move(st));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContinuationAnalysis::recordStart(Vec U, double lambda) {
  PetscFunctionBeginUser;
  PetscCall(recordPoint(U, lambda));
  if (!handover_->fromStart) PetscFunctionReturn(PETSC_SUCCESS);
  // after form finding each level's path starts from its own found shape: the coarser path is that shape
  // moved by the coarser level's displacements from its found shape (accuracy/found_shape_reuse.hpp), so the
  // nearest point and the steps of the coarser path are measured from this level's start
  handover_->start = handover_->record.back();
  coarsePath_.clear();
  for (const LevelState& d : handover_->guesses)
    if (d.nodes.size() == handover_->start.nodes.size()) coarsePath_.push_back(displacedFrom(handover_->start, d));
  if (coarsePath_.size() != handover_->guesses.size()) coarsePath_.clear();  // other nodes: no coarser path
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContinuationAnalysis::nearerPredictor(Vec U, double* lambda, Vec Upred, double lambdaPred,
                                                     bool* guessed) {
  PetscFunctionBeginUser;
  // both starts lie on the step's constraint; the one with the smaller |R(U, lambda)| is nearer the path
  LoadState ls;
  ls.loadFactor = ls.time = *lambda;
  PetscCall(asm_.residual(U, ls, work_));
  PetscReal fromCoarse, fromTangent;
  PetscCall(VecNorm(work_, NORM_2, &fromCoarse));
  ls.loadFactor = ls.time = lambdaPred;
  PetscCall(asm_.residual(Upred, ls, work_));
  PetscCall(VecNorm(work_, NORM_2, &fromTangent));
  if (fromTangent < fromCoarse) {
    PetscCall(VecCopy(Upred, U));
    *lambda = lambdaPred;
    *guessed = false;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContinuationAnalysis::coarsePathGuess(Vec U0, double lambda0, double ds, double w, Vec G, double* lambdaG,
                                                     bool* found) {
  PetscFunctionBeginUser;
  *found = false;
  const std::vector<LevelState>& path = coarsePath();
  Vec A, B;  // the coarser path's points j - 1 and j on this level's unknowns (rotations about Rref)
  PetscCall(VecDuplicate(U0, &A));
  PetscCall(VecDuplicate(U0, &B));
  // squared distance of point j from (U0, lambda0) in the constraint's metric, its unknowns into P
  auto distance2 = [&](std::size_t j, Vec P, double* d2) -> PetscErrorCode {
    PetscCall(VecCopy(U0, P));
    PetscCall(setUnknownsFromState(asm_, path[j], P));
    PetscCall(VecWAXPY(work_, -1.0, U0, P));
    PetscReal n;
    PetscCall(VecDot(work_, work_, &n));
    const double dl = path[j].loadFactor - lambda0;
    *d2 = n + w * dl * dl;
    return PETSC_SUCCESS;
  };
  // the point nearest to U0, scanning on from the last step's while the distance falls
  std::size_t nearest = std::min(guessCursor_, path.size() - 1);
  double dNearest = 0;
  PetscCall(distance2(nearest, A, &dNearest));
  for (std::size_t j = nearest + 1; j < path.size(); ++j) {
    double d2 = 0;
    PetscCall(distance2(j, B, &d2));
    if (d2 > dNearest) break;
    dNearest = d2, nearest = j;
  }
  // C0: the point of the coarser path (linear between its points) nearest to U0, on the segment before
  // or after the nearest point
  Vec C0;
  PetscCall(VecDuplicate(U0, &C0));
  double lamC0 = path[nearest].loadFactor, best = -1;
  const std::size_t from = nearest > 0 ? nearest - 1 : 0;
  for (std::size_t j = from; j + 1 < path.size() && j <= nearest; ++j) {
    double d = 0;
    PetscCall(distance2(j, A, &d));
    PetscCall(distance2(j + 1, B, &d));
    const double la = path[j].loadFactor, dlam = path[j + 1].loadFactor - la;
    PetscCall(VecWAXPY(work_, -1.0, A, B));  // B - A
    PetscReal bb, ab;
    PetscCall(VecDot(work_, work_, &bb));
    PetscCall(VecWAXPY(G, -1.0, A, U0));  // U0 - A
    PetscCall(VecDot(work_, G, &ab));
    const double a = bb + w * dlam * dlam;
    const double t = a > 0 ? std::clamp((ab + w * (lambda0 - la) * dlam) / a, 0.0, 1.0) : 0.0;
    PetscCall(VecWAXPY(G, t, work_, A));
    PetscCall(VecAXPY(G, -1.0, U0));
    PetscReal g2;
    PetscCall(VecDot(G, G, &g2));
    const double dl = la + t * dlam - lambda0, e = g2 + w * dl * dl;
    if (best < 0 || e < best) {
      best = e, lamC0 = la + t * dlam;
      PetscCall(VecWAXPY(C0, t, work_, A));
    }
  }
  if (best < 0) PetscCall(distance2(nearest, C0, &best));
  // from C0 on, where the coarser path leaves the ball of radius ds about C0: on the first segment A B
  // with the larger root of |P(t) - C0|^2 + w (lambda(t) - lambda_C0)^2 = ds^2 (P(t) = A + t (B - A)) in
  // [0, 1]; the guess is U0 plus the coarser path's increment C(t) - C0
  for (std::size_t j = from + 1; j < path.size() && !*found; ++j) {
    double dA = 0;
    PetscCall(distance2(j - 1, A, &dA));
    PetscCall(distance2(j, B, &dA));
    const double la = path[j - 1].loadFactor, dlam = path[j].loadFactor - la;
    PetscCall(VecWAXPY(work_, -1.0, A, B));  // B - A
    PetscReal bb, ab, aa;
    PetscCall(VecDot(work_, work_, &bb));
    PetscCall(VecWAXPY(G, -1.0, C0, A));  // A - C0
    PetscCall(VecDot(work_, G, &ab));
    PetscCall(VecDot(G, G, &aa));
    const double l0 = la - lamC0;
    const double a = bb + w * dlam * dlam, b = 2 * (ab + w * l0 * dlam), c = aa + w * l0 * l0 - ds * ds;
    const double disc = b * b - 4 * a * c;
    const double t = a > 0 && disc >= 0 ? (-b + std::sqrt(disc)) / (2 * a) : -1;
    if (t >= 0 && t <= 1) {
      PetscCall(VecAXPY(G, t, work_));  // C(t) - C0
      PetscCall(VecAXPY(G, 1.0, U0));
      *lambdaG = lambda0 + la + t * dlam - lamC0;
      *found = true;
    }
  }
  PetscCall(VecDestroy(&C0));
  guessCursor_ = nearest;
  PetscCall(VecDestroy(&A));
  PetscCall(VecDestroy(&B));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContinuationAnalysis::plannedStep(std::size_t k, Vec U, double lambda, double* ds, Vec G, double* lambdaG) {
  PetscFunctionBeginUser;
  const std::vector<LevelState>& path = coarsePath();
  Vec A;  // C_k - C_k-1 on this level's unknowns (the entries without a state: 0)
  PetscCall(VecDuplicate(U, &A));
  PetscCall(VecCopy(U, A));
  PetscCall(setUnknownsFromState(asm_, path[k], A));
  PetscCall(VecCopy(U, work_));
  PetscCall(setUnknownsFromState(asm_, path[k - 1], work_));
  PetscCall(VecAXPY(A, -1.0, work_));
  const double dl = path[k].loadFactor - path[k - 1].loadFactor;
  double w = 0;  // the constraint's metric |dU|^2 + psi^2 |q|^2 dlambda^2 (cylindrical: psi 0)
  if (opt_.constraint == "spherical") {
    PetscCall(loadDerivative(U, lambda, q_));
    PetscReal qn;
    PetscCall(VecNorm(q_, NORM_2, &qn));
    w = opt_.psi * opt_.psi * qn * qn;
  }
  PetscReal n2;
  PetscCall(VecDot(A, A, &n2));
  *ds = std::sqrt(n2 + w * dl * dl);
  if (G) {
    PetscCall(VecWAXPY(G, 1.0, U, A));
    *lambdaG = lambda + dl;
  }
  PetscCall(VecDestroy(&A));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
