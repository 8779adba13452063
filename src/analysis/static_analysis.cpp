#include "analysis/static_analysis.hpp"

#include <cmath>
#include <sstream>

namespace sinew {

StaticAnalysis::StaticAnalysis(Assembler& assembler, int loadsteps) : asm_(assembler), loadsteps_(loadsteps) {
  MPI_Comm comm = asm_.mesh().comm;
  PetscCallAbort(comm, asm_.createMatrix(&J_));
  PetscCallAbort(comm, asm_.createVector(&F_));
  PetscCallAbort(comm, SNESCreate(comm, &snes_));
  PetscCallAbort(comm, SNESSetType(snes_, SNESNEWTONLS));
  PetscCallAbort(comm, SNESSetFunction(snes_, F_, formFunction, this));
  PetscCallAbort(comm, SNESSetJacobian(snes_, J_, J_, formJacobian, this));
  PetscCallAbort(comm, SNESSetTolerances(snes_, 1e-50, 1e-10, 1e-9, 50, 10000));
  PetscCallAbort(comm, SNESSetDivergenceTolerance(snes_, -1.0));  // stiff axial modes make the first residual jump
  SNESLineSearch ls;
  PetscCallAbort(comm, SNESGetLineSearch(snes_, &ls));
  PetscCallAbort(comm, SNESLineSearchSetType(ls, SNESLINESEARCHBASIC));
  PetscCallAbort(comm, SNESSetConvergenceTest(snes_, convergenceTest, this, nullptr));
  KSP ksp;
  PC pc;
  PetscCallAbort(comm, SNESGetKSP(snes_, &ksp));
  PetscCallAbort(comm, KSPSetType(ksp, KSPPREONLY));
  PetscCallAbort(comm, KSPGetPC(ksp, &pc));
  PetscCallAbort(comm, PCSetType(pc, PCLU));
  PetscCallAbort(comm, PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PetscCallAbort(comm, SNESSetFromOptions(snes_));
  PetscReal rtol = forceRtol_;
  PetscBool set = PETSC_FALSE;
  PetscInt cuts = maxCuts_;
  PetscCallAbort(comm, PetscOptionsGetReal(nullptr, nullptr, "-force_rtol", &rtol, &set));
  PetscCallAbort(comm, PetscOptionsGetInt(nullptr, nullptr, "-max_cuts", &cuts, &set));
  forceRtol_ = rtol;
  PetscBool predictor = PETSC_TRUE;
  PetscCallAbort(comm, PetscOptionsGetBool(nullptr, nullptr, "-predictor", &predictor, &set));
  predictor_ = predictor;
  maxCuts_ = static_cast<int>(cuts);
}

StaticAnalysis::~StaticAnalysis() {
  SNESDestroy(&snes_);
  MatDestroy(&J_);
  VecDestroy(&F_);
}

PetscErrorCode StaticAnalysis::formFunction(SNES, Vec U, Vec F, void* ctx) {
  auto* self = static_cast<StaticAnalysis*>(ctx);
  return self->asm_.residual(U, self->ls_, F);
}

PetscErrorCode StaticAnalysis::formJacobian(SNES, Vec U, Mat, Mat P, void* ctx) {
  auto* self = static_cast<StaticAnalysis*>(ctx);
  return self->asm_.jacobian(U, self->ls_, P);
}

// Newton has converged when SNES's default test says so, or when the residual is down to the
// round-off level of the forces being balanced: ||F|| <= force_rtol * max(||f_int||, ||f_ext||).
PetscErrorCode StaticAnalysis::convergenceTest(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm,
                                               PetscReal fnorm, SNESConvergedReason* reason, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<StaticAnalysis*>(ctx);
  PetscCall(SNESConvergedDefault(snes, it, xnorm, snorm, fnorm, reason, nullptr));
  // a Newton update below stol * |x| ends the iteration only near equilibrium (round-off floor)
  if (*reason == SNES_CONVERGED_SNORM_RELATIVE && fnorm > 1e-6 * std::max(self->asm_.externalForceNorm(), self->asm_.internalForceNorm()))
    *reason = SNES_CONVERGED_ITERATING;
  if (*reason == SNES_CONVERGED_ITERATING) {
    const double scale = std::max(self->asm_.externalForceNorm(), self->asm_.internalForceNorm());
    if (fnorm <= self->forceRtol_ * scale) *reason = SNES_CONVERGED_FNORM_ABS;
  }
  if (!std::isfinite(fnorm)) *reason = SNES_DIVERGED_FNORM_NAN;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode StaticAnalysis::solveIncrement(Vec U, double lambda, bool* ok, int* its, double* fnorm,
                                              SNESConvergedReason* why) {
  PetscFunctionBeginUser;
  ls_.loadFactor = lambda;
  ls_.time = lambda;
  PetscCall(SNESSolve(snes_, nullptr, U));
  PetscCall(SNESGetConvergedReason(snes_, why));
  PetscInt n;
  PetscCall(SNESGetIterationNumber(snes_, &n));
  PetscReal f;
  PetscCall(SNESGetFunctionNorm(snes_, &f));
  *its = static_cast<int>(n);
  *fnorm = f;
  *ok = *why > 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode StaticAnalysis::run(Vec U, const StepCallback& onStep, bool* converged) {
  PetscFunctionBeginUser;
  MPI_Comm comm = asm_.mesh().comm;
  Vec Usave, dU;  // state before the increment; last converged increment (secant predictor)
  PetscCall(VecDuplicate(U, &Usave));
  PetscCall(VecDuplicate(U, &dU));
  double dlPrev = 0.0;
  *converged = true;
  double lambda = 0.0;
  for (int step = 1; step <= loadsteps_; ++step) {
    const double target = static_cast<double>(step) / loadsteps_;
    StepReport rep;
    rep.step = step;
    double dl = target - lambda;
    int cuts = 0;
    while (lambda < target) {
      const double next = std::min(target, lambda + dl);
      PetscCall(VecCopy(U, Usave));
      const auto Rsave = asm_.referenceRotations();
      // predictor: extrapolate the last increment (rotation increments included)
      if (dlPrev > 0 && predictor_) PetscCall(VecAXPY(U, (next - lambda) / dlPrev, dU));
      bool ok = false;
      int its = 0;
      double fnorm = 0;
      SNESConvergedReason why;
      PetscCall(solveIncrement(U, next, &ok, &its, &fnorm, &why));
      rep.newtonIterations += its;
      ++rep.increments;
      rep.residualNorm = fnorm;
      if (ok) {
        PetscCall(VecWAXPY(dU, -1.0, Usave, U));
        dlPrev = next - lambda;
        PetscCall(asm_.absorbRotations(U));
        lambda = next;
        continue;
      }
      PetscCall(VecCopy(Usave, U));
      asm_.setReferenceRotations(Rsave);
      if (++cuts > maxCuts_) {
        std::ostringstream msg;
        msg << "load step " << step << " of " << loadsteps_ << " did not converge: Newton stopped at load factor "
            << next << " (" << SNESConvergedReasons[why] << ", residual norm " << fnorm << ") after " << maxCuts_
            << " halvings of the increment (last converged load factor " << lambda
            << "). Try more load steps (-loadsteps), a line search (-snes_linesearch_type bt|l2), "
               "-snes_monitor to watch the residual, or check supports and rigid modes for a mechanism.";
        failure_ = msg.str();
        *converged = false;
        break;
      }
      dl *= 0.5;
      PetscCall(PetscPrintf(comm, "  step %d: Newton failed at load factor %.6g (%s); retrying with increment %.3g\n",
                            step, next, SNESConvergedReasons[why], dl));
    }
    if (!*converged) break;
    rep.loadFactor = lambda;
    reports_.push_back(rep);
    if (onStep) PetscCall(onStep(rep, U));
  }
  PetscCall(VecDestroy(&Usave));
  PetscCall(VecDestroy(&dU));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
