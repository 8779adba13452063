#include "elements/membrane.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sinew {

namespace {

constexpr NodeKind kMemNodes[4] = {NodeKind::Point3, NodeKind::Point3, NodeKind::Point3, NodeKind::Point3};

/// Forward-mode dual number with M directional derivatives (exact tangents of the URS force).
template <int M> struct Dual {
  double v = 0.0;
  std::array<double, M> d{};
  Dual() = default;
  Dual(double a) : v(a) {}  // NOLINT: implicit, constants mix with duals
  friend Dual operator+(const Dual& a, const Dual& b) {
    Dual r(a.v + b.v);
    for (int i = 0; i < M; ++i) r.d[i] = a.d[i] + b.d[i];
    return r;
  }
  friend Dual operator-(const Dual& a, const Dual& b) {
    Dual r(a.v - b.v);
    for (int i = 0; i < M; ++i) r.d[i] = a.d[i] - b.d[i];
    return r;
  }
  friend Dual operator-(const Dual& a) {
    Dual r(-a.v);
    for (int i = 0; i < M; ++i) r.d[i] = -a.d[i];
    return r;
  }
  friend Dual operator*(const Dual& a, const Dual& b) {
    Dual r(a.v * b.v);
    for (int i = 0; i < M; ++i) r.d[i] = a.d[i] * b.v + a.v * b.d[i];
    return r;
  }
  friend Dual operator/(const Dual& a, const Dual& b) {
    const double ib = 1.0 / b.v;
    Dual r(a.v * ib);
    for (int i = 0; i < M; ++i) r.d[i] = (a.d[i] - r.v * b.d[i]) * ib;
    return r;
  }
  Dual& operator+=(const Dual& b) {
    v += b.v;
    for (int i = 0; i < M; ++i) d[i] += b.d[i];
    return *this;
  }
  friend Dual sqrt(const Dual& a) {
    Dual r(std::sqrt(a.v));
    const double g = 0.5 / r.v;
    for (int i = 0; i < M; ++i) r.d[i] = g * a.d[i];
    return r;
  }
  friend double primalValue(const Dual& a) { return a.v; }
};

void shape(int nn, double xi, double eta, double N[4], double dN[4][2]) {
  if (nn == 3) {
    N[0] = 1 - xi - eta, N[1] = xi, N[2] = eta, N[3] = 0;
    dN[0][0] = -1, dN[0][1] = -1, dN[1][0] = 1, dN[1][1] = 0, dN[2][0] = 0, dN[2][1] = 1;
    dN[3][0] = dN[3][1] = 0;
    return;
  }
  static constexpr double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  for (int a = 0; a < 4; ++a) {
    N[a] = 0.25 * (1 + sx[a] * xi) * (1 + sy[a] * eta);
    dN[a][0] = 0.25 * sx[a] * (1 + sy[a] * eta);
    dN[a][1] = 0.25 * sy[a] * (1 + sx[a] * xi);
  }
}

Vec3 nodeVec(const double* q, int a) { return {q[3 * a], q[3 * a + 1], q[3 * a + 2]}; }

}  // namespace

Membrane::Membrane(std::span<const Vec3> X, const MembraneProps& props, const PrestressFrame& frame)
    : props_(props), frame_(frame) {
  if (X.size() != 3 && X.size() != 4) throw std::invalid_argument("membrane: 3 or 4 nodes expected");
  nn_ = static_cast<int>(X.size());
  ngp_ = nn_ == 3 ? 1 : 4;
  const double c = props.emod / (1.0 - props.nu * props.nu);
  C_[0][0] = C_[1][1] = c;
  C_[0][1] = C_[1][0] = c * props.nu;
  C_[2][2] = c * 0.5 * (1.0 - props.nu);
  sAct_ = props.prestress;
  sBase_ = props.prestress;
  double Xs[12];
  for (int a = 0; a < nn_; ++a)
    for (int k = 0; k < 3; ++k) Xs[3 * a + k] = X[a][k];
  setReference(Xs);
}

std::span<const NodeKind> Membrane::nodeKinds() const { return {kMemNodes, static_cast<size_t>(nn_)}; }

void Membrane::setPrestress(const std::array<double, 3>& s0) {
  props_.prestress = s0;
  sAct_ = s0;
  sBase_ = s0;
}

void Membrane::saveCheckpoint(double* out) const {
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 3; ++k) out[3 * a + k] = a < nn_ ? X_[a][k] : 0.0;
  for (int k = 0; k < 3; ++k) {
    out[12 + k] = props_.prestress[k];
    out[15 + k] = sBase_[k];
    out[18 + k] = sAct_[k];
  }
}

void Membrane::loadCheckpoint(const double* in) {
  setReference(in);
  for (int k = 0; k < 3; ++k) {
    props_.prestress[k] = in[12 + k];
    sBase_[k] = in[15 + k];
    sAct_[k] = in[18 + k];
  }
}

void Membrane::setFormFinding(bool on, double lambda) {
  ff_ = on;
  lambda_ = lambda;
}

void Membrane::setStressAdaption(double lambdaMax, double mueRelax) {
  lambdaMax_ = lambdaMax;
  mueRelax_ = mueRelax;
}

void Membrane::setReference(const double* X) {
  Vec3 pc{};
  for (int a = 0; a < nn_; ++a) {
    X_[a] = nodeVec(X, a);
    pc += (1.0 / nn_) * X_[a];
  }
  const Vec3 s = frame_.seed<double>(pc);
  const double g = 1.0 / std::sqrt(3.0);
  const double xiQ[4][2] = {{-g, -g}, {g, -g}, {g, g}, {-g, g}};
  for (int p = 0; p <= ngp_; ++p) {
    double xi, eta, w;
    if (nn_ == 3) {
      xi = eta = 1.0 / 3.0;
      w = 0.5;
    } else if (p < ngp_) {
      xi = xiQ[p][0], eta = xiQ[p][1], w = 1.0;
    } else {
      xi = eta = 0.0, w = 4.0;
    }
    Point& P = pts_[p];
    double dxi[4][2];
    shape(nn_, xi, eta, P.N, dxi);
    Vec3 G1{}, G2{};
    for (int a = 0; a < nn_; ++a) {
      G1 += dxi[a][0] * X_[a];
      G2 += dxi[a][1] * X_[a];
    }
    Vec3 n = cross(G1, G2);
    const double j = norm(n);
    if (!(j > 0.0)) throw std::invalid_argument("membrane: degenerate reference element");
    n = (1.0 / j) * n;
    Vec3 E1, E2;
    PrestressFrame::axes<double>(n, s, E1, E2);
    // Jm[alpha][i] = G_alpha . E_i;  dN/dX = Jm^-1 dN/dxi
    const double J00 = dot(G1, E1), J01 = dot(G1, E2), J10 = dot(G2, E1), J11 = dot(G2, E2);
    P.A[0][0] = J00, P.A[0][1] = J10, P.A[1][0] = J01, P.A[1][1] = J11;
    const double det = J00 * J11 - J01 * J10;
    const double I00 = J11 / det, I01 = -J01 / det, I10 = -J10 / det, I11 = J00 / det;
    for (int a = 0; a < 4; ++a) {
      P.dN[a][0] = I00 * dxi[a][0] + I01 * dxi[a][1];
      P.dN[a][1] = I10 * dxi[a][0] + I11 * dxi[a][1];
    }
    P.wJ0 = w * j;
  }
}

void Membrane::updateReference(const double* q) {
  if (lambdaMax_ > 1.0) {
    // principal stretches of the step deformation at the centre (old reference -> q)
    const Point& P = pts_[ngp_];
    Vec3 f1{}, f2{};
    for (int a = 0; a < nn_; ++a) {
      f1 += P.dN[a][0] * nodeVec(q, a);
      f2 += P.dN[a][1] * nodeVec(q, a);
    }
    const double c11 = dot(f1, f1), c22 = dot(f2, f2), c12 = dot(f1, f2);
    const double m = 0.5 * (c11 + c22), r = std::sqrt(0.25 * (c11 - c22) * (c11 - c22) + c12 * c12);
    const double th = 0.5 * std::atan2(2.0 * c12, c11 - c22);
    const double Nk[2][2] = {{std::cos(th), std::sin(th)}, {-std::sin(th), std::cos(th)}};
    const double lam[2] = {std::sqrt(m + r), std::sqrt(std::max(m - r, 0.0))};
    double W[2][2] = {};
    for (int k = 0; k < 2; ++k) {
      const double s = lam[k] / std::clamp(lam[k], 1.0 / lambdaMax_, lambdaMax_);
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) W[i][j] += std::sqrt(s) * Nk[k][i] * Nk[k][j];
    }
    const double S[2][2] = {{sBase_[0], sBase_[2]}, {sBase_[2], sBase_[1]}};
    double WS[2][2] = {}, Sh[2][2] = {};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k) WS[i][j] += W[i][k] * S[k][j];
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k) Sh[i][j] += WS[i][k] * W[k][j];
    const double mu = mueRelax_;
    sBase_ = {(1 - mu) * Sh[0][0] + mu * sBase_[0], (1 - mu) * Sh[1][1] + mu * sBase_[1],
              (1 - mu) * Sh[0][1] + mu * sBase_[2]};
  }
  setReference(q);
  applyDistortionControl();
}

void Membrane::setDistortionControl(double muMax) {
  muMax_ = muMax;
  applyDistortionControl();
}

void Membrane::applyDistortionControl() {
  sAct_ = sBase_;
  if (muMax_ > 1.0) {
    double n[2][2], mu[2];
    distortion(n, mu);
    double W[2][2] = {};
    for (int k = 0; k < 2; ++k) {
      const double w = mu[k] / std::clamp(mu[k], 1.0 / muMax_, muMax_);
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) W[i][j] += w * n[k][i] * n[k][j];
    }
    const double S[2][2] = {{sBase_[0], sBase_[2]}, {sBase_[2], sBase_[1]}};
    double Sh[2][2] = {};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k)
          for (int l = 0; l < 2; ++l) Sh[i][j] += W[i][k] * S[k][l] * W[l][j];
    sAct_ = {Sh[0][0], Sh[1][1], Sh[0][1]};
  }
}

void Membrane::distortion(double n[2][2], double mu[2]) const {
  // B = A T^-1, T = dY/dxi of the ideal element (triangle: nodes (0,0), (1,0), (1/2, sqrt(3)/2);
  // quad: the square of the isoparametric coordinates), evaluated at the centre point
  const Point& P = pts_[ngp_];
  double B[2][2];
  if (nn_ == 3) {
    const double r3 = std::sqrt(3.0);  // T^-1 = [1, -1/sqrt3; 0, 2/sqrt3]
    for (int i = 0; i < 2; ++i) B[i][0] = P.A[i][0], B[i][1] = -P.A[i][0] / r3 + 2.0 * P.A[i][1] / r3;
  } else {
    for (int i = 0; i < 2; ++i) B[i][0] = P.A[i][0], B[i][1] = P.A[i][1];
  }
  const double detB = std::abs(B[0][0] * B[1][1] - B[0][1] * B[1][0]);
  const double m11 = (B[0][0] * B[0][0] + B[0][1] * B[0][1]) / detB;
  const double m22 = (B[1][0] * B[1][0] + B[1][1] * B[1][1]) / detB;
  const double m12 = (B[0][0] * B[1][0] + B[0][1] * B[1][1]) / detB;
  const double m = 0.5 * (m11 + m22), r = std::sqrt(0.25 * (m11 - m22) * (m11 - m22) + m12 * m12);
  const double th = 0.5 * std::atan2(2.0 * m12, m11 - m22);
  n[0][0] = std::cos(th), n[0][1] = std::sin(th), n[1][0] = -std::sin(th), n[1][1] = std::cos(th);
  mu[0] = std::sqrt(m + r);
  mu[1] = 1.0 / mu[0];  // det M = 1
}

double Membrane::shapeDistortion() const {
  double n[2][2], mu[2];
  distortion(n, mu);
  return mu[0];
}

// ---------------------------------------------------------------------------------------------
// URS internal force, generic in the scalar type.
template <class T> void Membrane::ffForce(const T* x, T* f) const {
  using V = pf::V3<T>;
  const int n = 3 * nn_;
  for (int i = 0; i < n; ++i) f[i] = T(0.0);
  const double lam = lambda_;
  const bool needCur = lam > 0.0 || xurs_;
  const double s11 = sAct_[0], s22 = sAct_[1], s12 = sAct_[2];
  V seed{};
  if (needCur) {
    V c{T(0.0), T(0.0), T(0.0)};
    for (int a = 0; a < nn_; ++a)
      for (int k = 0; k < 3; ++k) c[k] += T(1.0 / nn_) * x[3 * a + k];
    seed = frame_.seed<T>(c);
  }
  for (int p = 0; p < ngp_; ++p) {
    const Point& P = pts_[p];
    V f1{T(0.0), T(0.0), T(0.0)}, f2{T(0.0), T(0.0), T(0.0)};
    for (int a = 0; a < nn_; ++a)
      for (int k = 0; k < 3; ++k) {
        f1[k] += P.dN[a][0] * x[3 * a + k];
        f2[k] += P.dN[a][1] * x[3 * a + k];
      }
    V P1{T(0.0), T(0.0), T(0.0)}, P2{T(0.0), T(0.0), T(0.0)};
    T S[3] = {T(s11), T(s22), T(s12)};  // reference-term stress (S11 S22 S12)
    if (needCur) {
      V nrm = pf::cross(f1, f2);
      using std::sqrt;
      const T J = sqrt(pf::dot(nrm, nrm));
      nrm = pf::scale(T(1.0 / J), nrm);
      V e1, e2;
      PrestressFrame::axes<T>(nrm, seed, e1, e2);
      // sigma v = s11 e1 (e1.v) + s12 [e1 (e2.v) + e2 (e1.v)] + s22 e2 (e2.v)
      auto sigma = [&](const V& v) {
        const T a1 = pf::dot(e1, v), a2 = pf::dot(e2, v);
        const T c1 = s11 * a1 + s12 * a2, c2 = s12 * a1 + s22 * a2;
        return V{c1 * e1[0] + c2 * e2[0], c1 * e1[1] + c2 * e2[1], c1 * e1[2] + c2 * e2[2]};
      };
      if (lam > 0.0) {
        // current term: J sigma f^i, f^i dual basis of (f_1, f_2)
        const T a11 = pf::dot(f1, f1), a12 = pf::dot(f1, f2), a22 = pf::dot(f2, f2);
        const T idet = T(1.0) / (J * J);
        const V g1{(a22 * f1[0] - a12 * f2[0]) * idet, (a22 * f1[1] - a12 * f2[1]) * idet,
                   (a22 * f1[2] - a12 * f2[2]) * idet};
        const V g2{(a11 * f2[0] - a12 * f1[0]) * idet, (a11 * f2[1] - a12 * f1[1]) * idet,
                   (a11 * f2[2] - a12 * f1[2]) * idet};
        const T lJ = lam * J;
        P1 = pf::axpy(lJ, sigma(g1), P1);
        P2 = pf::axpy(lJ, sigma(g2), P2);
      }
      if (xurs_ && lam < 1.0) {
        // S~ = R^T sigma_c R, R = F U^-1, U = (C + sqrt(det C) I)/sqrt(tr C + 2 sqrt(det C))
        const T c11 = pf::dot(f1, f1), c12 = pf::dot(f1, f2), c22 = pf::dot(f2, f2);
        const T sd = J;  // sqrt(det C) = |f1 x f2|
        const T tU = sqrt(c11 + c22 + T(2.0) * sd);
        const T U11 = (c11 + sd) / tU, U12 = c12 / tU, U22 = (c22 + sd) / tU;
        const T iU11 = U22 / sd, iU12 = -U12 / sd, iU22 = U11 / sd;  // det U = sqrt(det C)
        const V r1 = pf::axpy(iU11, f1, pf::scale(iU12, f2));
        const V r2 = pf::axpy(iU12, f1, pf::scale(iU22, f2));
        const V sr1 = sigma(r1), sr2 = sigma(r2);
        S[0] = pf::dot(r1, sr1);
        S[1] = pf::dot(r2, sr2);
        S[2] = pf::dot(r1, sr2);
      }
    }
    if (lam < 1.0) {
      const T w = T(1.0 - lam);
      // reference term: P_i = S_ij f_j
      P1 = pf::axpy(w * S[0], f1, pf::axpy(w * S[2], f2, P1));
      P2 = pf::axpy(w * S[2], f1, pf::axpy(w * S[1], f2, P2));
    }
    const double wt = props_.thickness * P.wJ0;
    for (int a = 0; a < nn_; ++a) {
      const double d1 = wt * P.dN[a][0], d2 = wt * P.dN[a][1];
      for (int k = 0; k < 3; ++k) f[3 * a + k] += d1 * P1[k] + d2 * P2[k];
    }
  }
}

template <int M> void Membrane::ffTangent(const double* q, double* f, double* K) const {
  std::array<Dual<M>, M> x, fd;
  for (int k = 0; k < M; ++k) {
    x[k] = Dual<M>(q[k]);
    x[k].d[k] = 1.0;
  }
  ffForce<Dual<M>>(x.data(), fd.data());
  for (int i = 0; i < M; ++i) {
    f[i] = fd[i].v;
    for (int j = 0; j < M; ++j) K[M * i + j] = fd[i].d[j];
  }
}

void Membrane::evaluate(const KernelInput& in, const KernelNeeds& needs, KernelOutput& out) const {
  const double* q = in.q;
  const int n = 3 * nn_;
  out.f.assign(n, 0.0);
  if (needs.tangent) {
    out.K.assign(n * n, 0.0);
    if (needs.splitGeometric) out.Kg.assign(n * n, 0.0);
  }
  const bool damped = in.qdot && beta_ > 0.0 && !ff_;
  if (needs.damping) out.D.assign(static_cast<size_t>(n) * n, 0.0);  // zero without strain-rate damping
  if (ff_) {
    if (!needs.tangent) {
      ffForce<double>(q, out.f.data());
      return;
    }
    double* Kt = needs.splitGeometric ? out.Kg.data() : out.K.data();
    if (lambda_ == 0.0 && !xurs_) {
      // reference problem only: f linear in x, K = t int (S_ij N_a,i N_b,j) I dA (constant)
      ffForce<double>(q, out.f.data());
      const double S[3] = {sAct_[0], sAct_[1], sAct_[2]};
      for (int p = 0; p < ngp_; ++p) {
        const Point& P = pts_[p];
        const double wt = props_.thickness * P.wJ0;
        for (int a = 0; a < nn_; ++a)
          for (int b = 0; b < nn_; ++b) {
            const double G = wt * (S[0] * P.dN[a][0] * P.dN[b][0] + S[1] * P.dN[a][1] * P.dN[b][1] +
                                   S[2] * (P.dN[a][0] * P.dN[b][1] + P.dN[a][1] * P.dN[b][0]));
            for (int k = 0; k < 3; ++k) Kt[n * (3 * a + k) + 3 * b + k] += G;
          }
      }
      return;
    }
    if (nn_ == 3)
      ffTangent<9>(q, out.f.data(), Kt);
    else
      ffTangent<12>(q, out.f.data(), Kt);
    return;
  }
  // Elastic St. Venant-Kirchhoff: S = S0 + C E, P_i = S_ij f_j
  double* Kg = needs.splitGeometric ? out.Kg.data() : out.K.data();
  const double t = props_.thickness;
  for (int p = 0; p < ngp_; ++p) {
    const Point& P = pts_[p];
    Vec3 f1{}, f2{};
    for (int a = 0; a < nn_; ++a) {
      f1 += P.dN[a][0] * nodeVec(q, a);
      f2 += P.dN[a][1] * nodeVec(q, a);
    }
    const double Ev[3] = {0.5 * (dot(f1, f1) - 1.0), 0.5 * (dot(f2, f2) - 1.0), dot(f1, f2)};
    double S[3];
    for (int i = 0; i < 3; ++i) S[i] = sAct_[i] + C_[i][0] * Ev[0] + C_[i][1] * Ev[1] + C_[i][2] * Ev[2];
    // strain-rate damping: S_d = beta C Ed, Ed = [f1.v1, f2.v2, f1.v2 + f2.v1] (v_i = dv/dX^i)
    Vec3 v1{}, v2{};
    if (damped) {
      for (int a = 0; a < nn_; ++a) {
        v1 += P.dN[a][0] * nodeVec(in.qdot, a);
        v2 += P.dN[a][1] * nodeVec(in.qdot, a);
      }
      const double Ed[3] = {dot(f1, v1), dot(f2, v2), dot(f1, v2) + dot(f2, v1)};
      for (int i = 0; i < 3; ++i) S[i] += beta_ * (C_[i][0] * Ed[0] + C_[i][1] * Ed[1] + C_[i][2] * Ed[2]);
    }
    const Vec3 P1 = S[0] * f1 + S[2] * f2, P2 = S[2] * f1 + S[1] * f2;
    const double wt = t * P.wJ0;
    for (int a = 0; a < nn_; ++a)
      for (int k = 0; k < 3; ++k) out.f[3 * a + k] += wt * (P.dN[a][0] * P1[k] + P.dN[a][1] * P2[k]);
    if (!needs.tangent && !(damped && needs.damping)) continue;
    // B (Voigt strain variation per dof) and C B
    double B[3][12], CB[3][12];
    for (int a = 0; a < nn_; ++a)
      for (int k = 0; k < 3; ++k) {
        const int c = 3 * a + k;
        B[0][c] = P.dN[a][0] * f1[k];
        B[1][c] = P.dN[a][1] * f2[k];
        B[2][c] = P.dN[a][0] * f2[k] + P.dN[a][1] * f1[k];
      }
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < n; ++c) CB[i][c] = C_[i][0] * B[0][c] + C_[i][1] * B[1][c] + C_[i][2] * B[2][c];
    if (damped && needs.damping)  // D = d f_d / d v = beta t int B^T C B dA
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c)
          out.D[n * r + c] += beta_ * wt * (B[0][r] * CB[0][c] + B[1][r] * CB[1][c] + B[2][r] * CB[2][c]);
    if (!needs.tangent) continue;
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        out.K[n * r + c] += wt * (B[0][r] * CB[0][c] + B[1][r] * CB[1][c] + B[2][r] * CB[2][c]);
    if (damped) {  // S_d through Ed at fixed v: beta t int B^T C B(v) dA (the S_d stress part is in S below)
      double CBv[3][12];
      for (int a = 0; a < nn_; ++a)
        for (int k = 0; k < 3; ++k) {
          const int c = 3 * a + k;
          const double Bv[3] = {P.dN[a][0] * v1[k], P.dN[a][1] * v2[k], P.dN[a][0] * v2[k] + P.dN[a][1] * v1[k]};
          for (int i = 0; i < 3; ++i) CBv[i][c] = C_[i][0] * Bv[0] + C_[i][1] * Bv[1] + C_[i][2] * Bv[2];
        }
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c)
          out.K[n * r + c] += beta_ * wt * (B[0][r] * CBv[0][c] + B[1][r] * CBv[1][c] + B[2][r] * CBv[2][c]);
    }
    for (int a = 0; a < nn_; ++a)
      for (int b = 0; b < nn_; ++b) {
        const double G = wt * (S[0] * P.dN[a][0] * P.dN[b][0] + S[1] * P.dN[a][1] * P.dN[b][1] +
                               S[2] * (P.dN[a][0] * P.dN[b][1] + P.dN[a][1] * P.dN[b][0]));
        for (int k = 0; k < 3; ++k) Kg[n * (3 * a + k) + 3 * b + k] += G;
      }
  }
}

std::array<double, 3> Membrane::secondPK(const double* q) const {
  const Point& P = pts_[ngp_];
  Vec3 f1{}, f2{};
  for (int a = 0; a < nn_; ++a) {
    f1 += P.dN[a][0] * nodeVec(q, a);
    f2 += P.dN[a][1] * nodeVec(q, a);
  }
  const double Ev[3] = {0.5 * (dot(f1, f1) - 1.0), 0.5 * (dot(f2, f2) - 1.0), dot(f1, f2)};
  std::array<double, 3> S;
  for (int i = 0; i < 3; ++i) S[i] = sAct_[i] + C_[i][0] * Ev[0] + C_[i][1] * Ev[1] + C_[i][2] * Ev[2];
  return S;
}

void Membrane::cauchyAt(const double* q, int p, double sig[3]) const {
  const Point& P = pts_[p];
  Vec3 f1{}, f2{}, c{};
  for (int a = 0; a < nn_; ++a) {
    f1 += P.dN[a][0] * nodeVec(q, a);
    f2 += P.dN[a][1] * nodeVec(q, a);
    c += (1.0 / nn_) * nodeVec(q, a);
  }
  Vec3 nrm = cross(f1, f2);
  const double J = norm(nrm);
  nrm = (1.0 / J) * nrm;
  Vec3 e1, e2;
  frame_.axesAt(nrm, c, e1, e2);
  double S[3];
  double wRef = 1.0, wCur = 0.0;
  if (ff_) {
    wCur = lambda_, wRef = 1.0 - lambda_;
    S[0] = sAct_[0], S[1] = sAct_[1], S[2] = sAct_[2];
    if (xurs_) {
      // S~ = R^T sigma_c R (see ffForce)
      const double c11 = dot(f1, f1), c12 = dot(f1, f2), c22 = dot(f2, f2), sd = J;
      const double tU = std::sqrt(c11 + c22 + 2 * sd);
      const double U11 = (c11 + sd) / tU, U12 = c12 / tU, U22 = (c22 + sd) / tU;
      const Vec3 r[2] = {(U22 / sd) * f1 + (-U12 / sd) * f2, (-U12 / sd) * f1 + (U11 / sd) * f2};
      double rho[2][2];  // rho[k][i] = e_k . r_i
      for (int i = 0; i < 2; ++i) rho[0][i] = dot(e1, r[i]), rho[1][i] = dot(e2, r[i]);
      const double s[2][2] = {{sAct_[0], sAct_[2]}, {sAct_[2], sAct_[1]}};
      double St[2][2] = {};
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
          for (int k = 0; k < 2; ++k)
            for (int l = 0; l < 2; ++l) St[i][j] += rho[k][i] * s[k][l] * rho[l][j];
      S[0] = St[0][0], S[1] = St[1][1], S[2] = St[0][1];
    }
  } else {
    const double Ev[3] = {0.5 * (dot(f1, f1) - 1.0), 0.5 * (dot(f2, f2) - 1.0), dot(f1, f2)};
    for (int i = 0; i < 3; ++i) S[i] = sAct_[i] + C_[i][0] * Ev[0] + C_[i][1] * Ev[1] + C_[i][2] * Ev[2];
  }
  // push forward: sigma_kl = (1/J) S_ij (e_k . f_i)(e_l . f_j)
  const double m[2][2] = {{dot(e1, f1), dot(e1, f2)}, {dot(e2, f1), dot(e2, f2)}};
  const double Sm[2][2] = {{S[0], S[2]}, {S[2], S[1]}};
  double sg[2][2] = {};
  for (int k = 0; k < 2; ++k)
    for (int l = 0; l < 2; ++l)
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) sg[k][l] += m[k][i] * Sm[i][j] * m[l][j];
  sig[0] = wRef * sg[0][0] / J + wCur * sAct_[0];
  sig[1] = wRef * sg[1][1] / J + wCur * sAct_[1];
  sig[2] = wRef * sg[0][1] / J + wCur * sAct_[2];
}

double Membrane::vonMisesMax(const double* q, const double* /*lambda*/) const {
  double vm = 0.0;
  for (int p = 0; p < ngp_; ++p) {
    double s[3];
    cauchyAt(q, p, s);
    vm = std::max(vm, std::sqrt(s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3.0 * s[2] * s[2]));
  }
  return vm;
}

void Membrane::elementForce(const double* q, std::vector<double>& out) const {
  double s[3];
  cauchyAt(q, ngp_, s);
  const double t = props_.thickness;
  out.assign(3, 0.0);
  out[0] = t * s[0], out[1] = t * s[1], out[2] = t * s[2];
}

void Membrane::mass(const double* /*q*/, std::vector<double>& M) const {
  const int n = 3 * nn_;
  M.assign(n * n, 0.0);
  const double rt = props_.dens * props_.thickness;
  for (int a = 0; a < nn_; ++a)
    for (int b = 0; b < nn_; ++b) {
      double m = 0.0;
      if (nn_ == 3)
        m = rt * pts_[0].wJ0 / 12.0 * (a == b ? 2.0 : 1.0);
      else
        for (int p = 0; p < ngp_; ++p) m += rt * pts_[p].N[a] * pts_[p].N[b] * pts_[p].wJ0;
      for (int k = 0; k < 3; ++k) M[n * (3 * a + k) + 3 * b + k] = m;
    }
}

void Membrane::bodyForce(const double* /*q*/, const Vec3& acc, std::vector<double>& f) const {
  const int n = 3 * nn_;
  f.assign(n, 0.0);
  const double rt = props_.dens * props_.thickness;
  for (int a = 0; a < nn_; ++a) {
    double w = 0.0;
    for (int p = 0; p < ngp_; ++p) w += rt * pts_[p].N[a] * pts_[p].wJ0;
    for (int k = 0; k < 3; ++k) f[3 * a + k] = w * acc[k];
  }
}

double Membrane::meshQuality(const double* q) const {
  double qmin = 1e300;
  for (int a = 0; a < nn_; ++a) {
    const Vec3 x0 = nodeVec(q, a), xp = nodeVec(q, (a + 1) % nn_), xm = nodeVec(q, (a + nn_ - 1) % nn_);
    const Vec3 u = xp - x0, v = xm - x0;
    const double s = norm(cross(u, v)) / (norm(u) * norm(v));
    qmin = std::min(qmin, nn_ == 3 ? s / (0.5 * std::sqrt(3.0)) : s);
  }
  return qmin;
}

template void Membrane::ffForce<double>(const double*, double*) const;

namespace {
/// Area vector of a triangle, or half the cross product of a quad's diagonals, at the states q.
Vec3 areaVector(int nn, const double* q) {
  auto v = [&](int a, int b) { return Vec3{q[3 * b] - q[3 * a], q[3 * b + 1] - q[3 * a + 1], q[3 * b + 2] - q[3 * a + 2]}; };
  return nn == 3 ? 0.5 * cross(v(0, 1), v(0, 2)) : 0.5 * cross(v(0, 2), v(1, 3));
}
}  // namespace

double Membrane::size(const double* q) const { return norm(areaVector(nn_, q)); }

Vec3 Membrane::shapeAxis(const double* q) const {
  Vec3 a = areaVector(nn_, q);
  const double l = norm(a);
  if (l > 0.0) a = (1.0 / std::sqrt(l)) * a;  // a a^T = A n n^T
  return a;
}

}  // namespace sinew
