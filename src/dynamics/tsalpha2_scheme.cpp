#include "dynamics/tsalpha2_scheme.hpp"

namespace sinew {

TSAlpha2Scheme::~TSAlpha2Scheme() {
  TSDestroy(&ts_);
  VecDestroy(&qd_);
}

PetscErrorCode TSAlpha2Scheme::create(Vec F, Mat J, double rho, double dt, double tend, int maxRejections) {
  PetscFunctionBeginUser;
  PetscCall(TSCreate(PetscObjectComm(reinterpret_cast<PetscObject>(F)), &ts_));
  PetscCall(TSSetType(ts_, TSALPHA2));
  PetscCall(TSSetI2Function(ts_, F, i2Function, this));
  PetscCall(TSSetI2Jacobian(ts_, J, J, i2Jacobian, this));
  PetscCall(TSAlpha2SetRadius(ts_, rho));
  PetscCall(TSSetTimeStep(ts_, dt));
  PetscCall(TSSetMaxTime(ts_, tend));
  PetscCall(TSSetExactFinalTime(ts_, TS_EXACTFINALTIME_MATCHSTEP));
  PetscCall(TSSetMaxSNESFailures(ts_, -1));  // a failed step is retried with a smaller step
  PetscCall(TSSetMaxStepRejections(ts_, maxRejections));
  PetscCall(TSSetErrorIfStepFails(ts_, PETSC_FALSE));  // a failed step ends with Sinew's message (converged reason)
  PetscCall(VecDuplicate(F, &qd_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TSAlpha2Scheme::snes(SNES* snes) const {
  PetscFunctionBeginUser;
  PetscCall(TSGetSNES(ts_, snes));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TSAlpha2Scheme::i2Function(TS, PetscReal t, Vec U, Vec V, Vec A, Vec F, void* ctx) {
  PetscFunctionBeginUser;
  PetscCall(static_cast<TSAlpha2Scheme*>(ctx)->equations_.motionResidual(t, U, V, A, F));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TSAlpha2Scheme::i2Jacobian(TS, PetscReal t, Vec U, Vec V, Vec, PetscReal shiftV, PetscReal shiftA, Mat,
                                          Mat P, void* ctx) {
  PetscFunctionBeginUser;
  PetscCall(static_cast<TSAlpha2Scheme*>(ctx)->equations_.motionTangent(t, U, V, shiftV, shiftA, P));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TSAlpha2Scheme::monitor(TS ts, PetscInt step, PetscReal t, Vec U, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<TSAlpha2Scheme*>(ctx);
  if (step == 0 || !self->monitor_) PetscFunctionReturn(PETSC_SUCCESS);  // t = 0 is the caller's
  Vec X, V;
  PetscCall(TS2GetSolution(ts, &X, &V));
  bool stop = false;
  PetscCall(self->monitor_(static_cast<int>(step), t, U, V, &stop));
  if (stop) PetscCall(TSSetMaxSteps(ts, step));  // TSSolve ends after the step in progress
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TSAlpha2Scheme::solve(Vec q, Monitor monitor) {
  PetscFunctionBeginUser;
  monitor_ = std::move(monitor);
  q_ = q;
  PetscCall(TSMonitorSet(ts_, TSAlpha2Scheme::monitor, this, nullptr));
  PetscCall(TS2SetSolution(ts_, q, qd_));
  PetscCall(TSSetFromOptions(ts_));
  PetscCall(TSSolve(ts_, q));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TSAlpha2Scheme::statistics(int* newtonIterations, int* rejected, TSConvergedReason* why, double* t) const {
  PetscFunctionBeginUser;
  PetscInt snesIts = 0, rej = 0;
  PetscReal tEnd = 0;
  PetscCall(TSGetSNESIterations(ts_, &snesIts));
  PetscCall(TSGetStepRejections(ts_, &rej));
  PetscCall(TSGetConvergedReason(ts_, why));
  PetscCall(TSGetTime(ts_, &tEnd));
  *newtonIterations = static_cast<int>(snesIts);
  *rejected = static_cast<int>(rej);
  *t = tEnd;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
