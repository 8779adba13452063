// The implicit midpoint rule (-dynamics_scheme midpoint; docs/dynamics.md):
//   qd_{n+1} = 2 (q_{n+1} - q_n)/h - qd_n
//   M (qd_{n+1} - qd_n)/h + f_int(q_{n+1/2}, qd_{n+1/2}) = f_ext(t_{n+1/2}),
//   q_{n+1/2} = (q_n + q_{n+1})/2, qd_{n+1/2} = (qd_n + qd_{n+1})/2,
// spins by Simo & Wong (1991): w_{n+1} = 2 theta/h - exp(theta) w_n, theta = log(R_{n+1} R_n^T), the
// mid rotation exp(theta/2) R_n. It keeps linear and angular momentum exactly, and the energy of a
// linear system (a symplectic, symmetric rule).
#pragma once
#include "dynamics/time_scheme.hpp"

namespace sinew {

class MidpointScheme : public StepScheme {
 public:
  MidpointScheme(Vec like, Vec multipliers, Assembler* rotations);
  ~MidpointScheme() override;
  PetscErrorCode beginStep(double h) override;
  /// q = q_n + h qd_n.
  PetscErrorCode predict(Vec q) const override;
  /// qd_{n+1}, the velocity change (qd_{n+1} - qd_n)/h (as a_{n+1} and qdd_{n+1}) and the mid state.
  PetscErrorCode rates(Vec q) override;
  /// At (q_{n+1/2}, qd_{n+1/2}, (qd_{n+1} - qd_n)/h, t_{n+1} - h/2): d/dq_{n+1} of the residual is
  /// (K + (2/h) C + (4/h^2) M)/2 at the mid state.
  EvaluationPoint evaluation(Vec q) const override;
  /// With multipliers: 1 on their rows (their constraints hold at the step's end), else null.
  Vec constraintRows() const { return notKeep_; }
  /// With multipliers: 2 on their rows, 1 elsewhere (the Jacobian's row and column scale), else null.
  Vec constraintScale() const { return constraintScale_; }

 private:
  Vec qm_ = nullptr, vm_ = nullptr;  ///< mid state and velocity of the iterate
  Vec notKeep_ = nullptr, constraintScale_ = nullptr;
};

}  // namespace sinew
