// Path following (opt.continuation): ContinuationAnalysis writes one result row per path point.
#include <cstdio>
#include <string>

#include "analysis/continuation_analysis.hpp"
#include "analysis/path_report.hpp"
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
  path.setStopFlag(ctx.status.stopFlag());
  path.setStartCarriesInitialLoads(ctx.model.formfinding.has_value());  // runs after form finding
  if (ctx.restart && ctx.restart->phase() == CheckpointPhase::Continuation) PetscCall(ctx.restart->resumeContinuation(ctx, path));
  else path.setHandover(ctx.settings.accuracy.handover.get(), ctx.settings.accuracy.pathPlan);  // a -target_error level
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
  ctx.guardedWrite([&]() { ctx.file.writeArray("path/critical_points", rows, {static_cast<long>(path.criticalPoints().size()), 4}); });
  ctx.summaryLines += path.summary();
  if (!ok) ctx.status.fail(path.failureMessage());
  // why the path ended (/path attribute stop_reason); max_steps before the scene's stop criterion is short of it
  const std::vector<PathPoint>& pts = path.points();
  const ContinuationOptions& opts = *ctx.model.opt.continuation;
  const PathEnd end = pathEnd(opts, static_cast<int>(pts.size()), pts.empty() ? 0.0 : pts.back().loadFactor,
                              pts.empty() ? 0.0 : pts.back().controlValue, !ok, ctx.status.stopping());
  ctx.guardedWrite([&]() { ctx.file.writeStateAttribute("path", "stop_reason", end.reason); });
  ctx.summaryLines += "  path ended: " + end.reason + "\n";
  if (end.endedShort)
    ctx.status.fail("path following ended short: " + end.reason + "; give a larger opt.continuation.max_steps (or ds_max, the largest step)");
  std::vector<double> lambdas, controls;
  for (const PathPoint& p : pts) {
    lambdas.push_back(p.loadFactor);
    controls.push_back(p.controlValue);
  }
  if (const PathRetrace r = pathRetrace(lambdas, controls); r.point >= 0) {
    const PathPoint& a = pts[static_cast<size_t>(r.point)];
    char w[400];
    std::snprintf(w, sizeof w,
                  "warning: the path turns back on itself: from path point %d (load factor %.6g, control displacement %.6g) "
                  "it runs back along path points %d..%d, revisiting their states; try a smaller ds or ds_max, or "
                  "displacement control (docs/continuation.md)\n",
                  a.step, a.loadFactor, a.controlValue, pts[static_cast<size_t>(r.earlier)].step,
                  pts[static_cast<size_t>(r.earlier) + 1].step);
    PetscCall(PetscPrintf(ctx.comm, "%s", w));
    ctx.summaryLines += std::string("  ") + w;
  } else if (const PathTurnBack t = pathTurnBack(lambdas, controls); t.turn >= 0) {
    const PathPoint &l = pts[static_cast<size_t>(t.limit)], &a = pts[static_cast<size_t>(t.turn)], &b = pts[static_cast<size_t>(t.back)];
    char w[600];
    std::snprintf(w, sizeof w,
                  "warning: the path turns back on itself: after the limit point at path point %d (load factor %.6g), "
                  "the control displacement turns back at path point %d (%.6g) and runs back to %.6g at path point %d "
                  "(load factor %.6g), over %.0f%% of its way there, revisiting displacements it passed; check which "
                  "branch it follows (a smaller ds or ds_max, or displacement control; docs/continuation.md)\n",
                  l.step, l.loadFactor, a.step, a.controlValue, b.controlValue, b.step, b.loadFactor, 100 * t.fraction);
    PetscCall(PetscPrintf(ctx.comm, "%s", w));
    ctx.summaryLines += std::string("  ") + w;
  }
  ctx.times.continuation = MPI_Wtime() - t0 - (ctx.times.output - outBefore) - (ctx.times.analyses - anaBefore);
  ctx.times.continuationIts = 0;
  for (const StepReport& r : ctx.reports) ctx.times.continuationIts += r.newtonIterations;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
