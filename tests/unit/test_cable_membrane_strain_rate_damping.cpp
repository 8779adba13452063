// Stiffness-proportional damping on the strain rates of the 3D cable and the membrane
// (setStrainRateDamping; docs/dynamics.md "Damping"): cable N_d = beta EA/L ld, membrane S_d = beta C Ed,
// Ed = sym(F^T Fdot). Checked: d f / d q at fixed qdot and D = d f / d qdot against central differences,
// no damping force for a rigid velocity field v = v0 + w x x at a deformed state, D = beta K_mat, none
// while the cable is slack, and the energy-momentum step force's tangent with beta and its
// dissipation (zero for a rigid step).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "elements/cable3d.hpp"
#include "elements/membrane.hpp"
#include "membrane_test_support.hpp"
#include "sinew/rotation.hpp"

using namespace sinew;

namespace {

using Dofs = std::vector<double>;

double maxAbs(const Dofs& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

Dofs force(const ElementKernel& k, const Dofs& q, const double* qdot) {
  KernelInput in;
  in.q = q.data();
  in.qdot = qdot;
  KernelOutput out;
  k.evaluate(in, KernelNeeds{}, out);
  return out.f;
}

/// Relative errors of K (d f/d q at fixed qdot) and D (d f/d qdot) against central differences.
std::pair<double, double> tangentErrors(const ElementKernel& k, const Dofs& q, const Dofs& qd) {
  KernelInput in;
  in.q = q.data();
  in.qdot = qd.data();
  KernelNeeds needs;
  needs.tangent = true;
  needs.damping = true;
  KernelOutput out;
  k.evaluate(in, needs, out);
  const int n = static_cast<int>(q.size());
  double err = 0, errD = 0;
  const double h = 1e-6 * std::max(1.0, maxAbs(q));
  for (int j = 0; j < n; ++j) {
    Dofs qp = q, qm = q, vp = qd, vm = qd;
    qp[j] += h;
    qm[j] -= h;
    const double hv = 1e-6 * std::max(1.0, maxAbs(qd));
    vp[j] += hv;
    vm[j] -= hv;
    const Dofs fp = force(k, qp, qd.data()), fm = force(k, qm, qd.data());
    const Dofs gp = force(k, q, vp.data()), gm = force(k, q, vm.data());
    for (int i = 0; i < n; ++i) {
      err = std::max(err, std::abs((fp[i] - fm[i]) / (2 * h) - out.K[i * n + j]));
      errD = std::max(errD, std::abs((gp[i] - gm[i]) / (2 * hv) - out.D[i * n + j]));
    }
  }
  return {err / maxAbs(out.K), errD / maxAbs(out.D)};
}

/// v = v0 + w x x at every node of q.
Dofs rigidVelocity(const Dofs& q, const Vec3& v0, const Vec3& w) {
  Dofs v(q.size());
  for (size_t a = 0; a < q.size() / 3; ++a) {
    const Vec3 vx = v0 + cross(w, Vec3{q[3 * a], q[3 * a + 1], q[3 * a + 2]});
    for (int k = 0; k < 3; ++k) v[3 * a + k] = vx[k];
  }
  return v;
}

Dofs someVelocity(size_t n, double s) {
  Dofs v(n);
  for (size_t k = 0; k < n; ++k) v[k] = s * std::sin(1.0 + 1.3 * static_cast<double>(k));
  return v;
}

/// Largest change of the force by the velocity qd, relative to the elastic force.
double dampingForce(const ElementKernel& k, const Dofs& q, const Dofs& qd) {
  const Dofs f0 = force(k, q, nullptr), fv = force(k, q, qd.data());
  double d = 0;
  for (size_t i = 0; i < f0.size(); ++i) d = std::max(d, std::abs(fv[i] - f0[i]));
  return d / maxAbs(f0);
}

/// beta K_mat (the split material tangent at rest) against D.
double dampingMatrixVsMaterial(const ElementKernel& k, const Dofs& q, const Dofs& qd, double beta) {
  KernelInput in;
  in.q = q.data();
  KernelNeeds split;
  split.tangent = true;
  split.splitGeometric = true;
  KernelOutput mat;
  k.evaluate(in, split, mat);
  in.qdot = qd.data();
  KernelNeeds nd;
  nd.damping = true;
  KernelOutput d;
  k.evaluate(in, nd, d);
  double e = 0;
  for (size_t i = 0; i < d.D.size(); ++i) e = std::max(e, std::abs(d.D[i] - beta * mat.K[i]));
  return e / maxAbs(d.D);
}

Membrane patch(int nn) {
  const MembranePatch p = skewMembranePatch(nn);
  return Membrane(p.X, p.props);
}

Dofs referenceOf(const Membrane& m) {
  Dofs q;
  for (int a = 0; a < m.numNodes(); ++a) q.insert(q.end(), m.reference()[a].begin(), m.reference()[a].end());
  return q;
}

/// q rotated by R about the origin and perturbed by s.
Dofs deformed(const Dofs& q, const Mat3& R, double s) {
  Dofs r(q.size());
  for (size_t a = 0; a < q.size() / 3; ++a) {
    const Vec3 x = R * Vec3{q[3 * a], q[3 * a + 1], q[3 * a + 2]};
    for (int k = 0; k < 3; ++k) r[3 * a + k] = x[k] + s * std::cos(2.0 + 0.7 * static_cast<double>(3 * a + k));
  }
  return r;
}

}  // namespace

TEST(CableMembraneStrainRateDamping, CableTangentsRigidMotionAndSlack) {
  Cable3D c(Vec3{0.1, -0.2, 0.3}, Vec3{1.0, 0.4, 0.1}, 1e-4, 2e11, 7850, 50.0);
  const double beta = 2e-3;
  EXPECT_TRUE(c.setStrainRateDamping(beta) && c.strainRateDamped() && c.hasDamping());
  const Dofs q = {0.12, -0.21, 0.33, 1.01, 0.42, 0.09};  // stretched a little
  const Dofs qd = someVelocity(6, 3.0);
  const auto [eK, eD] = tangentErrors(c, q, qd);
  const double rel = dampingForce(c, q, qd);
  const Dofs vr = rigidVelocity(q, Vec3{-0.4, 0.2, 0.9}, Vec3{0.7, -1.1, 2.3});
  const double rigid = dampingForce(c, q, vr);
  const double dK = dampingMatrixVsMaterial(c, q, qd, beta);
  std::printf("  cable: d f/d q vs central differences %.2e, D %.2e, |D - beta K_mat| %.1e; damping/elastic force: deformational %.2f, rigid %.1e\n",
              eK, eD, dK, rel, rigid);
  EXPECT_LT(eK, 1e-7);
  EXPECT_LT(eD, 1e-8);
  EXPECT_LT(dK, 1e-15);
  EXPECT_GT(rel, 0.01);
  EXPECT_LT(rigid, 1e-14);
  // slack: no force, no damping
  const Dofs qs = {0.1, -0.2, 0.3, 0.8, 0.3, 0.1};
  ASSERT_TRUE(c.isSlack(qs.data()));
  EXPECT_EQ(maxAbs(force(c, qs, qd.data())), 0.0);
  KernelInput in;
  in.q = qs.data();
  in.qdot = qd.data();
  KernelNeeds nd;
  nd.tangent = true;
  nd.damping = true;
  KernelOutput out;
  c.evaluate(in, nd, out);
  EXPECT_EQ(out.D.size(), 36u);  // the assembler reads D whenever it asks for it
  EXPECT_EQ(maxAbs(out.D), 0.0);
}

TEST(CableMembraneStrainRateDamping, MembraneTangentsAndRigidMotion) {
  for (int nn : {3, 4}) {
    Membrane m = patch(nn);
    const double beta = 1e-3;
    EXPECT_TRUE(m.setStrainRateDamping(beta) && m.strainRateDamped() && m.hasDamping());
    const Dofs q = deformed(referenceOf(m), expSO3(Vec3{0.3, -0.8, 1.2}), 0.02);
    const Dofs qd = someVelocity(q.size(), 2.0);
    const auto [eK, eD] = tangentErrors(m, q, qd);
    const double rel = dampingForce(m, q, qd);
    const double rigid = dampingForce(m, q, rigidVelocity(q, Vec3{-0.4, 0.2, 0.9}, Vec3{0.7, -1.1, 2.3}));
    const double dK = dampingMatrixVsMaterial(m, q, qd, beta);
    std::printf("  membrane%d: d f/d q vs central differences %.2e, D %.2e, |D - beta K_mat| %.1e; damping/elastic force: deformational %.2f, rigid %.1e\n",
                nn, eK, eD, dK, rel, rigid);
    EXPECT_LT(eK, 1e-7);
    EXPECT_LT(eD, 1e-8);
    EXPECT_LT(dK, 1e-14);
    EXPECT_GT(rel, 0.01);
    EXPECT_LT(rigid, 1e-14);
  }
}

// The energy-momentum step force with beta: tangent vs central differences, the dissipation
// beta/h (E1 - E0) . C (E1 - E0) >= 0 of a deforming step, none for a rigid step.
TEST(CableMembraneStrainRateDamping, StepForceDissipatesDeformationOnly) {
  Cable3D c(Vec3{0.1, -0.2, 0.3}, Vec3{0.995, 0.397, 0.1}, 1e-4, 2e11, 7850, 50.0);  // taut at qc below
  Membrane m3 = patch(3), m4 = patch(4);
  const Dofs qc = {0.1, -0.2, 0.3, 1.0, 0.4, 0.1};
  for (ElementKernel* k : std::vector<ElementKernel*>{&c, &m3, &m4}) {
    const Dofs X = k == &c ? qc : referenceOf(k == &m3 ? m3 : m4);
    const Dofs q0 = deformed(X, expSO3(Vec3{0.1, 0.2, -0.3}), 1e-3);
    const Dofs q1 = deformed(X, expSO3(Vec3{0.15, 0.1, -0.2}), 2e-3);
    const Dofs q1r = deformed(q0, expSO3(Vec3{0.05, -0.1, 0.2}), 0.0);
    auto work = [&](const Dofs& a, const Dofs& b, double beta) {
      k->setStrainRateDamping(beta);
      StepForceInput in;
      in.q0 = a.data();
      in.q1 = b.data();
      in.h = 1e-3;
      KernelOutput out;
      k->stepForce(in, false, out);
      double w = 0;
      for (size_t i = 0; i < a.size(); ++i) w += out.f[i] * (b[i] - a[i]);
      return w;
    };
    const double w0 = work(q0, q1, 0.0), wd = work(q0, q1, 1e-4);
    const double r0 = work(q0, q1r, 0.0), rd = work(q0, q1r, 1e-4);
    // tangent with beta by central differences
    k->setStrainRateDamping(1e-4);
    StepForceInput in;
    in.q0 = q0.data();
    in.q1 = q1.data();
    in.h = 1e-3;
    KernelOutput out;
    k->stepForce(in, true, out);
    const int n = static_cast<int>(q1.size());
    double err = 0;
    for (int j = 0; j < n; ++j) {
      Dofs p = q1, mm = q1;
      p[j] += 1e-7;
      mm[j] -= 1e-7;
      KernelOutput op, om;
      in.q1 = p.data();
      k->stepForce(in, false, op);
      in.q1 = mm.data();
      k->stepForce(in, false, om);
      for (int i = 0; i < n; ++i) err = std::max(err, std::abs((op.f[i] - om.f[i]) / 2e-7 - out.K[i * n + j]));
    }
    err /= maxAbs(out.K);
    std::printf("  %s: dissipated by beta %.3e (of the work %.3e), rigid step %.1e; tangent vs central differences %.2e\n",
                k->name(), wd - w0, w0, rd - r0, err);
    EXPECT_GT(wd - w0, 0.0);
    EXPECT_LT(std::abs(rd - r0), 1e-12 * std::abs(wd - w0));
    EXPECT_LT(err, 1e-6);
  }
}
