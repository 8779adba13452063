// The properties of an eprops set, one struct per element kind (design.md section 2; field names as
// in the scene file). ElementSet (sinew/model.hpp) holds the fields common to every kind and one of
// these.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "sinew/linalg3.hpp"

namespace sinew {

enum class CrossSection { None, Rect, Circ };

/// type: beam (SPACAR Light).
struct BeamProperties {
  std::array<bool, 6> flex{};  ///< flexible deformation modes 1..6
  bool cw = false;
  double emod = 0, smod = 0, dens = 0;
  CrossSection cshape = CrossSection::None;
  std::vector<double> dim;    ///< rect: [width, height]; circ: [diameter]
  std::optional<Vec3> orien;  ///< local y axis of the section (rect: width direction)
};

/// type: cable (3D, tension only).
struct CableProperties {
  double area = 0, emod = 0, dens = 0;
  std::optional<double> prestress;         ///< force
  std::optional<double> prestress_stress;  ///< stress
};

/// type: membrane.
struct MembraneProperties {
  double thickness = 0, emod = 0, nu = 0, dens = 0;
  std::array<double, 3> prestress{};  ///< s11 s22 s12
  std::optional<Vec3> prestress_dir, prestress_radial_axis;
  double pressure = 0, pressure_initial = 0;  ///< follower surface pressure along the element normal (ramped / initial)
  std::string pressure_t;  ///< pressure as a function of time t (its text; empty: the number `pressure`)
};

/// type: ancf_cable2d (Exudyn names).
struct AncfCable2DProperties {
  double physicsMassPerLength = 0, physicsBendingStiffness = 0, physicsAxialStiffness = 0;
  double physicsBendingDamping = 0, physicsAxialDamping = 0;
  double physicsReferenceAxialStrain = 0, physicsReferenceCurvature = 0;
  double strainIsRelativeToReference = 0;
  int useReducedOrderIntegration = 0;
  std::string axialForceUserFunction, bendingMomentUserFunction;
  std::optional<Vec3> massProportionalLoad;
};

}  // namespace sinew
