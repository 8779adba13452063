// The 3D cable's strain energy and energy-momentum step force (-dynamics_scheme energy_momentum;
// docs/dynamics.md, "Energy-momentum scheme").
//
// The elastic cable's energy is a function of its length l alone: N(l) = max(EA/L (l - l_s), 0) with the
// slack length l_s = L (1 - N0/EA), U(l) = EA/(2L) (l - l_s)^2 above l_s and 0 below (U = N0 l, always
// taut, when EA = 0). With d = x_q - x_p, (d0 + d1) . (d1 - d0) = l1^2 - l0^2, so the force
//   f_q = -f_p = N_bar (d0 + d1) / (l0 + l1),   N_bar = (U(l1) - U(l0)) / (l1 - l0)
// does the work N_bar (l1 - l0) = U(l1) - U(l0) exactly (Gonzalez's discrete gradient), has no resultant
// and no moment about the mid positions (it is parallel to the mid chord). Taut at both ends N_bar =
// N((l0 + l1)/2); a step through the slack length takes the secant of the kinked energy. The energy
// decay xi adds xi/2 EA/L (l1 - l0) to N_bar where the cable is taut at either end (dissipating
// xi/2 EA/L (l1 - l0)^2); strain-rate damping beta likewise adds beta/h EA/L (l1 - l0).
#include <cmath>

#include "elements/cable3d.hpp"

namespace sinew {

namespace {

Vec3 chordOf(const double* q) { return {q[3] - q[0], q[4] - q[1], q[5] - q[2]}; }

}  // namespace

bool Cable3D::strainEnergy(const double* q, double* energy) const {
  if (ff_) return false;
  const double l = length(q), EA = E_ * A_;
  if (EA <= 0.0) {
    *energy = N0_ * l;
    return true;
  }
  const double ls = L_ * (1.0 - N0_ / EA);
  *energy = l > ls ? 0.5 * EA / L_ * (l - ls) * (l - ls) : 0.0;
  return true;
}

void Cable3D::stepForce(const StepForceInput& in, bool tangent, KernelOutput& out) const {
  const Vec3 d0 = chordOf(in.q0), d1 = chordOf(in.q1);
  const double l0 = norm(d0), l1 = norm(d1), EA = E_ * A_;
  // N_bar and its derivative by l1
  double N = N0_, dN = 0.0;
  if (EA > 0.0) {
    const double ls = L_ * (1.0 - N0_ / EA), k = EA / L_;
    const bool taut0 = l0 > ls, taut1 = l1 > ls;
    if (taut0 && taut1) {
      N = k * (0.5 * (l0 + l1) - ls);
      dN = 0.5 * k;
    } else if (taut0 || taut1) {  // through the slack length: the secant of the kinked energy
      double U0 = 0.0, U1 = 0.0;
      strainEnergy(in.q0, &U0);
      strainEnergy(in.q1, &U1);
      N = (U1 - U0) / (l1 - l0);
      const double N1 = taut1 ? k * (l1 - ls) : 0.0;
      dN = (N1 - N) / (l1 - l0);
    } else {
      N = 0.0;
    }
    if ((taut0 || taut1) && in.decay > 0.0) {
      N += 0.5 * in.decay * k * (l1 - l0);
      dN += 0.5 * in.decay * k;
    }
    if ((taut0 || taut1) && beta_ > 0.0 && in.h > 0.0) {  // strain-rate damping: beta EA/L (l1 - l0)/h
      N += beta_ / in.h * k * (l1 - l0);
      dN += beta_ / in.h * k;
    }
  }
  const Vec3 w = d0 + d1;
  const double s = l0 + l1;
  out.f.assign(6, 0.0);
  for (int c = 0; c < 3; ++c) {
    out.f[c] = -N * w[c] / s;
    out.f[3 + c] = N * w[c] / s;
  }
  if (!tangent) return;
  // dG/dd1 = N/s I + w (dN/s - N/s^2) e1^T, e1 = d1/l1; f_q = G, f_p = -G, d1 = x_q - x_p
  out.K.assign(36, 0.0);
  const Vec3 e1 = (1.0 / l1) * d1;
  const double a = dN / s - N / (s * s);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double B = (i == j ? N / s : 0.0) + w[i] * a * e1[j];
      out.K[6 * i + j] += B;
      out.K[6 * (i + 3) + j + 3] += B;
      out.K[6 * i + j + 3] -= B;
      out.K[6 * (i + 3) + j] -= B;
    }
}

}  // namespace sinew
