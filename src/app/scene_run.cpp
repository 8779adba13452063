#include "app/scene_run.hpp"

#include <petscsnes.h>

#include <algorithm>
#include <filesystem>

#include "analysis/constraint_check.hpp"
#include "app/command_line.hpp"
#include "app/input_summary.hpp"
#include "app/interrupt.hpp"
#include "app/phases/restart.hpp"
#include "assembly/kernel_factory.hpp"
#include "dynamics/dynamic_analysis.hpp"
#include "elements/element_kinds.hpp"
#include "mesh/fe_mesh.hpp"
#include "parallel/collective_error.hpp"
#include "scene/scene_reader.hpp"
#include "scene/scene_tree.hpp"
#include "settings/read_settings.hpp"
#include "step/step_analysis.hpp"

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
                    "warning: eprops(%zu) (%s set) is form-found with zero prestress (%s): it carries no force and "
                    "gives no stiffness in form finding\n",
                    static_cast<size_t>(set) + 1, elementTypeName(s.type()), fields);
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

/// How the header names the scene.
std::string sceneName(const SceneSource& s) {
  if (!s.path.empty()) return s.path;
  return s.model ? "(a model built in code)" : "(scene text)";
}

}  // namespace

SceneRun::SceneRun(MPI_Comm comm, SceneSource scene, const Settings& settings, bool toFile)
    : comm_(comm), scene_(std::move(scene)), settings_(settings), toFile_(toFile) {}

SceneRun::~SceneRun() {
  if (ctx_) VecDestroy(&ctx_->U);
}

PetscErrorCode SceneRun::fail(int exitCode, const std::string& message) {
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm_, "%s\n", message.c_str()));
  exitCode_ = exitCode;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Scene -> model -> distributed mesh -> plan, and the checks that need the distributed mesh
// (SceneError: exit 2).
void SceneRun::readModel() {
  // a restart's listed output steps are checked against its plan once the checkpoint is read (setUp)
  const bool restart = toFile_ && !settings_.output.restart.empty();
  if (scene_.model) {
    model_ = std::move(*scene_.model);
    scene_.model.reset();
    checkBuiltModel(model_);
  } else if (!scene_.path.empty()) {
    model_ = readScene(scene_.path, sceneOverrides(settings_), restart);
  } else if (scene_.tree) {  // the text only for the result file (its scene attribute, the fingerprint)
    model_ = parseSceneTree(*scene_.tree, scene_.baseDir, sceneOverrides(settings_), restart);
    if (toFile_) model_.sceneText = sceneTreeText(*scene_.tree);
  } else {
    model_ = parseScene(scene_.text, scene_.baseDir, sceneOverrides(settings_), restart);
  }
  plan_ = makePlan(model_);
  const FeMesh fe = discretize(model_);
  dmesh_ = std::make_unique<DistributedMesh>(
      distributeMesh(comm_, model_, fe, makeKernelFactory(model_, settings_.dynamics.beamMassInUse())));
  checkContinuationControl(model_, *dmesh_);  // collective, after the collective distribution
  // nfreq: all asks SLEPc for every eigenpair: a dense-sized problem, bounded to small models
  constexpr long kAllFrequenciesMax = 2000;
  if (plan_.frequencies && model_.opt.nfreq == Options::kAllFrequencies && dmesh_->numGlobalUnknowns > kAllFrequenciesMax)
    throw SceneError("opt.nfreq", "all frequencies of a model with " + std::to_string(dmesh_->numGlobalUnknowns) +
                                      " unknowns (all is for models up to " + std::to_string(kAllFrequenciesMax) +
                                      " unknowns): give the number of frequencies wanted");
  if (plan_.dynamics) DynamicAnalysis::checkScheme(*dmesh_, settings_.dynamics.scheme);
  if (plan_.dynamics && model_.opt.dynamics) DynamicAnalysis::checkStepControl(*dmesh_, *model_.opt.dynamics, settings_.dynamics);
  // the checkpoints' and -restart's check that a file belongs to this scene: runs to a file only
  if (toFile_) fingerprint_ = sceneFingerprint(model_, static_cast<long>(fe.X.size()), static_cast<long>(fe.elements.size()));
}

void SceneRun::fillLayout(ResultLayout& layout) {
  results_->fillLayout(layout);
  fillLook(model_, *dmesh_, layout);
  layout.version = sinewVersion();
  layout.scene = model_.sceneText;
  {  // SPACAR Light's ndof: free node coordinates minus the rigid-mode constraints (no multipliers)
    long free = 0;
    for (int i = 0; i < dmesh_->numOwnedNodes; ++i) {
      const LocalNode& n = dmesh_->nodes[static_cast<std::size_t>(i)];
      for (int k = 0; k < n.ndof; ++k) free += n.status[k] == DofStatus::Free;
    }
    MPI_Allreduce(MPI_IN_PLACE, &free, 1, MPI_LONG, MPI_SUM, comm_);
    layout.nunknowns = dmesh_->numGlobalUnknowns;
    layout.nnodedofs = free;
    layout.nconstraints = dmesh_->numGlobalUnknowns - free;
    layout.ndof = free - layout.nconstraints;
  }
  layout.nranks = dmesh_->size;
  layout.inputOnly = model_.opt.showinputonly;
  if (plan_.dynamics) layout.stepName = "time";
}

PetscErrorCode SceneRun::setUp() {
  PetscFunctionBeginUser;
  t0_ = MPI_Wtime();
  // ---- scene -> model -> distributed mesh (scene errors: rank 0 prints, everyone exits 2)
  std::string setupError;
  int code = 0;
  PetscCall(PetscLogEventBegin(SinewEvents::get().setup, 0, 0, 0, 0));
  try {
    readModel();
  } catch (const SceneError& ex) {
    setupError = std::string("error: ") + ex.what();
    code = 2;
  } catch (const std::exception& ex) {
    setupError = std::string("error: ") + ex.what();
    code = 1;
  }
  // every rank ends with the message and exit code of the lowest failing rank
  if (const RunFailure f = agreeOnFailure(comm_, RunFailure{code, setupError})) PetscCall(fail(f.exitCode, f.message));
  if (exitCode_) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventEnd(SinewEvents::get().setup, 0, 0, 0, 0));
  if (!model_.opt.silent) warnings(comm_, model_);

  // The result file is checked and locked before any analysis (a directory, a device, the scene
  // itself, a missing directory, another run writing it: exit 1; -o without a value: exit 2).
  if (toFile_) {
    h5_ = outputPath(model_, scene_.path, settings_.output);
    if (h5_.empty()) PetscCall(fail(2, "error: -o needs a file name (-o result.h5)"));
    else if (const std::string problem = claimOutput(comm_, h5_, scene_.path, outputLock_); !problem.empty())
      PetscCall(fail(1, "error: result file: " + problem));
    if (exitCode_) PetscFunctionReturn(PETSC_SUCCESS);
  }
  // -restart old.h5: the checkpoint must belong to this scene (refused with exit 2 before any file is written)
  if (const std::string& from = settings_.output.restart; !from.empty() && !model_.opt.showinputonly) {
    std::string error = toFile_ ? "" : "error: -restart continues into a result file: give one (-o result.h5)";
    if (toFile_) {
      try {
        restart_ = std::make_unique<Restart>(comm_, from, h5_, fingerprint_, model_, plan_, settings_.dynamics.scheme);
        // listed output steps: those of the plan the restart runs (it may go on past opt.loadsteps)
        const Options& o = model_.opt;
        if (o.output_steps.kind == OutputSteps::Kind::List && !o.continuation) {
          try {
            checkOutputSteps(o, lastLoadStepOf(restart_.get(), model_, settings_));
          } catch (const SceneError& ex) {
            const auto flag = settings_.sceneOpt.find("output_steps");
            if (flag == settings_.sceneOpt.end()) throw;
            throw SceneError("", std::string(ex.what()) + " (from the command line: -output_steps " + flag->second + ")");
          }
        }
      } catch (const std::exception& ex) {
        error = std::string("error: ") + ex.what();
      }
    }
    int failed = !error.empty();
    MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, comm_);
    if (failed) PetscCall(fail(2, error.empty() ? "error: -restart failed on another rank" : error));
    if (exitCode_) PetscFunctionReturn(PETSC_SUCCESS);
  }
  assembler_ = std::make_unique<Assembler>(*dmesh_, model_.opt.gravity, settings_.statics.assemblyCoo);
  results_ = std::make_unique<StepResults>(*assembler_, StepResultOptions{plan_.stress, plan_.stressPerElement});
  ResultLayout layout;
  fillLayout(layout);
  const int nranks = dmesh_->size;
  if (model_.opt.showinputonly) {
    long feElements = static_cast<long>(dmesh_->elements.size());
    MPI_Allreduce(MPI_IN_PLACE, &feElements, 1, MPI_LONG, MPI_SUM, comm_);
    inputText_ = inputSummary(model_, {dmesh_->numFeNodes, feElements, dmesh_->numGlobalUnknowns, layout.ndof});
  }
  // the global model arrays are not needed past set-up
  if (dmesh_->rank == 0) initialPositions_ = model_.nodes;
  const std::string formfindingHint = model_.formfinding ? formFindingCollapseCauses(model_) : std::string();
  model_.nodes.clear();
  model_.nodes.shrink_to_fit();
  model_.elements.clear();
  model_.elements.shrink_to_fit();
  model_.elementSet.clear();
  model_.elementSet.shrink_to_fit();
  times_.setup = MPI_Wtime() - t0_;

  const std::string planLine = plan_.describe(model_, lastLoadStepOf(restart_.get(), model_, settings_));
  SummaryHeader header{model_.title, sceneName(scene_), nranks, dmesh_->numGlobalUnknowns, planLine,
                       model_.opt.showinputonly};
  if (!model_.opt.silent) PetscCall(printHeader(comm_, header));
  if (!model_.opt.silent && nranks > 1 && !model_.opt.showinputonly) {  // partition balance: elements, owned unknowns, ghosts per rank
    long mine[3] = {static_cast<long>(dmesh_->elements.size()), dmesh_->numOwnedUnknowns,
                    static_cast<long>(dmesh_->ghostUnknowns.size())};
    long lo[3], hi[3];
    MPI_Allreduce(mine, lo, 3, MPI_LONG, MPI_MIN, comm_);
    MPI_Allreduce(mine, hi, 3, MPI_LONG, MPI_MAX, comm_);
    PetscCall(PetscPrintf(comm_, "  partition (METIS): elements %ld..%ld, owned unknowns %ld..%ld, ghost unknowns %ld..%ld per rank\n",
                          lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]));
  }

  // Mechanisms and redundant constraints are model errors (exit 2), found before any file exists.
  {
    PhaseScope checkPhase("the constraint check");
    PetscCall(checkModelBeforeRun(model_, plan_, *assembler_, h5_, settings_.check, settings_.statics.denseMaxUnknowns, &check_, &times_, &exitCode_));
  }
  if (exitCode_) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(createResults(layout));
  if (exitCode_) PetscFunctionReturn(PETSC_SUCCESS);
  ctx_->formfindingHint = formfindingHint;
  PetscCall(restoreRestart(layout));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The result file (or store), /node/p0, the run's context with its step analyses and checkpoints.
PetscErrorCode SceneRun::createResults(const ResultLayout& layout) {
  PetscFunctionBeginUser;
  if (toFile_) {
    try {
      auto file = std::make_unique<Hdf5ResultFile>(comm_, h5_, layout);
      file->setSyncInterval(settings_.output.fsyncInterval);
      hdf5_ = file.get();
      file_ = std::move(file);
    } catch (const std::exception& ex) {
      PetscCall(fail(1, "error: cannot create " + h5_ + ": " + ex.what()));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  } else {
    auto store = std::make_unique<ResultStore>(comm_, layout);
    store_ = store.get();
    file_ = std::move(store);
  }
  std::vector<double> p0;
  for (const Vec3& x : initialPositions_) p0.insert(p0.end(), x.begin(), x.end());
  const long numInitial = static_cast<long>(initialPositions_.size());
  initialPositions_ = {};

  ctx_ = std::make_unique<RunContext>(model_, plan_, settings_, *assembler_, *results_, *file_);
  RunContext& ctx = *ctx_;
  ctx.comm = comm_;
  ctx.times = times_;
  ctx.progress.setStart(t0_);
  ctx.guardedWrite([&] { file_->writeArray("node/p0", p0, {numInitial, 3}); });
  PetscCall(assembler_->createVector(&ctx.U));
  PetscCall(VecSet(ctx.U, 0.0));
  if (!model_.opt.showinputonly) {  // an input-only run computes nothing
    PhaseScope phase("the set-up of the analyses");
    PetscCall(addStepAnalyses(ctx));
  }
  // -checkpoint false: no /checkpoint (the run cannot be continued); none in memory
  if (settings_.output.checkpoint && toFile_) {
    checkpointWriter_ = std::make_unique<CheckpointWriter>(*assembler_, fingerprint_);
    ctx.checkpoint = checkpointWriter_.get();
  }
  ctx.restart = restart_.get();
  PetscFunctionReturn(PETSC_SUCCESS);
}

// -restart: the earlier run's rows and state, committed with its checkpoint before the analysis goes on.
PetscErrorCode SceneRun::restoreRestart(const ResultLayout& layout) {
  PetscFunctionBeginUser;
  RunContext& ctx = *ctx_;
  if (!restart_ || !ctx.status.writeOk()) PetscFunctionReturn(PETSC_SUCCESS);
  PetscErrorCode ierr = PETSC_SUCCESS;
  std::vector<Vec> work;
  CheckpointData restored;
  ctx.guardedWrite([&] {
    try {
      restart_->restore(ctx, layout);
    } catch (const std::exception& ex) {
      throw std::runtime_error("-restart " + restart_->source() + ": " + ex.what());
    }
    ierr = restart_->restoredState(ctx, restored, &work);
    if (!ierr) {
      ctx.checkpointState = [&restored](CheckpointData& d) -> PetscErrorCode {
        d = restored;
        return PETSC_SUCCESS;
      };
      ierr = ctx.writeCheckpoint();
      ctx.checkpointState = nullptr;
    }
    if (!ierr) file_->commit();
  });
  PetscCall(ierr);
  for (Vec& w : work) PetscCall(VecDestroy(&w));
  if (ctx.status.writeOk() && !model_.opt.silent)
    PetscCall(PetscPrintf(comm_, "  restart: %d step rows copied from %s, continuing the %s\n", ctx.nextStep,
                          restart_->source().c_str(), phaseName(restart_->phase())));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SceneRun::runAnalyses() {
  PetscFunctionBeginUser;
  RunContext& ctx = *ctx_;
  // a restart continues its checkpoint's phase (form finding, then the load analysis, as usual)
  const bool runFF = plan_.formfinding && (!restart_ || restart_->phase() == CheckpointPhase::FormFinding);
  const bool resumeStatics = restart_ && restart_->phase() == CheckpointPhase::Statics;
  // nothing to do after a file error (reported by finish()) or for SPACAR Light's input check: the
  // file holds the input geometry (/node/p0, /mesh/p0, the cells, the element look), no step rows;
  // converged = 0 and showinputonly = 1 (nothing was solved)
  if (!ctx.status.writeOk() || model_.opt.showinputonly) PetscFunctionReturn(PETSC_SUCCESS);
  if (runFF) {
    PhaseScope phase("form finding");
    PetscCall(runFormFinding(ctx));
    PhaseScope checkAfter("the constraint check after form finding");
    if (!ctx.status.stopping()) PetscCall(checkLoadedModelAfterFormFinding(ctx, check_, &modelError_));
  }
  const bool go = ctx.status.converged() && !ctx.status.stopping();  // not after an interrupted form finding
  // opt.dynamics start: static runs the load steps first (a restart from a dynamics checkpoint
  // continues the time loop), then the dynamics from their end (after this if-chain)
  const bool resumeDynamics = restart_ && restart_->phase() == CheckpointPhase::Dynamics;
  if (go && plan_.dynamics && !plan_.preload) {
    PhaseScope phase("dynamics");
    PetscCall(runDynamics(ctx));
  } else if (go && plan_.continuation) {
    PhaseScope phase("path following");
    PetscCall(runContinuation(ctx));
  } else if (go && plan_.statics && !resumeDynamics) {
    PhaseScope phase("statics");
    PetscCall(runStatics(ctx, resumeStatics, check_, &modelError_));
  }
  if (plan_.preload && go && ctx.status.converged() && !ctx.status.stopping()) {  // from the last load step's equilibrium, at rest
    PhaseScope phase("dynamics");
    PetscCall(runDynamics(ctx));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SceneRun::finish() {
  PetscFunctionBeginUser;
  RunContext& ctx = *ctx_;
  const double tClose = MPI_Wtime();
  const RunStatus& status = ctx.status;
  const bool completed =
      status.converged() && status.interruptSignal() == 0 && status.writeOk() && !model_.opt.showinputonly;
  if (status.writeOk()) ctx.guardedWrite([&] { file_->close(completed); });
  else {
    try {
      file_->close(false);  // cleans up; the published file keeps the steps committed before the failure
    } catch (const std::exception&) {
      // the first failure is the one reported
    }
  }
  ctx.times.output += MPI_Wtime() - tClose;
  const std::string where = hdf5_ ? hdf5_->path() : std::string("in memory");
  if (!status.writeOk() || status.interruptSignal()) {
    const int kept = file_->failed() ? -1 : file_->stepsWritten();
    std::string msg;
    if (!status.writeOk()) msg = "error: writing the results failed: " + status.ioError() + "\n";
    else
      msg = std::string(status.interruptSignal() == RunStatus::kStopAfterStep
                            ? "stopped by -stop_after_step"
                            : std::string("interrupted by ") + signalName(status.interruptSignal())) +
            " after " + status.position() + "\n";
    msg += "  results: " + where +
           (kept >= 0 ? " (" + std::to_string(kept) + " steps, converged = 0)"
                      : " holds the steps written before the failure (converged = 0)") + "\n";
    PetscCall(PetscPrintf(comm_, "%s", msg.c_str()));
    exitCode_ = status.writeOk() ? 5 : 1;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (model_.opt.showinputonly) {
    if (!model_.opt.silent) {
      if (hdf5_)
        PetscCall(PetscPrintf(comm_, "%s\n  input geometry: %s (ParaView: %s)\n  picture: scripts/plot_input.py %s\n",
                              inputText_.c_str(), hdf5_->path().c_str(), hdf5_->xdmfPath().c_str(), hdf5_->path().c_str()));
      else
        PetscCall(PetscPrintf(comm_, "%s\n  input geometry: in memory\n", inputText_.c_str()));
    }
    exitCode_ = 0;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(printSummary());
  exitCode_ = status.converged() ? 0 : (modelError_ ? 2 : 3);
  PetscFunctionReturn(PETSC_SUCCESS);
}

void SceneRun::closeResults() {
  try {
    file_->close(false);
  } catch (const std::exception&) {
    // the PETSc error is the one reported
  }
}

PetscErrorCode SceneRun::printSummary() {
  PetscFunctionBeginUser;
  RunContext& ctx = *ctx_;
  SummaryBody body;
  body.reports = ctx.reports;
  body.nodes = results_->summaryRows();
  body.planar = model_.dimension == 2;
  body.commits = hdf5_ ? hdf5_->commits() : 0;
  body.syncedCommits = hdf5_ ? hdf5_->syncedCommits() : 0;
  body.stress = plan_.stress && ctx.nextStep > 0;
  body.stressMax = results_->lastStressMax();
  body.stressElement = results_->lastStressElement();
  body.rotations = dmesh_->anyRotations;
  body.tensileOnly = !dmesh_->anyRotations && !dmesh_->anyAncf && !model_.eprops.empty() &&
                     std::all_of(model_.eprops.begin(), model_.eprops.end(), [](const ElementSet& s) {
                       return s.type() == ElementType::Cable || s.type() == ElementType::Membrane;
                     });
  body.tensile = results_->tensileSummary();
  body.mostMoving = results_->mostMovingNode();
  body.verbose = settings_.output.verbose;
  body.analysisLines = ctx.summaryLines + ctx.stepAnalysisLine();
  for (auto& a : ctx.stepAnalyses) body.analysisLines += a->summary();
  for (const ElementKind& kind : elementKinds()) {  // the evaluation counters of the kinds the model uses
    if (!kind.counters || std::none_of(model_.eprops.begin(), model_.eprops.end(),
                                       [&](const ElementSet& s) { return s.type() == kind.type; }))
      continue;
    std::vector<long> n = kind.counters();
    MPI_Allreduce(MPI_IN_PLACE, n.data(), static_cast<int>(n.size()), MPI_LONG, MPI_SUM, comm_);
    body.developerLines += kind.countersLine(n);
  }
  body.counters = assembler_->counters();
  body.times = ctx.times;
  if (hdf5_) {
    body.h5 = hdf5_->path();
    body.xdmf = hdf5_->xdmfPath();
  }
  body.converged = ctx.status.converged();
  body.failure = ctx.status.failure();
  if (!model_.opt.silent) PetscCall(sinew::printSummary(comm_, body));
  else if (!body.converged) PetscCall(PetscPrintf(comm_, "error: %s\n", body.failure.c_str()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int reportRunFailure(MPI_Comm comm, PetscErrorCode ierr) {
  RunFailure f = recordedFailure();
  if (!f)
    f = {kExitSolverError, "error: internal solver error in " + std::string(currentPhase()) + " (PETSc error " +
                               std::to_string(static_cast<int>(ierr)) + ")"};
  PetscPrintf(comm, "%s\n", f.message.c_str());
  return f.exitCode;
}

RunResults SceneRun::takeResults() { return store_ ? std::move(store_->results()) : RunResults{}; }

}  // namespace sinew
