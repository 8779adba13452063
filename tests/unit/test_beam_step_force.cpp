// Energy-momentum step force of the corotational beam (src/elements/beam_step_force.cpp) and the
// Cayley rotary step (src/elements/rotary_momentum.hpp): exact work, zero resultants about the mid
// positions, the energy decay's dissipation, and the dual-number tangent against central differences.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "elements/beam_corotational.hpp"
#include "elements/rotary_momentum.hpp"
#include "sinew/rotation.hpp"
#include "beam_test_support.hpp"

using namespace sinew;

namespace {

using Modes = std::array<BeamMode, 6>;
constexpr BeamMode F = BeamMode::Flexible, Rg = BeamMode::Rigid, Rl = BeamMode::Released;


const Vec3 kXp{0.1, -0.2, 0.3}, kXq{1.3, 0.4, 0.1};

using State = test::BeamState;
State makeState(const Vec3& xp, const Mat3& Rp, const Vec3& xq, const Mat3& Rq) {
  State q{};
  for (int i = 0; i < 3; ++i) q[i] = xp[i], q[12 + i] = xq[i];
  for (int i = 0; i < 9; ++i) q[3 + i] = Rp[i], q[15 + i] = Rq[i];
  return q;
}

// A deformed, turned state: both ends moved by a rigid motion (turn Q about c, shift t) and deformed.
State randomState(std::mt19937& g, double def) {
  std::uniform_real_distribution<double> u(-1, 1);
  auto rv = [&](double s) { return Vec3{s * u(g), s * u(g), s * u(g)}; };
  const Mat3 Q = expSO3(rv(0.8));
  const Vec3 t = rv(0.5);
  return makeState(Q * kXp + t + rv(def), expSO3(rv(def)) * Q, Q * kXq + t + rv(def), expSO3(rv(def)) * Q);
}

struct Step {
  KernelOutput out;
  double work = 0, dU = 0;  // f . (dx, theta_c) and U(q1) - U(q0)
  Vec3 force{}, moment{};   // resultants about the origin with the mid positions
};

Step runStep(const BeamCorotational& b, const State& q0, const State& q1, double decay, const std::vector<double>& lambda,
             bool tangent = false) {
  StepForceInput in;
  in.q0 = q0.data();
  in.q1 = q1.data();
  in.lambda = lambda.empty() ? nullptr : lambda.data();
  in.decay = decay;
  Step s;
  b.stepForce(in, tangent, s.out);
  double U0 = 0, U1 = 0;
  b.strainEnergy(q0.data(), &U0);
  b.strainEnergy(q1.data(), &U1);
  s.dU = U1 - U0;
  for (int n = 0; n < 2; ++n) {
    const Vec3 dx = test::nodePosition(q1, n) - test::nodePosition(q0, n), xm = 0.5 * (test::nodePosition(q0, n) + test::nodePosition(q1, n));
    const Vec3 tc = cayleyVector(logSO3(test::nodeRotation(q1, n) * transpose(test::nodeRotation(q0, n))));
    const Vec3 fx{s.out.f[6 * n], s.out.f[6 * n + 1], s.out.f[6 * n + 2]};
    const Vec3 m{s.out.f[6 * n + 3], s.out.f[6 * n + 4], s.out.f[6 * n + 5]};
    s.work += dot(fx, dx) + dot(m, tc);
    s.force += fx;
    s.moment += cross(xm, fx) + m;
  }
  return s;
}

double fnorm(const KernelOutput& o) {
  double m = 0;
  for (int k = 0; k < 12; ++k) m = std::max(m, std::abs(o.f[k]));
  return m;
}

}  // namespace

TEST(BeamStepForce, WorkIsTheStrainEnergyChangeAndResultantsVanish) {
  std::mt19937 g(7);
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, test::comparableSection(), Modes{F, F, F, F, F, F}, false, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const State q0 = randomState(g, 0.05), q1 = randomState(g, 0.05);  // large turns between the ends of the step
    const Step s = runStep(b, q0, q1, 0.0, {});
    const double f = fnorm(s.out);
    EXPECT_NEAR(s.work, s.dU, 1e-13 * std::max(1.0, std::abs(s.dU))) << trial;
    EXPECT_LT(norm(s.force), 1e-14 * f) << trial;
    EXPECT_LT(norm(s.moment), 1e-13 * f) << trial;
  }
}

TEST(BeamStepForce, ReleasedAndRigidModes) {
  std::mt19937 g(11);
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, test::comparableSection(), Modes{F, Rg, F, Rl, F, F}, false, 1.0);
  const std::vector<double> lambda{0.37};
  for (int trial = 0; trial < 10; ++trial) {
    const State q0 = randomState(g, 0.05), q1 = randomState(g, 0.05);
    const Step s = runStep(b, q0, q1, 0.0, lambda);
    // the multiplier's work is lambda (g(q1) - g(q0)); with it the work is again the energy change
    const double g0 = b.generalizedStrains(q0.data())[1], g1 = b.generalizedStrains(q1.data())[1];
    EXPECT_NEAR(s.work, s.dU + lambda[0] * (g1 - g0), 1e-13 * std::max(1.0, std::abs(s.dU)));
    EXPECT_LT(norm(s.moment), 1e-13 * fnorm(s.out));
    EXPECT_NEAR(s.out.f[12], g1, 1e-15);  // the constraint row holds at the step's end
  }
}

TEST(BeamStepForce, EnergyDecayDissipates) {
  std::mt19937 g(3);
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, test::comparableSection(), Modes{F, F, F, F, F, F}, false, 1.0);
  const double xi = 0.3;
  for (int trial = 0; trial < 10; ++trial) {
    const State q0 = randomState(g, 0.05), q1 = randomState(g, 0.05);
    const Step s = runStep(b, q0, q1, xi, {});
    const auto e0 = b.generalizedStrains(q0.data()), e1 = b.generalizedStrains(q1.data());
    double D = 0;  // xi / 2 de^T S de
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) D += 0.5 * xi * (e1[i] - e0[i]) * b.stiffness()[6 * i + j] * (e1[j] - e0[j]);
    EXPECT_GT(D, 0.0);
    EXPECT_NEAR(s.work - s.dU, D, 1e-12 * std::max(1.0, std::abs(s.dU)));
    EXPECT_LT(norm(s.moment), 1e-13 * fnorm(s.out));
  }
}

TEST(BeamStepForce, TangentMatchesCentralDifferences) {
  std::mt19937 g(5);
  for (int variant = 0; variant < 2; ++variant) {
    const Modes modes = variant == 0 ? Modes{F, F, F, F, F, F} : Modes{F, Rg, F, Rl, F, F};
    const std::vector<double> lambda = variant == 0 ? std::vector<double>{} : std::vector<double>{0.37};
    const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, test::comparableSection(), modes, false, 1.0);
    const State q0 = randomState(g, 0.05), q1 = randomState(g, 0.05);
    const Step s = runStep(b, q0, q1, 0.2, lambda, true);
    const int n = 12 + b.numConstraints();
    ASSERT_EQ(s.out.K.size(), static_cast<size_t>(n * n));
    const double d = 1e-6;
    double err = 0, scale = 0;
    for (int c = 0; c < n; ++c) {
      KernelOutput op, om;
      if (c < 12) {
        op = runStep(b, q0, test::perturbed(q1, c, d), 0.2, lambda).out;
        om = runStep(b, q0, test::perturbed(q1, c, -d), 0.2, lambda).out;
      } else {
        std::vector<double> lp = lambda, lm = lambda;
        lp[c - 12] += d;
        lm[c - 12] -= d;
        op = runStep(b, q0, q1, 0.2, lp).out;
        om = runStep(b, q0, q1, 0.2, lm).out;
      }
      for (int r = 0; r < n; ++r) {
        const double fd = (op.f[r] - om.f[r]) / (2 * d), K = s.out.K[static_cast<size_t>(r) * n + c];
        err = std::max(err, std::abs(fd - K));
        scale = std::max(scale, std::abs(K));
      }
    }
    printf("step force tangent (variant %d): max |K - K_fd| / max |K| = %.2e\n", variant, err / scale);
    EXPECT_LT(err, 1e-8 * scale);
  }
}

TEST(BeamStepForce, SmallStepApproachesTheForce) {
  // q1 -> q0: the step force becomes the internal force of q0 (consistency of the scheme)
  std::mt19937 g(9);
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, test::comparableSection(), Modes{F, F, F, F, F, F}, false, 1.0);
  const State q0 = randomState(g, 0.05);
  State q1 = q0;
  for (int k = 0; k < 12; ++k) q1 = test::perturbed(q1, k, 1e-7 * (k % 3 - 1));
  KernelInput in;
  in.q = q0.data();
  KernelOutput o;
  b.evaluate(in, KernelNeeds{}, o);
  const Step s = runStep(b, q0, q1, 0.0, {});
  for (int k = 0; k < 12; ++k) EXPECT_NEAR(s.out.f[k], o.f[k], 1e-5 * fnorm(o));  // f(q_mid) - f(q0) = O(|q1 - q0|)
}

TEST(RotaryCayleyStep, DerivativeAndKineticEnergyIdentity) {
  const Mat3 J0{0.01, 0.002, -0.001, 0.002, 0.02, 0.003, -0.001, 0.003, 0.03};
  const Mat3 R0 = expSO3(Vec3{0.3, -0.7, 0.4});
  const Vec3 w0{1.2, -0.5, 2.0}, theta{0.25, -0.1, 0.3};
  const double h = 0.1, d = 1e-6;
  const RotaryMomentumStep s = rotaryCayleyStep(J0, R0, theta, w0, h);
  double err = 0, scale = 0;
  for (int c = 0; c < 3; ++c) {
    Vec3 tp = theta, tm = theta;
    tp[c] += d;
    tm[c] -= d;
    const Vec3 fd = (0.5 / d) * (rotaryCayleyStep(J0, R0, tp, w0, h).r - rotaryCayleyStep(J0, R0, tm, w0, h).r);
    for (int r = 0; r < 3; ++r) {
      err = std::max(err, std::abs(fd[r] - s.dr[3 * r + c]));
      scale = std::max(scale, std::abs(s.dr[3 * r + c]));
    }
  }
  EXPECT_LT(err, 1e-7 * scale);
  // r . theta_c = T1 - T0 for any theta (not only the torque-free one)
  const Mat3 R1 = expSO3(theta) * R0;
  const double T0 = 0.5 * dot(w0, R0 * J0 * transpose(R0) * w0), T1 = 0.5 * dot(s.w1, R1 * J0 * transpose(R1) * s.w1);
  EXPECT_NEAR(dot(s.r, cayleyVector(theta)), T1 - T0, 1e-14 * T0);
  // the Cayley vector: exp(theta) = cay(theta_c), n1 - n0 = theta_c x (n0 + n1) / 2
  const Vec3 tc = cayleyVector(theta), n0{0.3, 0.5, -0.8};
  const Vec3 n1 = expSO3(theta) * n0;
  EXPECT_LT(norm(n1 - n0 - cross(tc, 0.5 * (n0 + n1))), 1e-15);
  Mat3 C;
  cayleyVector(Vec3{1e-4, 2e-4, -1e-4}, &C);
  EXPECT_NEAR(C[0], 1.0 + 6e-8 / 12 + 1e-8 / 6, 1e-15);
}
