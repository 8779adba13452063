// Checks of the model around the phases of a run: whether it is loaded at all (an unloaded model's
// start state is its equilibrium), whether anything acts at load factor 0, and the constraint check
// (mechanisms, redundant constraints) before the run and after form finding.
#pragma once
#include <petscsys.h>

#include <string>

#include "app/phases/run_context.hpp"
#include "app/plan.hpp"
#include "assembly/assembler.hpp"
#include "mesh/distributed_mesh.hpp"
#include "settings/settings.hpp"
#include "sinew/model.hpp"

namespace sinew {

struct Timings;

/// No external load of any kind: no gravity, massProportionalLoad or pressure (a zero vector, gravity
/// [0, 0], is none), and zero nodal loads and prescribed motions on every node (collective).
bool unloaded(const Model& model, const DistributedMesh& mesh, const Assembler& assembler);

/// Anything acting at load factor 0 (SPACAR Light's step 1): initial loads, pressures and prescribed
/// motions, cable and membrane prestress, ANCF reference strains/curvatures and force laws, a
/// form-found start state. Without any, step 1 is the start state itself and needs no solve.
bool initiallyLoaded(const Model& model, const DistributedMesh& mesh);

/// opt.continuation's control DOF (displacement control, stop_displacement, the followed displacement):
/// a free translation of a node with elements. Collective; throws SceneError (exit 2, before the
/// result file exists) naming the node (1-based) and the field on every rank.
void checkContinuationControl(const Model& model, const DistributedMesh& mesh);

/// -constraint_check (default true) and -constraint_check_max_unknowns: whether the model is checked.
struct ConstraintCheckSetting {
  bool enabled = true;
};

/// Mechanisms and redundant constraints before any analysis (and before the result file exists):
/// with form finding the form-finding problem (its kernels in the mode of step 1, prestress-only
/// stiffness of the form-found elements), otherwise the statics tangent at the reference state.
/// A singular model prints its message and sets *exitCode = 2. denseMaxUnknowns: -dense_max_unknowns.
PetscErrorCode checkModelBeforeRun(const Model& model, const Plan& plan, Assembler& assembler, const std::string& h5,
                                   const ModelCheckSettings& settings, int denseMaxUnknowns,
                                   ConstraintCheckSetting* setting, Timings* times, int* exitCode);

/// After form finding and the elastic restart, before a load analysis with loads: the loaded model's
/// tangent at the restart state. A singular one fails ctx.status and sets *modelError (exit 2).
PetscErrorCode checkLoadedModelAfterFormFinding(RunContext& ctx, const ConstraintCheckSetting& setting, bool* modelError);

}  // namespace sinew
