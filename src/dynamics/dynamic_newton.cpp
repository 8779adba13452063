// The Newton step of the Arnold-Bruls loop: the step solver (useDynamicsSolver), when the Newton
// matrix is kept, rebuilt from turned element blocks or assembled afresh (formJacobian), the refined
// step solves (setRefinements, applyNewtonMatrix) and the convergence test.
#include "dynamics/dynamic_analysis.hpp"
#include "settings/read_settings.hpp"
#include "solvers/ancf/node_rotated_pc.hpp"
#include "solvers/cut_corrected_lu.hpp"
#include "solvers/newton_test.hpp"
#include "solvers/solver_defaults.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {

// The effective matrix K + gamma/(beta h) C + (1 - alpha_m)/((1 - alpha_f) beta h^2) M is dominated
// by the mass term at the step sizes dynamics uses, so on one process a model without multipliers
// (no rigid modes or releases as constraints) is factored by PETSc's own LU (no pivoting needed;
// nested-dissection order) instead of MUMPS, whose fixed cost per factorization (about 0.1 ms)
// exceeds a whole time step of a small model. ANCF chains: PETSc's LU in band order (useChainLU), on
// several processes each rank's part with the exact correction of the unknowns coupling the ranks
// (useCutCorrectedLU; -dynamics_chain_lu redundant: every process factors the whole matrix). Other
// models up to -dense_max_unknowns unknowns: a dense LU with partial pivoting (PCDENSELU; on several
// processes redundant, every process factoring the whole matrix). Anything else: MUMPS, as everywhere.
PetscErrorCode DynamicAnalysis::useDynamicsSolver(KSP ksp) {
  PetscFunctionBeginUser;
  if (nodeRotation_ != NodeRotation::Off) {
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscCall(useNodeRotatedPC(ksp, *corotatedMatrix_, &rotating_, &ksp));
  }
  PetscCall(useDirectSolver(ksp));
  const DistributedMesh& mesh = asm_.mesh();
  int size = 1;
  MPI_Comm_size(mesh.comm, &size);
  if (chain_ && size > 1 && cutLU_) {
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscFunctionReturn(useCutCorrectedLU(ksp));
  }
  if (chain_) PetscFunctionReturn(useChainLU(ksp, mesh.comm));
  bool plain = size == 1;
  for (const LocalElement& e : mesh.elements) plain = plain && e.firstMultiplier < 0;
  // small models (-dense_max_unknowns) that would go to MUMPS: a dense LU with partial pivoting, on
  // several processes every process factoring the whole matrix (a 96-unknown leaf on 2 ranks spent 70 %
  // of its time steps in MUMPS's per-call work)
  if (!plain && mesh.numGlobalUnknowns <= static_cast<long>(denseMax_)) {
    if (size == 1) PetscFunctionReturn(useDenseLU(ksp));
    PetscFunctionReturn(useRedundantDenseLU(ksp));
  }
  if (!plain) {
    // MUMPS: the off-diagonal pivoting a wild Newton iterate needs (a step load on a fine cable)
    // overflows the default workspace estimate (INFOG(1) = -9, a failed linear solve); reserve 100 %
    // more (ICNTL(14), -mat_mumps_icntl_14) unless the user set it
    PetscCall(applySolverOptionDefault("-mat_mumps_icntl_14", mumpsWorkspace_));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(usePetscLU(ksp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::formJacobian(SNES snes, Vec U, Mat, Mat P, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<DynamicAnalysis*>(ctx);
  const double h = self->h_;
  // the scheme's dqd/dq (generalized alpha: gamma/(beta h)), for the damping of a corotated rebuild
  const double shiftV = self->stepScheme_->evaluation(U).shiftV;
  PetscInt it = 0;
  PetscReal fnorm = 0;
  if (snes) {
    PetscCall(SNESGetIterationNumber(snes, &it));
    PetscCall(SNESGetFunctionNorm(snes, &fnorm));
  }
  // auto: one more refinement (up to kMaxRefinements) each time Newton's updates on one matrix
  // contract by less than kRefineContraction (A1g: none up to 16384 elements, 1 from 32768, 3 at
  // 131072); a refinement that does not halve the next such contraction is taken back and auto
  // ends (the contraction was the kept matrix's staleness, not the LU's accuracy: A3 at 512 elements)
  if (it == 0) self->matrixIt_ = self->refineIt_ = -100;  // both updates of a theta came from this solve's matrix
  if (self->refineAuto_ && snes && it >= 2 && self->matrixIt_ <= it - 2 && self->refineIt_ <= it - 2) {
    KSP ksp;
    PetscCall(SNESGetKSP(snes, &ksp));
    if (self->refineCheck_) {
      self->refineCheck_ = false;
      if (self->newtonTest_.contraction() > 0.5 * self->refineTheta_) {
        self->refineAuto_ = false;
        PetscCall(self->setRefinements(ksp, self->refinements_ - 1));
      }
    } else if (self->refinements_ < kMaxRefinements && self->newtonTest_.contraction() > kRefineContraction) {
      self->refineIt_ = it;
      self->refineCheck_ = true;
      self->refineTheta_ = self->newtonTest_.contraction();
      PetscCall(self->setRefinements(ksp, self->refinements_ + 1));
    }
  }
  if (self->modifiedNewton_ && snes) {
    // Keep the factored Jacobian (P untouched: PCSetUp sees the same matrix state and does not
    // refactor) while it still makes Newton contract fast enough.
    constexpr double kContractivity = 0.5;
    constexpr int kMaxReuse = 8;
    // with the state predictor the residual soon reaches its round-off noise, which no Jacobian
    // reduces (A1g at 65536 elements: 10.7 -> 0.137 -> 0.089 N, then flat, refactoring at every
    // step: 89 iterations on 34 Jacobians in 20 steps): there the contraction theta of the Newton
    // updates judges the kept Jacobian (convergenceTest), the residual only at the first iteration and
    // when it grows (a stale Jacobian drifts in the stiff directions: small updates, residual up 1.5x)
    const bool slow = self->predictor_ == Predictor::State
                          ? (it == 1 && fnorm > (self->rotating_ ? kRotatedContractivity : kContractivity) * self->prevFnorm_) ||
                                (it >= 2 && ((self->newtonTest_.contraction() > kContractivity && self->matrixIt_ <= it - 2) ||
                                             fnorm > 1.5 * self->prevFnorm_))
                          : it > 0 && fnorm > kContractivity * self->prevFnorm_;
    self->prevFnorm_ = fnorm;
    // the same step size up to round-off: a step that ends on k dt has h = k dt - t, a few ulps off
    // dt, which must not count as a new step size (it refactored every other step)
    const bool sameH = std::abs(self->jacobianH_ - h) <= 1e-9 * h;
    // a kept matrix whose elements turned by half the turn at which a kept matrix stalled in an
    // earlier step is rebuilt at once, after the step's first update (which moves the state near
    // q_{n+1}), not one iteration later on a growing residual: A1g at 65536 elements stalls from a
    // turn of 2.3e-4 rad, which the clamped end's bending wave exceeds in every step after the fourth.
    // With node rotation (auto: when that first stall came at a turn below kRotationTurn) the kept LU
    // is turned with the nodes instead, and no turn forces a rebuild
    bool turned = false;
    double turn = 0.0;
    if (self->corotated_ && !self->rotating_ && self->jacobianValid_ && sameH && !self->lastCorotated_ &&
        self->corotatedMatrix_->valid() && (it >= 2 ? slow : it == 1 && !slow && self->staleTurn_ < HUGE_VAL)) {
      PetscCall(self->corotatedMatrix_->turn(U, self->ls_, &turn));
      const bool first = self->staleTurn_ == HUGE_VAL;
      if (it >= 2) self->staleTurn_ = std::min(self->staleTurn_, turn);
      turned = it == 1 && turn > 0.5 * self->staleTurn_;
      if (first && it >= 2 && self->nodeRotation_ == NodeRotation::Auto && turn < kRotationTurn) {
        self->rotating_ = true;
        turned = false;
      }
    }
    if (self->jacobianValid_ && sameH && !slow && !turned && self->reuseCount_ < kMaxReuse) {
      ++self->reuseCount_;
      self->lastCorotated_ = false;
      if (self->rotating_) PetscCall(self->corotatedMatrix_->turnToIterate(U, self->ls_));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    // a fine cable's kept Jacobian goes stale mainly by the rotation of its elements: rebuild it
    // from the kept blocks turned with their elements (A1g, 65536 elements, 20 steps of 1e-3 s: 1
    // Jacobian and 18 rebuilds against 31 Jacobians); a fresh one when the last rebuild did not help
    if (self->corotated_ && (slow || turned) && self->jacobianValid_ && sameH && !self->lastCorotated_ &&
        self->corotatedMatrix_->valid()) {
      self->matrixIt_ = it;
      PetscCall(self->corotatedMatrix_->assemble(U, self->ls_, P));
      PetscCall(self->damping_.addJacobian(shiftV, P));
      ++self->report_.jacobians;
      ++self->report_.corotatedJacobians;
      self->reuseCount_ = 0;
      self->lastCorotated_ = true;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  }
  self->lastCorotated_ = false;
  // d/dq_{n+1} of the step equation (generalized alpha: K + gamma/(beta h) C + (1 - alpha_m)/((1 -
  // alpha_f) beta h^2) M at q_{n+1}; midpoint: (K + (2/h) C + (4/h^2) M) / 2 at the mid state)
  PetscCall(self->stepScheme_->rates(U));
  PetscCall(self->stepJacobian(U, self->stepScheme_->evaluation(U), P));
  ++self->report_.jacobians;
  self->matrixIt_ = it;
  self->jacobianValid_ = true;
  self->jacobianH_ = h;
  self->reuseCount_ = 0;
  if (it == 0 || self->jacobianNorm_ == 0) PetscCall(MatNorm(P, NORM_INFINITY, &self->jacobianNorm_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// n refinements of the LU solve with the Newton matrix applied element by element (Jop_): Richardson
// with n + 1 iterations, x1 = P^-1 b, x_k+1 = x_k + P^-1 (b - J x_k), no norms; n = 0: the LU alone.
PetscErrorCode DynamicAnalysis::setRefinements(KSP ksp, int n) {
  PetscFunctionBeginUser;
  refinements_ = n;
  report_.refinements = n;
  if (n == 0) {
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(KSPSetType(ksp, KSPRICHARDSON));
  PetscCall(KSPSetTolerances(ksp, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, n + 1));
  PetscCall(KSPSetNormType(ksp, KSP_NORM_NONE));
  PetscCall(KSPSetConvergenceTest(ksp, KSPConvergedSkip, nullptr, nullptr));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::applyNewtonMatrix(Mat A, Vec x, Vec y) {
  PetscFunctionBeginUser;
  DynamicAnalysis* self = nullptr;
  PetscCall(MatShellGetContext(A, &self));
  ++self->report_.refinedSolves;  // one product per refinement of a solve
  PetscCall(self->corotatedMatrix_->apply(x, y));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The dynamics rules of the Newton test (solvers/newton_test.hpp): SNES's default test (its update
// verdict only at a residual below 1e-6 of the forces), the residual at -force_rtol of the forces it
// balances (as in statics), or at its round-off floor 8 eps ||J||_inf max|X|:
// - with the acceleration predictor, once it has dropped below 1e-3 of its start (stiff axial terms,
//   small loads);
// - starting at q_n (fine meshes), on the Newton update: the start residual is small and smooth, so a
//   1e-3 drop proves nothing (A1g at 4096 elements: accepted after one iteration, tip x 1.1e-8 m off a
//   run converged to 1e-9), and at 65536 elements no drop is possible (residual noise 0.09 N against a
//   start of 10.7 N). With the contraction theta of the last two updates the iterate's error is
//   ~ theta/(1 - theta) |dU|; converged below 1e-6 of |U| while the residual is not growing (a stale
//   Jacobian's drift in the stiff directions has small updates but residuals of 1..33 N against the
//   noise of 0.09 N, A1g at 65536 elements);
// - at rest: a model at rest under loads that are still zero (functions of time that start later)
//   starts at its floor and cannot drop by 1e-3; Newton's update is round-off too.
// The implicit midpoint rule keeps momentum exact only for a solved step (the residual is the momentum
// balance's error times 1/h, the floor estimate loose), so there a step ends when Newton's update is at
// the round-off of the coordinates. The energy-momentum scheme with the consistent beam mass (its inertia
// the kinetic energy's force at q_{n+1}, not a discrete gradient: energy and momenta are not exact anyway)
// ends also after an update computed from a residual at its floor (rule final update, finalUpdateAtFloor):
// on the spin-up at 6 rad/s 3 iterations per step instead of 4, the fourth moving the tip by 1e-15 m.
NewtonRules DynamicAnalysis::newtonRules() const {
  NewtonRules r;
  r.snes = NewtonRules::Snes::KeepButUpdate;
  r.snesUpdateForceRtol = 1e-6;
  r.forceRtol = forceRtol_;
  r.forceFromIteration = 1;
  if (predictor_ == Predictor::Acceleration) {
    r.droppedBelowFloor = true;
  } else {
    r.update = NewtonRules::Update::Contraction;
    r.updateRtol = kUpdateRtol;
  }
  r.atRest = true;
  if (midpointScheme_ || emScheme_) r.finalUpdateRtol = kMidpointUpdateRtol;
  r.finalUpdateAtFloor = stateMassSteps_;
  return r;
}

PetscErrorCode DynamicAnalysis::convergenceTest(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm, PetscReal fnorm,
                                                SNESConvergedReason* reason, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<DynamicAnalysis*>(ctx);
  NewtonIterate x(it, xnorm, snorm, fnorm);
  x.scale = forceScale(self->asm_.externalForceNorm(), self->asm_.internalForceNorm());
  x.floor = roundoffFloor(self->jacobianNorm_, self->coordMax_);
  x.coordMax = self->coordMax_;
  PetscCall(self->newtonTest_.judge(snes, x, reason));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
