// Stiffness-proportional damping on the strain rates of the corotational beam
// (BeamCorotational::setStrainRateDamping; docs/dynamics.md "Damping"): sigma_d = beta S epsd,
// epsd = grad eps . qdot, f_d = grad eps^T sigma_d. Checked: d f / d q (at fixed qdot) and D = d f / d qdot
// against central differences, no damping force for a rigid velocity field at a deformed state, and
// the small-motion limit beta K0 qdot (Rayleigh's beta K0 of an unstressed start).
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

constexpr BeamMode F = BeamMode::Flexible;

BeamSection section() {
  BeamSection s;
  s.shape = CrossSection::Rect;
  s.w = 0.3; s.t = 0.2;
  s.A = 0.06; s.Iy = 2e-4; s.Iz = 4.5e-4; s.Ip = 6.5e-4; s.It = 5e-4;
  s.EA = 3.0; s.GIt = 0.7; s.EIy = 1.3; s.EIz = 0.9; s.kGAy = 40.0; s.kGAz = 25.0;
  s.rhoA = 2.0; s.rhoIp = 0.1; s.rho = 2.0 / 0.06;
  return s;
}

using Q24 = test::BeamState;
using test::perturbed;
using test::setNode;

Vec3 rnd(std::mt19937& g, double s) {
  std::uniform_real_distribution<double> u(-s, s);
  return {u(g), u(g), u(g)};
}
Q24 randomState(std::mt19937& g, const Vec3& Xp, const Vec3& Xq) {
  Q24 q{};
  setNode(q, 0, Xp + rnd(g, 0.3), expSO3(rnd(g, 1.5)));
  setNode(q, 1, Xq + rnd(g, 0.3), expSO3(rnd(g, 1.5)));
  return q;
}
const Vec3 kXp{0.1, -0.2, 0.3}, kXq{1.0, 0.4, 0.1};

}  // namespace

std::array<double, 12> someVelocity(double s) {
  std::array<double, 12> v;
  for (int k = 0; k < 12; ++k) v[k] = s * std::sin(1.0 + 1.3 * k);
  return v;
}

// d f / d q at fixed qdot (elastic + damping force) and D = d f / d qdot equal central differences,
// with rigid and released modes too.
TEST(BeamStrainRateDamping, TangentsMatchFiniteDifferences) {
  std::mt19937 g(7);
  for (const auto& modes : {std::array<BeamMode, 6>{F, F, F, F, F, F},
                            std::array<BeamMode, 6>{BeamMode::Rigid, F, F, F, BeamMode::Released, F}}) {
    BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, section(), modes, true, 1.0);
    b.setStrainRateDamping(0.02);
    EXPECT_TRUE(b.hasDamping() && b.strainRateDamped());
    const Q24 q = randomState(g, kXp, kXq);
    const std::array<double, 12> qd = someVelocity(3.0);
    const int nd = 12, n = nd + b.numConstraints();
    std::vector<double> lambda(static_cast<size_t>(b.numConstraints()), 0.7);
    KernelInput in;
    in.q = q.data();
    in.qdot = qd.data();
    in.lambda = lambda.empty() ? nullptr : lambda.data();
    KernelNeeds needs;
    needs.tangent = true;
    needs.damping = true;
    KernelOutput out, plain;
    b.evaluate(in, needs, out);
    in.qdot = nullptr;
    b.evaluate(in, KernelNeeds{}, plain);
    in.qdot = qd.data();
    double dmp = 0;
    for (int i = 0; i < nd; ++i) dmp = std::max(dmp, std::abs(out.f[i] - plain.f[i]));
    EXPECT_GT(dmp, 0.1 * maxAbs(plain.f));  // the damping force is of the elastic one's order here
    double err = 0, scale = 0, errD = 0, scaleD = 0;
    const double h = 1e-6;
    for (int j = 0; j < nd; ++j) {
      const Q24 qp = perturbed(q, j, h), qm = perturbed(q, j, -h);
      KernelOutput op, om;
      in.q = qp.data();
      b.evaluate(in, KernelNeeds{}, op);
      in.q = qm.data();
      b.evaluate(in, KernelNeeds{}, om);
      in.q = q.data();
      for (int i = 0; i < n; ++i) {
        const double fd = (op.f[i] - om.f[i]) / (2 * h);
        err = std::max(err, std::abs(fd - out.K[i * n + j]));
        scale = std::max(scale, std::abs(out.K[i * n + j]));
      }
      std::array<double, 12> vp = qd, vm = qd;
      vp[j] += h;
      vm[j] -= h;
      in.qdot = vp.data();
      b.evaluate(in, KernelNeeds{}, op);
      in.qdot = vm.data();
      b.evaluate(in, KernelNeeds{}, om);
      in.qdot = qd.data();
      for (int i = 0; i < nd; ++i) {
        const double fd = (op.f[i] - om.f[i]) / (2 * h);
        errD = std::max(errD, std::abs(fd - out.D[i * nd + j]));
        scaleD = std::max(scaleD, std::abs(out.D[i * nd + j]));
      }
    }
    std::printf("  strain-rate damping: d f/d q vs central differences %.2e, D = d f/d qdot %.2e (damping / elastic force %.2f)\n",
                err / scale, errD / scaleD, dmp / maxAbs(plain.f));
    EXPECT_LT(err / scale, 1e-7);
    EXPECT_LT(errD / scaleD, 1e-8);
  }
}

// A rigid velocity field v = v0 + w x x, spins w, at a deformed state: epsd = 0, no damping force
// (a deformational velocity of the same size is damped, for comparison).
TEST(BeamStrainRateDamping, RigidMotionIsNotDamped) {
  std::mt19937 g(11);
  BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, section(), {F, F, F, F, F, F}, true, 1.0);
  b.setStrainRateDamping(0.05);
  const Q24 s = randomState(g, kXp, kXq);
  const Vec3 w{0.7, -1.1, 2.3}, v0{-0.4, 0.2, 0.9};
  std::array<double, 12> qd{};
  for (int node = 0; node < 2; ++node) {
    const Vec3 vx = v0 + cross(w, test::nodePosition(s, node));
    for (int k = 0; k < 3; ++k) {
      qd[6 * node + k] = vx[k];
      qd[6 * node + 3 + k] = w[k];
    }
  }
  KernelInput in;
  in.q = s.data();
  KernelOutput f0, fv, fd;
  b.evaluate(in, KernelNeeds{}, f0);
  in.qdot = qd.data();
  b.evaluate(in, KernelNeeds{}, fv);
  const std::array<double, 12> dv = someVelocity(norm(w));
  in.qdot = dv.data();
  b.evaluate(in, KernelNeeds{}, fd);
  double d = 0, dd = 0;
  for (int i = 0; i < 12; ++i) {
    d = std::max(d, std::abs(fv.f[i] - f0.f[i]));
    dd = std::max(dd, std::abs(fd.f[i] - f0.f[i]));
  }
  std::printf("  rigid velocity field: damping force %.2e of the elastic force (a deformational one: %.2e)\n",
              d / maxAbs(f0.f), dd / maxAbs(f0.f));
  EXPECT_LT(d, 1e-14 * maxAbs(f0.f));
  EXPECT_GT(dd, 1e-2 * maxAbs(f0.f));
}

// Small motion about the reference state: f_d = beta K0 qdot (Rayleigh's beta K0 of an unstressed start).
TEST(BeamStrainRateDamping, SmallMotionIsBetaTimesStiffness) {
  const double beta = 0.03;
  BeamCorotational b(kXp, kXq, Vec3{0, 0, 1}, section(), {F, F, F, F, F, F}, true, 1.0);
  b.setStrainRateDamping(beta);
  Q24 q0{};
  setNode(q0, 0, kXp, identity3());
  setNode(q0, 1, kXq, identity3());
  const std::array<double, 12> qd = someVelocity(1.0);
  KernelInput in;
  in.q = q0.data();
  in.qdot = qd.data();
  KernelOutput fd;
  b.evaluate(in, KernelNeeds{}, fd);
  KernelNeeds needs;
  needs.tangent = true;
  KernelOutput k0;
  in.qdot = nullptr;
  b.evaluate(in, needs, k0);
  double err = 0, scale = 0;
  for (int i = 0; i < 12; ++i) {
    double kv = 0;
    for (int j = 0; j < 12; ++j) kv += beta * k0.K[i * 12 + j] * qd[j];
    err = std::max(err, std::abs(fd.f[i] - kv));
    scale = std::max(scale, std::abs(kv));
  }
  std::printf("  small motion: f_d vs beta K0 qdot %.2e\n", err / scale);
  EXPECT_LT(err / scale, 1e-13);
}
