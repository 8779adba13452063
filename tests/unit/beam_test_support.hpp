// What the beam kernel unit tests share: a section whose stiffnesses are of comparable size (so every
// term shows in a relative error), and the kernel state of a 2-node beam, [x_p, R_p, x_q, R_q] with
// the rotations as 3x3 matrices, with its perturbation for central differences.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "elements/beam_section.hpp"
#include "sinew/linalg3.hpp"
#include "sinew/rotation.hpp"

namespace sinew::test {

inline BeamSection comparableSection() {
  BeamSection s;
  s.shape = CrossSection::Rect;
  s.w = 0.3; s.t = 0.2;
  s.A = 0.06; s.Iy = 2e-4; s.Iz = 4.5e-4; s.Ip = 6.5e-4; s.It = 5e-4;
  s.EA = 3.0; s.GIt = 0.7; s.EIy = 1.3; s.EIz = 0.9; s.kGAy = 40.0; s.kGAz = 25.0;
  s.rhoA = 2.0; s.rhoIp = 0.1; s.rho = 2.0 / 0.06;
  s.ymax = 0.15; s.zmax = 0.1; s.torsionStressFactor = 0.2 / 5e-4;
  return s;
}

/// The 24 state numbers of a 2-node beam kernel: per node its position and rotation matrix.
using BeamState = std::array<double, 24>;

inline void setNode(BeamState& q, int node, const Vec3& x, const Mat3& R) {
  for (int i = 0; i < 3; ++i) q[12 * node + i] = x[i];
  for (int i = 0; i < 9; ++i) q[12 * node + 3 + i] = R[i];
}
inline Vec3 nodePosition(const BeamState& q, int node) { return {q[12 * node], q[12 * node + 1], q[12 * node + 2]}; }
inline Mat3 nodeRotation(const BeamState& q, int node) {
  Mat3 R;
  for (int i = 0; i < 9; ++i) R[i] = q[12 * node + 3 + i];
  return R;
}
/// dof k of [x_p, w_p, x_q, w_q] moved by h: translations additive, rotations R -> exp(skew(h e_k)) R.
inline BeamState perturbed(const BeamState& q, int k, double h) {
  BeamState s = q;
  const int node = k / 6, c = k % 6;
  if (c < 3) {
    s[12 * node + c] += h;
  } else {
    Vec3 w{};
    w[c - 3] = h;
    setNode(s, node, nodePosition(q, node), expSO3(w) * nodeRotation(q, node));
  }
  return s;
}

/// Largest absolute entry.
inline double maxAbs(const std::vector<double>& a) {
  double m = 0;
  for (double v : a) m = std::max(m, std::abs(v));
  return m;
}

}  // namespace sinew::test
