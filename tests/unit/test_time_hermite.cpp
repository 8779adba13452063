// Cubic Hermite interpolation in time (math/time_hermite.hpp): the Newton starts of a -target_error
// level in time from the coarser level's steps (dynamics/level_time_reuse.cpp). Vectors: exact for
// cubics; rotations: exact for a constant spin whatever the turn, fourth order in the interval otherwise.
#include <gtest/gtest.h>

#include <cmath>

#include "math/time_hermite.hpp"
#include "rotation_test_support.hpp"
#include "sinew/rotation.hpp"

using namespace sinew;

namespace {
using test::maxDiff;

/// A rotation history R(t) = exp(phi(t)) R0 with a spin that changes in size and direction, and its
/// spatial angular velocity w = T(phi) dphi/dt.
const Mat3 kR0 = expSO3({0.4, -0.2, 1.1});
Vec3 phiOf(double t) { return {0.8 * t * t, 1.5 * t, -0.6 * t * t * t + 0.3 * t}; }
Vec3 phiDot(double t) { return {1.6 * t, 1.5, -1.8 * t * t + 0.3}; }
Mat3 rotationAt(double t) { return expSO3(phiOf(t)) * kR0; }
Vec3 spinAt(double t) { return dexpSO3(phiOf(t)) * phiDot(t); }
}  // namespace

TEST(TimeHermite, WeightsInterpolateCubics) {
  // x(t) = 1 + 2t - t^2 + 0.5 t^3 on [0.2, 0.9]: exact at every s
  const auto x = [](double t) { return 1 + 2 * t - t * t + 0.5 * t * t * t; };
  const auto xd = [](double t) { return 2 - 2 * t + 1.5 * t * t; };
  const double a = 0.2, b = 0.9, H = b - a;
  for (double s : {0.0, 0.25, 0.5, 0.8, 1.0}) {
    const HermiteWeights w = hermiteWeights(s);
    EXPECT_NEAR(w.h00 * x(a) + w.h10 * H * xd(a) + w.h01 * x(b) + w.h11 * H * xd(b), x(a + s * H), 1e-15);
  }
}

TEST(TimeHermite, InverseLeftJacobian) {
  // measured up to 2.1e-14 at |theta| = 2.3e-3: dexpSO3's (1 - cos t) / t^2 there
  for (const Vec3& t : {Vec3{1e-7, 0, 2e-7}, Vec3{1e-3, -2e-3, 5e-4}, Vec3{0.3, -1.2, 0.5}, Vec3{2.0, 1.0, -1.5}}) {
    EXPECT_LT(maxDiff(dexpInvSO3(t) * dexpSO3(t), identity3()), 1e-13) << t[0];
  }
}

TEST(TimeHermite, ConstantSpinIsExact) {
  // a turn of |w| H = 2.3 rad over the interval (a spin-up's coarse step): R(s) = exp(s H w) R_a
  const Vec3 w{0.3, -1.2, 2.0};
  const double H = 0.97;
  const Mat3 Rb = expSO3(H * w) * kR0;
  for (double s : {0.0, 0.3, 0.5, 0.75, 1.0}) {
    EXPECT_LT(maxDiff(hermiteRotation(kR0, w, Rb, w, H, s), expSO3(s * H * w) * kR0), 1e-14) << s;
  }
}

TEST(TimeHermite, FourthOrderInTheInterval) {
  // the midpoint of [t0, t0 + H]: the error falls 16x per halving of H (measured 15.x)
  const double t0 = 0.3;
  double previous = 0;
  for (double H : {0.4, 0.2, 0.1, 0.05}) {
    const Mat3 R = hermiteRotation(rotationAt(t0), spinAt(t0), rotationAt(t0 + H), spinAt(t0 + H), H, 0.5);
    const double err = norm(logSO3(R * transpose(rotationAt(t0 + 0.5 * H))));
    if (previous > 0) {
      EXPECT_GT(previous / err, 12.0) << H;
    }
    previous = err;
  }
  EXPECT_LT(previous, 1e-6);
}

TEST(TimeHermite, QuaternionRoundTrip) {
  for (const Vec3& t : {Vec3{0, 0, 0}, Vec3{0.3, -1.2, 0.5}, Vec3{3.1, 0.1, 0}}) {
    const Mat3 R = expSO3(t);
    const std::array<double, 4> q = quaternionOf(R);
    EXPECT_LT(maxDiff(rotationOfQuaternion(q.data()), R), 1e-15);
  }
}
