#include "dynamics/generalized_alpha_scheme.hpp"

#include <cmath>

namespace sinew {

GeneralizedAlphaParameters GeneralizedAlphaParameters::fromSpectralRadius(double rho) {
  GeneralizedAlphaParameters p;
  p.alphaM = (2.0 * rho - 1.0) / (rho + 1.0);
  p.alphaF = rho / (rho + 1.0);
  p.gamma = 0.5 + p.alphaF - p.alphaM;
  p.beta = 0.25 * (p.gamma + 0.5) * (p.gamma + 0.5);
  return p;
}

GeneralizedAlphaScheme::GeneralizedAlphaScheme(double spectralRadius, Vec like, Vec multipliers, Assembler* rotations)
    : StepScheme(like, multipliers, rotations), p_(GeneralizedAlphaParameters::fromSpectralRadius(spectralRadius)) {}

PetscErrorCode GeneralizedAlphaScheme::beginStep(double h) {
  PetscFunctionBeginUser;
  h_ = h;
  PetscCall(VecCopy(qn_, work_));
  PetscCall(VecAXPBYPCZ(work_, h, h * h * (0.5 - p_.beta), 1.0, vn_, an_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode GeneralizedAlphaScheme::predict(Vec q) const {
  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(q, h_ * h_ * p_.beta, an_, work_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode GeneralizedAlphaScheme::rates(Vec q) {
  PetscFunctionBeginUser;
  const double h = h_, bh2 = p_.beta * h * h;
  const double alphaM = p_.alphaM, alphaF = p_.alphaF, gamma = p_.gamma;
  // a_{n+1} = (q_{n+1} - Cu) / (beta h^2)
  PetscCall(VecWAXPY(a1_, -1.0, work_, q));
  PetscCall(VecScale(a1_, 1.0 / bh2));
  // qd_{n+1} = qd_n + h (1 - gamma) a_n + h gamma a_{n+1}
  PetscCall(VecCopy(vn_, v1_));
  PetscCall(VecAXPBYPCZ(v1_, h * (1.0 - gamma), h * gamma, 1.0, an_, a1_));
  // qdd_{n+1} = ((1 - alpha_m) a_{n+1} + alpha_m a_n - alpha_f qdd_n) / (1 - alpha_f)
  PetscCall(VecSet(qdd1_, 0.0));
  PetscCall(VecAXPBYPCZ(qdd1_, (1.0 - alphaM) / (1.0 - alphaF), alphaM / (1.0 - alphaF), 0.0, a1_, an_));
  PetscCall(VecAXPY(qdd1_, -alphaF / (1.0 - alphaF), qddn_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

EvaluationPoint GeneralizedAlphaScheme::evaluation(Vec q) const {
  const double h = h_;
  EvaluationPoint e;
  e.q = q;
  e.qd = v1_;
  e.qdd = qdd1_;
  e.shiftV = p_.gamma / (p_.beta * h);
  e.shiftA = (1.0 - p_.alphaM) / ((1.0 - p_.alphaF) * p_.beta * h * h);
  return e;
}

// The update q_{n+1} = q_n + h qd_n + h^2 (1/2 - beta) a_n + h^2 beta a_{n+1} differs from the Taylor
// series by h^3 (beta - 1/6) da/dt + O(h^4), and h da/dt ~ a_{n+1} - a_n (multipliers masked).
PetscErrorCode GeneralizedAlphaScheme::localError(Vec work, double* err) const {
  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(work, -1.0, an_, a1_));
  if (keep_) PetscCall(VecPointwiseMult(work, keep_, work));
  PetscReal da = 0;
  PetscCall(VecNorm(work, NORM_INFINITY, &da));
  *err = h_ * h_ * std::abs(p_.beta - 1.0 / 6.0) * da;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
