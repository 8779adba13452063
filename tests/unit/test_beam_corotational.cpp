// SPACAR-style corotational beam kernel (beam_corotational.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "elements/beam_corotational.hpp"
#include "sinew/rotation.hpp"
#include "beam_test_support.hpp"

using namespace sinew;
using test::maxAbs;

namespace {

using Modes = std::array<BeamMode, 6>;
constexpr BeamMode F = BeamMode::Flexible, Rg = BeamMode::Rigid, Rl = BeamMode::Released;


struct State {
  std::array<double, 24> q{};
  void set(int node, const Vec3& x, const Mat3& R) {
    for (int i = 0; i < 3; ++i) q[12 * node + i] = x[i];
    for (int i = 0; i < 9; ++i) q[12 * node + 3 + i] = R[i];
  }
  Vec3 x(int node) const { return {q[12 * node], q[12 * node + 1], q[12 * node + 2]}; }
  Mat3 R(int node) const {
    Mat3 r;
    for (int i = 0; i < 9; ++i) r[i] = q[12 * node + 3 + i];
    return r;
  }
  // dof k of [x_p, w_p, x_q, w_q]: translations additive, rotations R -> exp(skew(h e)) R
  State perturbed(int k, double h) const {
    State s = *this;
    const int node = k / 6, c = k % 6;
    if (c < 3) {
      s.q[12 * node + c] += h;
    } else {
      Vec3 w{};
      w[c - 3] = h;
      s.set(node, x(node), expSO3(w) * R(node));
    }
    return s;
  }
};

Vec3 randomVec(std::mt19937& g, double s) {
  std::uniform_real_distribution<double> u(-s, s);
  return {u(g), u(g), u(g)};
}

// Max |K - K_fd| / max |K| over the full (dofs + multipliers) square matrix.
double tangentError(const BeamCorotational& b, const State& s, const std::vector<double>& lambda, bool split) {
  const int nd = b.numDofs(), n = nd + b.numConstraints();
  KernelInput in;
  in.q = s.q.data();
  in.lambda = lambda.empty() ? nullptr : lambda.data();
  KernelNeeds needs;
  needs.tangent = true;
  needs.splitGeometric = split;
  KernelOutput out;
  b.evaluate(in, needs, out);
  std::vector<double> K = out.K;
  if (split)
    for (size_t i = 0; i < K.size(); ++i) K[i] += out.Kg[i];
  EXPECT_EQ(static_cast<int>(out.f.size()), n);
  double err = 0, scale = 0;
  const double h = 1e-5;
  for (int j = 0; j < n; ++j) {
    KernelOutput op, om;
    KernelNeeds fonly;
    if (j < nd) {
      const State sp = s.perturbed(j, h), sm = s.perturbed(j, -h);
      in.q = sp.q.data();
      b.evaluate(in, fonly, op);
      in.q = sm.q.data();
      b.evaluate(in, fonly, om);
      in.q = s.q.data();
    } else {
      std::vector<double> lp = lambda, lm = lambda;
      lp[j - nd] += h;
      lm[j - nd] -= h;
      in.lambda = lp.data();
      b.evaluate(in, fonly, op);
      in.lambda = lm.data();
      b.evaluate(in, fonly, om);
      in.lambda = lambda.data();
    }
    for (int i = 0; i < n; ++i) {
      const double fd = (op.f[i] - om.f[i]) / (2 * h);
      err = std::max(err, std::abs(fd - K[i * n + j]));
      scale = std::max(scale, std::abs(K[i * n + j]));
    }
  }
  return err / scale;
}

State randomState(std::mt19937& g, const Vec3& Xp, const Vec3& Xq) {
  State s;
  s.set(0, Xp + randomVec(g, 0.3), expSO3(randomVec(g, 1.5)));
  s.set(1, Xq + randomVec(g, 0.3), expSO3(randomVec(g, 1.5)));
  return s;
}

State referenceState(const Vec3& Xp, const Vec3& Xq) {
  State s;
  s.set(0, Xp, identity3());
  s.set(1, Xq, identity3());
  return s;
}

double maxAbsDiff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

const Vec3 kXp{0.1, -0.2, 0.3}, kXq{1.0, 0.4, 0.1};

}  // namespace

TEST(BeamCorotational, InitialTriad) {
  const BeamSection s = test::comparableSection();
  const Modes all{F, F, F, F, F, F};
  BeamCorotational b({0, 0, 0}, {2, 0, 0}, std::nullopt, s, all, false, 1.0);
  EXPECT_NEAR(b.ey0()[2], 1.0, 1e-15);  // default orien = global z
  EXPECT_NEAR(b.ez0()[1], -1.0, 1e-15);
  EXPECT_DOUBLE_EQ(b.l0(), 2.0);
  BeamCorotational bz({0, 0, 0}, {0, 0, 1}, std::nullopt, s, all, false, 1.0);
  EXPECT_NEAR(bz.ey0()[1], 1.0, 1e-15);  // chord along z: global y
  BeamCorotational bo({0, 0, 0}, {1, 1, 0}, Vec3{1, 0, 1}, s, all, false, 1.0);
  EXPECT_NEAR(dot(bo.ey0(), Vec3{1, 1, 0}), 0.0, 1e-15);  // projected perpendicular to the chord
  EXPECT_NEAR(norm(bo.ey0()), 1.0, 1e-15);
  try {
    BeamCorotational bad({0, 0, 0}, {1, 0, 0}, Vec3{2, 0, 0}, s, all, false, 1.0);
    FAIL() << "parallel orien accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.path(), "eprops.orien");
  }
}

TEST(BeamCorotational, ReferenceStateIsStressFree) {
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, test::comparableSection(), {F, F, F, F, F, F}, false, 1.0);
  const State s = referenceState(kXp, kXq);
  for (double e : b.generalizedStrains(s.q.data())) EXPECT_NEAR(e, 0.0, 1e-15);
}

TEST(BeamCorotational, TangentMatchesFiniteDifferencesAllFlexible) {
  std::mt19937 g(11);
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, test::comparableSection(), {F, F, F, F, F, F}, false, 1.0);
  double worst = 0;
  for (int r = 0; r < 6; ++r) worst = std::max(worst, tangentError(b, randomState(g, kXp, kXq), {}, false));
  std::printf("  all flexible: max relative tangent error %.2e\n", worst);
  EXPECT_LT(worst, 1e-6);  // measured 4.0e-10
}

TEST(BeamCorotational, TangentMatchesFiniteDifferencesRigidModes) {
  std::mt19937 g(12);
  const BeamCorotational b(kXp, kXq, Vec3{0.3, 0.2, 1}, test::comparableSection(), {Rg, F, Rg, F, F, Rg}, false, 2.5);
  ASSERT_EQ(b.numConstraints(), 3);
  double worst = 0;
  for (int r = 0; r < 6; ++r) {
    const std::vector<double> lambda{0.7, -1.3, 0.4};
    worst = std::max(worst, tangentError(b, randomState(g, kXp, kXq), lambda, false));
  }
  std::printf("  rigid modes 1,3,6: max relative tangent error %.2e\n", worst);
  EXPECT_LT(worst, 1e-6);  // measured 1.9e-10
}

TEST(BeamCorotational, TangentMatchesFiniteDifferencesReleasedModes) {
  std::mt19937 g(13);
  const BeamCorotational b(kXp, kXq, Vec3{0, 1, 0}, test::comparableSection(), {F, Rl, Rl, F, Rl, Rl}, false, 1.0);
  const BeamCorotational b2(kXp, kXq, Vec3{0, 1, 0}, test::comparableSection(), {F, F, F, Rl, Rg, Rl}, false, 1.0);
  double worst = 0;
  for (int r = 0; r < 4; ++r) {
    worst = std::max(worst, tangentError(b, randomState(g, kXp, kXq), {}, false));
    worst = std::max(worst, tangentError(b2, randomState(g, kXp, kXq), {0.9}, false));
  }
  std::printf("  released modes: max relative tangent error %.2e\n", worst);
  EXPECT_LT(worst, 1e-6);  // measured 2.2e-10
}

TEST(BeamCorotational, SplitTangentSumsToFullTangent) {
  std::mt19937 g(14);
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, test::comparableSection(), {F, Rg, F, F, Rg, F}, false, 3.0);
  const State s = randomState(g, kXp, kXq);
  const std::vector<double> lambda{0.5, -0.8};
  KernelInput in;
  in.q = s.q.data();
  in.lambda = lambda.data();
  KernelNeeds full, split;
  full.tangent = split.tangent = true;
  split.splitGeometric = true;
  KernelOutput a, c;
  b.evaluate(in, full, a);
  b.evaluate(in, split, c);
  std::vector<double> sum = c.K;
  for (size_t i = 0; i < sum.size(); ++i) sum[i] += c.Kg[i];
  std::printf("  split: |K + Kg - K_full| / |K_full| = %.2e\n", maxAbsDiff(sum, a.K) / maxAbs(a.K));
  EXPECT_LT(maxAbsDiff(sum, a.K), 1e-14 * maxAbs(a.K));
  EXPECT_GT(maxAbs(c.Kg), 1e-3 * maxAbs(a.K));           // the stress part is really present here
  EXPECT_LT(tangentError(b, s, lambda, true), 1e-6);
  // material part: symmetric
  const int n = 14;
  double asym = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) asym = std::max(asym, std::abs(c.K[i * n + j] - c.K[j * n + i]));
  EXPECT_LT(asym, 1e-14 * maxAbs(c.K));
}

TEST(BeamCorotational, RigidBodyInvariance) {
  std::mt19937 g(15);
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, test::comparableSection(), {F, F, F, F, F, F}, false, 1.0);
  const State s = randomState(g, kXp, kXq);
  const Mat3 Q = expSO3({0.9, -2.0, 0.4});
  const Vec3 c{3.0, -1.0, 7.0};
  State t;
  for (int node = 0; node < 2; ++node) t.set(node, Q * s.x(node) + c, Q * s.R(node));
  const auto e0 = b.generalizedStrains(s.q.data()), e1 = b.generalizedStrains(t.q.data());
  double de = 0;
  for (int i = 0; i < 6; ++i) de = std::max(de, std::abs(e0[i] - e1[i]));
  std::printf("  rigid motion: strain change %.2e\n", de);
  EXPECT_LT(de, 1e-14);
  KernelInput in;
  KernelNeeds needs;
  KernelOutput o0, o1;
  in.q = s.q.data();
  b.evaluate(in, needs, o0);
  in.q = t.q.data();
  b.evaluate(in, needs, o1);
  double df = 0;
  for (int blk = 0; blk < 4; ++blk) {
    const Vec3 v{o0.f[3 * blk], o0.f[3 * blk + 1], o0.f[3 * blk + 2]};
    const Vec3 rv = Q * v;
    for (int i = 0; i < 3; ++i) df = std::max(df, std::abs(rv[i] - o1.f[3 * blk + i]));
  }
  std::printf("  rigid motion: relative force rotation error %.2e\n", df / maxAbs(o0.f));
  EXPECT_LT(df, 1e-13 * maxAbs(o0.f));
  // self-equilibrated internal forces: sum of forces and of moments about the origin vanish
  Vec3 F{}, M{};
  for (int node = 0; node < 2; ++node) {
    const Vec3 fn{o0.f[6 * node], o0.f[6 * node + 1], o0.f[6 * node + 2]};
    const Vec3 mn{o0.f[6 * node + 3], o0.f[6 * node + 4], o0.f[6 * node + 5]};
    F += fn;
    M += mn + cross(s.x(node), fn);
  }
  EXPECT_LT(norm(F), 1e-13 * maxAbs(o0.f));
  EXPECT_LT(norm(M), 1e-13 * maxAbs(o0.f));
}

TEST(BeamCorotational, SmallDisplacementStiffnessIsTimoshenko) {
  // beam along global x with local y = global y: dofs [u v w thx thy thz] per node (Przemieniecki).
  const BeamSection s = test::comparableSection();
  const double L = 1.7;
  const BeamCorotational b({0, 0, 0}, {L, 0, 0}, Vec3{0, 1, 0}, s, {F, F, F, F, F, F}, false, 1.0);
  const State st = referenceState({0, 0, 0}, {L, 0, 0});
  KernelInput in;
  in.q = st.q.data();
  KernelNeeds needs;
  needs.tangent = true;
  KernelOutput out;
  b.evaluate(in, needs, out);
  std::vector<double> K(144, 0.0);
  auto add = [&](int i, int j, double v) { K[i * 12 + j] += v; };
  auto sym = [&](int i, int j, double v) { add(i, j, v); if (i != j) add(j, i, v); };
  sym(0, 0, s.EA / L); sym(6, 6, s.EA / L); sym(0, 6, -s.EA / L);
  sym(3, 3, s.GIt / L); sym(9, 9, s.GIt / L); sym(3, 9, -s.GIt / L);
  // x-y plane: v (1, 7), theta_z (5, 11), Phi_y = 12 EIz / (kGA_y L^2)
  {
    const double P = 12 * s.EIz / (s.kGAy * L * L), k = s.EIz / (L * L * L * (1 + P));
    sym(1, 1, 12 * k); sym(7, 7, 12 * k); sym(1, 7, -12 * k);
    sym(1, 5, 6 * L * k); sym(1, 11, 6 * L * k); sym(7, 5, -6 * L * k); sym(7, 11, -6 * L * k);
    sym(5, 5, (4 + P) * L * L * k); sym(11, 11, (4 + P) * L * L * k); sym(5, 11, (2 - P) * L * L * k);
  }
  // x-z plane: w (2, 8), theta_y (4, 10), Phi_z = 12 EIy / (kGA_z L^2)
  {
    const double P = 12 * s.EIy / (s.kGAz * L * L), k = s.EIy / (L * L * L * (1 + P));
    sym(2, 2, 12 * k); sym(8, 8, 12 * k); sym(2, 8, -12 * k);
    sym(2, 4, -6 * L * k); sym(2, 10, -6 * L * k); sym(8, 4, 6 * L * k); sym(8, 10, 6 * L * k);
    sym(4, 4, (4 + P) * L * L * k); sym(10, 10, (4 + P) * L * L * k); sym(4, 10, (2 - P) * L * L * k);
  }
  const double err = maxAbsDiff(out.K, K) / maxAbs(K);
  std::printf("  linear stiffness vs Timoshenko 12x12: relative error %.2e\n", err);
  EXPECT_LT(err, 1e-14);  // measured 1.7e-16
}

TEST(BeamCorotational, PureBendingCircularArc) {
  // Ends rotated by -+theta/2 about local y on a circular arc of radius l0/theta (arc length l0):
  // the exact moment is EIy theta / l0 and the arc length is unchanged (eps1 = 0).
  BeamSection s = test::comparableSection();
  const double l0 = 2.0;
  const BeamCorotational b({0, 0, 0}, {l0, 0, 0}, Vec3{0, 1, 0}, s, {F, F, F, F, F, F}, false, 1.0);
  double prevErr = 0;
  for (double theta : {0.2, 0.1, 0.05}) {
    const double rho = l0 / theta;
    State st;
    st.set(0, {0, 0, 0}, expSO3({0, -theta / 2, 0}));
    st.set(1, {2 * rho * std::sin(theta / 2), 0, 0}, expSO3({0, theta / 2, 0}));
    const auto e = b.generalizedStrains(st.q.data());
    EXPECT_NEAR(e[2], e[3], 1e-15);  // pure bending: e3 = e4
    EXPECT_NEAR(e[2], l0 * std::sin(theta / 2), 1e-15);
    // arc - chord cancels the chord shortening l0 theta^2/24 up to O(theta^4):
    // eps1 = l0 theta^4 (1/1920 - 1/288) + O(theta^6) (Taylor of 2 rho sin(theta/2) and sin^2(theta/2))
    const double e1 = std::abs(2 * rho * std::sin(theta / 2) - l0);
    EXPECT_LT(std::abs(e[0]), 0.1 * theta * theta * e1);  // measured 0.071 theta^2 |e1|
    EXPECT_NEAR(e[0], l0 * std::pow(theta, 4) * (1.0 / 1920 - 1.0 / 288), 0.01 * std::abs(e[0]));
    KernelInput in;
    in.q = st.q.data();
    KernelOutput out;
    b.evaluate(in, KernelNeeds{}, out);
    const double M = s.EIy * theta / l0;
    const double err = std::abs(std::abs(out.f[10]) - M) / M;  // moment about y at node q
    EXPECT_LT(err, 0.2 * theta * theta);  // ~ theta^2 / 6
    EXPECT_NEAR(out.f[10], -out.f[4], 1e-12 * M);
    if (prevErr > 0) {
      EXPECT_NEAR(prevErr / err, 4.0, 0.05);  // second order
    }
    prevErr = err;
    std::printf("  theta %.3f: eps1 %.2e, moment relative error %.3e\n", theta, e[0], err);
  }
}

TEST(BeamCorotational, ReleasedEndGivesHingeStiffness) {
  // e3 released (hinge about y at p): rotation stiffness at q becomes 3 EIy / l0 (Euler-Bernoulli).
  BeamSection s = test::comparableSection();
  s.kGAy = s.kGAz = 0.0;  // no shear flexibility
  const double L = 1.0;
  const BeamCorotational b({0, 0, 0}, {L, 0, 0}, Vec3{0, 1, 0}, s, {F, F, Rl, F, F, F}, false, 1.0);
  const State st = referenceState({0, 0, 0}, {L, 0, 0});
  KernelInput in;
  in.q = st.q.data();
  KernelNeeds needs;
  needs.tangent = true;
  KernelOutput out;
  b.evaluate(in, needs, out);
  EXPECT_NEAR(out.K[10 * 12 + 10], 3 * s.EIy / L, 1e-14);
  EXPECT_NEAR(out.K[4 * 12 + 4], 0.0, 1e-14);
}

TEST(BeamCorotational, MassMatrix) {
  std::mt19937 g(16);
  const BeamSection s = test::comparableSection();
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, s, {F, F, F, F, F, F}, true, 1.0);
  ASSERT_TRUE(b.hasInertia());
  const State st = randomState(g, kXp, kXq);
  std::vector<double> M;
  b.mass(st.q.data(), M);
  ASSERT_EQ(M.size(), 144u);
  double asym = 0;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) asym = std::max(asym, std::abs(M[i * 12 + j] - M[j * 12 + i]));
  EXPECT_LT(asym, 1e-15);
  const double m = s.rhoA * b.l0();
  for (int d = 0; d < 3; ++d) {  // rigid translation along each axis: u^T M u = rhoA l0
    double mt = 0;
    for (int i : {d, 6 + d})
      for (int j : {d, 6 + d}) mt += M[i * 12 + j];
    EXPECT_NEAR(mt, m, 1e-14 * m);
  }
  // positive definite: check u^T M u > 0 for random u
  for (int r = 0; r < 20; ++r) {
    std::vector<double> u(12);
    for (double& v : u) v = std::uniform_real_distribution<double>(-1, 1)(g);
    double e = 0;
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) e += u[i] * M[i * 12 + j] * u[j];
    EXPECT_GT(e, 0.0);
  }
  std::vector<double> fb;
  b.bodyForce(st.q.data(), {0, 0, -9.81}, fb);
  EXPECT_NEAR(fb[2] + fb[8], -9.81 * m, 1e-13);
  EXPECT_EQ(fb[5], 0.0);
}

// -beam_mass lumped: no mass matrix; each node rhoA l0 / 2 and l0 / 2 (rho Ip, rho Iy, rho Iz) about
// the reference axes (ex0, ey0, ez0)
TEST(BeamCorotational, LumpedInertia) {
  const BeamSection s = test::comparableSection();
  BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, s, {F, F, F, F, F, F}, true, 1.0);
  double mJ[14];
  EXPECT_FALSE(b.lumpedInertia(mJ));  // consistent mass by default
  b.setLumpedMass(true);
  EXPECT_FALSE(b.hasInertia());
  ASSERT_TRUE(b.lumpedInertia(mJ));
  Vec3 ex = kXq - kXp;
  ex = (1.0 / norm(ex)) * ex;
  const Vec3 axes[3] = {ex, b.ey0(), b.ez0()};
  const double rot[3] = {s.rhoIp, s.rhoIy, s.rhoIz};
  const double h = 0.5 * b.l0();
  for (int n = 0; n < 2; ++n) {
    const double* v = mJ + 7 * n;
    EXPECT_NEAR(v[0], h * s.rhoA, 1e-15 * s.rhoA);
    const Mat3 J{v[1], v[2], v[3], v[2], v[4], v[5], v[3], v[5], v[6]};
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(dot(axes[a], J * axes[c]), a == c ? h * rot[a] : 0.0, 1e-14 * h * s.rhoIp);
  }
}

// -beam_mass linear (Simo & Vu-Quoc): a constant symmetric mass rhoA l0 / 6 [2 I, I; I, 2 I] on the
// translations (no rotation rows), the rotary inertia lumped on the nodes with no nodal mass; a rigid
// translation carries the element's mass rhoA l0, a rigid rotation the exact kinetic energy of the
// straight rod (linear velocity along it: rhoA l0^3 / 12 |w_perp|^2 / 2, plus l0 w^T J_section w / 2).
TEST(BeamCorotational, LinearMass) {
  BeamSection s = test::comparableSection();
  s.rhoIy = 0.03, s.rhoIz = 0.07;
  BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, s, {F, F, F, F, F, F}, true, 1.0);
  b.setLinearMass(true);
  EXPECT_TRUE(b.hasInertia());
  EXPECT_FALSE(b.massDependsOnState());
  EXPECT_FALSE(b.hasInertiaForce());
  const double* M0 = b.constantMass();
  ASSERT_NE(M0, nullptr);
  // the same matrix in a turned and stretched configuration
  State st = referenceState(kXp, kXq);
  const Mat3 Rt = expSO3({0.4, -1.1, 0.7});
  st.set(0, Rt * kXp + Vec3{0.3, 0, -0.2}, Rt * expSO3({0.1, 0.2, -0.3}));
  st.set(1, Rt * kXq + Vec3{0.1, 0.05, 0.2}, Rt * expSO3({-0.2, 0.1, 0.3}));
  std::vector<double> M;
  b.mass(st.q.data(), M);
  ASSERT_EQ(M.size(), 144u);
  const double m = s.rhoA * b.l0();
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      EXPECT_EQ(M[12 * i + j], M0[12 * i + j]);  // configuration independent
      EXPECT_EQ(M[12 * i + j], M[12 * j + i]);   // symmetric
      const bool rotation = i % 6 >= 3 || j % 6 >= 3;
      const double expected = rotation || i % 3 != j % 3 ? 0.0 : (i / 6 == j / 6 ? m / 3 : m / 6);
      EXPECT_NEAR(M[12 * i + j], expected, 1e-15 * m);
    }
  double mJ[14];
  ASSERT_TRUE(b.lumpedInertia(mJ));
  EXPECT_EQ(mJ[0], 0.0);  // the translations' mass is in the element matrix
  EXPECT_EQ(mJ[7], 0.0);
  // kinetic energy 1/2 v^T M v + sum_nodes 1/2 w^T J w (J of the reference axes: the reference state)
  auto kinetic = [&](const std::array<double, 12>& v) {
    double t = 0;
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) t += 0.5 * v[i] * M0[12 * i + j] * v[j];
    for (int n = 0; n < 2; ++n) {
      const double* J = mJ + 7 * n + 1;
      const Mat3 Jn{J[0], J[1], J[2], J[1], J[3], J[4], J[2], J[4], J[5]};
      const Vec3 w{v[6 * n + 3], v[6 * n + 4], v[6 * n + 5]};
      t += 0.5 * dot(w, Jn * w);
    }
    return t;
  };
  const Vec3 u{0.3, -1.2, 0.5};
  std::array<double, 12> vt{};
  for (int k = 0; k < 3; ++k) vt[k] = vt[6 + k] = u[k];
  EXPECT_NEAR(kinetic(vt), 0.5 * m * dot(u, u), 1e-14 * m * dot(u, u));  // total mass rhoA l0
  const Vec3 w{0.7, 0.2, -0.9}, c = 0.5 * (kXp + kXq);
  std::array<double, 12> vr{};
  const Vec3 vp = cross(w, kXp - c), vq = cross(w, kXq - c);
  for (int k = 0; k < 3; ++k) vr[k] = vp[k], vr[6 + k] = vq[k], vr[3 + k] = vr[9 + k] = w[k];
  const Vec3 ex = (1.0 / b.l0()) * (kXq - kXp);
  const Vec3 wPerp = w - dot(w, ex) * ex;
  const double l = b.l0();
  const double exact = 0.5 * (s.rhoA * l * l * l / 12 * dot(wPerp, wPerp) +
                              l * (s.rhoIp * std::pow(dot(w, ex), 2) + s.rhoIy * std::pow(dot(w, b.ey0()), 2) +
                                   s.rhoIz * std::pow(dot(w, b.ez0()), 2)));
  EXPECT_NEAR(kinetic(vr), exact, 1e-14 * exact);
}

TEST(BeamCorotational, VonMisesPureBendingAndTorsion) {
  // Rect w x t along x, local y = global y. Bending about y by theta: sigma = E t/2 theta/l0.
  BeamProperties set;
  set.flex = {true, true, true, true, true, true};
  set.emod = 200e9; set.smod = 80e9; set.cshape = CrossSection::Rect; set.dim = {0.02, 0.001};
  const BeamSection s = beamSection(set, 0.1);
  const double l0 = 0.1, theta = 1e-3;
  const BeamCorotational b({0, 0, 0}, {l0, 0, 0}, Vec3{0, 1, 0}, s, {F, F, F, F, F, F}, false, 1.0);
  State st;
  st.set(0, {0, 0, 0}, expSO3({0, -theta / 2, 0}));
  st.set(1, {2 * l0 / theta * std::sin(theta / 2), 0, 0}, expSO3({0, theta / 2, 0}));
  const double expected = s.E * s.zmax * theta / l0;
  EXPECT_NEAR(b.vonMisesMax(st.q.data(), nullptr), expected, 1e-6 * expected);
  // twist phi: tau = G It phi / l0 * t / It, VM = sqrt(3) tau
  const double phi = 1e-3;
  st.set(0, {0, 0, 0}, identity3());
  st.set(1, {l0, 0, 0}, expSO3({phi, 0, 0}));
  const double tau = s.GIt * phi / l0 * s.torsionStressFactor;
  EXPECT_NEAR(b.vonMisesMax(st.q.data(), nullptr), std::sqrt(3.0) * tau, 1e-6 * tau);
  // rigid torsion: the multiplier gives the stress (sigma_2 = scale * lambda = T / l0)
  const BeamCorotational r({0, 0, 0}, {l0, 0, 0}, Vec3{0, 1, 0}, s, {F, Rg, F, F, F, F}, false, 10.0);
  const double lambda = 0.3, T = 10.0 * lambda * l0;
  st.set(1, {l0, 0, 0}, identity3());
  EXPECT_NEAR(r.generalizedStresses(st.q.data(), &lambda)[1], 3.0, 1e-15);
  EXPECT_NEAR(r.vonMisesMax(st.q.data(), &lambda), std::sqrt(3.0) * T * s.torsionStressFactor, 1e-6);
}

// Mixed-stress Newton: the linearized stresses sigma = S (eps(q0) + grad eps(q0) . d) agree with
// S eps(q1) to second order in the step d (log-map rotation vectors), and a tangent built from the
// stresses of q itself is the ordinary tangent.
TEST(BeamCorotational, LinearizedStressesAreSecondOrderAccurate) {
  std::mt19937 g(7);
  const Vec3 Xp{0.1, -0.2, 0.3}, Xq{1.2, 0.4, -0.1};
  BeamCorotational b(Xp, Xq, Vec3{0, 0, 1}, test::comparableSection(), Modes{F, F, F, F, F, F}, false, 1.0);
  const State s0 = randomState(g, Xp, Xq);
  std::array<double, 12> dir{};
  for (double& v : dir) v = std::uniform_real_distribution<double>(-1, 1)(g);
  double sigExact[6], sigLin[6], errPrev = 0;
  for (double h : {1e-2, 5e-3, 2.5e-3}) {
    State s1 = s0;
    for (int node = 0; node < 2; ++node) {
      const Vec3 dx{dir[6 * node] * h, dir[6 * node + 1] * h, dir[6 * node + 2] * h};
      const Vec3 dw{dir[6 * node + 3] * h, dir[6 * node + 4] * h, dir[6 * node + 5] * h};
      s1.set(node, s0.x(node) + dx, expSO3(dw) * s0.R(node));
    }
    b.linearizedStresses(nullptr, s1.q.data(), sigExact);
    b.linearizedStresses(s0.q.data(), s1.q.data(), sigLin);
    double err = 0, scale = 0;
    for (int i = 0; i < 6; ++i) {
      err = std::max(err, std::abs(sigLin[i] - sigExact[i]));
      scale = std::max(scale, std::abs(sigExact[i]));
    }
    std::printf("  step h = %.2e: |sigma_lin - sigma(q1)| = %.3e (scale %.3e)\n", h, err, scale);
    if (errPrev > 0) {
      EXPECT_NEAR(errPrev / err, 4.0, 0.4);  // halving h quarters the error
    }
    errPrev = err;
  }
  // sigmaMixed = the stresses of q: the ordinary tangent (to round-off)
  const std::array<double, 6> sig = b.generalizedStresses(s0.q.data(), nullptr);
  KernelInput in{s0.q.data()};
  KernelNeeds needs;
  needs.tangent = true;
  KernelOutput plain, mixed;
  b.evaluate(in, needs, plain);
  in.sigmaMixed = sig.data();
  b.evaluate(in, needs, mixed);
  EXPECT_LT(maxAbsDiff(plain.K, mixed.K), 1e-13 * maxAbs(plain.K));
  EXPECT_EQ(maxAbsDiff(plain.f, mixed.f), 0.0);
  // other stresses change the stress part only: f stays, K differs
  std::array<double, 6> other = sig;
  for (double& v : other) v = 2.0 * v + 0.1;
  in.sigmaMixed = other.data();
  b.evaluate(in, needs, mixed);
  EXPECT_EQ(maxAbsDiff(plain.f, mixed.f), 0.0);
  EXPECT_GT(maxAbsDiff(plain.K, mixed.K), 1e-6 * maxAbs(plain.K));
}

// Strain energy 1/2 eps^T S eps (issue 14, -dynamics_energy): its gradient along every dof (spins:
// R -> exp(h e) R) is the internal force at large rotations, and at small displacements u from
// the reference it is the quadratic form 1/2 u^T K0 u of the reference tangent.
TEST(BeamCorotational, StrainEnergyGradientAndQuadraticForm) {
  std::mt19937 g(21);
  const BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, test::comparableSection(), {F, F, F, F, F, F}, false, 1.0);
  const BeamCorotational br(kXp, kXq, Vec3{0, 1, 0}, test::comparableSection(), {F, Rl, Rl, F, Rl, Rl}, false, 1.0);
  double worst = 0;
  for (const BeamCorotational* k : {&b, &br})
    for (int r = 0; r < 4; ++r) {
      const State s = randomState(g, kXp, kXq);
      KernelInput in;
      in.q = s.q.data();
      KernelOutput out;
      k->evaluate(in, KernelNeeds{}, out);
      double err = 0;
      const double h = 1e-6;
      for (int j = 0; j < 12; ++j) {
        double ep = 0, em = 0;
        ASSERT_TRUE(k->strainEnergy(s.perturbed(j, h).q.data(), &ep));
        ASSERT_TRUE(k->strainEnergy(s.perturbed(j, -h).q.data(), &em));
        err = std::max(err, std::abs((ep - em) / (2 * h) - out.f[j]));
      }
      worst = std::max(worst, err / maxAbs(out.f));
    }
  std::printf("  strain energy: max relative |dE/dq - f| %.2e\n", worst);
  EXPECT_LT(worst, 1e-6);  // measured 2.7e-9 (central differences, h = 1e-6)

  // linear range: u = 1e-6 x random, E vs 1/2 u^T K0 u
  const State s0 = referenceState(kXp, kXq);
  KernelInput in;
  in.q = s0.q.data();
  KernelNeeds needs;
  needs.tangent = true;
  KernelOutput out;
  b.evaluate(in, needs, out);
  std::array<double, 12> u{};
  std::uniform_real_distribution<double> d(-1e-6, 1e-6);
  for (double& x : u) x = d(g);
  State s = s0;
  for (int node = 0; node < 2; ++node) {
    const Vec3 dx{u[6 * node], u[6 * node + 1], u[6 * node + 2]}, dw{u[6 * node + 3], u[6 * node + 4], u[6 * node + 5]};
    s.set(node, s0.x(node) + dx, expSO3(dw) * s0.R(node));
  }
  double quad = 0;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) quad += 0.5 * u[i] * out.K[i * 12 + j] * u[j];
  double e = 0;
  ASSERT_TRUE(b.strainEnergy(s.q.data(), &e));
  std::printf("  strain energy at |u| ~ 1e-6: E / (1/2 u^T K0 u) - 1 = %.2e\n", e / quad - 1);
  EXPECT_NEAR(e / quad, 1.0, 1e-4);  // measured 7.8e-8 (the cubic terms at u ~ 1e-6)
}
