#include "app/runner.hpp"

#include <petscsnes.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "analysis/constraint_check.hpp"
#include "analysis/continuation_analysis.hpp"
#include "analysis/formfinding_analysis.hpp"
#include "analysis/static_analysis.hpp"
#include "app/command_line.hpp"
#include "app/input_summary.hpp"
#include "app/interrupt.hpp"
#include "app/phases/model_checks.hpp"
#include "app/phases/restart.hpp"
#include "app/phases/run_context.hpp"
#include "app/plan.hpp"
#include "app/summary.hpp"
#include "assembly/assembler.hpp"
#include "assembly/kernel_factory.hpp"
#include "dynamics/dynamic_analysis.hpp"
#include "elements/element_kinds.hpp"
#include "mesh/distributed_mesh.hpp"
#include "mesh/fe_mesh.hpp"
#include "output/output_target.hpp"
#include "parallel/collective_error.hpp"
#include "scene/scene_reader.hpp"
#include "settings/read_settings.hpp"
#include "sinew/result_file.hpp"
#include "step/step_analysis.hpp"
#include "step/step_results.hpp"

namespace sinew {
namespace {

/// The result file: -o, else <opt.filename or scene stem>.h5. An -o without a value gives "".
std::string outputPath(const Model& model, const std::string& scenePath, const OutputSettings& output) {
  if (output.file) return *output.file;
  const std::string stem = model.opt.filename.empty() ? std::filesystem::path(scenePath).stem().string() : model.opt.filename;
  return stem + ".h5";
}

void warnings(MPI_Comm comm, const Model& model) {
  for (const std::string& w : model.warnings) PetscPrintf(comm, "warning: %s\n", w.c_str());
  if (model.formfinding) {  // form-found sets without prestress (issue 10 item 17)
    for (const int set : formFoundSets(*model.formfinding, model.eprops)) {
      const ElementSet& s = model.eprops[static_cast<size_t>(set)];
      const ElementKind& kind = elementKind(s.type());
      const char* fields = kind.missingPrestress ? kind.missingPrestress(s) : nullptr;
      if (fields)
        PetscPrintf(comm,
                    "warning: eprops[%zu] (%s set %zu) is form-found with zero prestress (%s): it carries no force and "
                    "gives no stiffness in form finding\n",
                    static_cast<size_t>(set), elementTypeName(s.type()), static_cast<size_t>(set) + 1, fields);
    }
  }
  if (model.nodes.size() > model.connectedNodes) {
    const std::size_t first = model.connectedNodes + 1, last = model.nodes.size();
    PetscPrintf(comm,
                "warning: node%s %zu%s%s %s not connected to any element (trailing nodes, allowed as in SPACAR Light): "
                "held fixed at %s input position%s, no unknowns\n",
                first == last ? "" : "s", first, first == last ? "" : "..", first == last ? "" : std::to_string(last).c_str(),
                first == last ? "is" : "are", first == last ? "its" : "their", first == last ? "" : "s");
  }
  // the kinds' own warnings about their sets (beams: rect without orien, L/w < 3 without cw)
  for (size_t set = 0; set < model.eprops.size(); ++set) {
    const ElementKind& kind = elementKind(model.eprops[set].type());
    if (!kind.warnings) continue;
    for (const std::string& w : kind.warnings(model, set)) PetscPrintf(comm, "warning: %s\n", w.c_str());
  }
  if (model.opt.customvis)
    PetscPrintf(comm, "note: opt.customvis (SPACAR Light's custom visualization) is accepted but not drawn by Sinew; "
                      "the XDMF file beside the result file shows the mesh (eprops color, opacity, hide)\n");
}

/// SPACAR Light's element look (eprops color, opacity, hide) per visualization cell, in the order of
/// StepResults::fillLayout, when any set gives one: /mesh/<kind>_color, _opacity, _visible and the
/// XDMF cell attributes, drawn by scripts/plot_input.py and plot_results.py. Cells without a colour
/// are blue (the first colour of the seed's table), rigid elements (in no set) grey.
void fillLook(const Model& model, const DistributedMesh& mesh, ResultLayout& layout) {
  for (const ElementSet& s : model.eprops) layout.look |= s.color.has_value() || s.opacity != 1.0 || s.hide;
  if (!layout.look) return;
  const std::array<double, 3> blue{0.0, 0.447, 0.741}, grey{198 / 255.0, 198 / 255.0, 198 / 255.0};  // the seed's grey
  for (const LocalElement& el : mesh.elements) {
    auto& look = el.numNodes == 2 ? layout.lineLook : (el.numNodes == 3 ? layout.triangleLook : layout.quadLook);
    const ElementSet* s = el.set >= 0 ? &model.eprops[static_cast<std::size_t>(el.set)] : nullptr;
    const std::array<double, 3> c = s ? s->color.value_or(blue) : grey;
    look.insert(look.end(), {c[0], c[1], c[2], s ? s->opacity : 1.0, s && s->hide ? 0.0 : 1.0});
  }
}

PetscErrorCode runScene(int argc, char** argv, int* exitCode) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PETSC_COMM_WORLD;
  *exitCode = 0;
  PetscBool help = PETSC_FALSE;
  PetscCall(petscHelpRequested(&help));
  if (argc < 2 || argv[1][0] == '-') {
    if (!help) {
      PetscCall(PetscPrintf(comm, "usage: sinew scene.yaml [-o result.h5] [options]; sinew -help lists the options\n"));
      *exitCode = 2;
    }
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  const std::string scenePath = argv[1];
  // every flag's setting, read once (the command line was checked by handleCommandLine)
  Settings settings;
  PetscCall(readSettings(nullptr, &settings));
  Timings times;
  double t0 = MPI_Wtime();

  // ---- scene -> model -> distributed mesh (scene errors: rank 0 prints, everyone exits 2)
  Model model;
  std::unique_ptr<DistributedMesh> dmesh;
  Plan plan;
  std::string setupError;
  std::string fingerprint;  // of the scene, stored with every checkpoint (app/phases/restart.hpp)
  PetscCall(PetscLogEventBegin(SinewEvents::get().setup, 0, 0, 0, 0));
  try {
    model = readScene(scenePath, sceneOverrides(settings));
    plan = makePlan(model);
    const FeMesh fe = discretize(model);
    dmesh = std::make_unique<DistributedMesh>(
        distributeMesh(comm, model, fe, makeKernelFactory(model, settings.dynamics.beamMass)));
    checkContinuationControl(model, *dmesh);  // collective, after the collective distribution
    // nfreq: all asks SLEPc for every eigenpair: a dense-sized problem, bounded to small models
    constexpr long kAllFrequenciesMax = 2000;
    if (plan.frequencies && model.opt.nfreq == Options::kAllFrequencies && dmesh->numGlobalUnknowns > kAllFrequenciesMax)
      throw SceneError("opt.nfreq", "all frequencies of a model with " + std::to_string(dmesh->numGlobalUnknowns) +
                                        " unknowns (all is for models up to " + std::to_string(kAllFrequenciesMax) +
                                        " unknowns): give the number of frequencies wanted");
    if (plan.dynamics) DynamicAnalysis::checkScheme(*dmesh, settings.dynamics.scheme);
    if (plan.dynamics && model.opt.dynamics)
      DynamicAnalysis::checkStepControl(*dmesh, *model.opt.dynamics, settings.dynamics);
    fingerprint = sceneFingerprint(model, static_cast<long>(fe.X.size()), static_cast<long>(fe.elements.size()));
  } catch (const SceneError& ex) {
    setupError = std::string("error: ") + ex.what();
    *exitCode = 2;
  } catch (const std::exception& ex) {
    setupError = std::string("error: ") + ex.what();
    *exitCode = 1;
  }
  // every rank ends with the message and exit code of the lowest failing rank
  if (const RunFailure f = agreeOnFailure(comm, RunFailure{*exitCode, setupError})) {
    PetscCall(PetscPrintf(comm, "%s\n", f.message.c_str()));
    *exitCode = f.exitCode;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscLogEventEnd(SinewEvents::get().setup, 0, 0, 0, 0));
  if (!model.opt.silent) warnings(comm, model);

  // The result file is checked and locked before any analysis (a directory, a device, the scene
  // itself, a missing directory, another run writing it: exit 1; -o without a value: exit 2).
  const std::string h5 = outputPath(model, scenePath, settings.output);
  if (h5.empty()) {
    PetscCall(PetscPrintf(comm, "error: -o needs a file name (-o result.h5)\n"));
    *exitCode = 2;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  OutputLock outputLock;
  if (const std::string problem = claimOutput(comm, h5, scenePath, outputLock); !problem.empty()) {
    PetscCall(PetscPrintf(comm, "error: result file: %s\n", problem.c_str()));
    *exitCode = 1;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  // -restart old.h5: the checkpoint must belong to this scene (refused with exit 2 before any file is written)
  std::unique_ptr<Restart> restart;
  if (const std::string& from = settings.output.restart; !from.empty() && !model.opt.showinputonly) {
    std::string error;
    try {
      restart = std::make_unique<Restart>(comm, from, h5, fingerprint, model, plan, settings.dynamics.scheme);
    } catch (const std::exception& ex) {
      error = std::string("error: ") + ex.what();
    }
    int failed = !error.empty();
    MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, comm);
    if (failed) {
      PetscCall(PetscPrintf(comm, "%s\n", error.empty() ? "error: -restart failed on another rank" : error.c_str()));
      *exitCode = 2;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  }
  Assembler assembler(*dmesh, model.opt.gravity, settings.statics.assemblyCoo);
  StepResults results(assembler, {plan.stress, plan.stressPerElement});
  ResultLayout layout;
  results.fillLayout(layout);
  fillLook(model, *dmesh, layout);
  layout.version = sinewVersion();
  layout.scene = model.sceneText;
  {  // SPACAR Light's ndof: free node coordinates minus the rigid-mode constraints (no multipliers)
    long free = 0;
    for (int i = 0; i < dmesh->numOwnedNodes; ++i) {
      const LocalNode& n = dmesh->nodes[static_cast<std::size_t>(i)];
      for (int k = 0; k < n.ndof; ++k) free += n.status[k] == DofStatus::Free;
    }
    MPI_Allreduce(MPI_IN_PLACE, &free, 1, MPI_LONG, MPI_SUM, comm);
    layout.nunknowns = dmesh->numGlobalUnknowns;
    layout.nnodedofs = free;
    layout.nconstraints = dmesh->numGlobalUnknowns - free;
    layout.ndof = free - layout.nconstraints;
  }
  layout.nranks = dmesh->size;
  layout.inputOnly = model.opt.showinputonly;
  if (plan.dynamics) layout.stepName = "time";
  int nranks = dmesh->size;
  std::string inputText;  // opt.showinputonly: what was read (before the global arrays go)
  if (model.opt.showinputonly) {
    long feElements = static_cast<long>(dmesh->elements.size());
    MPI_Allreduce(MPI_IN_PLACE, &feElements, 1, MPI_LONG, MPI_SUM, comm);
    inputText = inputSummary(model, {dmesh->numFeNodes, feElements, dmesh->numGlobalUnknowns, layout.ndof});
  }
  // the global model arrays are not needed past set-up
  std::vector<Vec3> initialPositions;
  if (dmesh->rank == 0) initialPositions = model.nodes;
  const std::string formfindingHint = model.formfinding ? formFindingCollapseCauses(model) : std::string();
  model.nodes.clear();
  model.nodes.shrink_to_fit();
  model.elements.clear();
  model.elements.shrink_to_fit();
  model.elementSet.clear();
  model.elementSet.shrink_to_fit();
  times.setup = MPI_Wtime() - t0;

  SummaryHeader header{model.title, scenePath, nranks, dmesh->numGlobalUnknowns, plan.describe(model), model.opt.showinputonly};
  if (!model.opt.silent) PetscCall(printHeader(comm, header));
  if (!model.opt.silent && nranks > 1 && !model.opt.showinputonly) {  // partition balance: elements, owned unknowns, ghosts per rank
    long mine[3] = {static_cast<long>(dmesh->elements.size()), dmesh->numOwnedUnknowns,
                    static_cast<long>(dmesh->ghostUnknowns.size())};
    long lo[3], hi[3];
    MPI_Allreduce(mine, lo, 3, MPI_LONG, MPI_MIN, comm);
    MPI_Allreduce(mine, hi, 3, MPI_LONG, MPI_MAX, comm);
    PetscCall(PetscPrintf(comm, "  partition (METIS): elements %ld..%ld, owned unknowns %ld..%ld, ghost unknowns %ld..%ld per rank\n",
                          lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]));
  }

  // Mechanisms and redundant constraints are model errors (exit 2), found before any file exists.
  ConstraintCheckSetting check;
  {
    PhaseScope checkPhase("the constraint check");
    PetscCall(checkModelBeforeRun(model, plan, assembler, h5, settings.check, &check, &times, exitCode));
  }
  if (*exitCode) PetscFunctionReturn(PETSC_SUCCESS);

  std::unique_ptr<Hdf5ResultFile> file;
  try {
    file = std::make_unique<Hdf5ResultFile>(comm, h5, layout);
    file->setSyncInterval(settings.output.fsyncInterval);
  } catch (const std::exception& ex) {
    PetscCall(PetscPrintf(comm, "error: cannot create %s: %s\n", h5.c_str(), ex.what()));
    *exitCode = 1;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  std::vector<double> p0;
  for (const Vec3& x : initialPositions) p0.insert(p0.end(), x.begin(), x.end());

  RunContext ctx(model, plan, settings, assembler, results, *file);
  ctx.formfindingHint = formfindingHint;
  bool modelError = false;  // a singular tangent found when Newton's linear solve failed
  ctx.comm = comm;
  ctx.times = times;
  ctx.progress.setStart(t0);
  ctx.guardedWrite([&] { file->writeArray("node/p0", p0, {static_cast<long>(initialPositions.size()), 3}); });
  PetscCall(assembler.createVector(&ctx.U));
  PetscCall(VecSet(ctx.U, 0.0));
  if (!model.opt.showinputonly) {  // an input-only run computes nothing
    PhaseScope phase("the set-up of the analyses");
    PetscCall(addStepAnalyses(ctx));
  }
  CheckpointWriter checkpointWriter(assembler, fingerprint);
  // -checkpoint false: no /checkpoint (the run cannot be continued)
  if (settings.output.checkpoint) ctx.checkpoint = &checkpointWriter;
  ctx.stopAfterRows = settings.output.stopAfterStep;
  ctx.restart = restart.get();
  if (restart && ctx.ioError.empty()) {
    // the earlier run's rows and state, committed with its checkpoint before the analysis goes on
    PetscErrorCode ierr = PETSC_SUCCESS;
    std::vector<Vec> work;
    CheckpointData restored;
    ctx.guardedWrite([&] {
      try {
        restart->restore(ctx, layout);
      } catch (const std::exception& ex) {
        throw std::runtime_error("-restart " + restart->source() + ": " + ex.what());
      }
      ierr = restart->restoredState(ctx, restored, &work);
      if (!ierr) {
        ctx.checkpointState = [&restored](CheckpointData& d) -> PetscErrorCode {
          d = restored;
          return PETSC_SUCCESS;
        };
        ierr = ctx.writeCheckpoint();
        ctx.checkpointState = nullptr;
      }
      if (!ierr) file->commit();
    });
    PetscCall(ierr);
    for (Vec& w : work) PetscCall(VecDestroy(&w));
    if (ctx.ioError.empty() && !model.opt.silent)
      PetscCall(PetscPrintf(comm, "  restart: %d step rows copied from %s, continuing the %s\n", ctx.nextStep,
                            restart->source().c_str(), phaseName(restart->phase())));
  }
  // a restart continues its checkpoint's phase (form finding, then the load analysis, as usual)
  const bool runFF = plan.formfinding && (!restart || restart->phase() == CheckpointPhase::FormFinding);
  const bool resumeStatics = restart && restart->phase() == CheckpointPhase::Statics;
  if (!ctx.ioError.empty()) {
    // nothing to do: the file error is reported below
  } else if (model.opt.showinputonly) {
    // SPACAR Light's input check: the file holds the input geometry (/node/p0, /mesh/p0, the cells,
    // the element look), no step rows; converged = 0 and showinputonly = 1 (nothing was solved)
  } else {
    if (runFF) {
      PhaseScope phase("form finding");
      PetscCall(runFormFinding(ctx));
      PhaseScope checkAfter("the constraint check after form finding");
      if (!ctx.stop) PetscCall(checkLoadedModelAfterFormFinding(ctx, check, &modelError));
    }
    const bool go = ctx.converged && !ctx.stop;  // not after an interrupted form finding
    // opt.dynamics start: static runs the load steps first (a restart from a dynamics checkpoint
    // continues the time loop), then the dynamics from their end (after this if-chain)
    const bool resumeDynamics = restart && restart->phase() == CheckpointPhase::Dynamics;
    if (go && plan.dynamics && !plan.preload) {
      PhaseScope phase("dynamics");
      PetscCall(runDynamics(ctx));
    } else if (go && plan.continuation) {
      PhaseScope phase("path following");
      PetscCall(runContinuation(ctx));
    } else if (go && plan.statics && !resumeDynamics) {
      PhaseScope phase("statics");
      PetscCall(runStatics(ctx, resumeStatics, check, &modelError));
    }
    if (plan.preload && go && ctx.converged && !ctx.stop) {  // from the last load step's equilibrium, at rest
      PhaseScope phase("dynamics");
      PetscCall(runDynamics(ctx));
    }
  }

  const double tClose = MPI_Wtime();
  const bool completed = ctx.converged && ctx.interruptSignal == 0 && ctx.ioError.empty() && !model.opt.showinputonly;
  if (ctx.ioError.empty()) ctx.guardedWrite([&] { file->close(completed); });
  else {
    try {
      file->close(false);  // cleans up; the published file keeps the steps committed before the failure
    } catch (const std::exception&) {
      // the first failure is the one reported
    }
  }
  ctx.times.output += MPI_Wtime() - tClose;
  if (!ctx.ioError.empty() || ctx.interruptSignal) {
    const int kept = file->failed() ? -1 : file->stepsWritten();
    std::string msg;
    if (!ctx.ioError.empty()) msg = "error: writing the results failed: " + ctx.ioError + "\n";
    else
      msg = std::string(ctx.interruptSignal == RunContext::kStopAfterStep ? "stopped by -stop_after_step"
                                                                          : std::string("interrupted by ") + signalName(ctx.interruptSignal)) +
            " after " +
            (ctx.lastStepName.empty() ? std::string("set-up") : ctx.lastStepName + " " + std::to_string(ctx.lastStepIndex)) + "\n";
    msg += "  results: " + h5 +
           (kept >= 0 ? " (" + std::to_string(kept) + " steps, converged = 0)"
                      : " holds the steps written before the failure (converged = 0)") + "\n";
    PetscCall(PetscPrintf(comm, "%s", msg.c_str()));
    PetscCall(VecDestroy(&ctx.U));
    *exitCode = ctx.ioError.empty() ? 5 : 1;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (model.opt.showinputonly) {
    if (!model.opt.silent)
      PetscCall(PetscPrintf(comm, "%s\n  input geometry: %s (ParaView: %s)\n  picture: scripts/plot_input.py %s\n",
                            inputText.c_str(), file->path().c_str(), file->xdmfPath().c_str(), file->path().c_str()));
    PetscCall(VecDestroy(&ctx.U));
    *exitCode = 0;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  SummaryBody body;
  body.reports = ctx.reports;
  body.nodes = results.summaryRows();
  body.planar = model.dimension == 2;
  body.commits = file->commits();
  body.syncedCommits = file->syncedCommits();
  body.stress = plan.stress && ctx.nextStep > 0;
  body.stressMax = results.lastStressMax();
  body.stressElement = results.lastStressElement();
  body.rotations = dmesh->anyRotations;
  body.tensileOnly = !dmesh->anyRotations && !dmesh->anyAncf && !model.eprops.empty() &&
                     std::all_of(model.eprops.begin(), model.eprops.end(), [](const ElementSet& s) {
                       return s.type() == ElementType::Cable || s.type() == ElementType::Membrane;
                     });
  body.tensile = results.tensileSummary();
  body.mostMoving = results.mostMovingNode();
  body.verbose = settings.output.verbose;
  body.analysisLines = ctx.summaryLines + ctx.stepAnalysisLine();
  for (auto& a : ctx.stepAnalyses) body.analysisLines += a->summary();
  for (const ElementKind& kind : elementKinds()) {  // the evaluation counters of the kinds the model uses
    if (!kind.counters || std::none_of(model.eprops.begin(), model.eprops.end(),
                                       [&](const ElementSet& s) { return s.type() == kind.type; }))
      continue;
    std::vector<long> n = kind.counters();
    MPI_Allreduce(MPI_IN_PLACE, n.data(), static_cast<int>(n.size()), MPI_LONG, MPI_SUM, comm);
    body.developerLines += kind.countersLine(n);
  }
  body.counters = assembler.counters();
  body.times = ctx.times;
  body.h5 = file->path();
  body.xdmf = file->xdmfPath();
  body.converged = ctx.converged;
  body.failure = ctx.failure;
  if (!model.opt.silent) PetscCall(printSummary(comm, body));
  else if (!body.converged) PetscCall(PetscPrintf(comm, "error: %s\n", body.failure.c_str()));
  PetscCall(VecDestroy(&ctx.U));
  const bool converged = ctx.converged;
  *exitCode = converged ? 0 : (modelError ? 2 : 3);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// A PETSc error that every rank returned (a rank that could not reach the others was ended by the
/// solver error handler): rank 0 prints the recorded message; returns the run's exit code.
int reportRunFailure(MPI_Comm comm, PetscErrorCode ierr) {
  RunFailure f = recordedFailure();
  if (!f)
    f = {kExitSolverError, "error: internal solver error in " + std::string(currentPhase()) + " (PETSc error " +
                               std::to_string(static_cast<int>(ierr)) + ")"};
  PetscPrintf(comm, "%s\n", f.message.c_str());
  return f.exitCode;
}

}  // namespace

PetscErrorCode runFromCommandLine(int argc, char** argv, int* exitCode) {
  PetscFunctionBeginUser;
  // PETSc/SLEPc errors: recorded with the phase, returned on every rank together, reported once
  // (exit 4; exit 3 for a non-finite element force law). 10 s: how long a failing rank waits for the
  // others before it ends the job alone (they wait in a collective it will never join).
  SolverErrorGuard guard(PETSC_COMM_WORLD, 10.0);
  PetscErrorCode ierr = PETSC_SUCCESS;
  try {
    ierr = runScene(argc, argv, exitCode);
  } catch (const SolverCallError& e) {  // a constructor's PETSc call failed (SinewCallThrow)
    ierr = e.code();
  }
  if (ierr) *exitCode = reportRunFailure(PETSC_COMM_WORLD, ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
