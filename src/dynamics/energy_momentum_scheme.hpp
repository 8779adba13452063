// The energy-momentum scheme (-dynamics_scheme energy_momentum; docs/dynamics.md, "Energy-momentum
// scheme"): the implicit midpoint rule's momentum balance with the internal forces of the step instead
// of those of the mid configuration,
//   M (qd_{n+1} - qd_n)/h + f_step(q_n, q_{n+1}) = f_ext(t_{n+1/2}),
//   x_{n+1} - x_n = h (v_n + v_{n+1}) / 2,   w_{n+1} = 2 theta_c / h - exp(theta) w_n,
// theta_c the Cayley vector of the rotation increment theta (R_{n+1} = exp(theta) R_n), and the rotary
// inertia as the momentum change ((J_s w)_{n+1} - (J_s w)_n)/h (Simo & Wong's form). The kernels' step
// force (ElementKernel::stepForce) does the work U(q_{n+1}) - U(q_n) on (x_{n+1} - x_n, theta_c) exactly
// and has no resultant force or moment about the mid positions, so the total energy and the linear and
// angular momenta of a free structure are conserved to the Newton tolerance (Simo & Tarnow 1992). With the
// energy decay xi > 0 (-dynamics_energy_decay) the stresses gain xi/2 S (eps_{n+1} - eps_n) and the
// energy decreases at every step by xi/2 (eps_{n+1} - eps_n)^T S (eps_{n+1} - eps_n).
#pragma once
#include "dynamics/time_scheme.hpp"

namespace sinew {

class EnergyMomentumScheme : public StepScheme {
 public:
  EnergyMomentumScheme(double decay, Vec like, Vec multipliers, Assembler* rotations);
  ~EnergyMomentumScheme() override;
  PetscErrorCode beginStep(double h) override;
  /// q = q_n + h qd_n.
  PetscErrorCode predict(Vec q) const override;
  /// qd_{n+1} (translations 2 (x_{n+1} - x_n)/h - v_n, spins 2 theta_c/h - exp(theta) w_n), the velocity
  /// change (qd_{n+1} - qd_n)/h (as a_{n+1} and qdd_{n+1}) and the mid velocity.
  PetscErrorCode rates(Vec q) override;
  /// At (q_{n+1}, qd_{n+1/2}, (qd_{n+1} - qd_n)/h, t_{n+1} - h/2) with the step forces: d/dq_{n+1} of the
  /// residual is K_step + (1/h) C + (2/h^2) M.
  EvaluationPoint evaluation(Vec q) const override;
  double decay() const { return decay_; }

 private:
  double decay_ = 0.0;
  Vec qc_ = nullptr, vm_ = nullptr;  ///< the iterate with Cayley rotation vectors; mid velocity
};

}  // namespace sinew
