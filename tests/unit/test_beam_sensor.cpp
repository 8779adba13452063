// Sensors along a corotational beam element (BeamCorotational::sensorValue,
// src/elements/beam_corotational_sensor.cpp): frame invariance, rates = time derivatives of the
// field, rigid motion of a straight element, released ends.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "elements/beam_corotational.hpp"
#include "sinew/rotation.hpp"

using namespace sinew;

namespace {

constexpr BeamMode F = BeamMode::Flexible, Rl = BeamMode::Released;

BeamSection section() {
  BeamSection s;
  s.EA = 3.0; s.GIt = 0.7; s.EIy = 1.3; s.EIz = 0.9; s.kGAy = 40.0; s.kGAz = 25.0;
  return s;
}

Vec3 randomVec(std::mt19937& g, double a) {
  std::uniform_real_distribution<double> u(-a, a);
  return {u(g), u(g), u(g)};
}

// state of both nodes: x, R (12 values each)
std::array<double, 24> state(const Vec3& xp, const Mat3& Rp, const Vec3& xq, const Mat3& Rq) {
  std::array<double, 24> q{};
  for (int i = 0; i < 3; ++i) q[i] = xp[i], q[12 + i] = xq[i];
  for (int i = 0; i < 9; ++i) q[3 + i] = Rp[i], q[15 + i] = Rq[i];
  return q;
}

Vec3 value(const BeamCorotational& b, const char* var, double s, const std::array<double, 24>& q,
           const double* rates = nullptr) {
  const auto v = b.sensorValue(var, s, q.data(), nullptr, rates, nullptr);
  return {v[0], v[1], v[2]};
}

double maxAbs(const Vec3& a) { return std::max({std::abs(a[0]), std::abs(a[1]), std::abs(a[2])}); }

const Vec3 kXp{0.1, -0.2, 0.3}, kXq{1.1, 0.4, 0.1};

// a deformed state: node translations of 0.05 and end rotations of 0.2 rad about random axes
std::array<double, 24> deformed(std::mt19937& g) {
  return state(kXp + randomVec(g, 0.05), expSO3(randomVec(g, 0.2)), kXq + randomVec(g, 0.05), expSO3(randomVec(g, 0.2)));
}

}  // namespace

TEST(BeamSensor, RigidMotionOfTheDeformedElement) {
  // x -> Q x + c, R -> Q R: Position and the section frame follow, section forces stay
  std::mt19937 g(31);
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, section(), {F, F, F, F, F, F}, false, 1.0);
  double worst = 0;
  for (int r = 0; r < 5; ++r) {
    const auto q = deformed(g);
    const Mat3 Q = expSO3(randomVec(g, 2.0));
    const Vec3 c = randomVec(g, 1.0);
    const auto qm = state(Q * Vec3{q[0], q[1], q[2]} + c, Q * Mat3{q[3], q[4], q[5], q[6], q[7], q[8], q[9], q[10], q[11]},
                          Q * Vec3{q[12], q[13], q[14]} + c,
                          Q * Mat3{q[15], q[16], q[17], q[18], q[19], q[20], q[21], q[22], q[23]});
    for (double s : {0.0, 0.3, 0.5, 0.8, 1.0}) {
      worst = std::max(worst, maxAbs(value(b, "Position", s, qm) - (Q * value(b, "Position", s, q) + c)));
      const Mat3 d = expSO3(value(b, "Rotation", s, qm)) - Q * expSO3(value(b, "Rotation", s, q));
      for (double x : d) worst = std::max(worst, std::abs(x));
      for (const char* v : {"ForceLocal", "TorqueLocal"})
        worst = std::max(worst, maxAbs(value(b, v, s, qm) - value(b, v, s, q)));
    }
  }
  std::printf("  rigid motion: max difference %.2e\n", worst);
  EXPECT_LT(worst, 1e-12);  // measured 2.2e-15
}

TEST(BeamSensor, RatesAreTimeDerivativesOfTheField) {
  // Velocity / AngularVelocity vs central differences of Position / Rotation along x + t v,
  // exp(t w) R with h = 1e-4 (truncation ~1e-8)
  std::mt19937 g(32);
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, section(), {F, F, F, F, F, F}, false, 1.0);
  double worst = 0;
  for (int r = 0; r < 5; ++r) {
    const auto q = deformed(g);
    double rates[12];
    for (int k = 0; k < 4; ++k) {
      const Vec3 v = randomVec(g, 1.0);
      for (int i = 0; i < 3; ++i) rates[3 * k + i] = v[i];
    }
    const double h = 1e-4;
    auto moved = [&](double t) {
      std::array<double, 24> qt = q;
      for (int n = 0; n < 2; ++n) {
        for (int i = 0; i < 3; ++i) qt[12 * n + i] += t * rates[6 * n + i];
        const Mat3 R = expSO3(t * Vec3{rates[6 * n + 3], rates[6 * n + 4], rates[6 * n + 5]}) *
                       Mat3{q[12 * n + 3], q[12 * n + 4], q[12 * n + 5], q[12 * n + 6], q[12 * n + 7],
                            q[12 * n + 8], q[12 * n + 9], q[12 * n + 10], q[12 * n + 11]};
        for (int i = 0; i < 9; ++i) qt[12 * n + 3 + i] = R[i];
      }
      return qt;
    };
    const auto qa = moved(h), qb = moved(-h);
    for (double s : {0.0, 0.25, 0.5, 0.7, 1.0}) {
      const Vec3 v = value(b, "Velocity", s, q, rates);
      const Vec3 vfd = (0.5 / h) * (value(b, "Position", s, qa) - value(b, "Position", s, qb));
      const Vec3 w = value(b, "AngularVelocity", s, q, rates);
      const Vec3 wfd = (0.5 / h) * logSO3(expSO3(value(b, "Rotation", s, qa)) * transpose(expSO3(value(b, "Rotation", s, qb))));
      worst = std::max({worst, maxAbs(v - vfd) / maxAbs(v), maxAbs(w - wfd) / maxAbs(w)});
    }
  }
  std::printf("  rates vs central differences of the field: max relative difference %.2e\n", worst);
  EXPECT_LT(worst, 1e-6);  // measured 5.9e-9
}

TEST(BeamSensor, RigidMotionOfTheStraightElementIsExact) {
  // straight unloaded element turning about c with w and moving with u: v(s) = u + w x (x(s) - c)
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, section(), {F, F, F, F, F, F}, false, 1.0);
  const auto q = state(kXp, identity3(), kXq, identity3());
  const Vec3 w{0.3, -1.2, 0.7}, u{0.5, 0.1, -0.2}, c{0.4, 0.3, -0.1};
  double rates[12];
  for (int i = 0; i < 3; ++i) {
    rates[i] = (u + cross(w, kXp - c))[i];
    rates[6 + i] = (u + cross(w, kXq - c))[i];
    rates[3 + i] = rates[9 + i] = w[i];
  }
  double worst = 0;
  for (double s : {0.2, 0.5, 0.9}) {
    const Vec3 x = kXp + s * (kXq - kXp);
    worst = std::max(worst, maxAbs(value(b, "Velocity", s, q, rates) - (u + cross(w, x - c))));
    worst = std::max(worst, maxAbs(value(b, "AngularVelocity", s, q, rates) - w));
    worst = std::max(worst, maxAbs(value(b, "Position", s, q) - x));
  }
  std::printf("  straight element, rigid motion: max difference %.2e\n", worst);
  EXPECT_LT(worst, 1e-9);  // measured 3.3e-11 (the central difference of the rates)
}

TEST(BeamSensor, ReleasedEndTakesTheElasticSlope) {
  // mode 3 released (hinge about local y at p), Euler-Bernoulli: q turned by a about local y gives
  // the end slope -a/2 at p (pinned-fixed beam), so the section at s = 0 turns by -a/2, not as node p
  BeamSection sec = section();
  sec.kGAy = sec.kGAz = 0.0;
  const double L = 1.0, a = 1e-3;
  // chord along x, orien y: local y = global y, local z = global z
  const BeamCorotational b({0, 0, 0}, {L, 0, 0}, Vec3{0, 1, 0}, sec, {F, F, Rl, F, F, F}, false, 1.0);
  const auto q = state({0, 0, 0}, identity3(), {L, 0, 0}, expSO3(Vec3{0, a, 0}));
  const Vec3 r0 = value(b, "Rotation", 0.0, q), r1 = value(b, "Rotation", 1.0, q);
  std::printf("  released end: slope at s = 0 %.6e (expected %.6e), at s = 1 %.6e\n", r0[1], -a / 2, r1[1]);
  EXPECT_NEAR(r0[1], -a / 2, 1e-9);
  EXPECT_NEAR(r1[1], a, 1e-15);
  // the moment vanishes at the hinge and is 3 EI a / L at q
  const Vec3 m0 = value(b, "TorqueLocal", 0.0, q), m1 = value(b, "TorqueLocal", 1.0, q);
  EXPECT_NEAR(m0[1], 0.0, 1e-9);
  EXPECT_NEAR(m1[1], 3 * sec.EIy * a / L, 1e-6 * 3 * sec.EIy * a / L);
}

TEST(BeamSensor, UnknownVariableThrows) {
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, section(), {F, F, F, F, F, F}, false, 1.0);
  const auto q = state(kXp, identity3(), kXq, identity3());
  EXPECT_THROW(b.sensorValue("Acceleration", 0.5, q.data(), nullptr, nullptr, nullptr), std::invalid_argument);
}
