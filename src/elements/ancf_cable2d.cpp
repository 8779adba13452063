// Exudyn ObjectANCFCable2D kernel (see ancf_cable2d.hpp for the formulation).
#include "elements/ancf_cable2d.hpp"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace sinew {

namespace {
// force-law evaluation counters of this process (AncfCable2D::evaluationCounts)
std::atomic<long> gUserFunctionCalls{0}, gDampingTerms{0};

std::string number(double v) {
  if (std::isnan(v)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Integration rules on [-1, 1] (Exudyn's gaussRuleOrder9/7/5/3 and the 3-point Lobatto rule).
struct Rule {
  int n;
  double xi[5], w[5];
};
Rule gauss(int points) {
  Rule r{points, {}, {}};
  switch (points) {
    case 2: {
      const double a = 1.0 / std::sqrt(3.0);
      r = {2, {-a, a}, {1.0, 1.0}};
      break;
    }
    case 3: {
      const double a = std::sqrt(0.6);
      r = {3, {-a, 0.0, a}, {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};
      break;
    }
    case 4: {
      const double s = 2.0 / 7.0 * std::sqrt(6.0 / 5.0);
      const double a = std::sqrt(3.0 / 7.0 - s), b = std::sqrt(3.0 / 7.0 + s);
      const double wa = (18.0 + std::sqrt(30.0)) / 36.0, wb = (18.0 - std::sqrt(30.0)) / 36.0;
      r = {4, {-b, -a, a, b}, {wb, wa, wa, wb}};
      break;
    }
    case 5: {
      const double s = 2.0 * std::sqrt(10.0 / 7.0);
      const double a = std::sqrt(5.0 - s) / 3.0, b = std::sqrt(5.0 + s) / 3.0;
      const double wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0;
      const double wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
      r = {5, {-b, -a, 0.0, a, b}, {wb, wa, 128.0 / 225.0, wa, wb}};
      break;
    }
    default: throw std::invalid_argument("ancf_cable2d: unsupported Gauss rule");
  }
  return r;
}
Rule lobatto3() { return {3, {-1.0, 0.0, 1.0}, {1.0 / 3.0, 4.0 / 3.0, 1.0 / 3.0}}; }

/// v = sum_j S_j q_(j, 0..1): r, r', r'' from the compressed shape vector.
inline void map2(const std::array<double, 4>& S, const double* q, double v[2]) {
  v[0] = S[0] * q[0] + S[1] * q[2] + S[2] * q[4] + S[3] * q[6];
  v[1] = S[0] * q[1] + S[1] * q[3] + S[2] * q[5] + S[3] * q[7];
}

/// Strain measures and their derivatives at one point.
struct PointState {
  // axial: eps = |r'| - 1
  double eps = 0, eps_t = 0;
  double t[2] = {0, 0};  // unit tangent
  double n = 1;          // |r'|
  double g[8] = {};      // d eps / dq  (= d eps_t / d qdot)
  double geps_t[8] = {}; // d eps_t / dq
  // bending: K = (r' x r'')_z / |r'|^2
  double kap = 0, kap_t = 0;
  double h[8] = {};      // dK / dq (= d K_t / d qdot)
  double hk_t[8] = {};   // d K_t / dq = H_K qdot
  double Hk[64] = {};    // d2K / dq2 (only with tangent)
};

/// eps, d eps/dq and, with qdot, eps_t and d eps_t/dq (Exudyn: d eps = r'^T S'_i / |r'|).
void axialState(const std::array<double, 4>& Sx, const double* q, const double* qdot, PointState& s) {
  double rx[2];
  map2(Sx, q, rx);
  s.n = std::sqrt(rx[0] * rx[0] + rx[1] * rx[1]);
  s.eps = s.n - 1.0;
  s.t[0] = rx[0] / s.n;
  s.t[1] = rx[1] / s.n;
  for (int j = 0; j < 4; ++j) {
    s.g[2 * j] = Sx[j] * s.t[0];
    s.g[2 * j + 1] = Sx[j] * s.t[1];
  }
  if (qdot) {
    double rx_t[2];
    map2(Sx, qdot, rx_t);
    s.eps_t = s.t[0] * rx_t[0] + s.t[1] * rx_t[1];
    // d eps_t/dq = (I - t t^T)/|r'| r'_t, spread by S'
    const double p0 = (rx_t[0] - s.eps_t * s.t[0]) / s.n, p1 = (rx_t[1] - s.eps_t * s.t[1]) / s.n;
    for (int j = 0; j < 4; ++j) {
      s.geps_t[2 * j] = Sx[j] * p0;
      s.geps_t[2 * j + 1] = Sx[j] * p1;
    }
  } else {
    s.eps_t = 0.0;
    for (double& v : s.geps_t) v = 0.0;
  }
}

/// K = f/G with f = r' x r'', G = |r'|^2; dK/dq, optionally the Hessian, K_t and dK_t/dq.
void bendingState(const std::array<double, 4>& Sx, const std::array<double, 4>& Sxx, const double* q,
                  const double* qdot, bool hessian, PointState& s) {
  double rx[2], rxx[2];
  map2(Sx, q, rx);
  map2(Sxx, q, rxx);
  const double f = rx[0] * rxx[1] - rx[1] * rxx[0];
  const double G = rx[0] * rx[0] + rx[1] * rx[1];
  const double iG = 1.0 / G;
  s.kap = f * iG;
  double df[8], dG[8];
  for (int j = 0; j < 4; ++j) {
    df[2 * j] = Sx[j] * rxx[1] - Sxx[j] * rx[1];
    df[2 * j + 1] = -Sx[j] * rxx[0] + Sxx[j] * rx[0];
    dG[2 * j] = 2.0 * rx[0] * Sx[j];
    dG[2 * j + 1] = 2.0 * rx[1] * Sx[j];
  }
  for (int a = 0; a < 8; ++a) s.h[a] = (df[a] - s.kap * dG[a]) * iG;  // Exudyn eq. for dK
  if (hessian) {
    // H_K = H_f/G - (df dG^T + dG df^T)/G^2 + 2 f dG dG^T/G^3 - f H_G/G^2
    const double iG2 = iG * iG, c3 = 2.0 * f * iG2 * iG, cG = f * iG2;
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 2; ++i) {
        const int a = 2 * j + i;
        for (int k = 0; k < 4; ++k) {
          const double hf = Sx[j] * Sxx[k] - Sxx[j] * Sx[k];
          const double hg = 2.0 * Sx[j] * Sx[k];
          for (int l = 0; l < 2; ++l) {
            const int b = 2 * k + l;
            const double eps_il = (i == l) ? 0.0 : (i == 0 ? 1.0 : -1.0);
            double v = eps_il * hf * iG - (df[a] * dG[b] + dG[a] * df[b]) * iG2 + c3 * dG[a] * dG[b];
            if (i == l) v -= cG * hg;
            s.Hk[8 * a + b] = v;
          }
        }
      }
    }
  }
  if (qdot) {
    double kt = 0.0;
    for (int a = 0; a < 8; ++a) kt += s.h[a] * qdot[a];
    s.kap_t = kt;
    if (hessian) {
      for (int a = 0; a < 8; ++a) {
        double v = 0.0;
        for (int b = 0; b < 8; ++b) v += s.Hk[8 * a + b] * qdot[b];
        s.hk_t[a] = v;
      }
    }
  } else {
    s.kap_t = 0.0;
    for (double& v : s.hk_t) v = 0.0;
  }
}

}  // namespace

// ------------------------------------------------------------------------------------------------
AncfCable2DParameters ancfCable2DParameters(const ElementSet& set) {
  AncfCable2DParameters p;
  p.physicsMassPerLength = set.physicsMassPerLength;
  p.physicsBendingStiffness = set.physicsBendingStiffness;
  p.physicsAxialStiffness = set.physicsAxialStiffness;
  p.physicsBendingDamping = set.physicsBendingDamping;
  p.physicsAxialDamping = set.physicsAxialDamping;
  p.physicsReferenceAxialStrain = set.physicsReferenceAxialStrain;
  p.physicsReferenceCurvature = set.physicsReferenceCurvature;
  p.strainIsRelativeToReference = set.strainIsRelativeToReference;
  p.useReducedOrderIntegration = set.useReducedOrderIntegration;
  if (!set.axialForceUserFunction.empty())
    p.axialForceUserFunction = std::make_shared<const Expression>(
        Expression::compile(set.axialForceUserFunction, "axialForceUserFunction"));
  if (!set.bendingMomentUserFunction.empty())
    p.bendingMomentUserFunction = std::make_shared<const Expression>(
        Expression::compile(set.bendingMomentUserFunction, "bendingMomentUserFunction"));
  return p;
}

std::array<double, 4> AncfCable2D::shape(double x, double L) {
  const double xi = x / L;
  return {1.0 - 3.0 * xi * xi + 2.0 * xi * xi * xi, x - 2.0 * x * x / L + x * xi * xi,
          3.0 * xi * xi - 2.0 * xi * xi * xi, -x * xi + x * xi * xi};
}
std::array<double, 4> AncfCable2D::shape_x(double x, double L) {
  const double L2 = L * L, L3 = L2 * L;
  return {-6.0 * x / L2 + 6.0 * x * x / L3, 1.0 - 4.0 * x / L + 3.0 * x * x / L2, 6.0 * x / L2 - 6.0 * x * x / L3,
          -2.0 * x / L + 3.0 * x * x / L2};
}
std::array<double, 4> AncfCable2D::shape_xx(double x, double L) {
  const double L2 = L * L, L3 = L2 * L;
  return {12.0 * x / L3 - 6.0 / L2, 6.0 * x / L2 - 4.0 / L, 6.0 / L2 - 12.0 * x / L3, 6.0 * x / L2 - 2.0 / L};
}

AncfCable2D::AncfCable2D(const std::array<double, 8>& qRef, double L, const AncfCable2DParameters& p)
    : qRef_(qRef), L_(L), p_(p) {
  if (!(L > 0.0)) throw std::invalid_argument("ancf_cable2d: reference length must be positive");
  if (p.useReducedOrderIntegration < 0 || p.useReducedOrderIntegration > 2)
    throw std::invalid_argument("ancf_cable2d: useReducedOrderIntegration must be 0, 1 or 2");
  const Rule ra = p.useReducedOrderIntegration == 0 ? gauss(5)
                  : p.useReducedOrderIntegration == 1 ? gauss(4)
                                                      : lobatto3();
  const Rule rb = p.useReducedOrderIntegration == 0 ? gauss(3) : gauss(2);
  auto fill = [&](const Rule& r, std::array<IntegrationPoint, kMaxIp>& ips) {
    for (int i = 0; i < r.n; ++i) {
      IntegrationPoint& ip = ips[i];
      ip.x = 0.5 * L * r.xi[i] + 0.5 * L;  // x_ip = L/2 xi + L/2
      ip.w = 0.5 * L * r.w[i];
      ip.Sx = shape_x(ip.x, L);
      ip.Sxx = shape_xx(ip.x, L);
      ip.strainRef = axialStrainRef(ip.x);
      ip.curvatureRef = curvatureRef(ip.x);
    }
  };
  nAxial_ = ra.n;
  nBending_ = rb.n;
  fill(ra, axialIp_);
  fill(rb, bendingIp_);

  const Expression* ua = p_.axialForceUserFunction.get();
  const Expression* ub = p_.bendingMomentUserFunction.get();
  hasDamping_ = (!ua && p_.physicsAxialDamping != 0.0) || (!ub && p_.physicsBendingDamping != 0.0) ||
                (ua && (ua->uses(UfVar::axialStrain_t) || ua->uses(UfVar::curvature_t))) ||
                (ub && (ub->uses(UfVar::axialStrain_t) || ub->uses(UfVar::curvature_t)));
  axialNeedsCurvature_ =
      ua && (ua->uses(UfVar::curvature) || ua->uses(UfVar::curvature_t) || ua->uses(UfVar::curvatureRef));
  bendingNeedsStrain_ =
      ub && (ub->uses(UfVar::axialStrain) || ub->uses(UfVar::axialStrain_t) || ub->uses(UfVar::axialStrainRef));

  // M = rhoA int S^T S dx, Gauss order 7 (exact for the cubic shape functions).
  const Rule rm = gauss(4);
  for (int ipn = 0; ipn < rm.n; ++ipn) {
    const double x = 0.5 * L * rm.xi[ipn] + 0.5 * L;
    const double w = 0.5 * L * rm.w[ipn] * p_.physicsMassPerLength;
    const std::array<double, 4> S = shape(x, L);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        M_[8 * (2 * i) + 2 * j] += w * S[i] * S[j];
        M_[8 * (2 * i + 1) + 2 * j + 1] += w * S[i] * S[j];
      }
  }
}

std::span<const NodeKind> AncfCable2D::nodeKinds() const {
  static constexpr std::array<NodeKind, 2> kinds{NodeKind::Ancf2D, NodeKind::Ancf2D};
  return kinds;
}

double AncfCable2D::axialStrain(const double* q, double x) const {
  double rx[2];
  map2(shape_x(x, L_), q, rx);
  return std::sqrt(rx[0] * rx[0] + rx[1] * rx[1]) - 1.0;
}
double AncfCable2D::curvature(const double* q, double x) const {
  double rx[2], rxx[2];
  map2(shape_x(x, L_), q, rx);
  map2(shape_xx(x, L_), q, rxx);
  return (rx[0] * rxx[1] - rx[1] * rxx[0]) / (rx[0] * rx[0] + rx[1] * rx[1]);
}
double AncfCable2D::axialStrainRef(double x) const {
  double r = p_.physicsReferenceAxialStrain;
  if (p_.strainIsRelativeToReference != 0.0) r += p_.strainIsRelativeToReference * axialStrain(qRef_.data(), x);
  return r;
}
double AncfCable2D::curvatureRef(double x) const {
  double r = p_.physicsReferenceCurvature;
  if (p_.strainIsRelativeToReference != 0.0) r += p_.strainIsRelativeToReference * curvature(qRef_.data(), x);
  return r;
}

// Force laws: built-in linear visco-elastic or the compiled user function with Exudyn's arguments.
struct AncfCable2D::Law {
  static UserFunctionArgs args(const AncfCable2DParameters& p, double t, double xiNorm, const PointState& s,
                               double epsRef, double kapRef) {
    UserFunctionArgs a;
    a[UfVar::t] = t;
    a[UfVar::axialPositionNormalized] = xiNorm;
    a[UfVar::axialStrain] = s.eps;
    a[UfVar::axialStrain_t] = s.eps_t;
    a[UfVar::axialStrainRef] = epsRef;
    a[UfVar::curvature] = s.kap;
    a[UfVar::curvature_t] = s.kap_t;
    a[UfVar::curvatureRef] = kapRef;
    a[UfVar::physicsAxialStiffness] = p.physicsAxialStiffness;
    a[UfVar::physicsAxialDamping] = p.physicsAxialDamping;
    a[UfVar::physicsBendingStiffness] = p.physicsBendingStiffness;
    a[UfVar::physicsBendingDamping] = p.physicsBendingDamping;
    a[UfVar::physicsMassPerLength] = p.physicsMassPerLength;
    a[UfVar::physicsReferenceAxialStrain] = p.physicsReferenceAxialStrain;
    a[UfVar::physicsReferenceCurvature] = p.physicsReferenceCurvature;
    return a;
  }
  // N = EA (eps - eps_ref) + d_eps eps_t   (Exudyn eq. (N))
  static UserFunctionValue user(const Expression& e, const AncfCable2DParameters& p, double t, double xiNorm,
                                const PointState& s, double epsRef, double kapRef) {
    gUserFunctionCalls.fetch_add(1, std::memory_order_relaxed);
    if (e.uses(UfVar::axialStrain_t) || e.uses(UfVar::curvature_t)) gDampingTerms.fetch_add(1, std::memory_order_relaxed);
    return e.evaluate(args(p, t, xiNorm, s, epsRef, kapRef));
  }
  static UserFunctionValue axial(const AncfCable2DParameters& p, double t, double xiNorm, const PointState& s,
                                 double epsRef, double kapRef) {
    if (p.axialForceUserFunction) return user(*p.axialForceUserFunction, p, t, xiNorm, s, epsRef, kapRef);
    UserFunctionValue v;
    v.value = p.physicsAxialStiffness * (s.eps - epsRef);
    v.dAxialStrain = p.physicsAxialStiffness;
    if (p.physicsAxialDamping != 0.0) {
      gDampingTerms.fetch_add(1, std::memory_order_relaxed);
      v.value += p.physicsAxialDamping * s.eps_t;
      v.dAxialStrain_t = p.physicsAxialDamping;
    }
    return v;
  }
  // M = EI (K - K_ref) + d_K K_t   (Exudyn eq. (M))
  static UserFunctionValue bending(const AncfCable2DParameters& p, double t, double xiNorm, const PointState& s,
                                   double epsRef, double kapRef) {
    if (p.bendingMomentUserFunction) return user(*p.bendingMomentUserFunction, p, t, xiNorm, s, epsRef, kapRef);
    UserFunctionValue v;
    v.value = p.physicsBendingStiffness * (s.kap - kapRef);
    v.dCurvature = p.physicsBendingStiffness;
    if (p.physicsBendingDamping != 0.0) {
      gDampingTerms.fetch_add(1, std::memory_order_relaxed);
      v.value += p.physicsBendingDamping * s.kap_t;
      v.dCurvature_t = p.physicsBendingDamping;
    }
    return v;
  }
  // A force law that is not finite (its value, or with a tangent/damping the derivatives used) ends
  // the evaluation: the assembler reports it with the set, element and time instead of letting
  // inf/NaN reach the solvers (issue 13 item 6). strain / curvature: whether s holds them here.
  static void check(const AncfCable2DParameters& p, const UserFunctionValue& v, bool axialLaw, double t,
                    const PointState& s, bool strain, bool curvature, bool derivatives) {
    const double d[4] = {v.dAxialStrain, v.dAxialStrain_t, v.dCurvature, v.dCurvature_t};
    static const char* dNames[4] = {"axialStrain", "axialStrain_t", "curvature", "curvature_t"};
    int bad = -1;
    for (int k = 0; derivatives && k < 4 && bad < 0; ++k)
      if (!std::isfinite(d[k])) bad = k;
    if (std::isfinite(v.value) && bad < 0) return;
    // a non-finite state (a diverging Newton update) is not the law's doing: the solver handles it
    if (!std::isfinite(t) || (strain && !std::isfinite(s.eps)) || (curvature && !std::isfinite(s.kap))) return;
    const Expression* user = axialLaw ? p.axialForceUserFunction.get() : p.bendingMomentUserFunction.get();
    const std::string law = user ? user->name() + " \"" + user->text() + "\""
                            : axialLaw ? "the axial force physicsAxialStiffness*(axialStrain - axialStrainRef)"
                                       : "the bending moment physicsBendingStiffness*(curvature - curvatureRef)";
    const std::string returned = !std::isfinite(v.value)
                                     ? number(v.value)
                                     : "a non-finite derivative (d/d" + std::string(dNames[bad]) + " = " + number(d[bad]) + ")";
    std::string where = "time t = " + number(t);
    if (strain) where += ", axialStrain = " + number(s.eps);
    if (curvature) where += ", curvature = " + number(s.kap);
    throw ElementValueError(law, returned, where);
  }
};

AncfCable2D::EvaluationCounts AncfCable2D::evaluationCounts() {
  return {gUserFunctionCalls.load(std::memory_order_relaxed), gDampingTerms.load(std::memory_order_relaxed)};
}

void AncfCable2D::evaluate(const KernelInput& in, const KernelNeeds& needs, KernelOutput& out) const {
  const double* q = in.q;
  const double* qd = in.qdot;
  const bool wantK = needs.tangent;
  const bool wantD = needs.damping && hasDamping_;
  double f[8] = {};
  std::array<double, 64> Km{}, Kg{}, D{};
  PointState s;

  // Axial part: Q += w N d eps/dq
  for (int ip = 0; ip < nAxial_; ++ip) {
    const IntegrationPoint& P = axialIp_[ip];
    axialState(P.Sx, q, qd, s);
    if (axialNeedsCurvature_) bendingState(P.Sx, P.Sxx, q, qd, wantK, s);
    const UserFunctionValue N = Law::axial(p_, in.t, P.x / L_, s, P.strainRef, P.curvatureRef);
    Law::check(p_, N, true, in.t, s, true, axialNeedsCurvature_, wantK || wantD);
    const double w = P.w;
    for (int a = 0; a < 8; ++a) f[a] += w * N.value * s.g[a];
    if (wantK) {
      double dN[8];  // dN/dq
      for (int b = 0; b < 8; ++b) {
        dN[b] = N.dAxialStrain * s.g[b] + N.dAxialStrain_t * s.geps_t[b];
        if (axialNeedsCurvature_) dN[b] += N.dCurvature * s.h[b] + N.dCurvature_t * s.hk_t[b];
      }
      for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b) Km[8 * a + b] += w * s.g[a] * dN[b];
      // N d2eps/dq2 = N S'_j S'_k (I - t t^T)/|r'|
      const double c = w * N.value / s.n;
      const double P00 = c * (1.0 - s.t[0] * s.t[0]), P01 = -c * s.t[0] * s.t[1], P11 = c * (1.0 - s.t[1] * s.t[1]);
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k) {
          const double ss = P.Sx[j] * P.Sx[k];
          Kg[8 * (2 * j) + 2 * k] += ss * P00;
          Kg[8 * (2 * j) + 2 * k + 1] += ss * P01;
          Kg[8 * (2 * j + 1) + 2 * k] += ss * P01;
          Kg[8 * (2 * j + 1) + 2 * k + 1] += ss * P11;
        }
    }
    if (wantD) {
      for (int b = 0; b < 8; ++b) {
        double dNv = N.dAxialStrain_t * s.g[b];
        if (axialNeedsCurvature_) dNv += N.dCurvature_t * s.h[b];
        for (int a = 0; a < 8; ++a) D[8 * a + b] += w * s.g[a] * dNv;
      }
    }
  }

  // Bending part: Q += w M dK/dq
  for (int ip = 0; ip < nBending_; ++ip) {
    const IntegrationPoint& P = bendingIp_[ip];
    bendingState(P.Sx, P.Sxx, q, qd, wantK, s);
    if (bendingNeedsStrain_) axialState(P.Sx, q, qd, s);
    const UserFunctionValue M = Law::bending(p_, in.t, P.x / L_, s, P.strainRef, P.curvatureRef);
    Law::check(p_, M, false, in.t, s, bendingNeedsStrain_, true, wantK || wantD);
    const double w = P.w;
    for (int a = 0; a < 8; ++a) f[a] += w * M.value * s.h[a];
    if (wantK) {
      double dM[8];
      for (int b = 0; b < 8; ++b) {
        dM[b] = M.dCurvature * s.h[b] + M.dCurvature_t * s.hk_t[b];
        if (bendingNeedsStrain_) dM[b] += M.dAxialStrain * s.g[b] + M.dAxialStrain_t * s.geps_t[b];
      }
      const double c = w * M.value;
      for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b) {
          Km[8 * a + b] += w * s.h[a] * dM[b];
          Kg[8 * a + b] += c * s.Hk[8 * a + b];
        }
    }
    if (wantD) {
      for (int b = 0; b < 8; ++b) {
        double dMv = M.dCurvature_t * s.h[b];
        if (bendingNeedsStrain_) dMv += M.dAxialStrain_t * s.g[b];
        for (int a = 0; a < 8; ++a) D[8 * a + b] += w * s.h[a] * dMv;
      }
    }
  }

  out.f.assign(f, f + 8);
  if (wantK) {
    if (needs.splitGeometric) {
      out.K.assign(Km.begin(), Km.end());
      out.Kg.assign(Kg.begin(), Kg.end());
    } else {
      out.K.resize(64);
      for (int a = 0; a < 64; ++a) out.K[a] = Km[a] + Kg[a];
    }
  }
  if (needs.damping) {
    if (wantD) out.D.assign(D.begin(), D.end());
    else out.D.assign(64, 0.0);
  }
}

void AncfCable2D::mass(const double* /*q*/, std::vector<double>& M) const { M.assign(M_.begin(), M_.end()); }

void AncfCable2D::bodyForce(const double* /*q*/, const Vec3& a, std::vector<double>& f) const {
  // rhoA int S dx with 2-point Gauss (exact for cubics), as Exudyn's DisplacementMassIntegral_q.
  const Rule r = gauss(2);
  double SI[4] = {};
  for (int i = 0; i < r.n; ++i) {
    const std::array<double, 4> S = shape(0.5 * L_ * r.xi[i] + 0.5 * L_, L_);
    const double w = p_.physicsMassPerLength * 0.5 * L_ * r.w[i];
    for (int j = 0; j < 4; ++j) SI[j] += w * S[j];
  }
  f.resize(8);
  for (int j = 0; j < 4; ++j) {
    f[2 * j] = SI[j] * a[0];
    f[2 * j + 1] = SI[j] * a[1];
  }
}

double AncfCable2D::axialForceAt(const double* q, const double* qdot, double x, double t) const {
  PointState s;
  const std::array<double, 4> Sx = shape_x(x, L_);
  axialState(Sx, q, qdot, s);
  if (axialNeedsCurvature_) bendingState(Sx, shape_xx(x, L_), q, qdot, false, s);
  return Law::axial(p_, t, x / L_, s, axialStrainRef(x), curvatureRef(x)).value;
}

double AncfCable2D::bendingMomentAt(const double* q, const double* qdot, double x, double t) const {
  PointState s;
  const std::array<double, 4> Sx = shape_x(x, L_);
  bendingState(Sx, shape_xx(x, L_), q, qdot, false, s);
  if (bendingNeedsStrain_) axialState(Sx, q, qdot, s);
  return Law::bending(p_, t, x / L_, s, axialStrainRef(x), curvatureRef(x)).value;
}

void AncfCable2D::elementForce(const double* q, std::vector<double>& out) const {
  out.resize(3);
  out[0] = axialForceAt(q, nullptr, 0.0, 0.0);
  out[1] = axialForceAt(q, nullptr, 0.5 * L_, 0.0);
  out[2] = axialForceAt(q, nullptr, L_, 0.0);
}

const std::vector<std::string>& AncfCable2D::outputVariables() {
  static const std::vector<std::string> names = {
      "Position",       "Displacement", "Velocity",    "VelocityLocal",   "Rotation",
      "Director1",      "StrainLocal",  "CurvatureLocal", "ForceLocal",   "TorqueLocal",
      "AngularVelocity", "Acceleration", "AngularAcceleration"};
  return names;
}

std::vector<double> AncfCable2D::output(const std::string& variable, double x, const double* q, const double* qdot,
                                        const double* qddot, double t) const {
  static const double zeros[8] = {};
  const double* qd = qdot ? qdot : zeros;
  const double* qdd = qddot ? qddot : zeros;
  const std::array<double, 4> S = shape(x, L_), Sx = shape_x(x, L_);
  double rx[2];
  map2(Sx, q, rx);
  const double G = rx[0] * rx[0] + rx[1] * rx[1];
  if (variable == "Position") {
    double r[2];
    map2(S, q, r);
    return {r[0], r[1], 0.0};
  }
  if (variable == "Displacement") {
    double r[2], r0[2];
    map2(S, q, r);
    map2(S, qRef_.data(), r0);
    return {r[0] - r0[0], r[1] - r0[1], 0.0};
  }
  if (variable == "Velocity") {
    double v[2];
    map2(S, qd, v);
    return {v[0], v[1], 0.0};
  }
  if (variable == "VelocityLocal") {
    // R^T v with R = rotation by phi = atan2(r'_y, r'_x)
    double v[2];
    map2(S, qd, v);
    const double phi = std::atan2(rx[1], rx[0]), c = std::cos(phi), sn = std::sin(phi);
    return {c * v[0] + sn * v[1], -sn * v[0] + c * v[1], 0.0};
  }
  if (variable == "Acceleration") {
    double a[2];
    map2(S, qdd, a);
    return {a[0], a[1], 0.0};
  }
  if (variable == "Rotation") return {std::atan2(rx[1], rx[0])};
  if (variable == "Director1") return {rx[0], rx[1], 0.0};
  if (variable == "StrainLocal") return {axialStrain(q, x)};
  if (variable == "CurvatureLocal") return {curvature(q, x)};
  if (variable == "ForceLocal") return {axialForceAt(q, qdot, x, t)};
  if (variable == "TorqueLocal") return {bendingMomentAt(q, qdot, x, t)};
  if (variable == "AngularVelocity") {
    // omega = (-r'_y r'_x,t + r'_x r'_y,t) / |r'|^2
    double rx_t[2];
    map2(Sx, qd, rx_t);
    return {0.0, 0.0, (-rx[1] * rx_t[0] + rx[0] * rx_t[1]) / G};
  }
  if (variable == "AngularAcceleration") {
    // d/dt of omega = f/g with f = -y x_t + x y_t, g = x^2 + y^2 (x, y: slope components)
    double rx_t[2], rx_tt[2];
    map2(Sx, qd, rx_t);
    map2(Sx, qdd, rx_tt);
    const double fo = -rx[1] * rx_t[0] + rx[0] * rx_t[1];
    const double fo_t = -rx[1] * rx_tt[0] + rx[0] * rx_tt[1];
    const double g_t = 2.0 * (rx[0] * rx_t[0] + rx[1] * rx_t[1]);
    return {0.0, 0.0, (fo_t * G - fo * g_t) / (G * G)};
  }
  std::string valid;
  for (const std::string& n : outputVariables()) valid += (valid.empty() ? "" : ", ") + n;
  throw std::invalid_argument("ancf_cable2d: unknown output variable '" + variable + "'; valid: " + valid);
}

bool AncfCable2D::strainEnergy(const double* q, double* energy) const {
  if (p_.axialForceUserFunction || p_.bendingMomentUserFunction) return false;
  const int r = p_.useReducedOrderIntegration;
  const Rule ra = r == 0 ? gauss(5) : (r == 1 ? gauss(4) : lobatto3());
  const Rule rb = r == 0 ? gauss(3) : gauss(2);
  const double L = length();
  double e = 0.0;
  for (int i = 0; i < ra.n; ++i) {
    const double x = 0.5 * L * (ra.xi[i] + 1), d = axialStrain(q, x) - axialStrainRef(x);
    e += 0.25 * L * ra.w[i] * p_.physicsAxialStiffness * d * d;
  }
  for (int i = 0; i < rb.n; ++i) {
    const double x = 0.5 * L * (rb.xi[i] + 1), d = curvature(q, x) - curvatureRef(x);
    e += 0.25 * L * rb.w[i] * p_.physicsBendingStiffness * d * d;
  }
  *energy = e;
  return true;
}

}  // namespace sinew
