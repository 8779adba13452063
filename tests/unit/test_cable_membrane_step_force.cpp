// Energy-momentum step forces of the 3D cable and the membrane (src/elements/cable3d_step_force.cpp,
// membrane_step_force.cpp): the work on the step's increments is the change of the strain energy (also
// through the cable's slack length), no resultant force or moment about the mid positions, the energy
// decay's dissipation, the tangent by q1 against central differences, and the strain energy's gradient
// against the elastic force. Measured: cable work - dU <= 8e-15 (taut, through the slack length both
// ways), moments <= 2.1e-14, tangent 1.3e-9, dU/dq - f 1.4e-10; membrane (triangle, quad) work - dU
// 2.1e-13 of dU, tangent 8.6e-11 (with decay 8.3e-11), dU/dq - f 5.1e-11.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "elements/cable3d.hpp"
#include "elements/membrane.hpp"
#include "membrane_test_support.hpp"

using namespace sinew;

namespace {

using Dofs = std::vector<double>;

struct Step {
  KernelOutput out;
  double work = 0, dU = 0;
  Vec3 force{}, moment{};
};

Vec3 at(const Dofs& q, int a) { return {q[3 * a], q[3 * a + 1], q[3 * a + 2]}; }

Step runStep(const ElementKernel& k, const Dofs& q0, const Dofs& q1, double decay, bool tangent = false) {
  StepForceInput in;
  in.q0 = q0.data();
  in.q1 = q1.data();
  in.decay = decay;
  Step s;
  k.stepForce(in, tangent, s.out);
  double U0 = 0, U1 = 0;
  EXPECT_TRUE(k.strainEnergy(q0.data(), &U0));
  EXPECT_TRUE(k.strainEnergy(q1.data(), &U1));
  s.dU = U1 - U0;
  for (size_t a = 0; a < q0.size() / 3; ++a) {
    const Vec3 f = at(s.out.f, static_cast<int>(a)), xm = 0.5 * (at(q0, static_cast<int>(a)) + at(q1, static_cast<int>(a)));
    s.work += dot(f, at(q1, static_cast<int>(a)) - at(q0, static_cast<int>(a)));
    s.force += f;
    s.moment += cross(xm, f);
  }
  return s;
}

/// Largest |K - dF/dq1| / max |K| by central differences of the step force.
double tangentError(const ElementKernel& k, const Dofs& q0, const Dofs& q1, double decay) {
  const Step s = runStep(k, q0, q1, decay, true);
  const size_t n = q0.size();
  double err = 0, scale = 0;
  const double h = 1e-6;
  for (size_t j = 0; j < n; ++j) {
    Dofs p = q1, m = q1;
    p[j] += h;
    m[j] -= h;
    const Step sp = runStep(k, q0, p, decay), sm = runStep(k, q0, m, decay);
    for (size_t i = 0; i < n; ++i) {
      const double fd = (sp.out.f[i] - sm.out.f[i]) / (2 * h);
      err = std::max(err, std::abs(fd - s.out.K[n * i + j]));
      scale = std::max(scale, std::abs(s.out.K[n * i + j]));
    }
  }
  return err / scale;
}

/// Largest |f - dU/dq| / max |f| of the elastic force against the strain energy's central differences.
double energyGradientError(const ElementKernel& k, const Dofs& q) {
  KernelOutput o;
  k.evaluate(KernelInput{q.data()}, KernelNeeds{}, o);
  double err = 0, scale = 0;
  const double h = 1e-6;
  for (size_t j = 0; j < q.size(); ++j) {
    Dofs p = q, m = q;
    p[j] += h;
    m[j] -= h;
    double Up = 0, Um = 0;
    k.strainEnergy(p.data(), &Up);
    k.strainEnergy(m.data(), &Um);
    err = std::max(err, std::abs((Up - Um) / (2 * h) - o.f[j]));
    scale = std::max(scale, std::abs(o.f[j]));
  }
  return err / scale;
}

Dofs moved(const Dofs& q, std::mt19937& g, double size) {
  std::uniform_real_distribution<double> u(-size, size);
  Dofs r = q;
  for (double& x : r) x += u(g);
  return r;
}

}  // namespace

TEST(CableStepForce, ExactWorkNoResultantsAndTangent) {
  // EA = 1e4, N0 = 50: slack below l_s = L (1 - N0/EA); L = |(1.2, 0.5, -0.3)| = 1.334
  Cable3D c({0, 0, 0}, {1.2, 0.5, -0.3}, 1e-2, 1e6, 7800, 50.0);
  const double L = c.referenceLength(), ls = L * (1 - 50.0 / 1e4);
  auto stateOfLength = [&](double l, const Vec3& dir, const Vec3& xp) {
    const Vec3 e = (1.0 / norm(dir)) * dir;
    return Dofs{xp[0], xp[1], xp[2], xp[0] + l * e[0], xp[1] + l * e[1], xp[2] + l * e[2]};
  };
  struct Case {
    const char* what;
    Dofs q0, q1;
  };
  const Case cases[] = {
      {"taut, turned and stretched", stateOfLength(1.01 * L, {1.2, 0.5, -0.3}, {0, 0, 0}), stateOfLength(1.03 * L, {0.9, 0.9, 0.1}, {0.1, -0.2, 0.05})},
      {"going slack", stateOfLength(1.002 * L, {1.2, 0.5, -0.3}, {0, 0, 0}), stateOfLength(0.99 * ls, {1.0, 0.6, -0.1}, {0.02, 0, 0})},
      {"coming taut", stateOfLength(0.98 * ls, {1.2, 0.5, -0.3}, {0, 0, 0}), stateOfLength(1.001 * L, {1.1, 0.4, -0.2}, {0, 0.01, 0})},
      {"slack at both ends", stateOfLength(0.9 * ls, {1.2, 0.5, -0.3}, {0, 0, 0}), stateOfLength(0.95 * ls, {1, 1, 1}, {0, 0, 0})},
  };
  for (const Case& k : cases) {
    const Step s = runStep(c, k.q0, k.q1, 0.0);
    const double scale = std::max(std::abs(s.dU), 1e-12);
    std::printf("cable3d %s: work - dU %.2e (dU %.3e), |resultant| %.1e, |moment| %.1e\n", k.what, s.work - s.dU, s.dU,
                norm(s.force), norm(s.moment));
    EXPECT_LT(std::abs(s.work - s.dU), 1e-12 * std::max(scale, 1.0)) << k.what;
    EXPECT_LT(norm(s.force), 1e-12) << k.what;
    EXPECT_LT(norm(s.moment), 1e-12) << k.what;
    if (std::string(k.what) != "slack at both ends") {
      const double e = tangentError(c, k.q0, k.q1, 0.0);
      std::printf("  tangent vs central differences %.2e\n", e);
      EXPECT_LT(e, 1e-7) << k.what;
    }
  }
  // the energy decay dissipates xi/2 EA/L (l1 - l0)^2
  const Case& k = cases[0];
  const double xi = 0.3, dl = c.length(k.q1.data()) - c.length(k.q0.data());
  const Step d = runStep(c, k.q0, k.q1, xi);
  EXPECT_NEAR(d.work - d.dU, 0.5 * xi * 1e4 / L * dl * dl, 1e-10 * std::abs(d.dU));
  EXPECT_LT(tangentError(c, k.q0, k.q1, xi), 1e-7);
  // the strain energy's gradient is the elastic force
  const double g = energyGradientError(c, k.q1);
  std::printf("cable3d dU/dq - f %.2e\n", g);
  EXPECT_LT(g, 1e-8);
  // EA = 0: U = N0 l, the step force is N0 along the mid chord
  Cable3D p({0, 0, 0}, {1, 0, 0}, 1e-2, 0.0, 0.0, 20.0);
  const Step s0 = runStep(p, Dofs{0, 0, 0, 1, 0, 0}, Dofs{0, 0.1, 0, 1.1, 0.3, 0.2}, 0.0);
  EXPECT_NEAR(s0.work, s0.dU, 1e-13);
}

TEST(MembraneStepForce, ExactWorkNoResultantsAndTangent) {
  std::mt19937 g(7);
  for (int nn : {3, 4}) {
    const auto [X, mp] = skewMembranePatch(nn);
    Membrane m(X, mp);
    Dofs q;
    for (const Vec3& x : X) q.insert(q.end(), x.begin(), x.end());
    const Dofs q0 = moved(q, g, 0.02), q1 = moved(q, g, 0.05);
    const Step s = runStep(m, q0, q1, 0.0);
    std::printf("membrane%d: work - dU %.2e of dU %.3e, |resultant| %.1e, |moment| %.1e\n", nn, s.work - s.dU, s.dU,
                norm(s.force), norm(s.moment));
    EXPECT_LT(std::abs(s.work - s.dU), 1e-11 * std::abs(s.dU));
    EXPECT_LT(norm(s.force), 1e-9 * mp.emod * mp.thickness);
    EXPECT_LT(norm(s.moment), 1e-9 * mp.emod * mp.thickness);
    const double e = tangentError(m, q0, q1, 0.0), ed = tangentError(m, q0, q1, 0.2);
    std::printf("  tangent vs central differences %.2e (decay 0.2: %.2e)\n", e, ed);
    EXPECT_LT(e, 1e-7);
    EXPECT_LT(ed, 1e-7);
    const Step d = runStep(m, q0, q1, 0.2);
    EXPECT_GT(d.work - d.dU, 0.0);  // the decay dissipates
    const double gr = energyGradientError(m, q1);
    std::printf("  dU/dq - f %.2e\n", gr);
    EXPECT_LT(gr, 1e-7);
  }
}
