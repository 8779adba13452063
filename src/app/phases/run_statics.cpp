// The statics phase: SPACAR Light's load steps (StaticAnalysis) from the current state, each
// converged step written through the run context, the checkpoint state of the load stepping, and on
// a failed linear solve the constraint check that names a mechanism.
#include <algorithm>
#include <cstdio>
#include <string>

#include "analysis/constraint_check.hpp"
#include "analysis/static_analysis.hpp"
#include "app/phases/model_checks.hpp"
#include "app/phases/restart.hpp"
#include "app/phases/run_context.hpp"
#include "parallel/collective_error.hpp"

namespace sinew {

PetscErrorCode runStatics(RunContext& ctx, bool resumeStatics, const ConstraintCheckSetting& check, bool* modelError) {
  PetscFunctionBeginUser;
  const Model& model = ctx.model;
  const Plan& plan = ctx.plan;
  const Settings& settings = ctx.settings;
  Assembler& assembler = ctx.assembler;
  const DistributedMesh& dmesh = assembler.mesh();
  const Restart* restart = ctx.restart;
  const double tStatics = MPI_Wtime();
  const double outBefore = ctx.times.output, anaBefore = ctx.times.analyses;
  // a restart keeps the earlier run's ramp (its loadsteps and opt.load_ramp, checked equal by Restart):
  // -loadsteps is the last step, the load factor of step k stays StaticAnalysis::stepFactor(k)
  const int ramp = resumeStatics ? restart->rampLoadsteps() : model.opt.loadsteps;
  // a restart continues the interrupted plan to its end (load factor 1 at step `ramp`, also when the
  // scene's own opt.loadsteps is what the earlier run's -loadsteps overrode), or to a later step of
  // the scene; -loadsteps N on the restart is the last step, before or after the ramp's end
  const int lastStep = lastLoadStepOf(resumeStatics ? restart : nullptr, model, settings);
  StaticAnalysis statics(assembler, ramp, settings.statics, settings.ancf);
  statics.setLastStep(lastStep);
  statics.setUnloaded(unloaded(model, dmesh, assembler));
  statics.setStopFlag(ctx.status.stopFlag());
  statics.setUniformRamp(model.opt.load_ramp == "uniform");
  statics.setStartIsInitialState(!initiallyLoaded(model, dmesh));
  statics.setTimeZero(plan.preload);  // the time loop starts at t = 0 from the last load step
  if (!resumeStatics) statics.setHandover(settings.accuracy.handover.get());  // a -target_error level
  if (resumeStatics) PetscCall(restart->resumeStatics(ctx, statics));
  ctx.checkpointState = [&](CheckpointData& d) -> PetscErrorCode {
    const StaticsProgress& p = statics.progress();
    d.scalars[kCkPhase] = static_cast<double>(CheckpointPhase::Statics);
    d.scalars[kCkStep] = p.step;
    d.scalars[kCkStepValue] = p.lambda;
    d.scalars[kCkLoadsteps] = ramp;
    d.scalars[kCkLoadRamp] = model.opt.load_ramp == "uniform" ? 1.0 : 0.0;
    d.scalars[kCkLambda] = p.lambda;
    d.scalars[kCkDlPrev] = p.dlPrev;
    d.scalars[kCkDlAdapt] = p.dlAdapt;
    d.scalars[kCkFintConverged] = p.fintConverged;
    d.vectors = {{"U", ctx.U}, {"dU", statics.lastIncrement()}};
    return PETSC_SUCCESS;
  };
  if (resumeStatics && lastStep < ramp && !model.opt.silent)
    PetscCall(PetscPrintf(ctx.comm, "  note: -loadsteps %d ends this restart at load factor %.6g; the earlier run's ramp reaches "
                                    "load factor 1 at step %d (a restart without -loadsteps goes there)\n",
                          lastStep, statics.stepFactor(lastStep), ramp));
  ctx.startPhase(StepPhase::Statics, "load step", lastStep);
  auto onStep = [&](const StepReport& rep, Vec Ustep) -> PetscErrorCode {
    LoadState ls;
    ls.loadFactor = rep.loadFactor;
    ls.time = plan.preload ? 0.0 : rep.loadFactor;
    char detail[160];
    std::snprintf(detail, sizeof detail, "load factor %.4g  Newton %d  increments %d  residual %.3e", rep.loadFactor,
                  rep.newtonIterations, rep.increments, rep.residualNorm);
    RunContext::Step st{rep.step, rep.step == lastStep, rep.loadFactor, detail};
    if (plan.preload) {  // a row of /time (0: before the time loop) with its load factor in /load_factor
      st.value = 0.0;
      st.loadFactorRow = rep.loadFactor;
    }
    return ctx.convergedStep(st, Ustep, ls);
  };
  bool ok = false;
  PetscCall(statics.run(ctx.U, onStep, &ok));
  if (!ok) PetscCall(ctx.writeSkippedLast(ctx.U));  // ctx.U holds the last converged state
  else PetscCall(ctx.finishStepAnalyses(ctx.U));
  ctx.checkpointState = nullptr;
  ctx.reports = statics.reports();
  if (const CableCoarseSpace* cs = statics.coarseSpace())
    ctx.summaryLines += "  cable coarse space: " + std::to_string(cs->coarseNodes()) + " coarse nodes, " +
                        std::to_string(cs->setups()) + " set-ups, " + std::to_string(cs->applications()) +
                        " applications; coarse predictor " + std::to_string(cs->predictorIterations()) +
                        " Newton iterations\n";
  if (!ok && ctx.status.converged()) {
    ctx.status.fail(statics.failureMessage());
    if (statics.linearSolveFailed() && check.enabled) {  // name the mechanism / redundancy if there is one
      LoadState ls;
      ls.loadFactor = ls.time = ctx.reports.empty() ? 0.0 : ctx.reports.back().loadFactor;
      ConstraintReport report;
      PhaseScope checkAfter("the constraint check after the failed step");
      PetscCall(checkConstraints(assembler, model, ctx.U, ls, settings.check, settings.statics.denseMaxUnknowns, &report));
      if (report.singular) {
        ctx.status.explainFailure(report.message);
        *modelError = true;
      }
    }
  }
  ctx.times.statics = MPI_Wtime() - tStatics - (ctx.times.output - outBefore) - (ctx.times.analyses - anaBefore);
  ctx.times.staticsIts = 0;
  for (const StepReport& r : ctx.reports) ctx.times.staticsIts += r.newtonIterations;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
