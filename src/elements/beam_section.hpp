// Cross-section constants of a SPACAR Light beam set (eprops: cshape, dim, emod, smod, dens, cw).
// Local axes: x along the beam, y = orien direction (rect: width w), z = x cross y (rect: thickness t).
#pragma once
#include "sinew/element_properties.hpp"
#include "sinew/model.hpp"

namespace sinew {

struct BeamSection {
  CrossSection shape = CrossSection::None;
  double w = 0, t = 0, d = 0;  ///< rect width (y) and thickness (z); circ diameter
  double A = 0;                ///< area
  double Iy = 0, Iz = 0;       ///< second moments: Iy about local y (deflection along z), Iz about z
  double Ip = 0;               ///< polar moment Iy + Iz (rotary inertia in torsion)
  double It = 0;               ///< Saint-Venant torsion constant (reference B6 for rect)
  double kappa = 0;            ///< Timoshenko shear coefficient, Cowper's from nu (0 without smod)
  double Asy = 0, Asz = 0;     ///< shear areas kappa A for shear along y and z
  double E = 0, G = 0, nu = 0, rho = 0;
  double cwFactor = 1.0;       ///< constrained-warping factor (reference B5), 1 without cw
  double EA = 0, GIt = 0, EIy = 0, EIz = 0;  ///< GIt includes cwFactor
  double kGAy = 0, kGAz = 0;   ///< shear stiffnesses; 0 when G is unknown (Euler-Bernoulli)
  double rhoA = 0;             ///< mass per length
  double rhoIy = 0, rhoIz = 0, rhoIp = 0;  ///< rotary inertias per length
  double ymax = 0, zmax = 0;   ///< extreme fibre distances (circ: both d/2)
  double torsionStressFactor = 0;  ///< tau_max = torsionStressFactor * T (rect T t_min/It, circ T d/(2 It))
  bool stressRecovery = true;      ///< false: no Von Mises stress (rigid elements without opt.rigidstress)
};

/// Rect torsion constant of reference B6 for sides s1, s2 (any order), series summed to convergence.
double rectTorsionConstant(double s1, double s2);
/// Cowper's shear coefficient (J. Appl. Mech. 33, 1966) as SPACAR Light uses it, nu = E/(2G) - 1:
/// rect 10(1+nu)/(12+11nu), circ 6(1+nu)/(7+6nu).
double cowperShearCoefficient(CrossSection shape, double nu);
/// Constrained-warping factor of reference B5: a c / (a c - 2 tanh(a c / 2)), a = L / w, c = sqrt(24/(1+nu)).
double constrainedWarpingFactor(double L, double w, double nu);

/// Section of a beam set's properties; flexureLength = scene element length L (used by cw).
/// Throws SceneError when a quantity needed by the set (flexible modes, mass) is missing or <= 0.
BeamSection beamSection(const BeamProperties& set, double flexureLength);

/// True for a rect section with flexible torsion (mode 2) without cw whose L / w < 3 (warping
/// restraint matters).
bool beamNeedsWarpingWarning(const BeamProperties& set, double L);

}  // namespace sinew
