// Everything an analysis of a run needs: the model, the plan, the assembler, the result file and
// the step counter shared by form finding, statics and dynamics (their rows follow each other).
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/static_analysis.hpp"
#include "app/phases/run_status.hpp"
#include "app/plan.hpp"
#include "app/progress.hpp"
#include "app/summary.hpp"
#include "assembly/assembler.hpp"
#include "restart/checkpoint.hpp"
#include "settings/settings.hpp"
#include "sinew/model.hpp"
#include "sinew/result_file.hpp"
#include "step/step_analysis.hpp"
#include "step/step_results.hpp"

namespace sinew {

class Restart;

/// The procedures whose written rows the step analyses follow (opt.step_analyses, default per procedure).
enum class StepPhase { FormFinding, Statics, Continuation, Dynamics };

struct RunContext {
  MPI_Comm comm = MPI_COMM_WORLD;
  Model& model;  ///< global node/element arrays are released after set-up; eprops, opt, formfinding, sensors stay
  const Plan& plan;
  const Settings& settings;  ///< every flag's setting (read once at start-up)
  Assembler& assembler;
  StepResults& results;
  ResultFile& file;
  Vec U = nullptr;  ///< the current state (unknowns layout)
  std::vector<std::unique_ptr<StepAnalysis>> stepAnalyses;
  int nextStep = 0;  ///< next row of the step-indexed datasets
  Timings times;
  std::vector<StepReport> reports;
  RunStatus status;  ///< converged / failed, stopping (signal, -stop_after_step, result-file error)
  std::string summaryLines;  ///< extra lines for the stdout summary (rank 0)
  Progress progress;
  std::string formfindingHint;  ///< formFindingCollapseCauses of the scene (set before form finding)
  /// Checkpoints (src/restart/checkpoint.*, src/app/phases/restart.*): the writer, the running phase's
  /// state after its last converged step (set by the phase before its loop; none: no checkpoint),
  /// and the earlier run a -restart continues.
  CheckpointWriter* checkpoint = nullptr;
  std::function<PetscErrorCode(CheckpointData&)> checkpointState;
  const Restart* restart = nullptr;

  RunContext(Model& m, const Plan& p, const Settings& s, Assembler& a, StepResults& r, ResultFile& f)
      : model(m), plan(p), settings(s), assembler(a), results(r), file(f), progress(MPI_COMM_WORLD, m.opt.silent) {}

  /// A converged step of a step loop.
  struct Step {
    int index = 0;            ///< 1-based in its phase (time step 0: the initial state)
    bool last = false;        ///< the final step of the phase
    double value = 0;         ///< load factor or time (row of /load_factor or /time)
    std::string detail;       ///< middle of the progress line
    bool selectable = true;   ///< false: always written (form-finding steps)
    /// A load step of a dynamics run that starts from the static load steps (opt.dynamics start:
    /// static): its load factor, written as the row of /load_factor (NaN on the other rows)
    std::optional<double> loadFactorRow = std::nullopt;
  };
  /// Called by every step loop after a converged step: agrees on a pending interrupt (one
  /// allreduce), writes the step when opt.output_steps selects it (always the last one, and the
  /// one a run stops at), then `afterWrite` (extra rows of that step), commits the result file and
  /// prints the progress line. A result file error sets ioError and stop instead of throwing.
  PetscErrorCode convergedStep(const Step& s, Vec Ustate, const LoadState& ls,
                               const std::function<PetscErrorCode()>& afterWrite = {});
  /// Writes the last converged step from Ustate when output_steps skipped it and the phase ended
  /// early (a failed step): the file always ends with the last converged state.
  PetscErrorCode writeSkippedLast(Vec Ustate);
  /// Runs `write` (result file calls); a ResultFileError or other exception stops the run
  /// (status.writeFailed).
  bool guardedWrite(const std::function<void()>& write);

  /// Writes one step row: beginStep(stepValue), node/element/mesh results of U, the step analyses
  /// (frequencies, buckling, ...) in a step-analysis row when `analyses`, and the every-row ones
  /// (sensors). A failing step analysis fails the run (status).
  PetscErrorCode writeStep(double stepValue, Vec Ustate, const LoadState& ls, bool analyses);
  /// Starts a procedure's rows: its progress lines (`stepName`, `steps`) and the rows its step
  /// analyses run at (opt.step_analyses, or the procedure's default: every load step of statics,
  /// the last row of form finding, path following and dynamics).
  void startPhase(StepPhase phase, const char* stepName, int steps);
  /// At the end of a procedure that completed: runs the step analyses at its last written row (state
  /// Ustate) when opt.step_analyses asks for the last row and that row has none yet (path following
  /// does not know its last point in advance, form finding may end before formfinding_step).
  PetscErrorCode finishStepAnalyses(Vec Ustate);
  /// The summary line of the step analyses: which ran, at how many of the rows, and why ("" when
  /// the plan has none).
  std::string stepAnalysisLine() const;
  /// Writes the running phase's checkpoint (checkpointState) into the result file, to be published
  /// by the next commit with the step just written. ResultFileError on HDF5 failures.
  PetscErrorCode writeCheckpoint(const std::string& group = "checkpoint");

 private:
  struct Skipped {
    bool any = false;
    double value = 0;
    LoadState ls;
    std::optional<double> loadFactorRow;
  } skipped_;
  PetscErrorCode writeLoadFactorRow(const std::optional<double>& loadFactor);
  /// Whether the row about to be written (file row nextStep) gets the step analyses; `last`: the
  /// last row of the procedure.
  bool selectsAnalysisRow(bool last) const;
  /// Runs the step analyses of one kind at Ustate: every-row ones (sensors) or the selected ones in
  /// a step-analysis row of the file.
  PetscErrorCode runStepAnalyses(Vec Ustate, const LoadState& ls, bool everyRow);
  StepAnalysisRows rows_;  ///< rows of the running procedure's step analyses
  int phaseFirstRow_ = 0;  ///< file row of the running procedure's first row
  LoadState lastLoads_;    ///< loads of the last written row
  std::vector<std::pair<StepPhase, StepAnalysisRows>> phases_;  ///< procedures that ran, with their rows
};

/// Per-step analyses the plan asks for (frequencies, buckling, compliance, state-space).
PetscErrorCode addStepAnalyses(RunContext& ctx);
/// Form finding (formfinding block): writes its steps and leaves the found shape in ctx.U.
PetscErrorCode runFormFinding(RunContext& ctx);
/// What can make this model's form finding collapse (for the messages; computed before set-up
/// releases the scene's elements, src/app/phases/run_formfinding.cpp).
std::string formFindingCollapseCauses(const Model& m);
struct ConstraintCheckSetting;
/// Load-stepped statics (SPACAR Light's steps): writes every converged load step; a failed step fails
/// ctx.status, and sets *modelError when the constraint check finds a mechanism.
/// resumeStatics: continue the load steps of ctx.restart's checkpoint.
PetscErrorCode runStatics(RunContext& ctx, bool resumeStatics, const ConstraintCheckSetting& check, bool* modelError);
/// Time integration (opt.dynamics) instead of statics.
PetscErrorCode runDynamics(RunContext& ctx);
/// Path following (opt.continuation) instead of load steps: one result row per path point, and
/// /path/negative_eigenvalues, /path/critical_points.
PetscErrorCode runContinuation(RunContext& ctx);

}  // namespace sinew
