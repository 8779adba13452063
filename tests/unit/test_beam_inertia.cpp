// The complete consistent mass of the corotational beam (src/elements/beam_inertia.cpp): the inertia
// force is the Euler-Lagrange force of T = 1/2 v^T M(q) v, so along any motion its power equals dT/dt;
// at rest it is M(q) a; its dual-number tangent agrees with central differences. With the sections'
// rotary inertia (torsion rho Ip, bending rho Iy, rho Iz) a rigidly moving element has the rigid
// body's kinetic energy, and its force and moment resultants are the rates of its momenta.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "elements/beam_corotational.hpp"
#include "sinew/rotation.hpp"
#include "beam_test_support.hpp"

using namespace sinew;

namespace {

constexpr BeamMode F = BeamMode::Flexible;
using State = test::BeamState;
using Rates = std::array<double, 12>;

const Vec3 kXp{0.1, -0.2, 0.3}, kXq{1.3, 0.4, 0.1};

// comparableSection with the bending rotary inertia set (rotaryHeavy: larger than the translations'
// rhoA l0^2 / 12 = 0.31 about the bending axes, so the rotary terms dominate); its shear stiffness makes
// the rotation field the Timoshenko one (Phi = 0.34 about y, 0.15 about z).
BeamSection section(bool rotaryHeavy) {
  BeamSection s = test::comparableSection();
  s.rhoIy = rotaryHeavy ? 1.1 : 0.03;
  s.rhoIz = rotaryHeavy ? 0.7 : 0.07;
  return s;
}

BeamCorotational makeBeam(bool rotaryHeavy = false) {
  return BeamCorotational(kXp, kXq, Vec3{0.0, 0.0, 1.0}, section(rotaryHeavy), {F, F, F, F, F, F}, true, 1.0);
}

// A deformed, turned state of the beam above: both ends moved by a rigid turn Q and deformed.
State randomState(std::mt19937& g, double def) {
  std::uniform_real_distribution<double> u(-1, 1);
  auto rv = [&](double s) { return Vec3{s * u(g), s * u(g), s * u(g)}; };
  const Mat3 Q = expSO3(rv(0.8));
  State q{};
  test::setNode(q, 0, Q * Vec3{0.1, -0.2, 0.3} + rv(def), expSO3(rv(def)) * Q);
  test::setNode(q, 1, Q * Vec3{1.3, 0.4, 0.1} + rv(def), expSO3(rv(def)) * Q);
  return q;
}

Rates randomRates(std::mt19937& g, double s) {
  std::uniform_real_distribution<double> u(-s, s);
  Rates r;
  for (double& x : r) x = u(g);
  return r;
}

double kinetic(const BeamCorotational& b, const State& q, const Rates& v) {
  std::vector<double> M;
  b.mass(q.data(), M);
  double T = 0;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) T += 0.5 * v[i] * M[12 * i + j] * v[j];
  return T;
}

// The motion x(t) = x + t v + t^2/2 a, R(t) = exp(t w + t^2/2 wd) R at time t, with its velocities
// (the spins w(t) = dexp(phi) phi', spatial).
void motion(const State& q0, const Rates& v, const Rates& a, double t, State& q, Rates& vt) {
  q = q0;
  for (int n = 0; n < 2; ++n) {
    Vec3 x, phi, dphi, xd;
    for (int i = 0; i < 3; ++i) {
      x[i] = q0[12 * n + i] + t * v[6 * n + i] + 0.5 * t * t * a[6 * n + i];
      xd[i] = v[6 * n + i] + t * a[6 * n + i];
      phi[i] = t * v[6 * n + 3 + i] + 0.5 * t * t * a[6 * n + 3 + i];
      dphi[i] = v[6 * n + 3 + i] + t * a[6 * n + 3 + i];
    }
    test::setNode(q, n, x, expSO3(phi) * test::nodeRotation(q0, n));
    const Vec3 w = dexpSO3(phi) * dphi;
    for (int i = 0; i < 3; ++i) vt[6 * n + i] = xd[i], vt[6 * n + 3 + i] = w[i];
  }
}

}  // namespace

// Power of the inertia force = dT/dt along a motion (central difference of T), for fast motions of
// a deformed element; the frozen form M(q) a misses it by the frame terms.
TEST(BeamInertia, PowerIsRateOfKineticEnergy) {
  for (bool heavy : {false, true}) {
    const BeamCorotational b = makeBeam(heavy);
    std::mt19937 g(7);
    double worst = 0, worstFrozen = 0;
    for (int trial = 0; trial < 20; ++trial) {
      const State q0 = randomState(g, 0.2);
      const Rates v = randomRates(g, 3.0), a = randomRates(g, 5.0);
      InertiaOutput out;
      b.inertiaForce(q0.data(), v.data(), a.data(), false, out);
      std::vector<double> M;
      b.mass(q0.data(), M);
      double power = 0, powerFrozen = 0;
      for (int i = 0; i < 12; ++i) {
        power += v[i] * out.f[i];
        for (int j = 0; j < 12; ++j) powerFrozen += v[i] * M[12 * i + j] * a[j];
      }
      const double h = 2.5e-5;
      State qa, qb;
      Rates va, vb;
      motion(q0, v, a, h, qa, va);
      motion(q0, v, a, -h, qb, vb);
      const double dT = (kinetic(b, qa, va) - kinetic(b, qb, vb)) / (2 * h);
      const double scale = std::abs(dT) + std::abs(power) + 1.0;
      worst = std::max(worst, std::abs(power - dT) / scale);
      worstFrozen = std::max(worstFrozen, std::abs(powerFrozen - dT) / scale);
    }
    // measured (2026-11-27, h = 2.5e-5): 3.2e-9, rotary-heavy 3.3e-8 (the central difference's h^2
    // error: 1.3e-8 and 1.3e-7 with h = 5e-5); the frozen M(q) a: 0.93, rotary-heavy 2.37
    EXPECT_LT(worst, 2e-7) << "rotary-heavy " << heavy;
    EXPECT_GT(worstFrozen, 0.1) << "rotary-heavy " << heavy;
  }
}

// At rest (v = 0) the complete force is M(q) a, bit for bit in the sense of round-off.
TEST(BeamInertia, AtRestIsMassTimesAcceleration) {
  const BeamCorotational b = makeBeam();
  std::mt19937 g(3);
  const State q = randomState(g, 0.2);
  const Rates v{}, a = randomRates(g, 2.0);
  InertiaOutput out;
  b.inertiaForce(q.data(), v.data(), a.data(), true, out);
  std::vector<double> M;
  b.mass(q.data(), M);
  double err = 0, ref = 0;
  for (int i = 0; i < 12; ++i) {
    double s = 0;
    for (int j = 0; j < 12; ++j) s += M[12 * i + j] * a[j];
    err = std::max(err, std::abs(s - out.f[i]));
    ref = std::max(ref, std::abs(s));
  }
  EXPECT_LT(err, 1e-14 * ref);
  EXPECT_LT(test::maxAbs(out.Dv), 1e-30);  // linear in v: no derivative at v = 0
}

// d f / d q (translations, spatial spins R -> exp(h e_k) R, at fixed v and a) and d f / d v against
// central differences.
TEST(BeamInertia, TangentMatchesCentralDifferences) {
  for (bool heavy : {false, true}) {
    const BeamCorotational b = makeBeam(heavy);
    std::mt19937 g(11);
    double worstQ = 0, worstV = 0;
    for (int trial = 0; trial < 5; ++trial) {
      const State q = randomState(g, 0.2);
      const Rates v = randomRates(g, 3.0), a = randomRates(g, 5.0);
      InertiaOutput out, fp, fm;
      b.inertiaForce(q.data(), v.data(), a.data(), true, out);
      const double h = 1e-6;
      std::vector<double> numQ(144), numV(144);
      for (int k = 0; k < 12; ++k) {
        const State qp = test::perturbed(q, k, h), qm = test::perturbed(q, k, -h);
        b.inertiaForce(qp.data(), v.data(), a.data(), false, fp);
        b.inertiaForce(qm.data(), v.data(), a.data(), false, fm);
        for (int i = 0; i < 12; ++i) numQ[12 * i + k] = (fp.f[i] - fm.f[i]) / (2 * h);
        Rates vp = v, vm = v;
        vp[k] += h, vm[k] -= h;
        b.inertiaForce(q.data(), vp.data(), a.data(), false, fp);
        b.inertiaForce(q.data(), vm.data(), a.data(), false, fm);
        for (int i = 0; i < 12; ++i) numV[12 * i + k] = (fp.f[i] - fm.f[i]) / (2 * h);
      }
      std::vector<double> dq(144), dv(144);
      for (int i = 0; i < 144; ++i) dq[i] = numQ[i] - out.Kq[i], dv[i] = numV[i] - out.Dv[i];
      worstQ = std::max(worstQ, test::maxAbs(dq) / test::maxAbs(numQ));
      worstV = std::max(worstV, test::maxAbs(dv) / test::maxAbs(numV));
    }
    // measured (2026-11-27, h = 1e-6): d f / d q 2.1e-9, d f / d v 3.7e-9 of their largest entry;
    // rotary-heavy 1.1e-9, 1.3e-9
    EXPECT_LT(worstQ, 3e-8) << "rotary-heavy " << heavy;
    EXPECT_LT(worstV, 3e-8) << "rotary-heavy " << heavy;
  }
}

// A rigid motion of the undeformed, turned element: spin omega, spin rate alpha, centre velocity Vc and
// acceleration Ac. The element's inertia about its centre is the bar's rhoA l0^3 / 12 about the two
// transverse axes plus the sections' l0 (rho Ip e1 e1^T + rho Iy e2 e2^T + rho Iz e3 e3^T); T must be
// 1/2 m Vc^2 + 1/2 omega . Jc omega, the force resultant m Ac and the moment resultant about the centre
// Jc alpha + omega x Jc omega (Euler). Without the bending rotary inertia they miss l0 rho Iy, l0 rho Iz.
TEST(BeamInertia, RigidMotionHasRigidBodyMomenta) {
  for (bool heavy : {false, true}) {
    const BeamSection s = section(heavy);
    const BeamCorotational b = makeBeam(heavy);
    const double l = norm(kXq - kXp), m = s.rhoA * l;
    const Mat3 Q = expSO3(Vec3{0.3, -0.5, 0.7});
    const Vec3 c = Q * (0.5 * (kXp + kXq)) + Vec3{0.2, 0.1, -0.3};
    const Vec3 e1 = (1.0 / l) * (Q * (kXq - kXp)), ez = b.ez0(), ey = b.ey0();
    const Vec3 e2 = Q * ey, e3 = Q * ez;
    const Mat3 Jc = (m * l * l / 12.0) * (outer(e2, e2) + outer(e3, e3)) +
                    l * (s.rhoIp * outer(e1, e1) + s.rhoIy * outer(e2, e2) + s.rhoIz * outer(e3, e3));
    const Vec3 w{0.8, -1.7, 2.3}, al{-3.1, 0.6, 1.9}, Vc{0.4, -0.9, 0.2}, Ac{1.2, 0.3, -2.2};
    State q{};
    Rates v{}, a{};
    for (int n = 0; n < 2; ++n) {
      const Vec3 r = Q * ((n == 0 ? kXp : kXq) - 0.5 * (kXp + kXq));
      test::setNode(q, n, c + r, Q);
      const Vec3 vn = Vc + cross(w, r), an = Ac + cross(al, r) + cross(w, cross(w, r));
      for (int i = 0; i < 3; ++i) {
        v[6 * n + i] = vn[i], v[6 * n + 3 + i] = w[i];
        a[6 * n + i] = an[i], a[6 * n + 3 + i] = al[i];
      }
    }
    const double Tref = 0.5 * m * dot(Vc, Vc) + 0.5 * dot(w, Jc * w);
    EXPECT_NEAR(kinetic(b, q, v), Tref, 1e-13 * Tref) << "rotary-heavy " << heavy;
    InertiaOutput out;
    b.inertiaForce(q.data(), v.data(), a.data(), false, out);
    Vec3 F{}, Mc{};
    for (int n = 0; n < 2; ++n) {
      const Vec3 fn{out.f[6 * n], out.f[6 * n + 1], out.f[6 * n + 2]};
      const Vec3 mn{out.f[6 * n + 3], out.f[6 * n + 4], out.f[6 * n + 5]};
      F = F + fn;
      Mc = Mc + mn + cross(test::nodePosition(q, n) - c, fn);
    }
    // measured (2026-11-27): T, force and moment to 6.7e-16, 7.3e-16, 5.0e-16 of their size; without the
    // bending rotary inertia in the mass the moment misses by |dM| = 0.40 (rotary-heavy: 6.0)
    const Vec3 Fref = m * Ac, Mref = Jc * al + cross(w, Jc * w);
    EXPECT_LT(norm(F - Fref), 1e-12 * norm(Fref)) << "rotary-heavy " << heavy;
    EXPECT_LT(norm(Mc - Mref), 1e-12 * norm(Mref)) << "rotary-heavy " << heavy;
  }
}
