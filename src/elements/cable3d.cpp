#include "elements/cable3d.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sinew {

namespace {
constexpr NodeKind kCableNodes[2] = {NodeKind::Point3, NodeKind::Point3};

Vec3 chord(const double* q) { return {q[3] - q[0], q[4] - q[1], q[5] - q[2]}; }

/// Adds s * [B -B; -B B] for a 3x3 block B to the 6x6 row-major matrix K.
void addPair(double* K, const Mat3& B, double s) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double v = s * B[3 * i + j];
      K[6 * i + j] += v;
      K[6 * (i + 3) + j + 3] += v;
      K[6 * i + j + 3] -= v;
      K[6 * (i + 3) + j] -= v;
    }
}
}  // namespace

Cable3D::Cable3D(const Vec3& Xp, const Vec3& Xq, double area, double emod, double dens, double prestressForce)
    : A_(area), E_(emod), dens_(dens), N0_(prestressForce), L_(norm(Xq - Xp)) {
  if (!(L_ > 0.0)) throw std::invalid_argument("cable3d: zero reference length");
}

std::span<const NodeKind> Cable3D::nodeKinds() const { return {kCableNodes, 2}; }

double Cable3D::length(const double* q) const { return norm(chord(q)); }

double Cable3D::axialForce(const double* q) const {
  const double l = length(q);
  if (ff_) return lambda_ * N0_ + (1.0 - lambda_) * N0_ * l / L_;
  return std::max(N0_ + E_ * A_ * (l / L_ - 1.0), 0.0);
}

void Cable3D::setFormFinding(bool on, double lambda) {
  ff_ = on;
  lambda_ = lambda;
}

void Cable3D::setStressAdaption(double lambdaMax, double mueRelax) {
  lambdaMax_ = lambdaMax;
  mueRelax_ = mueRelax;
}

void Cable3D::updateReference(const double* q) {
  const double l = length(q);
  if (lambdaMax_ > 1.0) {
    const double stretch = l / L_;
    const double s = stretch / std::clamp(stretch, 1.0 / lambdaMax_, lambdaMax_);
    N0_ = (1.0 - mueRelax_) * s * N0_ + mueRelax_ * N0_;
  }
  L_ = l;
}

bool Cable3D::slack(const double* q, double* axialStiffness) const {
  if (ff_ || !isSlack(q)) return false;
  const double EA = E_ * A_;
  *axialStiffness = EA > 0.0 ? EA : N0_;
  return true;
}

Vec3 Cable3D::shapeAxis(const double* q) const {
  Vec3 a = chord(q);
  const double l = norm(a);
  if (l > 0.0) a = (1.0 / l) * a;
  return a;
}

void Cable3D::setReference(const double* X) { setReferenceLength(norm(Vec3{X[3] - X[0], X[4] - X[1], X[5] - X[2]})); }

void Cable3D::evaluate(const KernelInput& in, const KernelNeeds& needs, KernelOutput& out) const {
  const double* q = in.q;
  out.f.assign(6, 0.0);
  if (needs.tangent) {
    out.K.assign(36, 0.0);
    if (needs.splitGeometric) out.Kg.assign(36, 0.0);
  }
  if (needs.damping) out.D.assign(36, 0.0);  // stays zero while slack or form finding
  const Vec3 d = chord(q);
  const double l = norm(d);
  const Vec3 e = (1.0 / l) * d;
  double* Kg = needs.splitGeometric ? out.Kg.data() : out.K.data();

  if (ff_) {
    // URS weak form: lambda N delta l + (1 - lambda) (N/L^2) l delta l
    const double qd = lambda_ * N0_ / l + (1.0 - lambda_) * N0_ / L_;  // force density
    for (int k = 0; k < 3; ++k) {
      out.f[k] = -qd * d[k];
      out.f[3 + k] = qd * d[k];
    }
    if (needs.tangent) {
      const Mat3 P = identity3() - outer(e, e);
      addPair(Kg, P, lambda_ * N0_ / l);
      addPair(Kg, identity3(), (1.0 - lambda_) * N0_ / L_);
    }
    return;
  }

  const double N = N0_ + E_ * A_ * (l / L_ - 1.0);
  if (N <= 0.0) return;  // slack: zero force, tangent and damping (isSlack reports it)
  for (int k = 0; k < 3; ++k) {
    out.f[k] = -N * e[k];
    out.f[3 + k] = N * e[k];
  }
  if (needs.tangent) {
    addPair(out.K.data(), outer(e, e), E_ * A_ / L_);
    addPair(Kg, identity3() - outer(e, e), N / l);
  }
  if (in.qdot && beta_ > 0.0) addStrainRateDamping(in.qdot, d, needs, out);
}

void Cable3D::addStrainRateDamping(const double* qdot, const Vec3& d, const KernelNeeds& needs, KernelOutput& out) const {
  // N_d = c ld, c = beta EA/L, ld = e . (v_q - v_p)
  const double l = norm(d), c = beta_ * E_ * A_ / L_;
  const Vec3 e = (1.0 / l) * d;
  const Vec3 w{qdot[3] - qdot[0], qdot[4] - qdot[1], qdot[5] - qdot[2]};
  const double ld = dot(e, w), Nd = c * ld;
  for (int k = 0; k < 3; ++k) {
    out.f[k] -= Nd * e[k];
    out.f[3 + k] += Nd * e[k];
  }
  if (needs.damping) addPair(out.D.data(), outer(e, e), c);
  if (!needs.tangent) return;
  // d(N_d e)/d d = c/l (e w^T P) + N_d/l P: the first with the material part, the second (stress) with Kg
  const Mat3 P = identity3() - outer(e, e);
  Vec3 wP{};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) wP[j] += w[i] * P[3 * i + j];
  addPair(out.K.data(), outer(e, wP), c / l);
  addPair(needs.splitGeometric ? out.Kg.data() : out.K.data(), P, Nd / l);
}

void Cable3D::mass(const double* /*q*/, std::vector<double>& M) const {
  M.assign(36, 0.0);
  const double m = dens_ * A_ * L_ / 6.0;
  for (int k = 0; k < 3; ++k) {
    M[6 * k + k] = 2 * m;
    M[6 * (k + 3) + k + 3] = 2 * m;
    M[6 * k + k + 3] = m;
    M[6 * (k + 3) + k] = m;
  }
}

void Cable3D::bodyForce(const double* /*q*/, const Vec3& a, std::vector<double>& f) const {
  f.assign(6, 0.0);
  const double h = 0.5 * dens_ * A_ * L_;
  for (int k = 0; k < 3; ++k) f[k] = f[3 + k] = h * a[k];
}

double Cable3D::vonMisesMax(const double* q, const double* /*lambda*/) const {
  return A_ > 0.0 ? std::abs(axialForce(q)) / A_ : 0.0;
}

void Cable3D::elementForce(const double* q, std::vector<double>& out) const {
  out.assign(1, axialForce(q));
}

}  // namespace sinew
