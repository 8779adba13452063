// Everything an analysis of a run needs: the model, the plan, the assembler, the result file and
// the step counter shared by form finding, statics and dynamics (their rows follow each other).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "analysis/static_analysis.hpp"
#include "analysis/step_analysis.hpp"
#include "analysis/step_results.hpp"
#include "app/plan.hpp"
#include "app/summary.hpp"
#include "assembly/assembler.hpp"
#include "sinew/model.hpp"
#include "sinew/result_file.hpp"

namespace sinew {

struct RunContext {
  MPI_Comm comm = MPI_COMM_WORLD;
  Model& model;  ///< global node/element arrays are released after set-up; eprops, opt, formfinding, sensors stay
  const Plan& plan;
  Assembler& assembler;
  StepResults& results;
  ResultFile& file;
  Vec U = nullptr;  ///< the current state (unknowns layout)
  std::vector<std::unique_ptr<StepAnalysis>> stepAnalyses;
  int nextStep = 0;  ///< next row of the step-indexed datasets
  Timings times;
  std::vector<StepReport> reports;
  bool converged = true;
  std::string failure;
  std::string summaryLines;  ///< extra lines for the stdout summary (rank 0)

  RunContext(Model& m, const Plan& p, Assembler& a, StepResults& r, ResultFile& f)
      : model(m), plan(p), assembler(a), results(r), file(f) {}

  /// Writes one step row: beginStep(stepValue), node/element/mesh results of U, then every step
  /// analysis (frequencies, buckling, ...). A failing step analysis sets converged = false.
  PetscErrorCode writeStep(double stepValue, Vec Ustate, const LoadState& ls);
};

/// Per-step analyses the plan asks for (frequencies, buckling, compliance, state-space).
PetscErrorCode addStepAnalyses(RunContext& ctx);
/// Form finding (formfinding block): writes its steps and leaves the found shape in ctx.U.
PetscErrorCode runFormFinding(RunContext& ctx);
/// Time integration (opt.dynamics) instead of statics.
PetscErrorCode runDynamics(RunContext& ctx);
/// Path following (opt.continuation) instead of load steps: one result row per path point, and
/// /path/negative_eigenvalues, /path/critical_points.
PetscErrorCode runContinuation(RunContext& ctx);

}  // namespace sinew
