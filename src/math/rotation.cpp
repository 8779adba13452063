// Finite rotations (rotation.hpp): Rodrigues exponential, left Jacobian, logarithm via a
// Shepperd quaternion (robust near 0 and pi), and the SPACAR Light output parametrizations.
#include "sinew/rotation.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {
namespace {

// sin(t)/t, (1 - cos t)/t^2, (t - sin t)/t^3 with Taylor series for small t (t2 = t^2).
void rodriguesCoefficients(double t2, double& a, double& b, double& c) {
  if (t2 < 1e-6) {  // truncation error < 1e-21 (next terms t^6/5040 etc.)
    a = 1.0 - t2 / 6.0 * (1.0 - t2 / 20.0);
    b = 0.5 - t2 / 24.0 * (1.0 - t2 / 30.0);
    c = 1.0 / 6.0 - t2 / 120.0 * (1.0 - t2 / 42.0);
  } else {
    const double t = std::sqrt(t2);
    const double s = std::sin(t), co = std::cos(t);
    a = s / t;
    b = (1.0 - co) / t2;
    c = (t - s) / (t2 * t);
  }
}

}  // namespace

// R = I + sin(t)/t K + (1 - cos t)/t^2 K^2, K = skew(theta)  (Rodrigues)
Mat3 expSO3(const Vec3& theta) {
  double a, b, c;
  rodriguesCoefficients(dot(theta, theta), a, b, c);
  const Mat3 K = skew(theta);
  return identity3() + a * K + b * (K * K);
}

// T = I + (1 - cos t)/t^2 K + (t - sin t)/t^3 K^2  (left Jacobian of exp on SO(3))
Mat3 dexpSO3(const Vec3& theta) {
  double a, b, c;
  rodriguesCoefficients(dot(theta, theta), a, b, c);
  const Mat3 K = skew(theta);
  return identity3() + b * K + c * (K * K);
}

// Shepperd's method: take the largest of 4 q0^2, 4 qi^2 as pivot, so no cancellation near pi.
std::array<double, 4> quaternionOf(const Mat3& R) {
  const double tr = R[0] + R[4] + R[8];
  std::array<double, 4> q{};
  const double d[4] = {tr, R[0], R[4], R[8]};
  const int k = static_cast<int>(std::max_element(d, d + 4) - d);
  if (k == 0) {
    const double s = 2.0 * std::sqrt(std::max(1.0 + tr, 0.0));  // s = 4 q0
    q = {0.25 * s, (R[7] - R[5]) / s, (R[2] - R[6]) / s, (R[3] - R[1]) / s};
  } else if (k == 1) {
    const double s = 2.0 * std::sqrt(std::max(1.0 + R[0] - R[4] - R[8], 0.0));  // 4 q1
    q = {(R[7] - R[5]) / s, 0.25 * s, (R[1] + R[3]) / s, (R[2] + R[6]) / s};
  } else if (k == 2) {
    const double s = 2.0 * std::sqrt(std::max(1.0 + R[4] - R[0] - R[8], 0.0));  // 4 q2
    q = {(R[2] - R[6]) / s, (R[1] + R[3]) / s, 0.25 * s, (R[5] + R[7]) / s};
  } else {
    const double s = 2.0 * std::sqrt(std::max(1.0 + R[8] - R[0] - R[4], 0.0));  // 4 q3
    q = {(R[3] - R[1]) / s, (R[2] + R[6]) / s, (R[5] + R[7]) / s, 0.25 * s};
  }
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double sgn = q[0] < 0.0 ? -1.0 : 1.0;
  for (double& v : q) v *= sgn / n;
  return q;
}

// theta = 2 atan2(|v|, q0) v/|v|; for small |v| the factor 2 atan2(s, q0)/s -> 2/q0 (series).
Vec3 logSO3(const Mat3& R) {
  const auto q = quaternionOf(R);
  const Vec3 v{q[1], q[2], q[3]};
  const double s = norm(v);
  double f;
  if (s < 1e-8)
    f = 2.0 / q[0] * (1.0 - s * s / (3.0 * q[0] * q[0]));
  else
    f = 2.0 * std::atan2(s, q[0]) / s;
  return f * v;
}

std::array<double, 4> axisAngleOf(const Mat3& R) {
  const auto q = quaternionOf(R);
  const Vec3 v{q[1], q[2], q[3]};
  const double s = norm(v);
  if (s < 1e-300) return {0.0, 1.0, 0.0, 0.0};
  return {2.0 * std::atan2(s, q[0]), v[0] / s, v[1] / s, v[2] / s};
}

// R = Rz(rz) Ry(ry) Rx(rx): R20 = -sin ry, R10/R00 = tan rz, R21/R22 = tan rx.
// At gimbal lock (cos ry = 0) only rz -+ rx is defined: rx = 0, rz = atan2(-R01, R11).
Vec3 eulerZYXOf(const Mat3& R) {
  const double cy = std::sqrt(R[0] * R[0] + R[3] * R[3]);
  const double ry = std::atan2(-R[6], cy);
  if (cy < 1e-12) return {std::atan2(-R[1], R[4]), ry, 0.0};
  return {std::atan2(R[3], R[0]), ry, std::atan2(R[7], R[8])};
}

}  // namespace sinew
