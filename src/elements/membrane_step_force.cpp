// The membrane's strain energy and energy-momentum step force (-dynamics_scheme energy_momentum;
// docs/dynamics.md, "Energy-momentum scheme").
//
// St. Venant-Kirchhoff with prestress: U = t int (S0 . E + 1/2 E . C E) dA, E = (f_i . f_j - delta_ij)/2
// (Voigt, engineering shear). E is quadratic in the positions, so with the mid deformation gradient
// fm_i = (f_i(q0) + f_i(q1))/2 the change E1 - E0 = B(fm) (q1 - q0) exactly, and the stress
// S = S0 + C (E0 + E1)/2 (+ xi/2 C (E1 - E0) with the energy decay xi) on B(fm) does the work
// (S0 + C (E0 + E1)/2) . (E1 - E0) = U1 - U0 exactly (Simo & Tarnow 1992), with no resultant force or
// moment about the mid positions (the force of a frame-invariant energy at the mid configuration).
// The energy decay dissipates xi/2 (E1 - E0) . C (E1 - E0) at each integration point; strain-rate damping
// beta adds beta/h C (E1 - E0) to S (dissipating beta/h (E1 - E0) . C (E1 - E0); zero for a rigid step).
#include "elements/membrane.hpp"

namespace sinew {

namespace {

Vec3 nodeOf(const double* q, int a) { return {q[3 * a], q[3 * a + 1], q[3 * a + 2]}; }

}  // namespace

bool Membrane::strainEnergy(const double* q, double* energy) const {
  if (ff_) return false;
  double U = 0.0;
  for (int p = 0; p < ngp_; ++p) {
    const Point& P = pts_[p];
    Vec3 f1{}, f2{};
    for (int a = 0; a < nn_; ++a) {
      f1 += P.dN[a][0] * nodeOf(q, a);
      f2 += P.dN[a][1] * nodeOf(q, a);
    }
    const double E[3] = {0.5 * (dot(f1, f1) - 1.0), 0.5 * (dot(f2, f2) - 1.0), dot(f1, f2)};
    double u = 0.0;
    for (int i = 0; i < 3; ++i) {
      u += sAct_[i] * E[i];
      for (int j = 0; j < 3; ++j) u += 0.5 * E[i] * C_[i][j] * E[j];
    }
    U += props_.thickness * P.wJ0 * u;
  }
  *energy = U;
  return true;
}

void Membrane::stepForce(const StepForceInput& in, bool tangent, KernelOutput& out) const {
  const int n = 3 * nn_;
  out.f.assign(n, 0.0);
  if (tangent) out.K.assign(static_cast<size_t>(n) * n, 0.0);
  for (int p = 0; p < ngp_; ++p) {
    const Point& P = pts_[p];
    Vec3 g1[2] = {}, g2[2] = {};  // f_1, f_2 at the step's start (0) and end (1)
    for (int a = 0; a < nn_; ++a) {
      g1[0] += P.dN[a][0] * nodeOf(in.q0, a);
      g2[0] += P.dN[a][1] * nodeOf(in.q0, a);
      g1[1] += P.dN[a][0] * nodeOf(in.q1, a);
      g2[1] += P.dN[a][1] * nodeOf(in.q1, a);
    }
    double E[2][3];
    for (int s = 0; s < 2; ++s) {
      E[s][0] = 0.5 * (dot(g1[s], g1[s]) - 1.0);
      E[s][1] = 0.5 * (dot(g2[s], g2[s]) - 1.0);
      E[s][2] = dot(g1[s], g2[s]);
    }
    double S[3];
    // S0 + C ((E0 + E1)/2 + (xi/2 + beta/h) (E1 - E0))
    const double bh = beta_ > 0.0 && in.h > 0.0 ? beta_ / in.h : 0.0;
    const double w0 = 0.5 * (1.0 - in.decay), w1 = 0.5 * (1.0 + in.decay);
    for (int i = 0; i < 3; ++i) {
      S[i] = sAct_[i];
      for (int j = 0; j < 3; ++j) S[i] += C_[i][j] * (w0 * E[0][j] + w1 * E[1][j]);
      if (bh > 0.0)
        for (int j = 0; j < 3; ++j) S[i] += bh * C_[i][j] * (E[1][j] - E[0][j]);
    }
    const Vec3 m1 = 0.5 * (g1[0] + g1[1]), m2 = 0.5 * (g2[0] + g2[1]);
    const Vec3 P1 = S[0] * m1 + S[2] * m2, P2 = S[2] * m1 + S[1] * m2;
    const double wt = props_.thickness * P.wJ0;
    for (int a = 0; a < nn_; ++a)
      for (int k = 0; k < 3; ++k) out.f[3 * a + k] += wt * (P.dN[a][0] * P1[k] + P.dN[a][1] * P2[k]);
    if (!tangent) continue;
    // d/dq1: the stress through E1 ((w1 + beta/h) C B(f(q1))) on B(fm), and the mid gradient (1/2) with S
    double Bm[3][12], CB1[3][12];
    for (int a = 0; a < nn_; ++a)
      for (int k = 0; k < 3; ++k) {
        const int c = 3 * a + k;
        Bm[0][c] = P.dN[a][0] * m1[k];
        Bm[1][c] = P.dN[a][1] * m2[k];
        Bm[2][c] = P.dN[a][0] * m2[k] + P.dN[a][1] * m1[k];
        const double B1[3] = {P.dN[a][0] * g1[1][k], P.dN[a][1] * g2[1][k], P.dN[a][0] * g2[1][k] + P.dN[a][1] * g1[1][k]};
        for (int i = 0; i < 3; ++i) CB1[i][c] = (w1 + bh) * (C_[i][0] * B1[0] + C_[i][1] * B1[1] + C_[i][2] * B1[2]);
      }
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        out.K[static_cast<size_t>(n) * r + c] += wt * (Bm[0][r] * CB1[0][c] + Bm[1][r] * CB1[1][c] + Bm[2][r] * CB1[2][c]);
    for (int a = 0; a < nn_; ++a)
      for (int b = 0; b < nn_; ++b) {
        const double G = 0.5 * wt * (S[0] * P.dN[a][0] * P.dN[b][0] + S[1] * P.dN[a][1] * P.dN[b][1] +
                                     S[2] * (P.dN[a][0] * P.dN[b][1] + P.dN[a][1] * P.dN[b][0]));
        for (int k = 0; k < 3; ++k) out.K[static_cast<size_t>(n) * (3 * a + k) + 3 * b + k] += G;
      }
  }
}

}  // namespace sinew
