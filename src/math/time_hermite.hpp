// Cubic Hermite interpolation in time, for the Newton starts a -target_error level in time takes from
// the coarser level's time steps (dynamics/level_time_reuse.cpp): of a vector from its values and rates
// at the ends of an interval of length H, and of a rotation from its end rotations and spatial angular
// velocities, R(s) = exp(phi(s)) R_a with phi the cubic Hermite of the rotation vector relative to R_a:
//   phi(0) = 0, phi(1) = log(R_b R_a^T), phi'(0) = H w_a, phi'(1) = T(phi(1))^-1 H w_b
// (w = T(phi) dphi/dt for R = exp(phi) R_a, T the left Jacobian of exp), exact for a constant spin.
#pragma once
#include "sinew/linalg3.hpp"

namespace sinew {

/// The cubic Hermite basis at s in [0, 1]: x(s) = h00 x_a + h10 H x'_a + h01 x_b + h11 H x'_b.
struct HermiteWeights {
  double h00 = 0, h10 = 0, h01 = 0, h11 = 0;
};
HermiteWeights hermiteWeights(double s);

/// Inverse of the left Jacobian of exp (rotation.hpp's dexpSO3): T(theta)^-1.
Mat3 dexpInvSO3(const Vec3& theta);

/// The rotation at s in [0, 1] of the interval of length H from (Ra, wa) to (Rb, wb), w spatial angular
/// velocities (R' R^T = skew(w)).
Mat3 hermiteRotation(const Mat3& Ra, const Vec3& wa, const Mat3& Rb, const Vec3& wb, double H, double s);

/// The rotation of the unit quaternion q = [q0, q1, q2, q3] (scalar first; rotation.hpp's quaternionOf).
Mat3 rotationOfQuaternion(const double* q);

}  // namespace sinew
