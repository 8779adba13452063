#include "app/phases/model_checks.hpp"

#include <cmath>
#include <filesystem>

#include "analysis/constraint_check.hpp"
#include "analysis/formfinding_analysis.hpp"
#include "app/summary.hpp"
#include "elements/element_kinds.hpp"

namespace sinew {
namespace {

/// Prints a singular model's message, removes a stale result file under this name (it does not belong
/// to this scene) and sets exit code 2.
PetscErrorCode reportSingularModel(MPI_Comm comm, int rank, const std::string& message, const std::string& h5, int* exitCode) {
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "%s", message.c_str()));
  if (rank == 0) {
    std::error_code ec;
    std::filesystem::remove(h5, ec);
    std::filesystem::remove(h5 + ".part", ec);
  }
  *exitCode = 2;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// Residual and tangent at the reference state (load factor 0) are finite (collective; the tangent's
/// Frobenius norm, so entries above ~1e154, whose products overflow in a factorization, count as
/// non-finite). A non-finite one (a user function dividing by zero, a property overflowing) is no mechanism: the analysis fails
/// on it (exit 3) with its own message on every rank count, where the constraint check would call the
/// model singular on some (MUMPS refuses to factor a tangent with Inf/NaN, PETSc's serial LU does not).
/// A force law that is not finite here (at t = 0) is named in *law (the analysis starts at t > 0 and
/// fails on it there if it stays non-finite). *J: that tangent (the caller destroys it).
PetscErrorCode finiteAtReference(Assembler& assembler, bool* finite, std::string* law, Mat* J) {
  PetscFunctionBeginUser;
  assembler.setNonFiniteLawsFatal(false);
  Vec U0, F;
  PetscCall(assembler.createVector(&U0));
  PetscCall(VecDuplicate(U0, &F));
  PetscCall(VecSet(U0, 0.0));
  PetscCall(assembler.residual(U0, LoadState{}, F));
  PetscReal fn = 0, jn = 0;
  PetscCall(VecNorm(F, NORM_2, &fn));
  PetscCall(assembler.createMatrix(J));
  PetscCall(assembler.jacobian(U0, LoadState{}, *J));
  PetscCall(MatNorm(*J, NORM_FROBENIUS, &jn));
  *law = assembler.nonFiniteLaw();
  assembler.setNonFiniteLawsFatal(true);
  *finite = std::isfinite(fn) && std::isfinite(jn) && law->empty();
  PetscCall(VecDestroy(&F));
  PetscCall(VecDestroy(&U0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

void checkContinuationControl(const Model& model, const DistributedMesh& mesh) {
  if (!model.opt.continuation || model.opt.continuation->node < 0) return;
  const ContinuationOptions& c = *model.opt.continuation;
  // per owned FE node of the scene node: 1 free translation, 2 supported/prescribed
  int status[2] = {0, 0};
  for (int i = 0; i < mesh.numOwnedNodes; ++i) {
    const LocalNode& n = mesh.nodes[static_cast<size_t>(i)];
    if (n.sceneNode != c.node) continue;
    status[n.dof[static_cast<size_t>(c.direction)] >= 0 ? 0 : 1] = 1;
  }
  MPI_Allreduce(MPI_IN_PLACE, status, 2, MPI_INT, MPI_MAX, mesh.comm);
  if (status[0]) return;
  const std::string node = "node " + std::to_string(c.node + 1), axis(1, static_cast<char>('x' + c.direction));
  const std::string uses = c.method == "displacement" ? "displacement control"
                           : c.stop_displacement     ? "stop_displacement"
                                                     : "the followed displacement (/path/control_displacement)";
  if (status[1])
    throw SceneError("opt.continuation.node",
                     "the " + axis + " translation of " + node + " (opt.continuation.direction: " + axis +
                         ") is supported or prescribed (nprops " + std::to_string(c.node + 1) + ": fix, fix_pos, fix_" + axis +
                         " or displ_" + axis + "); " + uses + " follows a free translation: choose another node or direction");
  throw SceneError("opt.continuation.node", node + " is not connected to any element (it has no unknowns); " + uses +
                                                " follows a free translation of a node of the model");
}

/// No external load of any kind: no gravity, massProportionalLoad or pressure (a zero vector, gravity
/// [0, 0], is none), and zero nodal loads and prescribed motions on every node (collective).
bool unloaded(const Model& model, const DistributedMesh& mesh, const Assembler& assembler) {
  int loaded = (model.opt.gravity.has_value() && norm(*model.opt.gravity) > 0.0) || assembler.hasPressure();
  for (const ElementSet& s : model.eprops) loaded |= elementKind(s.type()).bodyLoaded(s);
  for (const LocalNode& n : mesh.nodes) {
    for (int k = 0; k < 6; ++k)
      loaded |= n.load[k] != 0.0 || n.loadInitial[k] != 0.0 || n.prescribed[k] != 0.0 || n.prescribedInitial[k] != 0.0;
    for (int k = 0; k < 3; ++k) loaded |= n.rot[k] != 0.0 || n.rotInitial[k] != 0.0;
    loaded |= n.timeFn != nullptr;  // a function of time may vanish at t = 0
  }
  MPI_Allreduce(MPI_IN_PLACE, &loaded, 1, MPI_INT, MPI_LOR, mesh.comm);
  return !loaded;
}

/// Anything acting at load factor 0 (SPACAR Light's step 1): initial loads, pressures and prescribed
/// motions, cable and membrane prestress, ANCF reference strains/curvatures and force laws, a
/// form-found start state. Without any, step 1 is the start state itself and needs no solve.
bool initiallyLoaded(const Model& model, const DistributedMesh& mesh) {
  int loaded = model.formfinding.has_value();
  for (const ElementSet& s : model.eprops) loaded |= elementKind(s.type()).initiallyLoaded(s);
  for (const LocalNode& n : mesh.nodes) {
    for (int k = 0; k < 6; ++k) loaded |= n.loadInitial[k] != 0.0 || n.prescribedInitial[k] != 0.0;
    for (int k = 0; k < 3; ++k) loaded |= n.rotInitial[k] != 0.0;
  }
  MPI_Allreduce(MPI_IN_PLACE, &loaded, 1, MPI_INT, MPI_LOR, mesh.comm);
  return loaded;
}

/// Mechanisms and redundant constraints before any analysis (and before the result file exists):
/// with form finding the form-finding problem (its kernels in the mode of step 1, prestress-only
/// stiffness of the form-found elements), otherwise the statics tangent at the reference state.
/// A singular model prints its message and sets *exitCode = 2.
PetscErrorCode checkModelBeforeRun(const Model& model, const Plan& plan, Assembler& assembler, const std::string& h5,
                                   const ModelCheckSettings& settings, int denseMaxUnknowns,
                                   ConstraintCheckSetting* setting, Timings* times, int* exitCode) {
  PetscFunctionBeginUser;
  const DistributedMesh& dmesh = assembler.mesh();
  MPI_Comm comm = dmesh.comm;
  bool checkModel = settings.enabled;
  // The check factors the tangent once (MUMPS): above this size it would cost as much memory as a
  // direct solve, so large models (often solved iteratively) skip it up front; a failing linear
  // solve still triggers it as a diagnostic.
  const long checkMax = settings.maxUnknowns;
  if (checkModel && dmesh.numGlobalUnknowns > checkMax) {
    checkModel = false;
    if (!model.opt.silent)
      PetscCall(PetscPrintf(comm, "  note: constraint check skipped (%ld unknowns > -constraint_check_max_unknowns %ld)\n",
                            dmesh.numGlobalUnknowns, checkMax));
  }
  setting->enabled = checkModel;
  const bool formfinding = plan.formfinding && model.formfinding.has_value();
  if (!checkModel || model.opt.showinputonly || !(plan.statics || formfinding)) PetscFunctionReturn(PETSC_SUCCESS);
  const double tCheck = MPI_Wtime();
  bool finite = true;
  std::string law;
  Mat J0;  // the tangent at the reference state, checked below
  PetscCall(finiteAtReference(assembler, &finite, &law, &J0));
  if (!finite) {
    PetscCall(MatDestroy(&J0));
    times->check = MPI_Wtime() - tCheck;
    if (law.rfind("error: ", 0) == 0) law = law.substr(7);
    if (!model.opt.silent)
      PetscCall(PetscPrintf(comm, "  note: constraint check skipped: the residual or tangent at the reference state is not finite (%s)\n",
                            law.empty() ? "Inf/NaN, or tangent entries above 1e154" : law.c_str()));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  ConstraintReport check;
  PetscCall(PetscLogEventBegin(SinewEvents::get().constraintCheck, 0, 0, 0, 0));
  if (formfinding) {
    PetscCall(checkFormFindingConstraints(assembler, model, settings, denseMaxUnknowns, &check));
    if (check.singular)
      check.message += "  (found in the form-finding problem: the form-found cables and membranes carry their prestress "
                       "only, as geometric stiffness; every other element is elastic)\n";
  } else {
    Vec U0;
    PetscCall(assembler.createVector(&U0));
    PetscCall(VecSet(U0, 0.0));
    PetscCall(checkConstraints(assembler, model, U0, LoadState{}, settings, denseMaxUnknowns, &check, J0));
    PetscCall(VecDestroy(&U0));
  }
  PetscCall(MatDestroy(&J0));
  PetscCall(PetscLogEventEnd(SinewEvents::get().constraintCheck, 0, 0, 0, 0));
  times->check = MPI_Wtime() - tCheck;
  // Rigid-body modes without any load are legitimate for a frequency analysis (a free-free body:
  // the unloaded reference state is the equilibrium; the modal shift handles the singular K).
  if (!formfinding && check.singular && check.redundant == 0 && plan.frequencies && unloaded(model, dmesh, assembler)) {
    check.singular = false;
    if (!model.opt.silent)
      PetscCall(PetscPrintf(comm, "  note: free motions with zero stiffness (rigid-body modes) and no loads: the frequency "
                                  "analysis runs about the unloaded reference state\n"));
  }
  if (check.singular) PetscCall(reportSingularModel(comm, dmesh.rank, check.message, h5, exitCode));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// After form finding and the elastic restart, before a load analysis with loads: the loaded model's
/// tangent at the restart state (elastic kernels, the found shape, load factor 0; e.g. a flat membrane
/// without prestress after a DISPLACEMENT restart has no stiffness across its surface). A singular one
/// fails ctx.status and sets *modelError (exit 2; the result file keeps the form-finding steps). Without any
/// load the found shape is the equilibrium and the load analysis ends at once, mechanism or not.
PetscErrorCode checkLoadedModelAfterFormFinding(RunContext& ctx, const ConstraintCheckSetting& setting, bool* modelError) {
  PetscFunctionBeginUser;
  if (!setting.enabled || !ctx.plan.statics || !ctx.status.converged()) PetscFunctionReturn(PETSC_SUCCESS);
  if (unloaded(ctx.model, ctx.assembler.mesh(), ctx.assembler)) PetscFunctionReturn(PETSC_SUCCESS);
  ConstraintReport check;
  const double tCheck = MPI_Wtime();
  PetscCall(PetscLogEventBegin(SinewEvents::get().constraintCheck, 0, 0, 0, 0));
  PetscCall(checkConstraints(ctx.assembler, ctx.model, ctx.U, LoadState{}, ctx.settings.check,
                             ctx.settings.statics.denseMaxUnknowns, &check));
  PetscCall(PetscLogEventEnd(SinewEvents::get().constraintCheck, 0, 0, 0, 0));
  ctx.times.check += MPI_Wtime() - tCheck;
  if (!check.singular) PetscFunctionReturn(PETSC_SUCCESS);
  ctx.status.fail("the load analysis after form finding cannot start (elastic_restart_method " +
           ctx.model.formfinding->elastic_restart_method + ", found shape):\n" + check.message +
           "  (a restart without prestress leaves flat or straight parts of the found shape without stiffness "
           "across them; elastic_restart_method FORCE keeps the prestress)\n");
  *modelError = true;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
