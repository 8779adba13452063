// Energy-momentum step force of the corotational beam (-dynamics_scheme energy_momentum;
// docs/dynamics.md, "Energy-momentum scheme"). In the spirit of Simo & Tarnow (1992) and Romero &
// Armero (2002): the strain energy U = 1/2 eps^T S eps is quadratic in the frame-indifferent
// deformations eps(q), so with an algorithmic strain matrix B that maps the step's increments exactly,
//   B (dx, theta_c) = eps(q1) - eps(q0),
// and the mean stress sigma = S (eps0 + eps1) / 2, the force f = B^T sigma does the work
// f . (dx, theta_c) = U(q1) - U(q0) exactly. The increments are the translations dx = x1 - x0 and, per
// node, the Cayley rotation vector theta_c of R1 R0^T (cay(theta_c) = (I - skew/2)^-1 (I + skew/2)), for
// which the directors n = R n0 change by exactly  n1 - n0 = theta_c x (n0 + n1) / 2.
// Every e_i is c (n . l) / |l| or a product of directors, so exact product rules give B:
//   d(a . b) = abar . db + bbar . da,   d|l| = 2 lbar . dl / (|l0| + |l1|),   d(1/|l|) = -d|l| / (|l0| |l1|),
//   d(quadratic arc term) = (Qh ebar) . de   (bars: step averages).
// Each row of B is built from averaged vectors only, so it vanishes on every rigid velocity field
// (t + w x xbar, w) about the mid positions xbar: f has zero resultant force and moment there, and the
// momenta of the scheme stay exact. Dissipation (energy decay xi, strain-rate damping beta) adds
// (xi / 2 + beta / h) S (eps1 - eps0) to sigma: its work is >= 0. Rigid modes carry their multipliers
// as stresses; their constraint rows are eps(q1) (the constraints hold at the step's end).
// The tangent d f / d q1 is exact: the same code run with dual numbers (src/math/dual.hpp).
#include <algorithm>
#include <array>

#include "elements/beam_corotational.hpp"
#include "elements/beam_kinematics.hpp"
#include "math/dual.hpp"

namespace sinew {
namespace {

constexpr int kDofs = 12;
constexpr int XP = 0, WP = 1, XQ = 2, WQ = 3;  // 3-dof blocks of [x_p, w_p, x_q, w_q]
using D12 = Dual<kDofs>;


// A quantity of the end state q1 with its gradient by q1's 12 dofs (ignored for T = double).
template <class T> T lift(double v, const double* grad);
template <> double lift<double>(double v, const double*) { return v; }
template <> D12 lift<D12>(double v, const double* grad) {
  D12 x(v);
  std::copy(grad, grad + kDofs, x.d.begin());
  return x;
}

template <class T> V3<T> fromDouble(const Vec3& a) { return {T(a[0]), T(a[1]), T(a[2])}; }
// the average (a0 + a1) / 2 of a start vector and an end vector
template <class T> V3<T> mean(const Vec3& a0, const V3<T>& a1) { return scale(0.5, add(fromDouble<T>(a0), a1)); }

// A unit director n = R n0 of the end state: d n / d w = -skew(n) on its node's spin block.
template <class T> V3<T> director(const Vec3& n, int wb) {
  V3<T> r;
  for (int i = 0; i < 3; ++i) {
    double g[kDofs] = {};
    const Mat3 S = skew(n);
    for (int k = 0; k < 3; ++k) g[3 * wb + k] = -S[3 * i + k];
    r[i] = lift<T>(n[i], g);
  }
  return r;
}

template <class T> void addRow(T* row, int block, const V3<T>& v, double sign) {
  for (int i = 0; i < 3; ++i) row[3 * block + i] = row[3 * block + i] + sign * v[i];
}

}  // namespace

template <class T>
void BeamCorotational::stepForceT(const Kinematics& k0, const Kinematics& k1, const double* q1, const StepForceInput& in,
                                  T* f, T (*B)[12]) const {
  const double l0 = l0_;
  // end-state quantities with their gradients by q1: chord l1 = x_q1 - x_p1, |l1|, directors, e_i, eps_i
  V3<T> l1;
  T L1;
  {
    double gL[kDofs] = {};
    for (int i = 0; i < 3; ++i) {
      double g[kDofs] = {};
      g[3 * XQ + i] = 1.0;
      g[3 * XP + i] = -1.0;
      l1[i] = lift<T>(q1[12 + i] - q1[i], g);
      gL[3 * XQ + i] = k1.lhat[i];
      gL[3 * XP + i] = -k1.lhat[i];
    }
    L1 = lift<T>(k1.L, gL);
  }
  const double* q0 = in.q0;
  const Vec3 l0v{q0[12] - q0[0], q0[13] - q0[1], q0[14] - q0[2]};
  const double L0 = k0.L;
  const V3<T> lbar = mean(l0v, l1);
  // d|l| = dL . dl, d(1/|l|) = dv . dl
  const T cL = 2.0 * inverse(L1 + L0);
  const V3<T> dL = scale(cL, lbar);
  const T v1 = inverse(L1), vbar = 0.5 * (v1 + 1.0 / L0);
  const V3<T> dv = scale(-(v1 * (1.0 / L0)), dL);
  T e[6][kDofs];  // rows of B for e_1..e_6
  for (auto& row : e) std::fill(row, row + kDofs, T(0.0));
  addRow(e[0], XQ, dL, 1.0);
  addRow(e[0], XP, dL, -1.0);
  // e_3..e_6 = c (n . l) / |l|: d e = c (vbar d(n . l) + gbar d(1/|l|)), d(n . l) = nbar . dl + (nbar x lbar) . theta_c
  const double c[4] = {-l0, l0, l0, -l0};
  const Vec3* n0[4] = {&k0.nzp, &k0.nzq, &k0.nyp, &k0.nyq};
  const Vec3* n1[4] = {&k1.nzp, &k1.nzq, &k1.nyp, &k1.nyq};
  const int wb[4] = {WP, WQ, WP, WQ};
  V3<T> nbar[4];
  for (int m = 0; m < 4; ++m) {
    const V3<T> n1T = director<T>(*n1[m], wb[m]);
    nbar[m] = mean(*n0[m], n1T);
    const T gbar = 0.5 * (dot(*n0[m], l0v) + dotT(n1T, l1));
    const V3<T> rowx = scale(T(c[m]), add(scale(vbar, nbar[m]), scale(gbar, dv)));
    addRow(e[2 + m], XQ, rowx, 1.0);
    addRow(e[2 + m], XP, rowx, -1.0);
    addRow(e[2 + m], wb[m], scale(c[m] * vbar, crossT(nbar[m], lbar)), 1.0);
  }
  // e_2 = l0 / 2 (nz^p . ny^q - ny^p . nz^q): d(a . b) = theta_c^p . (abar x bbar) + theta_c^q . (bbar x abar)
  {
    const V3<T>& a = nbar[0];  // nz^p
    const V3<T>& d = nbar[1];  // nz^q
    const V3<T>& cc = nbar[2];  // ny^p
    const V3<T>& b = nbar[3];  // ny^q
    const double c2 = 0.5 * l0;
    addRow(e[1], WP, scale(c2, sub(crossT(a, b), crossT(cc, d))), 1.0);
    addRow(e[1], WQ, scale(c2, sub(crossT(b, a), crossT(d, cc))), 1.0);
  }
  // eps_1 = e_1 + 1/2 e^T Qh e / (30 l0): its row adds (Qh ebar)_i / (30 l0) times the rows of e_3..e_6
  T ebar[6];
  for (int i = 2; i < 6; ++i) ebar[i] = 0.5 * (k0.e[i] + lift<T>(k1.e[i], k1.g[i]));
  const double inv30 = 1.0 / (30.0 * l0);
  for (int i = 0; i < 6; ++i) std::copy(e[i], e[i] + kDofs, B[i]);
  for (int pr = 0; pr < 2; ++pr) {
    const int i = 2 + 2 * pr;
    const double* Q = &Qh_[4 * pr];
    const T qa = inv30 * (Q[0] * ebar[i] + Q[1] * ebar[i + 1]);
    const T qb = inv30 * (Q[2] * ebar[i] + Q[3] * ebar[i + 1]);
    for (int a = 0; a < kDofs; ++a) B[0][a] = B[0][a] + qa * e[i][a] + qb * e[i + 1][a];
  }
  // stresses: S (eps0 + eps1) / 2 + (xi / 2 + beta / h) S (eps1 - eps0) on flexible modes, multipliers on rigid ones
  const double kd = 0.5 * in.decay + (in.h > 0.0 ? beta_ / in.h : 0.0);
  T eps1[6];
  for (int j = 0; j < 6; ++j) eps1[j] = lift<T>(k1.eps[j], k1.ge[j]);
  T sig[6];
  for (int i = 0; i < 6; ++i) {
    T s(0.0);
    for (int j = 0; j < 6; ++j) {
      const double Sij = S_[6 * i + j];
      if (Sij != 0.0) s = s + Sij * (0.5 * (eps1[j] + k0.eps[j]) + kd * (eps1[j] - k0.eps[j]));
    }
    sig[i] = s;
  }
  for (int r = 0; r < nRigid_; ++r) sig[rigidIndex_[r]] = T(in.lambda ? scale_ * in.lambda[r] : 0.0);
  for (int a = 0; a < kDofs; ++a) {
    T s(0.0);
    for (int i = 0; i < 6; ++i) s = s + sig[i] * B[i][a];
    f[a] = s;
  }
}

void BeamCorotational::stepForce(const StepForceInput& in, bool tangent, KernelOutput& out) const {
  Kinematics k0, k1;
  kinematics(in.q0, k0, in.disp0);
  kinematics(in.q1, k1, in.disp1);
  const int n = kDofs + nRigid_;
  out.f.assign(n, 0.0);
  for (int r = 0; r < nRigid_; ++r) out.f[kDofs + r] = scale_ * k1.eps[rigidIndex_[r]];  // g(q1) = 0 at the step's end
  if (!tangent) {
    double f[kDofs], B[6][kDofs];
    stepForceT<double>(k0, k1, in.q1, in, f, B);
    std::copy(f, f + kDofs, out.f.begin());
    return;
  }
  D12 f[kDofs], B[6][kDofs];
  stepForceT<D12>(k0, k1, in.q1, in, f, B);
  out.K.assign(static_cast<size_t>(n) * n, 0.0);
  for (int a = 0; a < kDofs; ++a) {
    out.f[a] = f[a].v;
    for (int b = 0; b < kDofs; ++b) out.K[static_cast<size_t>(a) * n + b] = f[a].d[b];
  }
  // multiplier columns: d f / d lambda_r = scale B_r; constraint rows: scale grad eps_r(q1)
  for (int r = 0; r < nRigid_; ++r) {
    const int i = rigidIndex_[r];
    for (int a = 0; a < kDofs; ++a) {
      out.K[static_cast<size_t>(a) * n + kDofs + r] = scale_ * B[i][a].v;
      out.K[static_cast<size_t>(kDofs + r) * n + a] = scale_ * k1.ge[i][a];
    }
  }
}

}  // namespace sinew
