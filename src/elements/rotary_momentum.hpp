// One step of the implicit midpoint rule for a body-frame rotary inertia J0 (a node's mominertia,
// or a lumped beam's section inertia), Simo & Wong (1991) in spatial form: with R1 = exp(theta) R0,
//   w1 = 2 theta / h - exp(theta) w0,     r = ((J_s w)_1 - (J_s w)_0) / h,   J_s = R J0 R^T,
// and the derivative dr/dtheta (T = dexp(theta), the left Jacobian: d(exp(theta)) = skew(T dtheta) exp(theta)):
//   dr/dtheta = [(J_s1 skew(w1) - skew(J_s1 w1)) T + J_s1 (2/h I + skew(exp(theta) w0) T)] / h.
// A pure kernel (no MPI, no PETSc); the midpoint rule's residual and Jacobian use it.
#pragma once
#include "sinew/linalg3.hpp"
#include "sinew/rotation.hpp"

#include <cmath>

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

/// The Cayley rotation vector of exp(theta): theta_c = 2 tan(phi / 2) / phi theta (phi = |theta| < pi), for
/// which cay(theta_c) = (I - skew(theta_c)/2)^-1 (I + skew(theta_c)/2) = exp(theta) and a vector turned
/// by it changes by exactly theta_c x (n0 + n1) / 2. dtheta_c / dtheta into *C when given.
inline Vec3 cayleyVector(const Vec3& theta, Mat3* C = nullptr) {
  const double phi = norm(theta);
  double g, dg;  // g(phi) = 2 tan(phi / 2) / phi and g'(phi) / phi
  if (phi < 1e-3) {
    const double p2 = phi * phi;
    g = 1.0 + p2 / 12.0 + p2 * p2 / 120.0;
    dg = 1.0 / 6.0 + p2 / 30.0;
  } else {
    const double t = std::tan(0.5 * phi), sec2 = 1.0 + t * t;
    g = 2.0 * t / phi;
    dg = (sec2 * phi - 2.0 * t) / (phi * phi * phi);
  }
  if (C) *C = g * identity3() + dg * outer(theta, theta);
  return g * theta;
}

/// The energy-momentum scheme's rotary step (Simo & Wong's form with the Cayley rotation vector, so
/// that the moments' work on theta_c is the kinetic energy change exactly): with R1 = exp(theta) R0,
///   w1 = 2 theta_c / h - exp(theta) w0,   r = ((J_s w)_1 - (J_s w)_0) / h,
/// so that r . theta_c = T1 - T0 exactly for any J0 (T = 1/2 w . J_s w; exp(theta) theta_c = theta_c),
/// and h r is the change of the spin momentum. dr / dtheta as above with 2/h dtheta_c / dtheta for 2/h I.
inline RotaryMomentumStep rotaryCayleyStep(const Mat3& J0, const Mat3& R0, const Vec3& theta, const Vec3& w0, double h) {
  const Mat3 E = expSO3(theta), R1 = E * R0, T = dexpSO3(theta);
  const Mat3 Js0 = R0 * J0 * transpose(R0), Js1 = R1 * J0 * transpose(R1);
  const Vec3 ew0 = E * w0;
  Mat3 C;
  const Vec3 thetaC = cayleyVector(theta, &C);
  RotaryMomentumStep s;
  s.w1 = (2.0 / h) * thetaC - ew0;
  const Vec3 p1 = Js1 * s.w1;
  s.r = (1.0 / h) * (p1 - Js0 * w0);
  s.dr = (1.0 / h) * ((Js1 * skew(s.w1) + (-1.0) * skew(p1)) * T + Js1 * ((2.0 / h) * C + skew(ew0) * T));
  return s;
}

}  // namespace sinew
