// The step schemes of src/dynamics/time_scheme.hpp on a linear oscillator M qdd + K q = 0 with two
// degrees of freedom (no scene, one process): generalized alpha's update formulas are the Newmark
// relations, the midpoint rule keeps the energy of a linear system, and a state copied out and put
// back continues bit for bit.
#include <gtest/gtest.h>
#include <petscvec.h>

#include <array>
#include <cmath>
#include <memory>

#include "dynamics/generalized_alpha_scheme.hpp"
#include "dynamics/midpoint_scheme.hpp"

namespace {

using sinew::EvaluationPoint;
using sinew::GeneralizedAlphaScheme;
using sinew::MidpointScheme;
using sinew::SchemeState;
using sinew::StepScheme;

using Vec2 = std::array<double, 2>;
using Mat2 = std::array<Vec2, 2>;

// two masses on springs: wall -k1- m1 -k2- m2
const Mat2 kMass{{{2.0, 0.0}, {0.0, 1.0}}};
const Mat2 kStiffness{{{300.0, -100.0}, {-100.0, 100.0}}};

Vec2 mult(const Mat2& A, const Vec2& x) { return {A[0][0] * x[0] + A[0][1] * x[1], A[1][0] * x[0] + A[1][1] * x[1]}; }
double dot(const Vec2& x, const Vec2& y) { return x[0] * y[0] + x[1] * y[1]; }
Vec2 solve(const Mat2& A, const Vec2& b) {
  const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
  return {(A[1][1] * b[0] - A[0][1] * b[1]) / det, (A[0][0] * b[1] - A[1][0] * b[0]) / det};
}

Vec2 get(Vec v) {
  const PetscScalar* a = nullptr;
  Vec2 x{};
  EXPECT_EQ(VecGetArrayRead(v, &a), 0);
  x = {a[0], a[1]};
  EXPECT_EQ(VecRestoreArrayRead(v, &a), 0);
  return x;
}
void set(Vec v, const Vec2& x) {
  PetscScalar* a = nullptr;
  ASSERT_EQ(VecGetArray(v, &a), 0);
  a[0] = x[0];
  a[1] = x[1];
  ASSERT_EQ(VecRestoreArray(v, &a), 0);
}

struct Vectors {  // four vectors of the oscillator's layout
  std::array<Vec, 4> v{};
  Vectors() {
    for (Vec& x : v) EXPECT_EQ(VecCreateSeq(PETSC_COMM_SELF, 2, &x), 0);
  }
  ~Vectors() {
    for (Vec& x : v) VecDestroy(&x);
  }
  SchemeState state() const { return {v[0], v[1], v[2], v[3]}; }
};

/// Puts q0 at rest with qdd0 = a0 = -M^-1 K q0 into the scheme.
void start(StepScheme& scheme, const Vec2& q0) {
  const Vec2 f = mult(kStiffness, q0);
  const Vec2 qdd0 = solve(kMass, {-f[0], -f[1]});
  Vectors s;
  set(s.v[0], q0);
  set(s.v[1], {0.0, 0.0});
  set(s.v[2], qdd0);
  set(s.v[3], qdd0);
  ASSERT_EQ(scheme.restore(s.state()), 0);
}

/// One step of size h: Newton on the step equation r = M qdd + K q at the scheme's evaluation point,
/// J = jacobianScale (K + shiftA M) (exact after one iteration; a second one polishes), then commit.
void step(StepScheme& scheme, Vec U, double h) {
  ASSERT_EQ(scheme.beginStep(h), 0);
  ASSERT_EQ(scheme.predict(U), 0);
  for (int it = 0; it < 2; ++it) {
    ASSERT_EQ(scheme.rates(U), 0);
    const EvaluationPoint e = scheme.evaluation(U);
    const Vec2 m = mult(kMass, get(e.qdd)), k = mult(kStiffness, get(e.q));
    const Vec2 r{m[0] + k[0], m[1] + k[1]};
    Mat2 J{};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) J[i][j] = e.jacobianScale * (kStiffness[i][j] + e.shiftA * kMass[i][j]);
    const Vec2 du = solve(J, r), u = get(U);
    set(U, {u[0] - du[0], u[1] - du[1]});
  }
  ASSERT_EQ(scheme.rates(U), 0);
  ASSERT_EQ(scheme.commit(U), 0);
}

double energy(const StepScheme& scheme) {
  const SchemeState s = scheme.state();
  const Vec2 q = get(s.q), v = get(s.qd);
  return 0.5 * dot(v, mult(kMass, v)) + 0.5 * dot(q, mult(kStiffness, q));
}

struct Oscillator : ::testing::Test {
  Vec like = nullptr, U = nullptr;
  void SetUp() override {
    ASSERT_EQ(VecCreateSeq(PETSC_COMM_SELF, 2, &like), 0);
    ASSERT_EQ(VecDuplicate(like, &U), 0);
  }
  void TearDown() override {
    VecDestroy(&U);
    VecDestroy(&like);
  }
};

TEST_F(Oscillator, GeneralizedAlphaParametersOfSpectralRadius) {
  // rho = 1: the trapezoidal rule (average acceleration), alpha_m = alpha_f = 1/2, gamma = 1/2, beta = 1/4
  const auto p1 = sinew::GeneralizedAlphaParameters::fromSpectralRadius(1.0);
  EXPECT_DOUBLE_EQ(p1.alphaM, 0.5);
  EXPECT_DOUBLE_EQ(p1.alphaF, 0.5);
  EXPECT_DOUBLE_EQ(p1.gamma, 0.5);
  EXPECT_DOUBLE_EQ(p1.beta, 0.25);
  // second order for any rho: gamma = 1/2 + alpha_f - alpha_m
  const auto p = sinew::GeneralizedAlphaParameters::fromSpectralRadius(0.6);
  EXPECT_DOUBLE_EQ(p.gamma, 0.5 + p.alphaF - p.alphaM);
}

TEST_F(Oscillator, GeneralizedAlphaUpdatesAreTheNewmarkRelations) {
  GeneralizedAlphaScheme scheme(0.7, like, nullptr, nullptr);
  const auto& p = scheme.parameters();
  start(scheme, {0.01, 0.02});
  const double h = 0.01;
  for (int n = 0; n < 50; ++n) {
    const SchemeState s = scheme.state();
    const Vec2 qn = get(s.q), vn = get(s.qd), an = get(s.a), qddn = get(s.qdd);
    step(scheme, U, h);
    const Vec2 q1 = get(s.q), v1 = get(s.qd), a1 = get(s.a), qdd1 = get(s.qdd);
    for (int i = 0; i < 2; ++i) {
      const double tol = 1e-13 * (std::abs(q1[i]) + h * std::abs(vn[i]) + h * h * (std::abs(an[i]) + std::abs(a1[i])));
      EXPECT_NEAR(q1[i], qn[i] + h * vn[i] + h * h * ((0.5 - p.beta) * an[i] + p.beta * a1[i]), tol) << "step " << n;
      EXPECT_NEAR(v1[i], vn[i] + h * ((1.0 - p.gamma) * an[i] + p.gamma * a1[i]),
                  1e-13 * (std::abs(vn[i]) + h * (std::abs(an[i]) + std::abs(a1[i]))))
          << "step " << n;
      EXPECT_NEAR((1.0 - p.alphaM) * a1[i] + p.alphaM * an[i], (1.0 - p.alphaF) * qdd1[i] + p.alphaF * qddn[i],
                  1e-13 * (std::abs(a1[i]) + std::abs(an[i]) + std::abs(qdd1[i]) + std::abs(qddn[i])))
          << "step " << n;
    }
    // equilibrium at t_{n+1}: M qdd_{n+1} + K q_{n+1} = 0
    const Vec2 m = mult(kMass, qdd1), k = mult(kStiffness, q1);
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(m[i] + k[i], 0.0, 1e-12 * (std::abs(m[i]) + std::abs(k[i])));
  }
}

TEST_F(Oscillator, MidpointRuleKeepsTheEnergyOfALinearSystem) {
  MidpointScheme scheme(like, nullptr, nullptr);
  start(scheme, {0.01, -0.02});
  const double e0 = energy(scheme);
  // h omega_max ~ 0.2 and 2000 steps: many periods of both modes
  const double h = 0.01;
  double drift = 0.0;
  for (int n = 0; n < 2000; ++n) {
    const SchemeState s = scheme.state();
    const Vec2 qn = get(s.q), vn = get(s.qd);
    step(scheme, U, h);
    const Vec2 q1 = get(s.q), v1 = get(s.qd);
    // the rule itself: qd_{n+1} = 2 (q_{n+1} - q_n)/h - qd_n, M (qd_{n+1} - qd_n)/h + K (q_n + q_{n+1})/2 = 0
    const Vec2 m = mult(kMass, {(v1[0] - vn[0]) / h, (v1[1] - vn[1]) / h});
    const Vec2 k = mult(kStiffness, {0.5 * (qn[0] + q1[0]), 0.5 * (qn[1] + q1[1])});
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(v1[i], 2.0 * (q1[i] - qn[i]) / h - vn[i], 1e-12 * (std::abs(v1[i]) + std::abs(vn[i])));
      EXPECT_NEAR(m[i] + k[i], 0.0, 1e-10 * (std::abs(m[i]) + std::abs(k[i])));
    }
    drift = std::max(drift, std::abs(energy(scheme) - e0));
  }
  EXPECT_LT(drift, 1e-12 * e0);
  // generalized alpha with rho < 1 damps the high mode: its energy decays
  GeneralizedAlphaScheme damped(0.5, like, nullptr, nullptr);
  start(damped, {0.01, -0.02});
  for (int n = 0; n < 2000; ++n) step(damped, U, 0.01);
  EXPECT_LT(energy(damped), (1.0 - 1e-6) * e0);
}

/// Runs `first` steps, copies the state out, runs `then` more; a new scheme restored from the copy
/// runs `then` steps to the same state, bit for bit.
template <class Make>
void expectRestartBitForBit(Vec U, Make make) {
  std::unique_ptr<StepScheme> run = make();
  start(*run, {0.01, 0.03});
  for (int n = 0; n < 17; ++n) step(*run, U, 0.005);
  Vectors saved;
  ASSERT_EQ(run->copyState(saved.state()), 0);
  for (int n = 0; n < 23; ++n) step(*run, U, 0.005);
  std::unique_ptr<StepScheme> resumed = make();
  ASSERT_EQ(resumed->restore(saved.state()), 0);
  for (int n = 0; n < 23; ++n) step(*resumed, U, 0.005);
  const SchemeState a = run->state(), b = resumed->state();
  for (auto [x, y] : {std::pair{a.q, b.q}, std::pair{a.qd, b.qd}, std::pair{a.a, b.a}, std::pair{a.qdd, b.qdd}}) {
    const Vec2 u = get(x), w = get(y);
    EXPECT_EQ(u[0], w[0]);
    EXPECT_EQ(u[1], w[1]);
  }
}

TEST_F(Oscillator, GeneralizedAlphaStateRestoredContinuesBitForBit) {
  expectRestartBitForBit(U, [&] { return std::make_unique<GeneralizedAlphaScheme>(0.8, like, nullptr, nullptr); });
}

TEST_F(Oscillator, MidpointStateRestoredContinuesBitForBit) {
  expectRestartBitForBit(U, [&] { return std::make_unique<MidpointScheme>(like, nullptr, nullptr); });
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (PetscInitialize(&argc, &argv, nullptr, nullptr)) return 1;
  const int failed = RUN_ALL_TESTS();
  if (PetscFinalize()) return 1;
  return failed;
}
