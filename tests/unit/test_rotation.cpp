// Finite rotation utilities (rotation.hpp): round trips and the left Jacobian.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "rotation_test_support.hpp"
#include "sinew/rotation.hpp"

using namespace sinew;

namespace {
using test::maxDiff;
Mat3 quatToMat(const std::array<double, 4>& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
          2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
}
Mat3 Rx(double a) { return {1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a)}; }
Mat3 Ry(double a) { return {std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a)}; }
Mat3 Rz(double a) { return {std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1}; }
Vec3 randomUnit(std::mt19937& g) {
  std::normal_distribution<double> n;
  Vec3 v{n(g), n(g), n(g)};
  return (1.0 / norm(v)) * v;
}
}  // namespace

TEST(Rotation, ExpMatchesAxisRotations) {
  // exp(a e_x) = Rx(a) etc.; measured error <= 2.2e-16
  for (double a : {1e-9, 0.3, 2.0, 3.1}) {
    EXPECT_LT(maxDiff(expSO3({a, 0, 0}), Rx(a)), 1e-15);
    EXPECT_LT(maxDiff(expSO3({0, a, 0}), Ry(a)), 1e-15);
    EXPECT_LT(maxDiff(expSO3({0, 0, a}), Rz(a)), 1e-15);
  }
}

TEST(Rotation, ExpIsOrthogonal) {
  std::mt19937 g(1);
  for (double t : {0.0, 1e-10, 1e-4, 0.5, 3.0, std::numbers::pi}) {
    const Mat3 R = expSO3(t * randomUnit(g));
    EXPECT_LT(maxDiff(R * transpose(R), identity3()), 2e-15);  // measured 7.8e-16
  }
}

TEST(Rotation, LogExpRoundTripIncludingZeroAndPi) {
  std::mt19937 g(2);
  const double pi = std::numbers::pi;
  double worst = 0;
  for (double t : {0.0, 1e-12, 1e-7, 1e-3, 0.7, 2.5, pi - 1e-3, pi - 1e-7}) {
    for (int r = 0; r < 20; ++r) {
      const Vec3 th = t * randomUnit(g);
      const Vec3 back = logSO3(expSO3(th));
      worst = std::max(worst, norm(back - th));
    }
  }
  // Shepperd pivoting keeps full accuracy at 0 and near pi: measured worst 9.2e-16 (t = 2.5, pi - 1e-7)
  EXPECT_LT(worst, 1e-14);
  // exactly pi: any of +-theta is correct; the rotation must be reproduced
  const Vec3 th = pi * Vec3{0.6, 0.0, 0.8};
  EXPECT_LT(maxDiff(expSO3(logSO3(expSO3(th))), expSO3(th)), 1e-14);
  EXPECT_NEAR(norm(logSO3(expSO3(th))), pi, 1e-14);
  EXPECT_EQ(norm(logSO3(identity3())), 0.0);
}

TEST(Rotation, QuaternionRoundTripAndSign) {
  std::mt19937 g(3);
  for (double t : {0.0, 1e-9, 0.4, 2.0, 3.14159}) {
    const Vec3 ax = randomUnit(g);
    const Mat3 R = expSO3(t * ax);
    const auto q = quaternionOf(R);
    EXPECT_GE(q[0], 0.0);
    EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0, 1e-15);
    EXPECT_LT(maxDiff(quatToMat(q), R), 1e-15);  // measured <= 4.4e-16
    EXPECT_NEAR(q[0], std::cos(t / 2), 1e-15);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(q[1 + i], std::sin(t / 2) * ax[i], 1e-15);
  }
}

TEST(Rotation, AxisAngle) {
  const Vec3 ax{0.0, 0.6, -0.8};
  const auto aa = axisAngleOf(expSO3(2.2 * ax));
  // SPACAR Light's order [angle; axis] (issue 10, item 3)
  EXPECT_NEAR(aa[0], 2.2, 1e-15);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(aa[1 + i], ax[i], 1e-15);
  const auto z = axisAngleOf(identity3());
  EXPECT_EQ(z[0], 0.0);
  EXPECT_EQ(z[1], 1.0);
}

TEST(Rotation, EulerZYXRoundTripAndGimbalLock) {
  std::mt19937 g(4);
  std::uniform_real_distribution<double> u(-3.0, 3.0), v(-1.5, 1.5);
  for (int r = 0; r < 50; ++r) {
    const double a = u(g), b = v(g), c = u(g);
    const Vec3 e = eulerZYXOf(Rz(a) * Ry(b) * Rx(c));
    EXPECT_NEAR(e[0], a, 1e-13);
    EXPECT_NEAR(e[1], b, 1e-13);
    EXPECT_NEAR(e[2], c, 1e-13);
  }
  for (double b : {std::numbers::pi / 2, -std::numbers::pi / 2}) {
    const Mat3 R = Rz(0.7) * Ry(b) * Rx(0.2);
    const Vec3 e = eulerZYXOf(R);
    EXPECT_LT(maxDiff(Rz(e[0]) * Ry(e[1]) * Rx(e[2]), R), 1e-15);
  }
}

TEST(Rotation, DexpMatchesFiniteDifferences) {
  // exp(theta + h d) exp(theta)^T = exp(h T d) + O(h^2): central differences of the rotation vector.
  std::mt19937 g(5);
  double worst = 0;
  for (double t : {0.0, 1e-6, 1e-3, 0.8, 2.5, 3.1}) {
    const Vec3 th = t * randomUnit(g);
    const Mat3 T = dexpSO3(th);
    const Mat3 Rt = transpose(expSO3(th));
    const double h = 1e-5;
    for (int k = 0; k < 3; ++k) {
      Vec3 d{};
      d[k] = h;
      const Vec3 wp = logSO3(expSO3(th + d) * Rt), wm = logSO3(expSO3(th - d) * Rt);
      const Vec3 fd = (0.5 / h) * (wp - wm);
      worst = std::max(worst, norm(fd - column(T, k)));
    }
  }
  EXPECT_LT(worst, 1e-8);  // measured 2.3e-11 (truncation h^2 + roundoff eps/h)
  EXPECT_LT(maxDiff(dexpSO3({0, 0, 0}), identity3()), 1e-300);
}
