// Accepted magnitudes of scene numbers (docs/scene.md, "Value bounds").
// Every number of a scene is finite, and either 0 (where the field allows it) or of magnitude in
// [min, max]. The bounds keep every product formed in assembly (E*A/L, E*I/L^3, rho*A*L, squared
// coordinates, EA/EI) far inside the range of a double, and are wide enough for SI units and for
// kN/mm/t style units alike.
#pragma once

namespace sinew::scene {

struct Magnitude {
  double min;        ///< smallest accepted nonzero |v|
  double max;        ///< largest accepted |v|
  const char* what;  ///< kind of value, for messages ("a modulus", "a coordinate", ...)
};

/// Any scene number (the default of every numeric field).
inline constexpr Magnitude kAnyNumber{1e-30, 1e20, "a number"};
/// Node coordinates, prescribed displacements, sensor positions.
inline constexpr Magnitude kCoordinate{1e-30, 1e8, "a coordinate"};
/// Young's and shear moduli, densities, stiffnesses EA/EI, masses, mass per length, damping.
inline constexpr Magnitude kMaterial{1e-20, 1e20, "a material or section value"};
/// Cross-section dimensions and membrane thickness.
inline constexpr Magnitude kSectionLength{1e-10, 1e8, "a cross-section length"};
/// Cross-section area of a cable.
inline constexpr Magnitude kArea{1e-20, 1e16, "an area"};
/// Forces, moments, pressures, prestresses, gravity, mass-proportional loads.
inline constexpr Magnitude kLoad{1e-30, 1e20, "a load"};
/// Nodal moments of inertia (off-diagonal entries may be round-off small).
inline constexpr Magnitude kInertia{1e-30, 1e20, "a moment of inertia"};
/// Prescribed rotations (axis * angle, radians).
inline constexpr Magnitude kRotation{1e-30, 1e6, "a rotation"};
/// Reference strain and other dimensionless values (damping ratio, form-finding factors).
inline constexpr Magnitude kRatio{1e-30, 1e6, "a dimensionless value"};
/// Reference curvature (1/length).
inline constexpr Magnitude kCurvature{1e-30, 1e12, "a curvature"};
/// End time and time step of dynamics.
inline constexpr Magnitude kTime{1e-12, 1e12, "a time"};

/// Shortest scene element, absolute (length units) and relative to the model size.
inline constexpr double kMinElementLength = 1e-9;
inline constexpr double kMinElementLengthRelative = 1e-12;
/// Most time steps of dynamics (tend / dt) and elements after nbeams splitting.
inline constexpr double kMaxTimeSteps = 1e9;
inline constexpr double kMaxSplitElements = 1e8;

}  // namespace sinew::scene
