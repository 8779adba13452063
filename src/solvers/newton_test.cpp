#include "solvers/newton_test.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace sinew {

double roundoffFloor(double jacobianNorm, double coordMax) { return 8.0 * DBL_EPSILON * jacobianNorm * coordMax; }

double forceScale(double external, double internal, double internalCap) {
  return std::max(external, std::min(internal, internalCap));
}

PetscErrorCode NewtonTest::judge(SNES snes, const NewtonIterate& x, SNESConvergedReason* reason) {
  PetscFunctionBeginUser;
  PetscCall(SNESConvergedDefault(snes, x.it, x.xnorm, x.snorm, x.fnorm, reason, nullptr));
  PetscReal atol, rtol, stol;
  PetscInt maxit, maxf;
  PetscCall(SNESGetTolerances(snes, &atol, &rtol, &stol, &maxit, &maxf));
  PetscReal lambda = 1.0;  // the full Newton update: a line search may have taken only a fraction lambda of it
  if (rules_.update == NewtonRules::Update::Relative && rules_.updateDividesLineSearch && x.it > 0) {
    SNESLineSearch lsearch;
    PetscCall(SNESGetLineSearch(snes, &lsearch));
    PetscCall(SNESLineSearchGetLambda(lsearch, &lambda));
  }
  decide(x, atol, rtol, lambda, reason);
  PetscFunctionReturn(PETSC_SUCCESS);
}

SNESConvergedReason NewtonTest::judge(const NewtonIterate& x) {
  SNESConvergedReason reason = SNES_CONVERGED_ITERATING;
  decide(x, 0.0, 0.0, 1.0, &reason);
  return reason;
}

void NewtonTest::decide(const NewtonIterate& x, double atol, double rtol, double lambda, SNESConvergedReason* reason) {
  const NewtonRules& r = rules_;
  const PetscInt it = x.it;
  const double fnorm = x.fnorm, floor = x.floor;
  if (it == 0) {
    fnorm0_ = fnorm;
    snormPrev_ = 0.0;
    onUpdate_ = false;
  }
  theta_ = it >= 2 && snormPrev_ > 0 ? x.snorm / snormPrev_ : 0.0;
  const auto iterating = [&] { return *reason == SNES_CONVERGED_ITERATING; };

  // SNES's own verdicts; then the rules of the start, the force scale and the round-off floor, the
  // first that holds deciding. Under Snes::Own they are judged whatever SNES said (statics).
  if (r.snes == NewtonRules::Snes::Own) {
    if (*reason > 0) *reason = SNES_CONVERGED_ITERATING;
  } else if (r.snes == NewtonRules::Snes::KeepButUpdate && *reason == SNES_CONVERGED_SNORM_RELATIVE &&
             (r.snesUpdateForceRtol <= 0 || fnorm > r.snesUpdateForceRtol * x.scale)) {
    *reason = SNES_CONVERGED_ITERATING;
  }
  bool decided = r.snes != NewtonRules::Snes::Own && !iterating();
  const auto rule = [&](bool holds, SNESConvergedReason why) {
    if (decided || !holds) return;
    *reason = why;
    decided = true;
  };
  if (r.snes == NewtonRules::Snes::Own) {
    rule(fnorm <= atol, SNES_CONVERGED_FNORM_ABS);
    rule(r.startRelative && fnorm <= rtol * fnormStart_, SNES_CONVERGED_FNORM_RELATIVE);
  }
  rule(r.forceRtol > 0 && it >= r.forceFromIteration && fnorm <= r.forceRtol * x.scale, SNES_CONVERGED_FNORM_ABS);
  rule(r.belowFloor && it >= r.forceFromIteration && fnorm <= floor, SNES_CONVERGED_FNORM_ABS);
  // the start state is in equilibrium to round-off
  // (not when the residual is a load increment, however small: that needs at least one Newton step)
  rule(it == 0 && r.startFloorFactor > 0 && fnorm <= r.startFloorFactor * floor && !(x.loadChange > 8.0 * DBL_EPSILON * x.scale),
       SNES_CONVERGED_FNORM_ABS);
  // below the floor estimate and stalled (less than 10x per iteration), fallen into it by a quadratic
  // step (1000x and more), or come from just above it (a further iteration can only move it within the noise)
  rule(r.stalledAtFloor && it > 0 && fnorm <= floor &&
           (fnorm > 0.1 * fnormPrev_ || fnorm <= 1e-3 * fnormPrev_ || fnormPrev_ <= 1e2 * floor) &&
           (fnorm <= 1e-3 * fnorm0_ || fnorm0_ <= floor),
       SNES_CONVERGED_FNORM_ABS);
  rule(r.droppedBelowFloor && it > 0 && fnorm <= 1e-3 * fnorm0_ && fnorm <= floor, SNES_CONVERGED_FNORM_ABS);

  // a wandering iteration is given up early, so that the increment is cut
  if (iterating() && r.divergedIts > 0 && it >= r.divergedIts && fnorm > fnorm0_) *reason = SNES_DIVERGED_DTOL;

  // the Newton update
  if (r.update == NewtonRules::Update::Relative) {
    if (it > 0) {
      relUpdate_ = x.xnorm > 0 ? x.snorm / std::max(lambda, 1e-300) / x.xnorm : 0.0;
    }
    const double at = r.updateFloorFactor * floor;
    if (iterating() && it > 1 && (r.updateFloorFactor == 0 || fnorm <= at) &&
        (!r.updateNeedsStartAtFloor || fnorm0_ <= at) &&
        updateConverged(relUpdate_, relUpdatePrev_, r.updateTight, r.updateLoose)) {
      *reason = SNES_CONVERGED_SNORM_RELATIVE;
      onUpdate_ = true;
    }
  } else if (r.update == NewtonRules::Update::Contraction && iterating() && it >= 2 && fnorm <= floor &&
             snormPrev_ > 0) {
    // the iterate's error is ~ theta/(1 - theta) |dU| (|dU| itself once the updates stall at the
    // noise), and the residual must not be growing (a stale Jacobian drifting in stiff directions)
    const double err = theta_ < 0.5 ? theta_ / (1.0 - theta_) * x.snorm : x.snorm;
    if (err <= r.updateRtol * x.xnorm && fnorm <= 1.5 * fnormPrev_) {
      *reason = SNES_CONVERGED_SNORM_RELATIVE;
      onUpdate_ = true;
    }
  }
  if (iterating() && r.atRest && it > 0 && fnorm <= floor && x.snorm <= 1e3 * DBL_EPSILON * x.coordMax)
    *reason = SNES_CONVERGED_SNORM_RELATIVE;  // at rest under loads still zero: residual and update at round-off

  // a verdict stands only once the update is at the round-off of the coordinates (midpoint rule)
  if (r.finalUpdateRtol > 0 && *reason > 0) {
    const double tol = r.finalUpdateRtol * std::max(x.xnorm, x.coordMax);
    const bool noiseUpdate = r.finalUpdateAtFloor && it >= 2 && fnormPrev_ <= floor && fnorm <= floor;
    if (!(it > 0 && (x.snorm <= tol || noiseUpdate))) *reason = SNES_CONVERGED_ITERATING;
  }
  if (it > 0) snormPrev_ = x.snorm;
  fnormPrev_ = fnorm;
  relUpdatePrev_ = relUpdate_;
  if (!std::isfinite(fnorm)) *reason = SNES_DIVERGED_FNORM_NAN;
}

PetscErrorCode solveNewton(SNES snes, Vec U, NewtonOutcome* outcome) {
  PetscFunctionBeginUser;
  PetscCall(SNESSolve(snes, nullptr, U));
  PetscCall(SNESGetConvergedReason(snes, &outcome->reason));
  PetscInt n = 0;
  PetscCall(SNESGetIterationNumber(snes, &n));
  outcome->iterations = static_cast<int>(n);
  PetscReal f = 0;
  PetscCall(SNESGetFunctionNorm(snes, &f));
  outcome->residualNorm = f;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
