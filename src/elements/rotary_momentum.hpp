// One step of the implicit midpoint rule for a body-frame rotary inertia J0 (a node's mominertia,
// or a lumped beam's section inertia), Simo & Wong (1991) in spatial form: with R1 = exp(theta) R0,
//   w1 = 2 theta / h - exp(theta) w0,     r = ((J_s w)_1 - (J_s w)_0) / h,   J_s = R J0 R^T,
// and the derivative dr/dtheta (T = dexp(theta), the left Jacobian: d(exp(theta)) = skew(T dtheta) exp(theta)):
//   dr/dtheta = [(J_s1 skew(w1) - skew(J_s1 w1)) T + J_s1 (2/h I + skew(exp(theta) w0) T)] / h.
// A pure kernel (no MPI, no PETSc); the midpoint rule's residual and Jacobian use it.
#pragma once
#include "sinew/linalg3.hpp"
#include "sinew/rotation.hpp"

namespace sinew {

struct RotaryMomentumStep {
  Vec3 r;   ///< momentum change over h
  Vec3 w1;  ///< spin at the step's end
  Mat3 dr;  ///< d r / d theta
};

inline RotaryMomentumStep rotaryMomentumStep(const Mat3& J0, const Mat3& R0, const Vec3& theta, const Vec3& w0, double h) {
  const Mat3 E = expSO3(theta), R1 = E * R0, T = dexpSO3(theta);
  const Mat3 Js0 = R0 * J0 * transpose(R0), Js1 = R1 * J0 * transpose(R1);
  const Vec3 ew0 = E * w0;
  RotaryMomentumStep s;
  s.w1 = (2.0 / h) * theta - ew0;
  const Vec3 p1 = Js1 * s.w1;
  s.r = (1.0 / h) * (p1 - Js0 * w0);
  s.dr = (1.0 / h) * ((Js1 * skew(s.w1) + (-1.0) * skew(p1)) * T + Js1 * ((2.0 / h) * identity3() + skew(ew0) * T));
  return s;
}

}  // namespace sinew
