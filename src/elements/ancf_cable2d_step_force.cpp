// The ANCF cable's energy-momentum step force (-dynamics_scheme energy_momentum; docs/dynamics.md,
// "Energy-momentum scheme"; formulation in ancf_cable2d.hpp).
//
// At an integration point the strains are functions of two invariants that are quadratic in the element
// vector q: a = r' . r' and b = r' x r'' (the 2D cross product), eps = sqrt(a) - 1 and K = b / a. A
// quadratic invariant changes over a step q0 -> q1 by exactly its gradient at the mid state times the step,
//   a1 - a0 = grad a(q_m) . dq,   b1 - b0 = grad b(q_m) . dq,   q_m = (q0 + q1)/2,
// and the strains by exact difference quotients of them (no division by a1 - a0: no round-off threshold):
//   eps1 - eps0 = (a1 - a0) / (sqrt(a0) + sqrt(a1)),
//   K1 - K0    = -(b0 + b1)/(2 a0 a1) (a1 - a0) + (a0 + a1)/(2 a0 a1) (b1 - b0)
// (the two-variable discrete gradient of b/a, averaged over both orders). So with the algorithmic strain
// gradients B_eps = grad a(q_m) / (sqrt(a0) + sqrt(a1)) and B_K = c_a grad a(q_m) + c_b grad b(q_m),
// B . dq = eps1 - eps0 and K1 - K0 exactly, and the force
//   f = sum_ip w (N_bar B_eps) + sum_ip w (M_bar B_K),
//   N_bar = EA ((eps0 + eps1)/2 - eps_ref) + (xi/2 EA + (d_eps + beta EA)/h) (eps1 - eps0),
//   M_bar = EI ((K0 + K1)/2 - K_ref)     + (xi/2 EI + (d_K + beta EI)/h) (K1 - K0),
// does the work U(q1) - U(q0) of U = sum_ip w (EA/2 (eps - eps_ref)^2) + sum_ip w (EI/2 (K - K_ref)^2)
// (strainEnergy, the integration rules of evaluate) plus a dissipation of sum w (xi/2 + (.)/h) dS^2 >= 0.
// grad a and grad b at q_m vanish on its rigid velocities (a translation leaves r' alone, a rotation
// J turns r' and r'' together: r'_m . J r'_m = 0, J r'_m x r''_m + r'_m x J r''_m = 0), so f has no
// resultant and no moment about q_m and the midpoint momentum balance keeps both momenta. The tangent
// d f / d q1 is analytic (unit test test_ancf_cable2d_energy_momentum against central differences).
#include <array>
#include <cmath>

#include "elements/ancf_cable2d.hpp"

namespace sinew {

namespace {

/// v = sum_j S_j q_(j, 0..1).
inline std::array<double, 2> map2(const std::array<double, 4>& S, const double* q) {
  return {S[0] * q[0] + S[1] * q[2] + S[2] * q[4] + S[3] * q[6], S[0] * q[1] + S[1] * q[3] + S[2] * q[5] + S[3] * q[7]};
}

inline double cross2(const std::array<double, 2>& u, const std::array<double, 2>& v) { return u[0] * v[1] - u[1] * v[0]; }
inline double dot2(const std::array<double, 2>& u, const std::array<double, 2>& v) { return u[0] * v[0] + u[1] * v[1]; }

/// grad a = 2 S'_j r'_i and grad b = (S'_j r''_y - S''_j r'_y, -S'_j r''_x + S''_j r'_x) at (r', r'').
void invariantGradients(const std::array<double, 4>& Sx, const std::array<double, 4>& Sxx, const std::array<double, 2>& rx,
                        const std::array<double, 2>& rxx, double ga[8], double gb[8]) {
  for (int j = 0; j < 4; ++j) {
    ga[2 * j] = 2.0 * Sx[j] * rx[0];
    ga[2 * j + 1] = 2.0 * Sx[j] * rx[1];
    gb[2 * j] = Sx[j] * rxx[1] - Sxx[j] * rx[1];
    gb[2 * j + 1] = -Sx[j] * rxx[0] + Sxx[j] * rx[0];
  }
}

}  // namespace

void AncfCable2D::stepForce(const StepForceInput& in, bool tangent, KernelOutput& out) const {
  const AncfCable2DParameters& p = *params_;
  const double EA = p.physicsAxialStiffness, EI = p.physicsBendingStiffness;
  // the factor of the strain jump in the stresses: energy decay xi/2 and the viscous laws over h
  const double rate = in.h > 0.0 ? 1.0 / in.h : 0.0;
  const double jumpA = 0.5 * in.decay * EA + (p.physicsAxialDamping + beta_ * EA) * rate;
  const double jumpB = 0.5 * in.decay * EI + (p.physicsBendingDamping + beta_ * EI) * rate;
  const double* q0 = in.q0;
  const double* q1 = in.q1;
  out.f.assign(8, 0.0);
  if (tangent) out.K.assign(64, 0.0);
  double* f = out.f.data();
  double* K = tangent ? out.K.data() : nullptr;
  const Geometry& geo = *geo_;

  // axial: N_bar B_eps, B_eps = S'_j u_i with u = (r'0 + r'1)/(n0 + n1)
  for (int ip = 0; ip < geo.nAxial; ++ip) {
    const IntegrationPoint& P = geo.axial[ip];
    const std::array<double, 2> r0 = map2(P.Sx, q0), r1 = map2(P.Sx, q1);
    const double n0 = std::sqrt(dot2(r0, r0)), n1 = std::sqrt(dot2(r1, r1)), s = n0 + n1;
    const double e0 = n0 - 1.0, e1 = n1 - 1.0;
    const double N = EA * (0.5 * (e0 + e1) - axialRef(ip).strain) + jumpA * (e1 - e0);
    const std::array<double, 2> sum{r0[0] + r1[0], r0[1] + r1[1]}, u{sum[0] / s, sum[1] / s};
    for (int j = 0; j < 4; ++j) {
      f[2 * j] += P.w * N * P.Sx[j] * u[0];
      f[2 * j + 1] += P.w * N * P.Sx[j] * u[1];
    }
    if (!K) continue;
    // d/dq1 (w N u S'_j): S'_j S'_k w [ dN/deps1 u t1^T + N (I/s - sum t1^T / s^2) ], t1 = r'1/n1
    const std::array<double, 2> t1{r1[0] / n1, r1[1] / n1};
    const double cN = P.w * (0.5 * EA + jumpA), cI = P.w * N / s, cS = P.w * N / (s * s);
    double B[2][2];
    for (int i = 0; i < 2; ++i)
      for (int l = 0; l < 2; ++l) B[i][l] = cN * u[i] * t1[l] + (i == l ? cI : 0.0) - cS * sum[i] * t1[l];
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        const double ss = P.Sx[j] * P.Sx[k];
        for (int i = 0; i < 2; ++i)
          for (int l = 0; l < 2; ++l) K[8 * (2 * j + i) + 2 * k + l] += ss * B[i][l];
      }
  }

  // bending: M_bar B_K, B_K = c_a grad a(q_m) + c_b grad b(q_m)
  for (int ip = 0; ip < geo.nBending; ++ip) {
    const IntegrationPoint& P = geo.bending[ip];
    const std::array<double, 2> x0 = map2(P.Sx, q0), x1 = map2(P.Sx, q1);
    const std::array<double, 2> xx0 = map2(P.Sxx, q0), xx1 = map2(P.Sxx, q1);
    const std::array<double, 2> xm{0.5 * (x0[0] + x1[0]), 0.5 * (x0[1] + x1[1])};
    const std::array<double, 2> xxm{0.5 * (xx0[0] + xx1[0]), 0.5 * (xx0[1] + xx1[1])};
    const double a0 = dot2(x0, x0), a1 = dot2(x1, x1), b0 = cross2(x0, xx0), b1 = cross2(x1, xx1);
    const double k0 = b0 / a0, k1 = b1 / a1, iaa = 1.0 / (2.0 * a0 * a1);
    const double ca = -(b0 + b1) * iaa, cb = (a0 + a1) * iaa;
    const double M = EI * (0.5 * (k0 + k1) - bendingRef(ip).curvature) + jumpB * (k1 - k0);
    double gam[8], gbm[8];
    invariantGradients(P.Sx, P.Sxx, xm, xxm, gam, gbm);
    double BK[8];
    for (int a = 0; a < 8; ++a) {
      BK[a] = ca * gam[a] + cb * gbm[a];
      f[a] += P.w * M * BK[a];
    }
    if (!K) continue;
    // w [ B_K (dM/dq1)^T + M (grad a_m dca^T + grad b_m dcb^T + ca H_a/2 + cb H_b/2) ] with
    // dM/dq1 = (EI/2 + jumpB) dK1/dq1, dK1/dq1 = (grad b1 - K1 grad a1)/a1,
    // dca/dq1 = -grad b1 iaa + (b0 + b1) iaa / a1 grad a1, dcb/dq1 = -grad a1 / (2 a1^2),
    // H_a = 2 S'_j S'_k I, H_b[(j,i),(k,l)] = e_il (S'_j S''_k - S''_j S'_k) (e_01 = 1, e_10 = -1)
    double ga1[8], gb1[8];
    invariantGradients(P.Sx, P.Sxx, x1, xx1, ga1, gb1);
    const double cM = P.w * (0.5 * EI + jumpB), wM = P.w * M;
    double dM[8], dca[8], dcb[8];
    for (int b = 0; b < 8; ++b) {
      dM[b] = cM * (gb1[b] - k1 * ga1[b]) / a1;
      dca[b] = -gb1[b] * iaa + (b0 + b1) * iaa / a1 * ga1[b];
      dcb[b] = -ga1[b] / (2.0 * a1 * a1);
    }
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b) K[8 * a + b] += BK[a] * dM[b] + wM * (gam[a] * dca[b] + gbm[a] * dcb[b]);
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        const double ha = wM * ca * P.Sx[j] * P.Sx[k];                                  // ca H_a / 2
        const double hb = 0.5 * wM * cb * (P.Sx[j] * P.Sxx[k] - P.Sxx[j] * P.Sx[k]);  // cb H_b / 2, e_01
        double* row0 = K + 8 * (2 * j) + 2 * k;
        double* row1 = row0 + 8;
        row0[0] += ha;
        row0[1] += hb;
        row1[0] -= hb;
        row1[1] += ha;
      }
  }
}

}  // namespace sinew
