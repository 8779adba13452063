#include "math/time_hermite.hpp"

#include <cmath>

#include "sinew/rotation.hpp"

namespace sinew {

HermiteWeights hermiteWeights(double s) {
  const double s2 = s * s, s3 = s2 * s;
  return {2 * s3 - 3 * s2 + 1, s3 - 2 * s2 + s, -2 * s3 + 3 * s2, s3 - s2};
}

// T^-1 = I - K/2 + (1/a^2) (1 - (a/2) cot(a/2)) K^2, K = skew(theta), a = |theta|; the coefficient of K^2
// is 1/12 + a^2/720 + a^4/30240 + O(a^6) for small a (below 1e-2: truncation below 1e-18).
Mat3 dexpInvSO3(const Vec3& theta) {
  const double a2 = dot(theta, theta), a = std::sqrt(a2);
  const double c = a < 1e-2 ? 1.0 / 12.0 + a2 / 720.0 + a2 * a2 / 30240.0 : (1.0 - 0.5 * a / std::tan(0.5 * a)) / a2;
  const Mat3 K = skew(theta);
  return identity3() - 0.5 * K + c * (K * K);
}

Mat3 hermiteRotation(const Mat3& Ra, const Vec3& wa, const Mat3& Rb, const Vec3& wb, double H, double s) {
  const Vec3 delta = logSO3(Rb * transpose(Ra));
  const HermiteWeights w = hermiteWeights(s);
  const Vec3 phi = w.h10 * (H * wa) + w.h01 * delta + w.h11 * (dexpInvSO3(delta) * (H * wb));
  return expSO3(phi) * Ra;
}

Mat3 rotationOfQuaternion(const double* q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

}  // namespace sinew
