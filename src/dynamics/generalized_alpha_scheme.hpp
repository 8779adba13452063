// Generalized alpha in the variant of Arnold & Brüls (2007), as Exudyn's GeneralizedAlpha solver uses it:
//   q_{n+1}  = q_n + h qd_n + h^2 (1/2 - beta) a_n + h^2 beta a_{n+1}
//   qd_{n+1} = qd_n + h (1 - gamma) a_n + h gamma a_{n+1}
//   (1 - alpha_m) a_{n+1} + alpha_m a_n = (1 - alpha_f) qdd_{n+1} + alpha_f qdd_n
//   M qdd_{n+1} + f_int(q_{n+1}, qd_{n+1}, t_{n+1}) = f_ext(t_{n+1})      (equilibrium at t_{n+1})
// with the algorithmic accelerations a_n as part of the state (a_0 = qdd_0).
#pragma once
#include "dynamics/time_scheme.hpp"

namespace sinew {

/// alpha_m = (2 rho - 1)/(rho + 1), alpha_f = rho/(rho + 1), gamma = 1/2 + alpha_f - alpha_m,
/// beta = (gamma + 1/2)^2 / 4 (rho = spectral radius at infinity).
struct GeneralizedAlphaParameters {
  double alphaM = 0, alphaF = 0, gamma = 0, beta = 0;
  static GeneralizedAlphaParameters fromSpectralRadius(double rho);
};

class GeneralizedAlphaScheme : public StepScheme {
 public:
  GeneralizedAlphaScheme(double spectralRadius, Vec like, Vec multipliers, Assembler* rotations);
  const GeneralizedAlphaParameters& parameters() const { return p_; }
  /// Cu = q_n + h qd_n + h^2 (1/2 - beta) a_n, the part of q_{n+1} known at the step start.
  PetscErrorCode beginStep(double h) override;
  /// q = q_n + h qd_n + h^2/2 a_n (= Cu + h^2 beta a_n).
  PetscErrorCode predict(Vec q) const override;
  /// a_{n+1} = (q_{n+1} - Cu)/(beta h^2), then qd_{n+1} and qdd_{n+1} by the update formulas.
  PetscErrorCode rates(Vec q) override;
  /// At (q_{n+1}, qd_{n+1}, qdd_{n+1}, t_{n+1}): dqd/dq = gamma/(beta h),
  /// dqdd/dq = (1 - alpha_m)/((1 - alpha_f) beta h^2).
  EvaluationPoint evaluation(Vec q) const override;
  /// Local error of q_{n+1} (Zienkiewicz & Xie 1991 type): h^2 |beta - 1/6| ||a_{n+1} - a_n||_inf
  /// over the coordinates (after rates; `work` a vector of the layout).
  PetscErrorCode localError(Vec work, double* err) const;

 private:
  GeneralizedAlphaParameters p_;
};

}  // namespace sinew
