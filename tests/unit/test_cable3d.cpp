// Cable3D kernel: tangent (finite differences), slack handling, mass, and the C4 catenary
// (/work/shared/references/README.md, section C).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "elements/cable3d.hpp"

namespace sinew {
// Fallback definitions of the two non-pure ElementKernel virtuals for the standalone kernel test
// binary (the library provides the real ones; a strong definition takes precedence over these).
__attribute__((weak)) void ElementKernel::mass(const double* /*q*/, std::vector<double>& M) const {
  M.assign(numDofs() * numDofs(), 0.0);
}
__attribute__((weak)) void ElementKernel::bodyForce(const double* /*q*/, const Vec3& /*a*/,
                                                    std::vector<double>& f) const {
  f.assign(numDofs(), 0.0);
}
}  // namespace sinew

using namespace sinew;

namespace {

/// Max-norm relative error of the kernel tangent against central differences of f;
/// also returns the mismatch of K_mat + K_geo (split) against the unsplit K.
void fdCheck(const ElementKernel& k, const std::vector<double>& q, double& errFd, double& errSplit) {
  const int n = k.numDofs();
  KernelOutput o, os, op, om;
  k.evaluate(KernelInput{q.data()}, KernelNeeds{true, false, false}, o);
  k.evaluate(KernelInput{q.data()}, KernelNeeds{true, false, true}, os);
  double kmax = 0.0, e = 0.0, es = 0.0;
  for (double v : o.K) kmax = std::max(kmax, std::abs(v));
  for (int i = 0; i < n * n; ++i) es = std::max(es, std::abs(os.K[i] + os.Kg[i] - o.K[i]));
  const double h = 1e-5;
  for (int j = 0; j < n; ++j) {
    std::vector<double> qp = q, qm = q;
    qp[j] += h;
    qm[j] -= h;
    k.evaluate(KernelInput{qp.data()}, KernelNeeds{}, op);
    k.evaluate(KernelInput{qm.data()}, KernelNeeds{}, om);
    for (int i = 0; i < n; ++i) e = std::max(e, std::abs((op.f[i] - om.f[i]) / (2 * h) - o.K[n * i + j]));
  }
  errFd = e / kmax;
  errSplit = es / kmax;
}

}  // namespace

// Measured (seed 7, 20 random states per mode, elastic and form finding lambda = 0, 0.3, 1):
// worst rel. err 6.0e-11; split mismatch K_mat + K_geo - K below 1e-14.
TEST(Cable3D, TangentFiniteDifference) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0;
  for (int mode = 0; mode < 4; ++mode) {
    for (int trial = 0; trial < 20; ++trial) {
      const Vec3 Xp{u(rng), u(rng), u(rng)}, Xq{2.0 + u(rng), u(rng), u(rng)};
      Cable3D c(Xp, Xq, 0.01 + 0.005 * (u(rng) + 1), 2e5 * (1.5 + u(rng)), 0.0, 50.0 * (1.5 + u(rng)));
      if (mode > 0) c.setFormFinding(true, mode == 1 ? 0.0 : (mode == 2 ? 0.3 : 1.0));
      // distorted, stretched (taut) state
      std::vector<double> q = {Xp[0] + 0.2 * u(rng), Xp[1] + 0.2 * u(rng), Xp[2] + 0.2 * u(rng),
                               Xq[0] + 0.3 + 0.2 * u(rng), Xq[1] + 0.2 * u(rng), Xq[2] + 0.2 * u(rng)};
      c.setReferenceLength(0.95 * c.length(q.data()));  // taut: 5 % strain
      ASSERT_FALSE(c.isSlack(q.data()));
      double e, es;
      fdCheck(c, q, e, es);
      EXPECT_LT(e, 1e-6) << "mode " << mode;
      EXPECT_LT(es, 1e-14);
      worst = std::max(worst, e);
    }
  }
  std::printf("cable FD tangent: worst rel. err %.2e\n", worst);
}

TEST(Cable3D, ForceSlackMassBody) {
  Cable3D c({0, 0, 0}, {2, 0, 0}, 0.5, 100.0, 3.0, 10.0);  // EA = 50, L = 2
  const double q[6] = {0, 0, 0, 0, 2.2, 0};                 // l = 2.2 along y
  std::vector<double> F;
  c.elementForce(q, F);
  ASSERT_EQ(F.size(), 1u);
  EXPECT_NEAR(F[0], 10.0 + 50.0 * 0.1, 1e-12);
  KernelOutput o;
  c.evaluate(KernelInput{q}, KernelNeeds{true, false, true}, o);
  EXPECT_NEAR(o.f[4], 15.0, 1e-12);
  EXPECT_NEAR(o.f[1], -15.0, 1e-12);
  EXPECT_NEAR(o.K[6 * 1 + 1], 25.0, 1e-12);   // EA/L
  EXPECT_NEAR(o.Kg[6 * 0 + 0], 15.0 / 2.2, 1e-12);  // N/l transverse
  // slack: N0 + EA (l/L - 1) = 10 + 50 (1.5/2 - 1) < 0
  const double qs[6] = {0, 0, 0, 1.5, 0, 0};
  EXPECT_TRUE(c.isSlack(qs));
  c.evaluate(KernelInput{qs}, KernelNeeds{true, false, false}, o);
  for (double v : o.f) EXPECT_EQ(v, 0.0);
  for (double v : o.K) EXPECT_EQ(v, 0.0);
  c.elementForce(qs, F);
  EXPECT_EQ(F[0], 0.0);
  // prestress as stress: N0 = s A
  c.setPrestressStress(40.0);
  EXPECT_NEAR(c.prestressForce(), 20.0, 1e-14);
  // mass rho A L/6 [2 1; 1 2], body force rho A L/2 a
  EXPECT_TRUE(c.hasInertia());
  std::vector<double> M, fb;
  c.mass(q, M);
  const double m = 3.0 * 0.5 * 2.0;
  EXPECT_NEAR(M[0], m / 3.0, 1e-14);
  EXPECT_NEAR(M[3], m / 6.0, 1e-14);
  EXPECT_NEAR(M[6 * 4 + 4], m / 3.0, 1e-14);
  double tot = 0.0;
  for (int i = 0; i < 6; i += 3)
    for (int j = 0; j < 6; j += 3) tot += M[6 * i + j];
  EXPECT_NEAR(tot, m, 1e-14);
  c.bodyForce(q, {0, 0, -9.81}, fb);
  EXPECT_NEAR(fb[2] + fb[5], -9.81 * m, 1e-12);
  Cable3D light({0, 0, 0}, {1, 0, 0}, 1.0, 1.0, 0.0);
  EXPECT_FALSE(light.hasInertia());
}

namespace {
/// Node positions along a catenary y = a cosh(x/a) of arc length S through (0,0) and (span,0),
/// equally spaced in arc length (a from 2 a sinh(span/2a) = S by bisection).
std::vector<double> catenaryNodes(double span, double S, int ne, double* aOut) {
  double lo = 0.1, hi = 1e3;
  for (int it = 0; it < 200; ++it) {
    const double a = 0.5 * (lo + hi);
    (2 * a * std::sinh(span / (2 * a)) > S ? lo : hi) = a;
  }
  const double a = 0.5 * (lo + hi);
  if (aOut) *aOut = a;
  std::vector<double> x(3 * (ne + 1));
  for (int i = 0; i <= ne; ++i) {
    const double s = -0.5 * S + S * i / ne;
    const double xi = a * std::asinh(s / a);
    x[3 * i] = 0.5 * span + xi;
    x[3 * i + 1] = 0.0;
    x[3 * i + 2] = a * std::cosh(xi / a) - a * std::cosh(0.5 * span / a);
  }
  return x;
}

/// Newton with backtracking for a chain of cables (dense; test-local).
int solveChain(const std::vector<std::unique_ptr<Cable3D>>& cab, std::vector<double>& x,
               const std::vector<double>& fext, double tol) {
  const int nn = static_cast<int>(cab.size()) + 1, n = 3 * nn;
  auto assemble = [&](const std::vector<double>& xx, std::vector<double>& r, std::vector<double>* K) {
    r.assign(n, 0.0);
    if (K) K->assign(n * n, 0.0);
    KernelOutput o;
    for (int e = 0; e + 1 < nn; ++e) {
      cab[e]->evaluate(KernelInput{&xx[3 * e]}, KernelNeeds{K != nullptr, false, false}, o);
      for (int i = 0; i < 6; ++i) {
        r[3 * e + i] += o.f[i];
        if (K)
          for (int j = 0; j < 6; ++j) (*K)[n * (3 * e + i) + 3 * e + j] += o.K[6 * i + j];
      }
    }
    for (int i = 0; i < n; ++i) r[i] -= fext[i];
    for (int k = 0; k < 3; ++k) r[k] = r[n - 3 + k] = 0.0;  // supports
  };
  std::vector<double> r, K, rt, xt;
  for (int it = 0; it < 200; ++it) {
    assemble(x, r, &K);
    double rn = 0.0;
    for (double v : r) rn += v * v;
    rn = std::sqrt(rn);
    if (rn < tol) return it;
    // free dofs 3 .. n-4; dense Gaussian elimination (banded matrix, no pivoting needed: SPD)
    const int m = n - 6;
    std::vector<double> A(m * m), b(m);
    for (int i = 0; i < m; ++i) {
      b[i] = -r[3 + i];
      for (int j = 0; j < m; ++j) A[m * i + j] = K[n * (3 + i) + 3 + j];
    }
    for (int k = 0; k < m; ++k)
      for (int i = k + 1; i < std::min(m, k + 6); ++i) {
        const double l = A[m * i + k] / A[m * k + k];
        for (int j = k; j < std::min(m, k + 6); ++j) A[m * i + j] -= l * A[m * k + j];
        b[i] -= l * b[k];
      }
    for (int i = m - 1; i >= 0; --i) {
      for (int j = i + 1; j < std::min(m, i + 6); ++j) b[i] -= A[m * i + j] * b[j];
      b[i] /= A[m * i + i];
    }
    double alpha = 1.0;
    for (int ls = 0; ls < 40; ++ls, alpha *= 0.5) {
      xt = x;
      for (int i = 0; i < m; ++i) xt[3 + i] += alpha * b[i];
      bool taut = true;
      for (int e = 0; e + 1 < nn; ++e) taut = taut && !cab[e]->isSlack(&xt[3 * e]);
      if (!taut) continue;
      assemble(xt, rt, nullptr);
      double rtn = 0.0;
      for (double v : rt) rtn += v * v;
      if (std::sqrt(rtn) < rn) break;
    }
    x = xt;
  }
  return -1;
}
}  // namespace

// C4: catenary, span 10, length 12, w = 1 (rho A g = 1 per unstretched length), 40 cables,
// EA = 1e7, consistent gravity loads. Reference sag 2.923438, T_max = 7.618853.
// Measured: 40 cables sag 2.924386 (err +9.5e-4, 3.2e-4 relative), support tension 7.618316
// (err -5.4e-4); 80 cables sag err +2.4e-4, tension err -1.4e-4: ratio 3.9, the O(h^2) error of
// lumping the distributed weight to the nodes (the elastic stretch at EA = 1e7 is below 1e-6).
TEST(Cable3D, CatenaryC4) {
  const double span = 10.0, S = 12.0, aRef = 4.695415;
  const double sagRef = aRef * std::cosh(span / (2 * aRef)) - aRef;
  EXPECT_NEAR(sagRef, 2.923438, 2e-6);
  double sagErr[2] = {0, 0};
  for (int pass = 0; pass < 2; ++pass) {
    const int ne = pass == 0 ? 40 : 80;
    std::vector<double> x = catenaryNodes(span, 1.08 * S, ne, nullptr);  // taut start, 8 % too long
    std::vector<std::unique_ptr<Cable3D>> cab;
    std::vector<double> fext(3 * (ne + 1), 0.0), fb;
    for (int e = 0; e < ne; ++e) {
      cab.push_back(std::make_unique<Cable3D>(Vec3{x[3 * e], x[3 * e + 1], x[3 * e + 2]},
                                              Vec3{x[3 * e + 3], x[3 * e + 4], x[3 * e + 5]}, 1.0, 1e7, 1.0));
      cab.back()->setReferenceLength(S / ne);
      cab.back()->bodyForce(&x[3 * e], {0, 0, -1.0}, fb);
      for (int i = 0; i < 6; ++i) fext[3 * e + i] += fb[i];
    }
    // continuation in EA (1e3 -> 1e7) from the stretched start keeps every cable taut
    int its = 0;
    for (double EA = 1e3; EA <= 1e7 * 1.01; EA *= 10.0) {
      for (auto& c : cab) c->setEmod(EA);
      const int k = solveChain(cab, x, fext, 1e-13 * EA);  // round-off floor ~1e-14 EA
      ASSERT_GE(k, 0) << "EA " << EA;
      its += k;
    }
    double zmin = 0.0, tmax = 0.0;
    std::vector<double> F;
    for (int i = 0; i <= ne; ++i) zmin = std::min(zmin, x[3 * i + 2]);
    // T_max = support reaction |f_int - f_ext| at node 1 (the lumped support load included)
    KernelOutput o;
    cab[0]->evaluate(KernelInput{&x[0]}, KernelNeeds{}, o);
    tmax = std::hypot(o.f[0] - fext[0], o.f[1] - fext[1], o.f[2] - fext[2]);
    cab[0]->elementForce(&x[0], F);
    EXPECT_LT(F[0], tmax);  // chord force of the end cable is below the support tension
    sagErr[pass] = -zmin - sagRef;
    std::printf("catenary %d cables: %d Newton its, sag %.6f (err %.2e), T_max %.6f (ref 7.618853)\n", ne, its,
                -zmin, sagErr[pass], tmax);
    EXPECT_NEAR(-zmin, sagRef, 1.2e-3);
    EXPECT_NEAR(tmax, 7.618853, 7e-4);
  }
  // discretisation error decreases like h^2
  EXPECT_LT(std::abs(sagErr[1]), 0.3 * std::abs(sagErr[0]));
}
