#include "elements/beam_section.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace sinew {

// B6: I_t = (1/3)(2a)^3 (2b) [1 - (192/pi^5)(a/b) sum_{n odd} tanh(n pi b / 2a) / n^5], a <= b.
// The sum as sum_{n odd} 1/n^5 = (31/32) zeta(5) less sum_{n odd} (1 - tanh(n c)) / n^5, c = pi b / 2a
// >= pi/2: 1 - tanh(n c) = 2 / (exp(2 n c) + 1) falls by exp(-pi) per odd n, so a few terms reach
// round-off (the plain series needs about a thousand).
double rectTorsionConstant(double s1, double s2) {
  const double a = 0.5 * std::min(s1, s2), b = 0.5 * std::max(s1, s2);
  const double pi = std::numbers::pi;
  const double zeta5 = 1.0369277551433699263;
  const double c = pi * b / (2.0 * a);
  double tail = 0.0;
  for (int n = 1; n < 200; n += 2) {
    const double n5 = static_cast<double>(n) * n * n * n * n;
    const double term = 2.0 / (std::exp(2.0 * n * c) + 1.0) / n5;
    tail += term;
    if (term < 1e-18) break;
  }
  const double sum = 31.0 / 32.0 * zeta5 - tail;
  return (1.0 / 3.0) * std::pow(2.0 * a, 3) * (2.0 * b) * (1.0 - 192.0 / std::pow(pi, 5) * (a / b) * sum);
}

// Cowper (1966), J. Appl. Mech. 33, 335-340, as SPACAR Light: rect 10(1+nu)/(12+11nu), circ 6(1+nu)/(7+6nu).
double cowperShearCoefficient(CrossSection shape, double nu) {
  if (shape == CrossSection::Rect) return 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu);
  if (shape == CrossSection::Circ) return 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);
  return 0.0;
}

// B5: factor = a c / (a c - 2 tanh(a c / 2)).
double constrainedWarpingFactor(double L, double w, double nu) {
  const double a = L / w, c = std::sqrt(24.0 / (1.0 + nu));
  const double ac = a * c;
  return ac / (ac - 2.0 * std::tanh(0.5 * ac));
}

namespace {
bool anyFlexible(const BeamProperties& set) {
  return std::any_of(set.flex.begin(), set.flex.end(), [](bool b) { return b; });
}
void requirePositive(double v, const char* field, const std::string& why) {
  if (!(v > 0.0)) {
    std::ostringstream m;
    m << "must be given and > 0 " << why << " (got " << v << ")";
    throw SceneError(std::string("eprops.") + field, m.str());
  }
}
}  // namespace

BeamSection beamSection(const BeamProperties& set, double flexureLength) {
  BeamSection s;
  const bool flexible = anyFlexible(set);
  const bool massive = set.dens > 0.0;
  if (set.dens < 0.0) throw SceneError("eprops.dens", "density must be >= 0");
  if (!flexible && !massive) return s;  // rigid massless beam: nothing needed
  const std::string why = flexible ? "for a beam set with flexible modes" : "for a beam set with density";
  s.shape = set.cshape;
  if (s.shape == CrossSection::Rect) {
    if (set.dim.size() != 2) throw SceneError("eprops.dim", "cshape rect needs dim: [width, thickness]");
    s.w = set.dim[0];
    s.t = set.dim[1];
    requirePositive(s.w, "dim", "(rect width)");
    requirePositive(s.t, "dim", "(rect thickness)");
    s.A = s.w * s.t;
    s.Iy = s.w * s.t * s.t * s.t / 12.0;
    s.Iz = s.t * s.w * s.w * s.w / 12.0;
    s.It = rectTorsionConstant(s.w, s.t);
    s.ymax = 0.5 * s.w;
    s.zmax = 0.5 * s.t;
    s.torsionStressFactor = std::min(s.w, s.t) / s.It;
  } else if (s.shape == CrossSection::Circ) {
    if (set.dim.size() != 1) throw SceneError("eprops.dim", "cshape circ needs dim: [diameter]");
    s.d = set.dim[0];
    requirePositive(s.d, "dim", "(circ diameter)");
    const double pi = std::numbers::pi;
    s.A = pi * s.d * s.d / 4.0;
    s.Iy = s.Iz = pi * std::pow(s.d, 4) / 64.0;
    s.It = pi * std::pow(s.d, 4) / 32.0;
    s.ymax = s.zmax = 0.5 * s.d;
    s.torsionStressFactor = s.d / (2.0 * s.It);
  } else {
    throw SceneError("eprops.cshape", "cshape (rect or circ) is required " + why);
  }
  s.Ip = s.Iy + s.Iz;
  s.rho = set.dens;
  s.rhoA = s.rho * s.A;
  s.rhoIy = s.rho * s.Iy;
  s.rhoIz = s.rho * s.Iz;
  s.rhoIp = s.rho * s.Ip;
  if (flexible) {
    // the same rule as the scene check (src/scene/eprops.cpp): E for elongation and bending (and
    // cw), G for torsion and the shear deformation of bending
    const auto& f = set.flex;
    const bool bending = f[2] || f[3] || f[4] || f[5];
    if (f[0] || bending || set.cw) requirePositive(set.emod, "emod", why);
    if (f[1] || bending) requirePositive(set.smod, "smod", why);
    s.E = set.emod;
    s.G = set.smod;
    s.nu = s.E > 0.0 && s.G > 0.0 ? s.E / (2.0 * s.G) - 1.0 : 0.0;
    if (!(s.nu > -1.0)) throw SceneError("eprops.smod", "emod/(2 smod) - 1 (Poisson's ratio of the shear coefficient) must be > -1");
    s.kappa = cowperShearCoefficient(s.shape, s.nu);
    s.Asy = s.Asz = s.kappa * s.A;
    s.EA = s.E * s.A;
    s.EIy = s.E * s.Iy;
    s.EIz = s.E * s.Iz;
    s.kGAy = s.G * s.Asy;
    s.kGAz = s.G * s.Asz;
    if (set.cw) {
      if (s.shape != CrossSection::Rect)
        throw SceneError("eprops.cw", "constrained warping (cw) applies to rect sections only");
      requirePositive(flexureLength, "cw", "(element length for the constrained-warping factor)");
      if (!(s.nu > -1.0)) throw SceneError("eprops.smod", "emod/(2 smod) - 1 must be > -1 for cw");
      s.cwFactor = constrainedWarpingFactor(flexureLength, s.w, s.nu);
    }
    s.GIt = s.G * s.It * s.cwFactor;
  }
  return s;
}

bool beamNeedsWarpingWarning(const BeamProperties& set, double L) {
  // only where torsion (deformation mode 2) is flexible: cw changes nothing else
  return set.cshape == CrossSection::Rect && !set.cw && set.flex[1] &&
         set.dim.size() == 2 && set.dim[0] > 0.0 && L / set.dim[0] < 3.0;
}

}  // namespace sinew
