// The form-finding phase of a run (analysis/formfinding_analysis.hpp): one result row per
// form-finding step (load factor 0; the last row is the found shape), /formfinding/residual and
// /formfinding/shape_change, a summary table, then the elastic restart so that the load analysis
// continues in ctx.U.
#include <cstdio>

#include "analysis/formfinding_analysis.hpp"
#include "app/run_context.hpp"

namespace sinew {

PetscErrorCode runFormFinding(RunContext& ctx) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().formfinding, 0, 0, 0, 0));
  const double t0 = MPI_Wtime();
  const double outBefore = ctx.times.output, anaBefore = ctx.times.analyses;
  const FormFinding& ff = *ctx.model.formfinding;
  FormFindingAnalysis analysis(ctx.assembler, ff, ctx.model.eprops);
  auto onStep = [&](const FormFindingStepReport&, Vec U) -> PetscErrorCode {
    LoadState ls;  // load factor 0
    return ctx.writeStep(0.0, U, ls);
  };
  bool ok = false;
  PetscCall(analysis.run(ctx.U, onStep, &ok));
  const auto& reps = analysis.reports();
  std::vector<double> res, change, normal;
  for (const auto& r : reps) {
    res.push_back(r.residualNorm);
    change.push_back(r.shapeChange);
    normal.push_back(r.shapeChangeNormal);
  }
  if (!reps.empty()) {  // (a step failing before any converged one leaves no history to write)
    ctx.file.writeArray("formfinding/residual", res, {static_cast<long>(res.size())});
    ctx.file.writeArray("formfinding/shape_change", change, {static_cast<long>(change.size())});
    ctx.file.writeArray("formfinding/shape_change_normal", normal, {static_cast<long>(normal.size())});
  }
  std::string s = "\n form finding (URS): " + std::to_string(analysis.numFormFoundElements()) +
                  " form-found elements, model size " ;
  char line[256];
  std::snprintf(line, sizeof line, "%.4g, restart %s\n  step  lambda  xURS  Newton its   residual  shape change  normal change  mesh quality\n",
                analysis.modelSize(), ff.elastic_restart_method.c_str());
  s += line;
  for (const auto& r : reps) {
    std::snprintf(line, sizeof line, " %5d  %6.3g  %4s  %10d  %9.3e  %12.4e  %13.4e  %12.4f%s\n", r.step, r.lambda,
                  r.xurs ? "yes" : "no", r.newtonIterations, r.residualNorm, r.shapeChange, r.shapeChangeNormal,
                  r.meshQuality,
                  r.equilibrium ? "" : "  (max_iter_equilibrium reached)");
    s += line;
  }
  std::snprintf(line, sizeof line, "  membrane mesh quality: initial %.4f, found %.4f (1 = equilateral/square)\n",
                analysis.initialMeshQuality(), reps.empty() ? analysis.initialMeshQuality() : reps.back().meshQuality);
  s += line;
  if (!reps.empty()) {
    const double tff = MPI_Wtime() - t0 - (ctx.times.output - outBefore) - (ctx.times.analyses - anaBefore);
    std::snprintf(line, sizeof line, "  form-finding time %.3f s (%.4f s per step, output excluded)\n", tff,
                  tff / static_cast<double>(reps.size()));
    s += line;
  }
  ctx.summaryLines += s;
  if (!ok) {
    ctx.converged = false;
    ctx.failure = analysis.failureMessage();
  } else {
    PetscCall(analysis.restart(ctx.U));
  }
  PetscCall(PetscLogEventEnd(SinewEvents::get().formfinding, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
