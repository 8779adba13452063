// Finite rotations: exponential map, its tangent (left Jacobian), and the output
// parametrizations SPACAR Light reports (quaternion, axis-angle, Euler ZYX).
#pragma once
#include <array>

#include "sinew/linalg3.hpp"

namespace sinew {

/// R = exp(skew(theta)) (Rodrigues).
Mat3 expSO3(const Vec3& theta);
/// Left Jacobian T(theta) of the exponential map: exp(skew(theta + d)) = exp(skew(T d)) exp(skew(theta)) + O(d^2).
Mat3 dexpSO3(const Vec3& theta);
/// Rotation vector of R (|theta| in [0, pi]).
Vec3 logSO3(const Mat3& R);
/// Unit quaternion [q0, q1, q2, q3] (scalar first, q0 >= 0) of R.
std::array<double, 4> quaternionOf(const Mat3& R);
/// SPACAR Light's `r_axang` order: [angle (rad, in [0, pi]), axis_x, axis_y, axis_z]; identity: [0, 1, 0, 0].
std::array<double, 4> axisAngleOf(const Mat3& R);
/// Euler angles ZYX [rz, ry, rx] of R = Rz(rz) Ry(ry) Rx(rx).
Vec3 eulerZYXOf(const Mat3& R);

}  // namespace sinew
