// Exudyn ObjectANCFCable2D kernel (see ancf_cable2d.hpp for the formulation).
#include "elements/ancf_cable2d.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <tuple>
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

/// Strain measures and their first derivatives at one point. Element vectors use a = 2 j + i
/// (Hermite function j = 0..3, direction i = x, y). Only what the caller asks for is filled: no
/// array is zeroed per call, and the Hessian of K is never stored (addBendingBlocks adds it).
struct PointState {
  // axial: eps = |r'| - 1
  double eps = 0, eps_t = 0;
  double t[2] = {1, 0};  // unit tangent r'/|r'|
  double n = 1;          // |r'|
  double p[2] = {0, 0};  // (I - t t^T) r'_t / |r'|: d eps_t/dq = S'_j p_i
  double g[8];           // d eps / dq (= d eps_t / d qdot) = S'_j t_i
  // bending: K = f/G, f = (r' x r'')_z, G = |r'|^2
  double kap = 0, kap_t = 0;
  double f = 0, iG = 1;
  double rx_t[2] = {0, 0}, rxx_t[2] = {0, 0};  // r'_t, r''_t
  double df[8], dG[8];                         // df/dq, dG/dq
  double h[8];                                 // dK / dq (= d K_t / d qdot)
};

/// eps, d eps/dq and, with qdot, eps_t and the direction p of d eps_t/dq
/// (Exudyn: d eps = r'^T S'_i / |r'|).
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
    s.p[0] = (rx_t[0] - s.eps_t * s.t[0]) / s.n;
    s.p[1] = (rx_t[1] - s.eps_t * s.t[1]) / s.n;
  } else {
    s.eps_t = 0.0;
    s.p[0] = s.p[1] = 0.0;
  }
}

/// d eps_t / dq = S'_j p_i (zero without velocities).
void strainRateGradient(const std::array<double, 4>& Sx, const PointState& s, double geps_t[8]) {
  for (int j = 0; j < 4; ++j) {
    geps_t[2 * j] = Sx[j] * s.p[0];
    geps_t[2 * j + 1] = Sx[j] * s.p[1];
  }
}

/// K = f/G with f = r' x r'', G = |r'|^2, dK/dq and, with qdot, K_t = dK/dq qdot.
void bendingState(const std::array<double, 4>& Sx, const std::array<double, 4>& Sxx, const double* q,
                  const double* qdot, PointState& s) {
  double rx[2], rxx[2];
  map2(Sx, q, rx);
  map2(Sxx, q, rxx);
  s.f = rx[0] * rxx[1] - rx[1] * rxx[0];
  const double G = rx[0] * rx[0] + rx[1] * rx[1];
  s.iG = 1.0 / G;
  s.kap = s.f * s.iG;
  for (int j = 0; j < 4; ++j) {
    s.df[2 * j] = Sx[j] * rxx[1] - Sxx[j] * rx[1];
    s.df[2 * j + 1] = -Sx[j] * rxx[0] + Sxx[j] * rx[0];
    s.dG[2 * j] = 2.0 * rx[0] * Sx[j];
    s.dG[2 * j + 1] = 2.0 * rx[1] * Sx[j];
  }
  for (int a = 0; a < 8; ++a) s.h[a] = (s.df[a] - s.kap * s.dG[a]) * s.iG;  // Exudyn eq. for dK
  if (qdot) {
    double kt = 0.0;
    for (int a = 0; a < 8; ++a) kt += s.h[a] * qdot[a];
    s.kap_t = kt;
    map2(Sx, qdot, s.rx_t);
    map2(Sxx, qdot, s.rxx_t);
  } else {
    s.kap_t = 0.0;
    s.rx_t[0] = s.rx_t[1] = s.rxx_t[0] = s.rxx_t[1] = 0.0;
  }
}

// The Hessian of K = f/G at the state of bendingState:
//   H_K = H_f/G - (df dG^T + dG df^T)/G^2 + 2 f dG dG^T/G^3 - f H_G/G^2,
// with the constant, block-structured parts (a = 2j+i, b = 2k+l)
//   H_f[a][b] = e_il (S'_j S''_k - S''_j S'_k)  (e_01 = 1, e_10 = -1, e_00 = e_11 = 0),
//   H_G[a][b] = d_il 2 S'_j S'_k.

/// K += a dK/dq (dK/dq)^T + c H_K (row-major 8x8) without forming either matrix. With u = df/dq,
/// v = dG/dq and dK/dq = (u - K v)/G the rank part of both terms is
///   [a u u^T - (a K + c)(u v^T + v u^T) + (a K^2 + 2 c K) v v^T] / G^2 = u x^T + v y^T,
/// and the rest, c (H_f/G - f H_G/G^2), is one 2x2 block per node pair (j, k).
void addBendingBlocks(const std::array<double, 4>& Sx, const std::array<double, 4>& Sxx, const PointState& s,
                      double a, double c, double* __restrict K) {
  const double iG2 = s.iG * s.iG, kap = s.kap;
  const double uu = a * iG2, uv = -(a * kap + c) * iG2, vv = (a * kap * kap + 2.0 * c * kap) * iG2;
  double x[8], y[8];
  for (int b = 0; b < 8; ++b) {
    x[b] = uu * s.df[b] + uv * s.dG[b];
    y[b] = uv * s.df[b] + vv * s.dG[b];
  }
  for (int r = 0; r < 8; ++r)
    for (int b = 0; b < 8; ++b) K[8 * r + b] += s.df[r] * x[b] + s.dG[r] * y[b];
  const double cf = c * s.iG, cg = 2.0 * c * s.f * iG2;
  for (int j = 0; j < 4; ++j)
    for (int k = 0; k < 4; ++k) {
      const double hf = cf * (Sx[j] * Sxx[k] - Sxx[j] * Sx[k]);  // c H_f/G: off-diagonal of the block
      const double hg = cg * Sx[j] * Sx[k];                       // c f H_G/G^2: diagonal of the block
      double* row0 = K + 8 * (2 * j) + 2 * k;
      double* row1 = row0 + 8;
      row0[0] -= hg;
      row0[1] += hf;
      row1[0] -= hf;
      row1[1] -= hg;
    }
}

/// K += S'_j S'_k B for every node pair (j, k), B a 2x2 matrix (row-major): the axial terms, whose
/// vectors all are S' times a direction (d eps/dq = S' t, d eps_t/dq = S' p, d2eps/dq2 = S' S'^T (I - t t^T)/|r'|).
void addAxialBlocks(const std::array<double, 4>& Sx, const double B[4], double* __restrict K) {
  for (int j = 0; j < 4; ++j)
    for (int k = 0; k < 4; ++k) {
      const double ss = Sx[j] * Sx[k];
      double* row0 = K + 8 * (2 * j) + 2 * k;
      double* row1 = row0 + 8;
      row0[0] += ss * B[0];
      row0[1] += ss * B[1];
      row1[0] += ss * B[2];
      row1[1] += ss * B[3];
    }
}

/// d K_t / dq = H_K qdot without forming H_K, using
/// H_f qdot = (S'_j r''_t,y - S''_j r'_t,y, -S'_j r''_t,x + S''_j r'_t,x) and H_G qdot = 2 S'_j r'_t.
void curvatureRateGradient(const std::array<double, 4>& Sx, const std::array<double, 4>& Sxx, const double* qdot,
                           const PointState& s, double hk_t[8]) {
  const double iG2 = s.iG * s.iG, c3 = 2.0 * s.f * iG2 * s.iG, cG = s.f * iG2;
  double f_t = 0.0, G_t = 0.0;  // df/dq qdot, dG/dq qdot
  for (int a = 0; a < 8; ++a) {
    f_t += s.df[a] * qdot[a];
    G_t += s.dG[a] * qdot[a];
  }
  for (int j = 0; j < 4; ++j) {
    const double Hf[2] = {Sx[j] * s.rxx_t[1] - Sxx[j] * s.rx_t[1], -Sx[j] * s.rxx_t[0] + Sxx[j] * s.rx_t[0]};
    for (int i = 0; i < 2; ++i) {
      const int a = 2 * j + i;
      hk_t[a] = Hf[i] * s.iG - (s.df[a] * G_t + s.dG[a] * f_t) * iG2 + c3 * s.dG[a] * G_t -
                cG * 2.0 * Sx[j] * s.rx_t[i];
    }
  }
}

/// K += c u v^T (8x8, row-major).
inline void addOuter(double c, const double u[8], const double v[8], double* __restrict K) {
  for (int a = 0; a < 8; ++a) {
    const double cu = c * u[a];
    for (int b = 0; b < 8; ++b) K[8 * a + b] += cu * v[b];
  }
}

}  // namespace

// ------------------------------------------------------------------------------------------------
AncfCable2DParameters ancfCable2DParameters(const AncfCable2DProperties& set) {
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

std::shared_ptr<const AncfCable2D::Geometry> AncfCable2D::geometry(double L, int rule, double rhoA) {
  static std::mutex mutex;
  static std::map<std::tuple<double, int, double>, std::weak_ptr<const Geometry>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  std::weak_ptr<const Geometry>* slot = std::isfinite(rhoA) ? &cache[{L, rule, rhoA}] : nullptr;
  if (slot)
    if (std::shared_ptr<const Geometry> g = slot->lock()) return g;
  auto g = std::make_shared<Geometry>();
  const Rule ra = rule == 0 ? gauss(5) : rule == 1 ? gauss(4) : lobatto3();
  const Rule rb = rule == 0 ? gauss(3) : gauss(2);
  auto fill = [&](const Rule& r, std::array<IntegrationPoint, kMaxIp>& ips) {
    for (int i = 0; i < r.n; ++i) {
      IntegrationPoint& ip = ips[i];
      ip.x = 0.5 * L * r.xi[i] + 0.5 * L;  // x_ip = L/2 xi + L/2
      ip.w = 0.5 * L * r.w[i];
      ip.xiNorm = ip.x / L;
      ip.Sx = shape_x(ip.x, L);
      ip.Sxx = shape_xx(ip.x, L);
    }
  };
  g->nAxial = ra.n;
  g->nBending = rb.n;
  fill(ra, g->axial);
  fill(rb, g->bending);

  // M = rhoA int S^T S dx, Gauss order 7 (exact for the cubic shape functions).
  const Rule rm = gauss(4);
  for (int ipn = 0; ipn < rm.n; ++ipn) {
    const double x = 0.5 * L * rm.xi[ipn] + 0.5 * L;
    const double w = 0.5 * L * rm.w[ipn] * rhoA;
    const std::array<double, 4> S = shape(x, L);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        g->M[8 * (2 * i) + 2 * j] += w * S[i] * S[j];
        g->M[8 * (2 * i + 1) + 2 * j + 1] += w * S[i] * S[j];
      }
  }
  // rhoA int S dx with 2-point Gauss (exact for cubics), as Exudyn's DisplacementMassIntegral_q:
  // the body force is this times the acceleration (bodyForce).
  const Rule r2 = gauss(2);
  for (int i = 0; i < r2.n; ++i) {
    const std::array<double, 4> S = shape(0.5 * L * r2.xi[i] + 0.5 * L, L);
    const double w = rhoA * 0.5 * L * r2.w[i];
    for (int j = 0; j < 4; ++j) g->massShapeIntegral[j] += w * S[j];
  }
  if (slot) *slot = g;
  return g;
}

AncfCable2D::AncfCable2D(const std::array<double, 8>& qRef, double L, const AncfCable2DParameters& p)
    : AncfCable2D(qRef, L, std::make_shared<const AncfCable2DParameters>(p)) {}

AncfCable2D::AncfCable2D(const std::array<double, 8>& qRef, double L, std::shared_ptr<const AncfCable2DParameters> params)
    : qRef_(qRef), L_(L), params_(std::move(params)) {
  const AncfCable2DParameters& p = *params_;
  if (!(L > 0.0)) throw std::invalid_argument("ancf_cable2d: reference length must be positive");
  if (p.useReducedOrderIntegration < 0 || p.useReducedOrderIntegration > 2)
    throw std::invalid_argument("ancf_cable2d: useReducedOrderIntegration must be 0, 1 or 2");
  geo_ = geometry(L, p.useReducedOrderIntegration, p.physicsMassPerLength);
  if (p.strainIsRelativeToReference != 0.0) {
    auto ref = std::make_shared<ReferenceTable>();
    for (int i = 0; i < geo_->nAxial; ++i)
      ref->axial[i] = {axialStrainRef(geo_->axial[i].x), curvatureRef(geo_->axial[i].x)};
    for (int i = 0; i < geo_->nBending; ++i)
      ref->bending[i] = {axialStrainRef(geo_->bending[i].x), curvatureRef(geo_->bending[i].x)};
    ref_ = std::move(ref);
  }

  const Expression* ua = params_->axialForceUserFunction.get();
  const Expression* ub = params_->bendingMomentUserFunction.get();
  hasDamping_ = (!ua && params_->physicsAxialDamping != 0.0) || (!ub && params_->physicsBendingDamping != 0.0) ||
                (ua && (ua->uses(UfVar::axialStrain_t) || ua->uses(UfVar::curvature_t))) ||
                (ub && (ub->uses(UfVar::axialStrain_t) || ub->uses(UfVar::curvature_t)));
  axialNeedsCurvature_ =
      ua && (ua->uses(UfVar::curvature) || ua->uses(UfVar::curvature_t) || ua->uses(UfVar::curvatureRef));
  bendingNeedsStrain_ =
      ub && (ub->uses(UfVar::axialStrain) || ub->uses(UfVar::axialStrain_t) || ub->uses(UfVar::axialStrainRef));
}

bool AncfCable2D::setStrainRateDamping(double beta) {
  beta_ = userForceLaw() ? 0.0 : beta;
  return !userForceLaw();
}

const char* AncfCable2D::userForceLaw() const {
  if (params_->axialForceUserFunction) return "axialForceUserFunction";
  if (params_->bendingMomentUserFunction) return "bendingMomentUserFunction";
  return nullptr;
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
  double r = params_->physicsReferenceAxialStrain;
  if (params_->strainIsRelativeToReference != 0.0) r += params_->strainIsRelativeToReference * axialStrain(qRef_.data(), x);
  return r;
}
double AncfCable2D::curvatureRef(double x) const {
  double r = params_->physicsReferenceCurvature;
  if (params_->strainIsRelativeToReference != 0.0) r += params_->strainIsRelativeToReference * curvature(qRef_.data(), x);
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
  // beta: the strain-rate damping (s) added as beta EA eps_t (beta EI K_t) to Exudyn's d_eps eps_t (d_K K_t)
  static UserFunctionValue axial(const AncfCable2DParameters& p, double beta, double t, double xiNorm,
                                 const PointState& s, double epsRef, double kapRef) {
    if (p.axialForceUserFunction) return user(*p.axialForceUserFunction, p, t, xiNorm, s, epsRef, kapRef);
    UserFunctionValue v;
    v.value = p.physicsAxialStiffness * (s.eps - epsRef);
    v.dAxialStrain = p.physicsAxialStiffness;
    const double d = p.physicsAxialDamping + beta * p.physicsAxialStiffness;
    if (d != 0.0) {
      gDampingTerms.fetch_add(1, std::memory_order_relaxed);
      v.value += d * s.eps_t;
      v.dAxialStrain_t = d;
    }
    return v;
  }
  // M = EI (K - K_ref) + d_K K_t   (Exudyn eq. (M))
  static UserFunctionValue bending(const AncfCable2DParameters& p, double beta, double t, double xiNorm,
                                   const PointState& s, double epsRef, double kapRef) {
    if (p.bendingMomentUserFunction) return user(*p.bendingMomentUserFunction, p, t, xiNorm, s, epsRef, kapRef);
    UserFunctionValue v;
    v.value = p.physicsBendingStiffness * (s.kap - kapRef);
    v.dCurvature = p.physicsBendingStiffness;
    const double d = p.physicsBendingDamping + beta * p.physicsBendingStiffness;
    if (d != 0.0) {
      gDampingTerms.fetch_add(1, std::memory_order_relaxed);
      v.value += d * s.kap_t;
      v.dCurvature_t = d;
    }
    return v;
  }
  // A force law that is not finite (its value, or with a tangent/damping the derivatives used) ends
  // the evaluation: the assembler reports it with the set, element and time instead of letting
  // inf/NaN reach the solvers (issue 13 item 6). strain / curvature: whether s holds them here.
  // The test is inline and branch-light; the message is built only on failure (fail).
  static void check(const AncfCable2DParameters& p, const UserFunctionValue& v, bool axialLaw, double t,
                    const PointState& s, bool strain, bool curvature, bool derivatives) {
    const bool finiteDerivatives = !derivatives || (std::isfinite(v.dAxialStrain) && std::isfinite(v.dAxialStrain_t) &&
                                                    std::isfinite(v.dCurvature) && std::isfinite(v.dCurvature_t));
    if (std::isfinite(v.value) && finiteDerivatives) [[likely]]
      return;
    fail(p, v, axialLaw, t, s, strain, curvature, derivatives);
  }
  [[gnu::cold, gnu::noinline]] static void fail(const AncfCable2DParameters& p, const UserFunctionValue& v,
                                                bool axialLaw, double t, const PointState& s, bool strain,
                                                bool curvature, bool derivatives) {
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
  // Velocities enter only through a law that reads them (a damping term or a *_t argument of a user
  // function: hasDamping_, or beta > 0); otherwise eps_t, K_t and their gradients are not computed.
  const double* qd = hasDamping() ? in.qdot : nullptr;
  const bool wantK = needs.tangent;
  const bool wantD = needs.damping && hasDamping();
  const bool derivatives = wantK || wantD;
  double f[8] = {};
  // Tangent blocks are accumulated in place: Km (material) and Kg (geometric) are the same 8x8
  // array unless the split is asked for; D only with a damping law.
  double *Km = nullptr, *Kg = nullptr, *D = nullptr;
  if (wantK) {
    out.K.assign(64, 0.0);
    Km = Kg = out.K.data();
    if (needs.splitGeometric) {
      out.Kg.assign(64, 0.0);
      Kg = out.Kg.data();
    }
  }
  if (needs.damping) out.D.assign(64, 0.0);
  if (wantD) D = out.D.data();
  double dN[8], geps_t[8], hk_t[8];
  // The strain states of all points first: independent square roots and divisions overlap.
  std::array<PointState, kMaxIp> states;

  // Axial part: Q += w N d eps/dq
  const Geometry& geo = *geo_;
  for (int ip = 0; ip < geo.nAxial; ++ip) {
    const IntegrationPoint& P = geo.axial[ip];
    axialState(P.Sx, q, qd, states[ip]);
    if (axialNeedsCurvature_) bendingState(P.Sx, P.Sxx, q, qd, states[ip]);
  }
  for (int ip = 0; ip < geo.nAxial; ++ip) {
    const IntegrationPoint& P = geo.axial[ip];
    const PointState& s = states[ip];
    const UserFunctionValue N = Law::axial(*params_, beta_, in.t, P.xiNorm, s, axialRef(ip).strain, axialRef(ip).curvature);
    Law::check(*params_, N, true, in.t, s, true, axialNeedsCurvature_, derivatives);
    const double w = P.w;
    for (int a = 0; a < 8; ++a) f[a] += w * N.value * s.g[a];
    if (wantK) {
      // material part w d eps/dq (dN/dq)^T = S'_j S'_k w t (dN/deps t + dN/deps_t p)^T (+ coupling below)
      const double ae = w * N.dAxialStrain, at = w * N.dAxialStrain_t;
      const double Bm[4] = {s.t[0] * (ae * s.t[0] + at * s.p[0]), s.t[0] * (ae * s.t[1] + at * s.p[1]),
                            s.t[1] * (ae * s.t[0] + at * s.p[0]), s.t[1] * (ae * s.t[1] + at * s.p[1])};
      // geometric part N d2eps/dq2 = N S'_j S'_k (I - t t^T)/|r'|
      const double c = w * N.value / s.n;
      const double Bg[4] = {c * (1.0 - s.t[0] * s.t[0]), -c * s.t[0] * s.t[1], -c * s.t[0] * s.t[1],
                            c * (1.0 - s.t[1] * s.t[1])};
      if (Kg == Km) {
        const double B[4] = {Bm[0] + Bg[0], Bm[1] + Bg[1], Bm[2] + Bg[2], Bm[3] + Bg[3]};
        addAxialBlocks(P.Sx, B, Km);
      } else {
        addAxialBlocks(P.Sx, Bm, Km);
        addAxialBlocks(P.Sx, Bg, Kg);
      }
      if (axialNeedsCurvature_) {  // a user law of the curvature: w d eps/dq (dN/dK dK/dq + dN/dK_t dK_t/dq)^T
        for (int b = 0; b < 8; ++b) dN[b] = N.dCurvature * s.h[b];
        if (qd) {
          curvatureRateGradient(P.Sx, P.Sxx, qd, s, hk_t);
          for (int b = 0; b < 8; ++b) dN[b] += N.dCurvature_t * hk_t[b];
        }
        addOuter(w, s.g, dN, Km);
      }
    }
    if (wantD) {  // w d eps/dq (dN/dqdot)^T
      for (int b = 0; b < 8; ++b) dN[b] = N.dAxialStrain_t * s.g[b];
      if (axialNeedsCurvature_)
        for (int b = 0; b < 8; ++b) dN[b] += N.dCurvature_t * s.h[b];
      addOuter(w, s.g, dN, D);
    }
  }

  // Bending part: Q += w M dK/dq
  double* dM = dN;
  for (int ip = 0; ip < geo.nBending; ++ip) {
    const IntegrationPoint& P = geo.bending[ip];
    bendingState(P.Sx, P.Sxx, q, qd, states[ip]);
    if (bendingNeedsStrain_) axialState(P.Sx, q, qd, states[ip]);
  }
  for (int ip = 0; ip < geo.nBending; ++ip) {
    const IntegrationPoint& P = geo.bending[ip];
    const PointState& s = states[ip];
    const UserFunctionValue M = Law::bending(*params_, beta_, in.t, P.xiNorm, s, bendingRef(ip).strain, bendingRef(ip).curvature);
    Law::check(*params_, M, false, in.t, s, bendingNeedsStrain_, true, derivatives);
    const double w = P.w;
    for (int a = 0; a < 8; ++a) f[a] += w * M.value * s.h[a];
    if (wantK) {
      // material part w dK/dq (dM/dq)^T = w dM/dK dK/dq dK/dq^T + w dK/dq (the other terms of dM/dq)^T,
      // geometric part M d2K/dq2
      const double a = w * M.dCurvature, c = w * M.value;
      if (Kg == Km) {
        addBendingBlocks(P.Sx, P.Sxx, s, a, c, Km);
      } else {
        addBendingBlocks(P.Sx, P.Sxx, s, a, 0.0, Km);
        addBendingBlocks(P.Sx, P.Sxx, s, 0.0, c, Kg);
      }
      if (qd || bendingNeedsStrain_) {
        for (int b = 0; b < 8; ++b) dM[b] = 0.0;
        if (qd) {
          curvatureRateGradient(P.Sx, P.Sxx, qd, s, hk_t);
          for (int b = 0; b < 8; ++b) dM[b] += M.dCurvature_t * hk_t[b];
        }
        if (bendingNeedsStrain_) {
          for (int b = 0; b < 8; ++b) dM[b] += M.dAxialStrain * s.g[b];
          if (qd) {
            strainRateGradient(P.Sx, s, geps_t);
            for (int b = 0; b < 8; ++b) dM[b] += M.dAxialStrain_t * geps_t[b];
          }
        }
        addOuter(w, s.h, dM, Km);
      }
    }
    if (wantD) {  // w dK/dq (dM/dqdot)^T
      for (int b = 0; b < 8; ++b) dM[b] = M.dCurvature_t * s.h[b];
      if (bendingNeedsStrain_)
        for (int b = 0; b < 8; ++b) dM[b] += M.dAxialStrain_t * s.g[b];
      addOuter(w, s.h, dM, D);
    }
  }

  out.f.assign(f, f + 8);
}

void AncfCable2D::mass(const double* /*q*/, std::vector<double>& M) const { M.assign(geo_->M.begin(), geo_->M.end()); }

void AncfCable2D::bodyForce(const double* /*q*/, const Vec3& a, std::vector<double>& f) const {
  f.resize(8);
  for (int j = 0; j < 4; ++j) {
    f[2 * j] = geo_->massShapeIntegral[j] * a[0];
    f[2 * j + 1] = geo_->massShapeIntegral[j] * a[1];
  }
}

double AncfCable2D::axialForceAt(const double* q, const double* qdot, double x, double t) const {
  PointState s;
  const std::array<double, 4> Sx = shape_x(x, L_);
  axialState(Sx, q, qdot, s);
  if (axialNeedsCurvature_) bendingState(Sx, shape_xx(x, L_), q, qdot, s);
  return Law::axial(*params_, beta_, t, x / L_, s, axialStrainRef(x), curvatureRef(x)).value;
}

double AncfCable2D::bendingMomentAt(const double* q, const double* qdot, double x, double t) const {
  PointState s;
  const std::array<double, 4> Sx = shape_x(x, L_);
  bendingState(Sx, shape_xx(x, L_), q, qdot, s);
  if (bendingNeedsStrain_) axialState(Sx, q, qdot, s);
  return Law::bending(*params_, beta_, t, x / L_, s, axialStrainRef(x), curvatureRef(x)).value;
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

int AncfCable2D::sensorValueCount(const std::string& v) const {
  static const std::array<const char*, 8> vectors = {"Position", "Displacement", "Velocity", "VelocityLocal",
                                                     "Acceleration", "Director1", "AngularVelocity", "AngularAcceleration"};
  return std::any_of(vectors.begin(), vectors.end(), [&](const char* s) { return v == s; }) ? 3 : 1;
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
  if (params_->axialForceUserFunction || params_->bendingMomentUserFunction) return false;
  const int r = params_->useReducedOrderIntegration;
  const Rule ra = r == 0 ? gauss(5) : (r == 1 ? gauss(4) : lobatto3());
  const Rule rb = r == 0 ? gauss(3) : gauss(2);
  const double L = length();
  double e = 0.0;
  for (int i = 0; i < ra.n; ++i) {
    const double x = 0.5 * L * (ra.xi[i] + 1), d = axialStrain(q, x) - axialStrainRef(x);
    e += 0.25 * L * ra.w[i] * params_->physicsAxialStiffness * d * d;
  }
  for (int i = 0; i < rb.n; ++i) {
    const double x = 0.5 * L * (rb.xi[i] + 1), d = curvature(q, x) - curvatureRef(x);
    e += 0.25 * L * rb.w[i] * params_->physicsBendingStiffness * d * d;
  }
  *energy = e;
  return true;
}

}  // namespace sinew
