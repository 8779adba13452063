// Beam cross-section constants (beam_section.hpp) against references B5, B6 and closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "elements/beam_section.hpp"

using namespace sinew;

namespace {
BeamProperties rectSet(double w, double t) {
  BeamProperties s;
  s.flex = {true, true, true, true, true, true};
  s.emod = 210e9;
  s.smod = 80e9;
  s.dens = 7800;
  s.cshape = CrossSection::Rect;
  s.dim = {w, t};
  return s;
}
}  // namespace

TEST(BeamSection, SquareTorsionConstantB6) {
  // B6 with a = b: I_t = 0.140577015 side^4 (Timoshenko & Goodier: 0.1406 side^4 = 2.25 a^4)
  const double side = 0.02;
  const double It = rectTorsionConstant(side, side);
  EXPECT_NEAR(It / std::pow(side, 4), 0.14057701495515554, 1e-12);  // measured 1e-16 relative
  EXPECT_NEAR(It / std::pow(side, 4), 0.1406, 1e-4);
}

TEST(BeamSection, RectTorsionConstantTable) {
  // I_t = beta b t^3 (Roark table 10.7, beta to 3 digits: b/t = 2: 0.229, 4: 0.281, 10: 0.312)
  const double t = 0.001;
  EXPECT_NEAR(rectTorsionConstant(2 * t, t) / (2 * t * t * t * t), 0.229, 5e-4);
  EXPECT_NEAR(rectTorsionConstant(t, 4 * t) / (4 * t * t * t * t), 0.281, 5e-4);
  EXPECT_NEAR(rectTorsionConstant(10 * t, t) / (10 * t * t * t * t), 0.312, 5e-4);
  // thin strip limit: I_t -> b t^3 / 3 (1 - 0.630 t / b); b/t = 1000
  const double It = rectTorsionConstant(1.0, 1e-3);
  EXPECT_NEAR(It / (1.0 * 1e-9 / 3.0), 1.0 - 0.630182 * 1e-3, 1e-6);
}

TEST(BeamSection, RectConstants) {
  const double w = 0.05, t = 0.002;
  const BeamSection s = beamSection(rectSet(w, t), 0.1);
  EXPECT_DOUBLE_EQ(s.A, w * t);
  EXPECT_DOUBLE_EQ(s.Iy, w * t * t * t / 12);
  EXPECT_DOUBLE_EQ(s.Iz, t * w * w * w / 12);
  EXPECT_DOUBLE_EQ(s.It, rectTorsionConstant(w, t));
  EXPECT_DOUBLE_EQ(s.EA, 210e9 * w * t);
  EXPECT_DOUBLE_EQ(s.GIt, 80e9 * s.It);
  EXPECT_DOUBLE_EQ(s.kGAz, 80e9 * s.kappa * w * t);
  EXPECT_NEAR(s.nu, 210.0 / 160.0 - 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(s.rhoA, 7800 * w * t);
  EXPECT_DOUBLE_EQ(s.rhoIp, 7800 * (s.Iy + s.Iz));
  EXPECT_DOUBLE_EQ(s.zmax, t / 2);
  EXPECT_DOUBLE_EQ(s.ymax, w / 2);
  EXPECT_DOUBLE_EQ(s.torsionStressFactor, t / s.It);  // ~ 3 / (w t^2) for thin strips
  EXPECT_NEAR(s.torsionStressFactor * w * t * t / 3.0, 1.0, 0.03);
  EXPECT_EQ(s.cwFactor, 1.0);
}

// Issue 10 item 11: SPACAR Light's (Cowper's) coefficient, not 5/6 / 9/10.
TEST(BeamSection, CowperShearCoefficient) {
  const BeamSection s = beamSection(rectSet(0.05, 0.002), 0.1);  // E 210e9, G 80e9: nu = 0.3125
  EXPECT_NEAR(s.kappa, 10.0 * 1.3125 / (12.0 + 11.0 * 0.3125), 1e-15);
  EXPECT_NEAR(s.kappa, 0.850, 5e-4);  // the 0.850
  EXPECT_GT(std::abs(s.kappa - 5.0 / 6.0), 0.016);
  EXPECT_NEAR(cowperShearCoefficient(CrossSection::Rect, 0.0), 5.0 / 6.0, 1e-15);  // nu = 0: 5/6
  EXPECT_NEAR(cowperShearCoefficient(CrossSection::Circ, 0.0), 6.0 / 7.0, 1e-15);
  EXPECT_NEAR(cowperShearCoefficient(CrossSection::Circ, 0.3), 7.8 / 8.8, 1e-15);
}

TEST(BeamSection, CircConstants) {
  BeamProperties set = rectSet(0, 0);
  set.cshape = CrossSection::Circ;
  set.dim = {0.01};
  const BeamSection s = beamSection(set, 1.0);
  const double pi = std::numbers::pi, d = 0.01;
  EXPECT_DOUBLE_EQ(s.A, pi * d * d / 4);
  EXPECT_DOUBLE_EQ(s.Iy, pi * std::pow(d, 4) / 64);
  EXPECT_DOUBLE_EQ(s.It, pi * std::pow(d, 4) / 32);
  EXPECT_DOUBLE_EQ(s.kGAy, 80e9 * s.kappa * s.A);
  EXPECT_NEAR(s.kappa, 6.0 * 1.3125 / (7.0 + 6.0 * 0.3125), 1e-15);  // Cowper circ, nu = 0.3125: 0.8873
  // tau = T r / J
  EXPECT_DOUBLE_EQ(s.torsionStressFactor, (d / 2) / s.It);
}

TEST(BeamSection, ConstrainedWarpingFactorB5) {
  BeamProperties set = rectSet(0.05, 0.0002);
  set.cw = true;
  const double L = 0.1;
  const BeamSection s = beamSection(set, L);
  const double nu = 210.0 / 160.0 - 1.0;
  const double a = L / 0.05, c = std::sqrt(24.0 / (1.0 + nu));
  const double expected = a * c / (a * c - 2.0 * std::tanh(a * c / 2.0));
  EXPECT_NEAR(s.cwFactor, expected, 1e-14);
  EXPECT_GT(s.cwFactor, 1.1);  // a = 2: factor 1.2962
  EXPECT_NEAR(s.GIt, 80e9 * s.It * expected, 1e-12 * s.GIt);
  // long flexures: factor -> 1 + 2/(a c)
  EXPECT_NEAR(constrainedWarpingFactor(100.0, 1.0, 0.3), 1.0 / (1.0 - 2.0 / (100.0 * std::sqrt(24 / 1.3))), 1e-12);
}

TEST(BeamSection, WarpingWarning) {
  BeamProperties set = rectSet(0.05, 0.001);
  EXPECT_TRUE(beamNeedsWarpingWarning(set, 0.1));    // L/w = 2
  EXPECT_FALSE(beamNeedsWarpingWarning(set, 0.2));   // L/w = 4
  set.cw = true;
  EXPECT_FALSE(beamNeedsWarpingWarning(set, 0.1));
  set.cw = false;
  set.cshape = CrossSection::Circ;
  set.dim = {0.05};
  EXPECT_FALSE(beamNeedsWarpingWarning(set, 0.1));
}

TEST(BeamSection, MissingDataThrowsSceneError) {
  BeamProperties set = rectSet(0.05, 0.001);
  set.emod = 0;
  try {
    beamSection(set, 1.0);
    FAIL() << "expected SceneError";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.path(), "eprops.emod");
  }
  set = rectSet(0.05, 0.001);
  set.dim = {0.05};
  EXPECT_THROW(beamSection(set, 1.0), SceneError);
  set = rectSet(0.05, -1.0);
  EXPECT_THROW(beamSection(set, 1.0), SceneError);
  set = rectSet(0.05, 0.001);
  set.cshape = CrossSection::None;
  EXPECT_THROW(beamSection(set, 1.0), SceneError);
  set = rectSet(0.05, 0.001);
  set.smod = 0;
  EXPECT_THROW(beamSection(set, 1.0), SceneError);
  // a rigid massless set needs nothing
  BeamProperties rigid;
  EXPECT_NO_THROW(beamSection(rigid, 1.0));
  // rigid with density needs the section but not emod
  BeamProperties heavy;
  heavy.dens = 1000;
  heavy.cshape = CrossSection::Circ;
  heavy.dim = {0.01};
  EXPECT_NEAR(beamSection(heavy, 1.0).rhoA, 1000 * std::numbers::pi * 1e-4 / 4, 1e-15);
}
