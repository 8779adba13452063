// Corotational SPACAR beam kernel; see beam_corotational.hpp for the deformation modes.
// Tangent: exact derivative of f along translations and spatial spins R -> exp(skew(dw)) R
// (not symmetric away from equilibrium). Each e_i is c * (a . b) with a, b in
// {lhat, ny^p, nz^p, ny^q, nz^q}; for n = R n0: J_n = -skew(n) (spin columns), H_n[c] = skew(c) skew(n);
// for lhat: J = +-P/L (P = I - lhat lhat^T), H[c] = -(1/L^2)((lhat.c) P + lhat (Pc)^T + (Pc) lhat^T).
// d(a.b) = J_a^T b + J_b^T a;  Hess(a.b) = J_a^T J_b + J_b^T J_a + H_a[b] + H_b[a].
#include "elements/beam_corotational.hpp"
#include "elements/beam_kinematics.hpp"

#include "sinew/rotation.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {
namespace {

constexpr NodeKind kNodeKinds[2] = {NodeKind::Frame6, NodeKind::Frame6};
constexpr int kDofs = 12;
// Block indices (3 dofs each) in [x_p, w_p, x_q, w_q].
constexpr int XP = 0, WP = 1, XQ = 2, WQ = 3;

inline Vec3 load3(const double* p) { return {p[0], p[1], p[2]}; }
inline Mat3 load9(const double* p) { return {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8]}; }
// skew(a) skew(b) = b a^T - (a.b) I
inline Mat3 skewskew(const Vec3& a, const Vec3& b) {
  Mat3 m = outer(b, a);
  const double ab = dot(a, b);
  m[0] -= ab; m[4] -= ab; m[8] -= ab;
  return m;
}
inline void addBlock(double* K, int ld, int bi, int bj, const Mat3& M, double s) {
  for (int i = 0; i < 3; ++i) {
    double* row = K + (3 * bi + i) * ld + 3 * bj;
    for (int j = 0; j < 3; ++j) row[j] += s * M[3 * i + j];
  }
}
inline void setVec(double* g, int b, const Vec3& v) { g[3 * b] = v[0]; g[3 * b + 1] = v[1]; g[3 * b + 2] = v[2]; }
// K(0:12, 0:12) += s * a b^T
inline void addOuter(double* K, int ld, const double* a, const double* b, double s) {
  for (int i = 0; i < kDofs; ++i) {
    const double ai = s * a[i];
    if (ai == 0.0) continue;
    double* row = K + i * ld;
    for (int j = 0; j < kDofs; ++j) row[j] += ai * b[j];
  }
}

}  // namespace

std::span<const NodeKind> BeamCorotational::nodeKinds() const { return {kNodeKinds, 2}; }

BeamCorotational::BeamCorotational(const Vec3& Xp, const Vec3& Xq, const std::optional<Vec3>& orien,
                                   const BeamSection& s, std::array<BeamMode, 6> modes, bool hasInertia,
                                   double constraintScale)
    : sec_(s), modes_(modes), hasInertia_(hasInertia), scale_(constraintScale) {
  const Vec3 d = Xq - Xp;
  l0_ = norm(d);
  if (!(l0_ > 0.0)) throw SceneError("elements", "beam element with coincident nodes (zero length)");
  ex0_ = (1.0 / l0_) * d;
  Vec3 o;
  if (orien) {
    o = *orien;
    const double on = norm(o);
    if (!(on > 0.0)) throw SceneError("eprops.orien", "orien must be a nonzero vector");
    o = (1.0 / on) * o;
    if (norm(cross(o, ex0_)) < 1e-6)
      throw SceneError("eprops.orien", "orien is parallel to the beam axis; choose a direction across the beam");
  } else {
    o = std::abs(ex0_[2]) > 1.0 - 1e-6 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  }
  const Vec3 yp = o - dot(o, ex0_) * ex0_;  // orien projected perpendicular to the chord
  ey0_ = (1.0 / norm(yp)) * yp;
  ez0_ = cross(ex0_, ey0_);

  // Flexible-mode stiffness (energy U = 1/2 eps^T S eps, eps_i of length dimension).
  const double l = l0_, l3 = l * l * l;
  std::array<double, 36> Sf{};
  Sf[0] = s.EA / l;       // axial
  Sf[7] = s.GIt / l3;     // torsion: U = 1/2 GIt/l (e2/l)^2
  // Timoshenko pair in end slopes s_a, s_b: EI/(l(1+Phi)) [[4+Phi, 2-Phi],[2-Phi, 4+Phi]];
  // with s_a = e3/l, s_b = -e4/l (resp. s_a = -e5/l, s_b = e6/l) the off-diagonal changes sign.
  auto pair = [&](int i, double EI, double kGA) {
    const double Phi = kGA > 0.0 ? 12.0 * EI / (kGA * l * l) : 0.0;
    const double k = EI / (l3 * (1.0 + Phi));
    Sf[6 * i + i] = Sf[6 * (i + 1) + i + 1] = k * (4.0 + Phi);
    Sf[6 * i + i + 1] = Sf[6 * (i + 1) + i] = -k * (2.0 - Phi);
  };
  pair(2, s.EIy, s.kGAz);  // bending about y, shear along z
  pair(4, s.EIz, s.kGAy);  // bending about z, shear along y
  // Released modes: condense out of their pair (sigma_r = 0); rigid and released rows/columns vanish.
  S_ = Sf;
  const double Qm[4] = {4.0, 1.0, 1.0, 4.0};  // Hessian of 2 a^2 + a b + 2 b^2
  for (int pr = 0; pr < 2; ++pr) {
    const int i = 2 + 2 * pr, j = i + 1;
    double C[4] = {1, 0, 0, 1};  // effective slope map e_hat = C e used in the arc-minus-chord term
    for (int side = 0; side < 2; ++side) {
      const int r = side == 0 ? i : j, f = side == 0 ? j : i;
      if (modes[r] != BeamMode::Released) continue;
      const int ri = r - i, fi = f - i;
      C[2 * ri + ri] = 0.0;
      if (modes[f] == BeamMode::Flexible && Sf[6 * r + r] > 0.0) {
        S_[6 * f + f] = Sf[6 * f + f] - Sf[6 * f + r] * Sf[6 * r + f] / Sf[6 * r + r];
        C[2 * ri + fi] = -Sf[6 * r + f] / Sf[6 * r + r];  // elastic value of the released end slope
      }
    }
    // Qh = C^T Qm C
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        double v = 0.0;
        for (int c = 0; c < 2; ++c)
          for (int e = 0; e < 2; ++e) v += C[2 * c + a] * Qm[2 * c + e] * C[2 * e + b];
        Qh_[4 * pr + 2 * a + b] = v;
      }
  }
  for (int i = 0; i < 6; ++i)
    if (modes[i] != BeamMode::Flexible)
      for (int j = 0; j < 6; ++j) S_[6 * i + j] = S_[6 * j + i] = 0.0;
  for (int i = 0; i < 6; ++i)
    if (modes[i] == BeamMode::Rigid) rigidIndex_[nRigid_++] = i;
  if (hasInertia_ && !(sec_.rhoA > 0.0)) hasInertia_ = false;
}

void BeamCorotational::kinematics(const double* q, Kinematics& k, const double* disp) const {
  const Vec3 xp = load3(q), xq = load3(q + 12);
  const Mat3 Rp = load9(q + 3), Rq = load9(q + 15);
  const Vec3 l = xq - xp;
  k.L = norm(l);
  k.lhat = (1.0 / k.L) * l;
  k.P = identity3() - outer(k.lhat, k.lhat);
  k.nyp = Rp * ey0_; k.nzp = Rp * ez0_;
  k.nyq = Rq * ey0_; k.nzq = Rq * ez0_;
  const double l0 = l0_;
  for (auto& row : k.g) std::fill(row, row + kDofs, 0.0);
  // e1 = |l| - l0. With the node translations u given, e1 = (|l|^2 - l0^2) / (|l| + l0) with
  // |l|^2 - l0^2 = 2 l0 ex0 . du + du . du (du = u_q - u_p): no cancellation of |l| against l0.
  if (disp) {
    const Vec3 du{disp[3] - disp[0], disp[4] - disp[1], disp[5] - disp[2]};
    k.e[0] = (2.0 * l0 * dot(ex0_, du) + dot(du, du)) / (k.L + l0);
  } else {
    k.e[0] = k.L - l0;
  }
  setVec(k.g[0], XP, -k.lhat);
  setVec(k.g[0], XQ, k.lhat);
  // e2 = l0 (nz^p . ny^q - ny^p . nz^q) / 2; d(a.b)/dw_a = a x b
  k.e[1] = 0.5 * l0 * (dot(k.nzp, k.nyq) - dot(k.nyp, k.nzq));
  setVec(k.g[1], WP, 0.5 * l0 * (cross(k.nzp, k.nyq) - cross(k.nyp, k.nzq)));
  setVec(k.g[1], WQ, 0.5 * l0 * (cross(k.nyq, k.nzp) - cross(k.nzq, k.nyp)));
  // e3..e6 = c n . lhat: grad_w = c n x lhat, grad_xq = c P n / L = -grad_xp
  const double c[4] = {-l0, l0, l0, -l0};
  const Vec3* n[4] = {&k.nzp, &k.nzq, &k.nyp, &k.nyq};
  const int wb[4] = {WP, WQ, WP, WQ};
  for (int m = 0; m < 4; ++m) {
    const int i = 2 + m;
    k.e[i] = c[m] * dot(*n[m], k.lhat);
    setVec(k.g[i], wb[m], c[m] * cross(*n[m], k.lhat));
    const Vec3 Pn = (c[m] / k.L) * (k.P * *n[m]);
    setVec(k.g[i], XQ, Pn);
    setVec(k.g[i], XP, -Pn);
  }
  // eps1 = e1 + (arc - chord), arc - chord = 1/2 e^T Qh e / (30 l0)  [2 e3^2 + e3 e4 + 2 e4^2 + ...]
  const double inv30 = 1.0 / (30.0 * l0);
  double quad = 0.0;
  for (int pr = 0; pr < 2; ++pr) {
    const int i = 2 + 2 * pr;
    const double* Q = &Qh_[4 * pr];
    k.Qe[i] = Q[0] * k.e[i] + Q[1] * k.e[i + 1];
    k.Qe[i + 1] = Q[2] * k.e[i] + Q[3] * k.e[i + 1];
    quad += 0.5 * (k.e[i] * k.Qe[i] + k.e[i + 1] * k.Qe[i + 1]);
  }
  for (int i = 0; i < 6; ++i) {
    k.eps[i] = k.e[i];
    std::copy(k.g[i], k.g[i] + kDofs, k.ge[i]);
  }
  k.eps[0] += quad * inv30;
  for (int i = 2; i < 6; ++i) {
    const double s = k.Qe[i] * inv30;
    for (int a = 0; a < kDofs; ++a) k.ge[0][a] += s * k.g[i][a];
  }
}

void BeamCorotational::stresses(const Kinematics& k, const double* lambda, double* sig) const {
  for (int i = 0; i < 6; ++i) {
    double s = 0.0;
    for (int j = 0; j < 6; ++j) s += S_[6 * i + j] * k.eps[j];
    sig[i] = s;  // sigma = S eps (flexible)
  }
  for (int r = 0; r < nRigid_; ++r) sig[rigidIndex_[r]] = lambda ? scale_ * lambda[r] : 0.0;
}

void BeamCorotational::evaluate(const KernelInput& in, const KernelNeeds& needs, KernelOutput& out) const {
  Kinematics k;
  kinematics(in.q, k, in.disp);
  double sig[6];  // total generalized stresses (flexible S eps, rigid scale * lambda)
  stresses(k, in.lambda, sig);
  const int n = kDofs + nRigid_;
  out.f.assign(n, 0.0);
  double* f = out.f.data();
  for (int i = 0; i < 6; ++i)  // f = sum sigma_i grad eps_i
    if (sig[i] != 0.0)
      for (int a = 0; a < kDofs; ++a) f[a] += sig[i] * k.ge[i][a];
  for (int r = 0; r < nRigid_; ++r) f[kDofs + r] = scale_ * k.eps[rigidIndex_[r]];
  // strain-rate damping: sigma_d = beta S epsd, epsd = grad eps . qdot, f_d = sum sigma_d_i grad eps_i
  double sigD[6] = {0, 0, 0, 0, 0, 0};
  const bool damped = in.qdot && beta_ > 0.0;
  if (damped) {
    double epsd[6];
    for (int i = 0; i < 6; ++i) {
      epsd[i] = 0.0;
      for (int a = 0; a < kDofs; ++a) epsd[i] += k.ge[i][a] * in.qdot[a];
    }
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) sigD[i] += beta_ * S_[6 * i + j] * epsd[j];
      if (sigD[i] != 0.0)
        for (int a = 0; a < kDofs; ++a) f[a] += sigD[i] * k.ge[i][a];
    }
  }
  if (!needs.tangent && !needs.damping) return;
  if (damped && needs.damping) {  // D = d f_d / d qdot = beta sum_ij S_ij grad eps_i grad eps_j^T
    out.D.assign(static_cast<size_t>(kDofs) * kDofs, 0.0);
    for (int i = 0; i < 6; ++i) {
      double SG[kDofs] = {};
      for (int j = 0; j < 6; ++j)
        if (S_[6 * i + j] != 0.0)
          for (int a = 0; a < kDofs; ++a) SG[a] += S_[6 * i + j] * k.ge[j][a];
      addOuter(out.D.data(), kDofs, k.ge[i], SG, beta_);
    }
  }
  if (!needs.tangent) return;

  out.K.assign(static_cast<size_t>(n) * n, 0.0);
  double* K = out.K.data();
  double* G = K;
  if (needs.splitGeometric) {
    out.Kg.assign(static_cast<size_t>(n) * n, 0.0);
    G = out.Kg.data();
  }
  // Material part: sum_ij S_ij grad eps_i grad eps_j^T
  for (int i = 0; i < 6; ++i) {
    if (modes_[i] != BeamMode::Flexible) continue;
    double SG[kDofs] = {};
    bool any = false;
    for (int j = 0; j < 6; ++j) {
      const double s = S_[6 * i + j];
      if (s == 0.0) continue;
      any = true;
      for (int a = 0; a < kDofs; ++a) SG[a] += s * k.ge[j][a];
    }
    if (any) addOuter(K, n, k.ge[i], SG, 1.0);
  }
  // Constraint gradient blocks: rows/columns scale * grad eps_i
  for (int r = 0; r < nRigid_; ++r) {
    const double* gi = k.ge[rigidIndex_[r]];
    for (int a = 0; a < kDofs; ++a) {
      K[a * n + kDofs + r] = scale_ * gi[a];
      K[(kDofs + r) * n + a] = scale_ * gi[a];
    }
  }
  // Newton with mixed stresses: the stress part uses the independent (linearized) stresses of the
  // flexible modes; rigid modes keep their multipliers.
  if (in.sigmaMixed)
    for (int i = 0; i < 6; ++i)
      if (modes_[i] == BeamMode::Flexible) sig[i] = in.sigmaMixed[i];
  for (int i = 0; i < 6; ++i) sig[i] += sigD[i];  // the damping stresses' part
  addStressTangent(k, sig, G, n);
  // strain-rate damping at fixed qdot: beta sum_ij S_ij grad eps_i (qdot . d grad eps_j / dq)^T
  if (damped) {
    std::vector<double> H(static_cast<size_t>(n) * n);
    double r[6][kDofs] = {};
    for (int j = 0; j < 6; ++j) {
      if (modes_[j] != BeamMode::Flexible) continue;
      double unit[6] = {0, 0, 0, 0, 0, 0};
      unit[j] = 1.0;
      std::fill(H.begin(), H.end(), 0.0);
      addStressTangent(k, unit, H.data(), n);
      for (int a = 0; a < kDofs; ++a)
        for (int c = 0; c < kDofs; ++c) r[j][c] += in.qdot[a] * H[static_cast<size_t>(a) * n + c];
    }
    for (int i = 0; i < 6; ++i) {
      double SR[kDofs] = {};
      for (int j = 0; j < 6; ++j)
        if (S_[6 * i + j] != 0.0)
          for (int c = 0; c < kDofs; ++c) SR[c] += S_[6 * i + j] * r[j][c];
      addOuter(K, n, k.ge[i], SR, beta_);
    }
  }
}

void BeamCorotational::addStressTangent(const Kinematics& k, const double* sig, double* G, int n) const {
  // Stress part: sum_i we_i Hess e_i + sigma_1/(30 l0) sum Qh_ij grad e_i grad e_j^T,
  // we_1 = sigma_1, we_2 = sigma_2, we_i = sigma_i + sigma_1 Qe_i / (30 l0) (chain rule through eps1).
  const double l0 = l0_, inv30 = 1.0 / (30.0 * l0);
  double we[6];
  we[0] = sig[0];
  we[1] = sig[1];
  for (int i = 2; i < 6; ++i) we[i] = sig[i] + sig[0] * k.Qe[i] * inv30;
  if (sig[0] != 0.0) {
    for (int pr = 0; pr < 2; ++pr) {
      const int i = 2 + 2 * pr;
      const double* Q = &Qh_[4 * pr];
      double a[kDofs], b[kDofs];
      for (int t = 0; t < kDofs; ++t) {
        a[t] = Q[0] * k.g[i][t] + Q[1] * k.g[i + 1][t];
        b[t] = Q[2] * k.g[i][t] + Q[3] * k.g[i + 1][t];
      }
      addOuter(G, n, k.g[i], a, sig[0] * inv30);
      addOuter(G, n, k.g[i + 1], b, sig[0] * inv30);
    }
  }
  // e3..e6 combined: sum = m_p . lhat + m_q . lhat with m_p = l0 (-we3 nz^p + we5 ny^p), m_q = l0 (we4 nz^q - we6 ny^q)
  const Vec3 mp = l0 * (we[4] * k.nyp - we[2] * k.nzp);
  const Vec3 mq = l0 * (we[3] * k.nzq - we[5] * k.nyq);
  const double iL = 1.0 / k.L;
  {
    const Vec3 mm = mp + mq;
    const Vec3 Pc = k.P * mm;
    // H_lhat[mm] + we1 P / L (e1 = |l| - l0)
    Mat3 Hxx = (-iL * iL) * (dot(k.lhat, mm) * k.P + outer(k.lhat, Pc) + outer(Pc, k.lhat)) + (we[0] * iL) * k.P;
    addBlock(G, n, XP, XP, Hxx, 1.0);
    addBlock(G, n, XQ, XQ, Hxx, 1.0);
    addBlock(G, n, XP, XQ, Hxx, -1.0);
    addBlock(G, n, XQ, XP, Hxx, -1.0);
  }
  auto frameLhat = [&](const Vec3& m, int w) {
    const Mat3 A = iL * (skew(m) * k.P);  // J_m^T J_lhat (x_q columns)
    const Mat3 At = transpose(A);
    addBlock(G, n, w, XQ, A, 1.0);
    addBlock(G, n, w, XP, A, -1.0);
    addBlock(G, n, XQ, w, At, 1.0);
    addBlock(G, n, XP, w, At, -1.0);
    addBlock(G, n, w, w, skewskew(k.lhat, m), 1.0);  // H_m[lhat] = skew(lhat) skew(m)
  };
  frameLhat(mp, WP);
  frameLhat(mq, WQ);
  // e2 = c2 (nz^p . ny^q - ny^p . nz^q)
  if (we[1] != 0.0) {
    const double c2 = 0.5 * l0 * we[1];
    const Mat3 Bpq = skewskew(k.nzp, k.nyq) - skewskew(k.nyp, k.nzq);
    addBlock(G, n, WP, WQ, Bpq, -c2);             // J_a^T J_b = -skew(a) skew(b)
    addBlock(G, n, WQ, WP, transpose(Bpq), -c2);
    addBlock(G, n, WP, WP, transpose(Bpq), c2);   // H_a[b] = skew(b) skew(a)
    addBlock(G, n, WQ, WQ, Bpq, c2);
  }
}

// sigma = S (eps(q0) + grad eps(q0) . d): the stress update of the mixed (Hellinger-Reissner) Newton
// iteration, d in the tangent's DOF layout [x_p, w_p, x_q, w_q] (spatial rotation vectors).
void BeamCorotational::linearizedStresses(const double* q0, const double* q1, double* sigma) const {
  Kinematics k;
  double eps[6];
  if (!q0) {
    kinematics(q1, k);
    std::copy(k.eps, k.eps + 6, eps);
  } else {
    kinematics(q0, k);
    double d[kDofs];
    for (int node = 0; node < 2; ++node) {
      const double* a = q0 + 12 * node;
      const double* b = q1 + 12 * node;
      for (int i = 0; i < 3; ++i) d[6 * node + i] = b[i] - a[i];
      const Vec3 w = logSO3(load9(b + 3) * transpose(load9(a + 3)));
      for (int i = 0; i < 3; ++i) d[6 * node + 3 + i] = w[i];
    }
    for (int i = 0; i < 6; ++i) {
      double v = k.eps[i];
      for (int a = 0; a < kDofs; ++a) v += k.ge[i][a] * d[a];
      eps[i] = v;
    }
  }
  for (int i = 0; i < 6; ++i) {
    double s = 0.0;
    for (int j = 0; j < 6; ++j) s += S_[6 * i + j] * eps[j];
    sigma[i] = s;
  }
}

void BeamCorotational::localMass(double* Ml) const {
  std::fill(Ml, Ml + kDofs * kDofs, 0.0);
  const double l = l0_, m = sec_.rhoA * l;
  auto set = [&](int i, int j, double v) { Ml[i * kDofs + j] = v; Ml[j * kDofs + i] = v; };
  // axial, linear shape functions: rhoA l [2 1; 1 2] / 6
  set(0, 0, m / 3); set(6, 6, m / 3); set(0, 6, m / 6);
  // torsion: rho Ip l [2 1; 1 2] / 6
  const double mt = sec_.rhoIp * l;
  set(3, 3, mt / 3); set(9, 9, mt / 3); set(3, 9, mt / 6);
  // cubic Hermite (Euler-Bernoulli consistent mass) rhoA l / 420 [156 22l 54 -13l; ...]
  const double h = m / 420.0;
  auto plane = [&](int v1, int t1, int v2, int t2, double sg) {  // sg = -1 when theta = -w'
    set(v1, v1, 156 * h); set(v2, v2, 156 * h); set(v1, v2, 54 * h);
    set(t1, t1, 4 * l * l * h); set(t2, t2, 4 * l * l * h); set(t1, t2, -3 * l * l * h);
    set(v1, t1, sg * 22 * l * h); set(v1, t2, -sg * 13 * l * h);
    set(v2, t1, sg * 13 * l * h); set(v2, t2, -sg * 22 * l * h);
  };
  plane(1, 5, 7, 11, 1.0);   // v, theta_z = v'
  plane(2, 4, 8, 10, -1.0);  // w, theta_y = -w'
  // the sections' rotary inertia in bending: 1/2 int rho I (d phi/dt)^2 dx (phi the section
  // rotation) with phi interpolated as by the exact static shapes of the Timoshenko pair
  // (Friedman & Kosmatka 1993; Phi = 12 EI / (kGA l^2), 0 without shear flexibility), xi = x / l:
  //   phi = mu [6 (xi^2 - xi) / l (v1 - v2) + (3 xi^2 - (4 + Phi) xi + 1 + Phi) t1 + (3 xi^2 - (2 - Phi) xi) t2],
  // mu = 1 / (1 + Phi); Phi = 0 gives the Hermite slopes v' (Rayleigh beam). A rigid turn (v2 - v1 = l t,
  // t1 = t2 = t) gives phi = t: exact for any Phi. Integrated by 3-point Gauss (degree 4, exact).
  auto rotary = [&](int v1, int t1, int v2, int t2, double sg, double rhoI, double EI, double kGA) {
    if (!(rhoI > 0.0)) return;
    const double Phi = kGA > 0.0 ? 12.0 * EI / (kGA * l * l) : 0.0, mu = 1.0 / (1.0 + Phi);
    const double gx[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)}, gw[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
    const int dof[4] = {v1, t1, v2, t2};
    for (int g = 0; g < 3; ++g) {
      const double xi = gx[g], a = sg * mu * 6.0 * (xi * xi - xi) / l;
      const double N[4] = {a, mu * (3 * xi * xi - (4 + Phi) * xi + 1 + Phi), -a, mu * (3 * xi * xi - (2 - Phi) * xi)};
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) Ml[dof[i] * kDofs + dof[j]] += gw[g] * rhoI * l * N[i] * N[j];
    }
  };
  rotary(1, 5, 7, 11, 1.0, sec_.rhoIz, sec_.EIz, sec_.kGAy);   // v, rotation theta_z about z
  rotary(2, 4, 8, 10, -1.0, sec_.rhoIy, sec_.EIy, sec_.kGAz);  // w, rotation theta_y about y (= -w')
}

void BeamCorotational::setLinearMass(bool linear) {
  linear_ = linear;
  linearMass_.clear();
  if (!linear) return;
  // int rhoA v.v dx with v = (1 - xi) v_p + xi v_q: rhoA l0 / 6 [2 1; 1 2] on each direction
  linearMass_.assign(kDofs * kDofs, 0.0);
  const double m = sec_.rhoA * l0_ / 6.0;
  for (int i = 0; i < 3; ++i) {
    linearMass_[i * kDofs + i] = linearMass_[(6 + i) * kDofs + 6 + i] = 2.0 * m;
    linearMass_[i * kDofs + 6 + i] = linearMass_[(6 + i) * kDofs + i] = m;
  }
}

void BeamCorotational::mass(const double* q, std::vector<double>& M) const {
  if (linear_) {
    M = linearMass_;
    return;
  }
  M.assign(kDofs * kDofs, 0.0);
  const Mat3 Lam = currentFrame(q);  // chord, averaged rotated y axis projected perpendicular to it
  double Ml[kDofs * kDofs];
  localMass(Ml);
  // M = T Ml T^T, T = blockdiag(Lam)
  for (int bi = 0; bi < 4; ++bi)
    for (int bj = 0; bj < 4; ++bj) {
      Mat3 B;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) B[3 * i + j] = Ml[(3 * bi + i) * kDofs + 3 * bj + j];
      const Mat3 Bg = Lam * B * transpose(Lam);
      addBlock(M.data(), kDofs, bi, bj, Bg, 1.0);
    }
}

bool BeamCorotational::lumpedInertia(double* mJ) const {
  if (!(lumped_ || linear_) || !hasInertia_) return false;
  // half the element on each node: translations rhoA l0 / 2 (lumped; linear: in the element mass), the
  // section's rotary inertia per length (torsion rho Ip about ex0, bending rho Iy about ey0 and rho Iz
  // about ez0) times l0 / 2
  const double h = 0.5 * l0_;
  const Mat3 J = h * (sec_.rhoIp * outer(ex0_, ex0_) + sec_.rhoIy * outer(ey0_, ey0_) + sec_.rhoIz * outer(ez0_, ez0_));
  for (int n = 0; n < 2; ++n) {
    double* v = mJ + 7 * n;
    v[0] = lumped_ ? h * sec_.rhoA : 0.0;
    v[1] = J[0], v[2] = J[1], v[3] = J[2], v[4] = J[4], v[5] = J[5], v[6] = J[8];
  }
  return true;
}

void BeamCorotational::bodyForce(const double* /*q*/, const Vec3& a, std::vector<double>& f) const {
  f.assign(kDofs, 0.0);
  const double h = 0.5 * sec_.rhoA * l0_;
  for (int i = 0; i < 3; ++i) {
    f[i] = h * a[i];
    f[6 + i] = h * a[i];
  }
}

std::array<double, 6> BeamCorotational::generalizedStrains(const double* q) const {
  Kinematics k;
  kinematics(q, k);
  std::array<double, 6> e;
  std::copy(k.eps, k.eps + 6, e.begin());
  return e;
}

std::array<double, 6> BeamCorotational::generalizedStresses(const double* q, const double* lambda, const double* disp) const {
  Kinematics k;
  kinematics(q, k, disp);
  std::array<double, 6> s;
  stresses(k, lambda, s.data());
  return s;
}

bool BeamCorotational::strainEnergy(const double* q, double* energy) const {
  Kinematics k;
  kinematics(q, k);
  double e = 0.0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) e += 0.5 * k.eps[i] * S_[6 * i + j] * k.eps[j];
  *energy = e;
  return true;
}

double BeamCorotational::vonMisesMax(const double* q, const double* lambda) const {
  if (!(sec_.A > 0.0) || !sec_.stressRecovery) return 0.0;
  Kinematics k;
  kinematics(q, k);
  double sig[6];
  stresses(k, lambda, sig);
  const double l = l0_, inv30 = 1.0 / (30.0 * l);
  // Section forces from the energy: N = dU/de1, T = dU/dphi = l0 sigma_2,
  // end moments |M| = l0 |dU/de_i| with dU/de_i = sigma_i + sigma_1 Qe_i / (30 l0).
  const double N = sig[0];
  const double T = l * sig[1];
  double M[6];
  for (int i = 2; i < 6; ++i) M[i] = l * std::abs(sig[i] + sig[0] * k.Qe[i] * inv30);
  const double tau = std::abs(T) * sec_.torsionStressFactor;
  const double nA = std::abs(N) / sec_.A;
  double vm = 0.0;
  for (int end = 0; end < 2; ++end) {
    const double My = M[2 + end], Mz = M[4 + end];
    if (sec_.shape == CrossSection::Circ) {
      // worst point on the perimeter; torsion shear is uniform along it
      const double s = nA + std::hypot(My, Mz) * sec_.zmax / sec_.Iy;
      vm = std::max(vm, std::sqrt(s * s + 3.0 * tau * tau));
    } else {
      const double sy = My * sec_.zmax / sec_.Iy, sz = Mz * sec_.ymax / sec_.Iz;
      const double corner = nA + sy + sz;  // corners: no torsion shear
      vm = std::max(vm, corner);
      // mid-sides: tau_max used on all four (exact on the long sides, an upper bound on the short ones)
      const double s1 = nA + sy, s2 = nA + sz;
      vm = std::max(vm, std::sqrt(s1 * s1 + 3.0 * tau * tau));
      vm = std::max(vm, std::sqrt(s2 * s2 + 3.0 * tau * tau));
    }
  }
  return vm;
}

}  // namespace sinew
