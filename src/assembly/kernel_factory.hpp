// Chooses and constructs the element kernel of each FE element from the scene's property sets.
#pragma once
#include "mesh/distributed_mesh.hpp"
#include "settings/settings.hpp"

namespace sinew {

/// Kernel factory for a model: beams (flexible, released and rigid modes; elements in no set are
/// rigid and massless), cables, membranes and ANCF cables, with the loads of every eprops set.
/// beamMass: the beams' inertia (-beam_mass, DynamicsSettings::beamMass).
ElementKernels makeKernelFactory(const Model& model, BeamMass beamMass);

/// Stiffness scale used for the rows of rigid-mode constraints: the largest EA / L of the
/// flexible beams (1 when there are none), so multipliers are forces of the model's size.
double constraintScaleOf(const Model& model);

}  // namespace sinew
