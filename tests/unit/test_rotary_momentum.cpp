// Midpoint-rule rotary momentum step (src/elements/rotary_momentum.hpp): its derivative against
// central finite differences, and the torque-free step keeps the spatial momentum (Simo & Wong 1991).
#include <gtest/gtest.h>

#include <cmath>

#include "elements/rotary_momentum.hpp"

using namespace sinew;

namespace {
const Mat3 kJ0{0.01, 0.002, -0.001, 0.002, 0.02, 0.003, -0.001, 0.003, 0.03};
const Mat3 kR0 = expSO3(Vec3{0.3, -0.7, 0.4});
const Vec3 kW0{1.2, -0.5, 2.0};
}  // namespace

TEST(RotaryMomentum, DerivativeMatchesFiniteDifferences) {
  const double h = 0.02;
  const Vec3 theta{0.05, -0.02, 0.07};
  const RotaryMomentumStep s = rotaryMomentumStep(kJ0, kR0, theta, kW0, h);
  const double d = 1e-6;
  double err = 0, scale = 0;
  for (int c = 0; c < 3; ++c) {
    Vec3 tp = theta, tm = theta;
    tp[c] += d;
    tm[c] -= d;
    const Vec3 fd = (0.5 / d) * (rotaryMomentumStep(kJ0, kR0, tp, kW0, h).r - rotaryMomentumStep(kJ0, kR0, tm, kW0, h).r);
    for (int r = 0; r < 3; ++r) {
      err = std::max(err, std::abs(fd[r] - s.dr[3 * r + c]));
      scale = std::max(scale, std::abs(s.dr[3 * r + c]));
    }
  }
  EXPECT_LT(err, 1e-7 * scale);
}

TEST(RotaryMomentum, TorqueFreeStepKeepsMomentumAndEnergy) {
  // r = 0 is the torque-free step: find theta by Newton with dr, then J_s1 w1 = J_s0 w0 and, the
  // rule being Simo & Wong's, the kinetic energy 1/2 w J_s w is kept too
  const double h = 0.05;
  Vec3 theta = h * kW0;
  RotaryMomentumStep s = rotaryMomentumStep(kJ0, kR0, theta, kW0, h);
  for (int it = 0; it < 30 && norm(s.r) > 1e-16; ++it) {
    // solve dr dtheta = -r (3x3, Cramer)
    const Mat3& A = s.dr;
    const double det = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) + A[2] * (A[3] * A[7] - A[4] * A[6]);
    Vec3 x;
    for (int k = 0; k < 3; ++k) {
      Mat3 B = A;
      for (int r = 0; r < 3; ++r) B[3 * r + k] = -s.r[r];
      x[k] = (B[0] * (B[4] * B[8] - B[5] * B[7]) - B[1] * (B[3] * B[8] - B[5] * B[6]) + B[2] * (B[3] * B[7] - B[4] * B[6])) / det;
    }
    theta = theta + x;
    s = rotaryMomentumStep(kJ0, kR0, theta, kW0, h);
  }
  const Mat3 R1 = expSO3(theta) * kR0;
  const Mat3 Js0 = kR0 * kJ0 * transpose(kR0), Js1 = R1 * kJ0 * transpose(R1);
  const Vec3 p0 = Js0 * kW0, p1 = Js1 * s.w1;
  EXPECT_LT(norm(p1 - p0), 1e-14 * norm(p0));
  const double T0 = 0.5 * dot(kW0, p0), T1 = 0.5 * dot(s.w1, p1);
  EXPECT_NEAR(T1, T0, 1e-13 * T0);
}
