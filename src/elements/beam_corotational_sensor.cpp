// Sensors along a corotational beam element (Exudyn's SensorBody on a beam): values at s in [0, 1]
// interpolated consistently with the kernel. In the current element frame Lam = [ex, ey, ez]
// (ex along the chord, currentFrame) the end sections have the local rotations
// th_p = log(Lam^T R_p E0), th_q (E0 = [ex0, ey0, ez0], the reference element frame). Chord and
// torsion angle are linear in s. In each bending plane the field is the kernel's own (Timoshenko,
// Phi = 12 EI / (kGA l0^2), no load inside the element): with end slopes a, b relative to the chord,
//   slope(s) = a + m s + d s^2 / 2,  deflection(s) / L = a s + m s^2 / 2 + d s^3 / 6 - d Phi s / 12,
//   d = 6 (a + b) / (1 + Phi),  m = b - a - d / 2
// (Phi = 0: cubic Hermite, N2 = s (1 - s)^2, N4 = s^2 (s - 1)), so slope(1) = b, deflection(1) = 0.
// Plane (e3, e4): a = th_p,y, b = th_q,y, w = -deflection; plane (e5, e6): a = th_p,z, b = th_q,z,
// v = deflection (w' = -theta_y, v' = theta_z). A released end (rls) takes the elastic slope the
// kernel condenses (-(2 - Phi) / (4 + Phi) times the other end's; 0 if that one is not flexible).
// The section at s sits at x_p + s (x_q - x_p) + Lam (0, v, w) and turns by R(s) = Lam exp(th(s)) E0^T:
// without releases R(0) = R_p, R(1) = R_q. Velocity and AngularVelocity are the time derivatives
// of this field along the nodal rates (sensorValue). Section forces (from the kernel's generalized
// stresses sigma, as vonMisesMax): N = sigma_1, T = l0 sigma_2, end moments My(0) = l0 sigma_3*, My(1) = l0 sigma_4*,
// Mz(0) = l0 sigma_5*, Mz(1) = l0 sigma_6* (sigma_i* = sigma_i + sigma_1 Qe_i / (30 l0)), linear
// in s; the shear forces balance them: Qz = dMy/dx, Qy = -dMz/dx (x along the chord, length L).
// Sign convention: the force and moment the part at larger s exerts on the section, M = EI kappa.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "elements/beam_corotational.hpp"
#include "sinew/rotation.hpp"

namespace sinew {
namespace {
inline Vec3 load3(const double* p) { return {p[0], p[1], p[2]}; }
inline Mat3 load9(const double* p) { return {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8]}; }
}  // namespace

const std::vector<std::string>& BeamCorotational::sensorVariables() {
  static const std::vector<std::string> v = {"Position",        "Displacement", "Rotation",   "Velocity",
                                             "AngularVelocity", "ForceLocal",   "TorqueLocal"};
  return v;
}

Mat3 BeamCorotational::currentFrame(const double* q) const {
  const Vec3 xp = load3(q), xq = load3(q + 12);
  const Mat3 Rp = load9(q + 3), Rq = load9(q + 15);
  Vec3 ex = xq - xp;
  ex = (1.0 / norm(ex)) * ex;
  Vec3 ey = Rp * ey0_ + Rq * ey0_;
  ey = ey - dot(ey, ex) * ex;
  if (norm(ey) < 1e-8) {  // ends twisted by ~pi relative to each other: use node p's axis
    ey = Rp * ez0_;
    ey = ey - dot(ey, ex) * ex;
  }
  ey = (1.0 / norm(ey)) * ey;
  return fromColumns(ex, ey, cross(ex, ey));
}

void BeamCorotational::sectionField(const double* q, double s, Vec3& offset, Mat3& R) const {
  const Vec3 xp = load3(q), xq = load3(q + 12);
  const double L = norm(xq - xp);
  const Mat3 Lam = currentFrame(q), LamT = transpose(Lam);
  const Mat3 E0 = fromColumns(ex0_, ey0_, ez0_);
  const Vec3 tp = logSO3(LamT * load9(q + 3) * E0), tq = logSO3(LamT * load9(q + 15) * E0);
  // bending planes: c = 1 (about y; modes 3, 4) and c = 2 (about z; modes 5, 6)
  double slope[3] = {(1 - s) * tp[0] + s * tq[0], 0, 0}, defl[3] = {0, 0, 0};
  for (int c = 1; c < 3; ++c) {
    const double EI = c == 1 ? sec_.EIy : sec_.EIz, kGA = c == 1 ? sec_.kGAz : sec_.kGAy;
    const double Phi = kGA > 0.0 ? 12.0 * EI / (kGA * l0_ * l0_) : 0.0;
    const int mp = 2 * c, mq = mp + 1;
    double a = tp[c], b = tq[c];
    const double rel = -(2.0 - Phi) / (4.0 + Phi);  // elastic end slope at a released end per slope at the other
    if (modes_[mp] == BeamMode::Released) a = modes_[mq] == BeamMode::Flexible ? rel * b : 0.0;
    if (modes_[mq] == BeamMode::Released) b = modes_[mp] == BeamMode::Flexible ? rel * a : 0.0;
    const double d = 6.0 * (a + b) / (1.0 + Phi), m = b - a - 0.5 * d;
    slope[c] = a + s * (m + 0.5 * d * s);
    defl[c] = L * (s * (a - d * Phi / 12.0) + s * s * (0.5 * m + d * s / 6.0));
  }
  offset = Lam * Vec3{0.0, defl[2], -defl[1]};
  R = Lam * expSO3(Vec3{slope[0], slope[1], slope[2]}) * transpose(E0);
}

std::array<double, 3> BeamCorotational::sensorValue(const std::string& var, double s, const double* q,
                                                    const double* disp, const double* rates,
                                                    const double* lambda) const {
  const Vec3 xp = load3(q), xq = load3(q + 12);
  const double L = norm(xq - xp);
  auto out = [](const Vec3& v) { return std::array<double, 3>{v[0], v[1], v[2]}; };
  if (var == "ForceLocal" || var == "TorqueLocal") {
    const std::array<double, 6> sig = generalizedStresses(q, lambda, disp);
    // e3..e6 (beam_corotational.hpp) and the arc-minus-chord term's Qe_i = d(1/2 e^T Qh e)/de_i
    const Vec3 lhat = (1.0 / L) * (xq - xp);
    const Mat3 Rp = load9(q + 3), Rq = load9(q + 15);
    const double l = l0_, inv30 = 1.0 / (30.0 * l);
    const double e[6] = {0, 0, -l * dot(Rp * ez0_, lhat), l * dot(Rq * ez0_, lhat), l * dot(Rp * ey0_, lhat),
                         -l * dot(Rq * ey0_, lhat)};
    double M[6] = {};
    for (int i = 2; i < 6; ++i) {
      const int pr = (i - 2) / 2, a = (i - 2) % 2, first = 2 + 2 * pr;
      const double Qe = Qh_[4 * pr + 2 * a] * e[first] + Qh_[4 * pr + 2 * a + 1] * e[first + 1];
      M[i] = l * (sig[i] + sig[0] * Qe * inv30);
    }
    if (var == "ForceLocal") return {sig[0], -(M[5] - M[4]) / L, (M[3] - M[2]) / L};
    return {l * sig[1], (1 - s) * M[2] + s * M[3], (1 - s) * M[4] + s * M[5]};
  }
  if (var == "Velocity" || var == "AngularVelocity") {
    // d/dt of the field along the nodal rates: the state moves on x + tau v, exp(tau w) R; the
    // section's offset from the chord and its rotation relative to the nearer node (both small)
    // are differenced centrally, so the nodal rates carry over exactly and the difference only
    // acts on the deformation inside the element (tau r = 1e-5: truncation ~1e-10, round-off ~1e-11)
    if (!rates) return {0, 0, 0};
    const Vec3 vp = load3(rates), wp = load3(rates + 3), vq = load3(rates + 6), wq = load3(rates + 9);
    const double r = std::max({norm(vp) / L, norm(vq) / L, norm(wp), norm(wq)});
    if (!(r > 0.0)) return {0, 0, 0};
    const double h = 1e-5 / r;
    const int near = s <= 0.5 ? 0 : 1;
    Vec3 off[2];
    Mat3 D[2];
    for (int side = 0; side < 2; ++side) {
      const double tau = side == 0 ? h : -h;
      double qt[24];
      Mat3 Rn;
      for (int node = 0; node < 2; ++node) {
        const Vec3 x = load3(q + 12 * node) + tau * load3(rates + 6 * node);
        const Mat3 Rt = expSO3(tau * load3(rates + 6 * node + 3)) * load9(q + 12 * node + 3);
        for (int k = 0; k < 3; ++k) qt[12 * node + k] = x[k];
        for (int k = 0; k < 9; ++k) qt[12 * node + 3 + k] = Rt[k];
        if (node == near) Rn = Rt;
      }
      Mat3 R;
      sectionField(qt, s, off[side], R);
      D[side] = transpose(Rn) * R;  // R = R_near D
    }
    if (var == "Velocity") return out(vp + s * (vq - vp) + (0.5 / h) * (off[0] - off[1]));
    // R = R_n D: w = w_n + R_n vee(Ddot D^T)
    const Mat3 Rn0 = load9(q + 12 * near + 3);
    return out((near == 0 ? wp : wq) + Rn0 * ((0.5 / h) * logSO3(D[0] * transpose(D[1]))));
  }
  Vec3 off;
  Mat3 R;
  sectionField(q, s, off, R);
  if (var == "Position") return out(xp + s * (xq - xp) + off);
  if (var == "Displacement") {
    const Vec3 up = disp ? load3(disp) : Vec3{}, uq = disp ? load3(disp + 3) : Vec3{};
    return out(up + s * (uq - up) + off);
  }
  if (var == "Rotation") return out(logSO3(R));
  throw std::invalid_argument("beam sensors: unknown variable '" + var + "'");
}

}  // namespace sinew
