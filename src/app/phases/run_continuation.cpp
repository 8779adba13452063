// Path following (opt.continuation): ContinuationAnalysis writes one result row per path point.
#include <cstdio>
#include <string>

#include "analysis/continuation_analysis.hpp"
#include "app/phases/restart.hpp"
#include "app/phases/run_context.hpp"

namespace sinew {

PetscErrorCode runContinuation(RunContext& ctx) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  const double outBefore = ctx.times.output, anaBefore = ctx.times.analyses;
  ContinuationAnalysis path(ctx.assembler, *ctx.model.opt.continuation, ctx.settings.continuation,
                            ctx.settings.statics.maxCuts);
  std::vector<double> negative;
  path.setStopFlag(&ctx.stop);
  path.setStartCarriesInitialLoads(ctx.model.formfinding.has_value());  // runs after form finding
  if (ctx.restart && ctx.restart->phase() == CheckpointPhase::Continuation) PetscCall(ctx.restart->resumeContinuation(ctx, path));
  const long ckSize = ContinuationAnalysis::checkpointSize(ctx.model.opt.continuation->max_steps);
  ctx.checkpointState = [&](CheckpointData& d) -> PetscErrorCode {
    const std::vector<PathPoint>& pts = path.points();
    d.scalars[kCkPhase] = static_cast<double>(CheckpointPhase::Continuation);
    d.scalars[kCkStep] = static_cast<double>(pts.size());
    d.scalars[kCkStepValue] = pts.empty() ? 0.0 : pts.back().loadFactor;
    d.scalars[kCkLambda] = d.scalars[kCkStepValue];
    d.vectors = {{"U", ctx.U}, {"dU", path.lastIncrement()}};
    d.path = path.checkpointState();
    d.pathSize = ckSize;
    return PETSC_SUCCESS;
  };
  ctx.startPhase(StepPhase::Continuation, "path point", ctx.model.opt.continuation->max_steps);
  auto onPoint = [&](const PathPoint& p, Vec U) -> PetscErrorCode {
    PetscFunctionBeginUser;
    LoadState ls;
    ls.loadFactor = ls.time = p.loadFactor;
    char detail[160];
    std::snprintf(detail, sizeof detail, "load factor %.6g  corrector %d  cuts %d  negative eigenvalues %d", p.loadFactor,
                  p.iterations, p.cuts, p.negativeEigenvalues);
    RunContext::Step st{p.step, false, p.loadFactor, detail};
    st.selectable = false;  // every path point is a result row (output_steps does not thin a path)
    PetscCall(ctx.convergedStep(st, U, ls, [&]() -> PetscErrorCode {
      ctx.file.writeStepRow("path/negative_eigenvalues", std::vector<double>{static_cast<double>(p.negativeEigenvalues)});
      ctx.file.writeStepRow("path/control_displacement", std::vector<double>{p.controlValue});
      if (path.computesLowestEigenvalue())
        ctx.file.writeStepRow("path/lowest_eigenvalue", std::vector<double>{p.lowestEigenvalue});
      return PETSC_SUCCESS;
    }));
    StepReport rep;
    rep.step = p.step;
    rep.loadFactor = p.loadFactor;
    rep.newtonIterations = p.iterations;
    rep.increments = p.cuts + 1;
    rep.residualNorm = p.residualNorm;
    ctx.reports.push_back(rep);
    PetscFunctionReturn(PETSC_SUCCESS);
  };
  bool ok = false;
  PetscCall(path.run(ctx.U, onPoint, &ok));
  if (ok) PetscCall(ctx.finishStepAnalyses(ctx.U));  // the last path point is known only now
  ctx.checkpointState = nullptr;
  // critical points: rows [kind (1 limit, 2 bifurcation), after path point, load factor, control displacement]
  std::vector<double> rows;
  for (const CriticalPoint& c : path.criticalPoints())
    rows.insert(rows.end(), {static_cast<double>(c.kind), static_cast<double>(c.afterStep), c.loadFactor, c.controlValue});
  ctx.lastStepName = "path point";
  ctx.guardedWrite([&]() { ctx.file.writeArray("path/critical_points", rows, {static_cast<long>(path.criticalPoints().size()), 4}); });
  ctx.summaryLines += path.summary();
  if (!ok && ctx.converged) {
    ctx.converged = false;
    ctx.failure = path.failureMessage();
  }
  ctx.times.continuation = MPI_Wtime() - t0 - (ctx.times.output - outBefore) - (ctx.times.analyses - anaBefore);
  ctx.times.continuationIts = 0;
  for (const StepReport& r : ctx.reports) ctx.times.continuationIts += r.newtonIterations;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
