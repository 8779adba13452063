// The form-finding phase of a run (analysis/formfinding_analysis.hpp): one result row per
// form-finding step (load factor 0; the last row is the found shape; /formfinding/step numbers
// these rows), /formfinding/residual and /formfinding/shape_change, a summary table, then the
// elastic restart so that the load analysis continues in ctx.U.
#include <algorithm>
#include <cstdio>
#include <map>
#include <span>
#include <string>

#include "analysis/formfinding_analysis.hpp"
#include "app/phases/restart.hpp"
#include "app/phases/run_context.hpp"

namespace sinew {

namespace {
bool hasFormFound(const Model& m, ElementType type) {
  for (int s : formFoundSets(*m.formfinding, m.eprops))
    if (m.eprops[static_cast<size_t>(s)].type() == type) return true;
  return false;
}

}  // namespace

/// The causes of a collapse this model can have (issue 10 item 17): free membrane edges (boundary
/// edges of the form-found membranes with neither a 2-node element along them nor both nodes
/// supported), form-found edge cables, initial loads. Needs the scene's elements (before set-up
/// releases them).
std::string formFindingCollapseCauses(const Model& m) {
  const std::vector<int> sets = formFoundSets(*m.formfinding, m.eprops);
  bool cables = false, membranes = false, loads = false;
  std::map<std::pair<int, int>, int> edges;
  for (int s : sets) {
    const ElementSet& es = m.eprops[static_cast<size_t>(s)];
    cables |= es.type() == ElementType::Cable;
    if (es.type() != ElementType::Membrane) continue;
    membranes = true;
    for (int e : es.elems) {
      const auto& el = m.elements[static_cast<size_t>(e)];
      for (size_t j = 0; j < el.size(); ++j) {
        const int a = el[j], b = el[(j + 1) % el.size()];
        ++edges[{std::min(a, b), std::max(a, b)}];
      }
    }
  }
  for (const ElementSet& es : m.eprops)
    if (const auto* mp = es.as<MembraneProperties>()) loads |= mp->pressure_initial != 0.0;
  auto held = [&](int node) {
    auto it = m.nprops.find(node);
    if (it == m.nprops.end()) return false;
    const NodeProps& p = it->second;
    return p.fix || p.fix_pos || (p.fix_x && p.fix_y && p.fix_z);
  };
  for (const auto& [node, p] : m.nprops) loads |= norm(p.force_initial) > 0.0 || norm(p.moment_initial) > 0.0;
  std::map<std::pair<int, int>, bool> lines;  // 2-node elements (cables, beams) along membrane edges
  for (const auto& el : m.elements)
    if (el.size() == 2) lines[{std::min(el[0], el[1]), std::max(el[0], el[1])}] = true;
  long freeEdges = 0;
  for (const auto& [e, n] : edges)
    if (n == 1 && !lines.count(e) && !(held(e.first) && held(e.second))) ++freeEdges;
  std::vector<std::string> causes;
  if (freeEdges > 0)
    causes.push_back(std::to_string(freeEdges) +
                     " membrane edges lie on no support and no cable (a free edge contracts: add an edge cable or supports)");
  if (cables && membranes) causes.push_back("the membrane prestress is too low against the edge cables (raise it or lower the cable prestress)");
  if (cables && !membranes) causes.push_back("the cable prestresses do not balance (a cable is pulled to zero length)");
  if (loads) causes.push_back("the prestress is too low for the initial loads (force_initial, moment_initial, pressure_initial)");
  if (causes.empty())
    return "no free membrane edge, no edge cable and no initial load here: no surface with this prestress spans "
           "this boundary (e.g. a catenoid whose rings are more than 1.3255 radii apart)";
  std::string s;
  for (size_t i = 0; i < causes.size(); ++i) s += (i ? (i + 1 == causes.size() ? ", or " : ", ") : "") + causes[i];
  return s;
}

PetscErrorCode runFormFinding(RunContext& ctx) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().formfinding, 0, 0, 0, 0));
  const double t0 = MPI_Wtime();
  const double outBefore = ctx.times.output, anaBefore = ctx.times.analyses;
  const FormFinding& ff = *ctx.model.formfinding;
  FormFindingAnalysis analysis(ctx.assembler, ff, ctx.model.eprops, ctx.settings.formfinding);
  analysis.setStopFlag(ctx.status.stopFlag());
  analysis.setFailureHint(ctx.formfindingHint);
  if (ctx.restart && ctx.restart->phase() == CheckpointPhase::FormFinding)
    ctx.restart->resumeFormFinding(ctx, analysis);  // -restart: continue after its steps
  ctx.startPhase(StepPhase::FormFinding, "form-finding step", ff.formfinding_step);
  // the checkpoint of a written step: U, the form-finding history (the kernels' states are added
  // by the writer)
  auto state = [&](CheckpointData& d) -> PetscErrorCode {
    d.scalars[kCkPhase] = static_cast<double>(CheckpointPhase::FormFinding);
    d.scalars[kCkStep] = analysis.reports().empty() ? 0 : analysis.reports().back().step;
    d.formfinding = formfindingRows(analysis.reports());
    d.formfindingRows = ff.formfinding_step;
    d.vectors = {{"U", ctx.U}};
    return PETSC_SUCCESS;
  };
  ctx.checkpointState = state;
  auto onStep = [&](const FormFindingStepReport& r, Vec U) -> PetscErrorCode {
    LoadState ls;  // load factor 0
    char detail[160];
    std::snprintf(detail, sizeof detail, "Newton %d  residual %.3e  shape change %.3e", r.newtonIterations,
                  r.residualNorm, r.shapeChange);
    // every form-finding step is written (output_steps counts load and time steps), with its
    // number in /formfinding/step (NaN on the load or time steps): the XDMF times of these rows
    const double step = r.step;
    return ctx.convergedStep({r.step, r.step == ff.formfinding_step, 0.0, detail, false}, U, ls, [&] {
      ctx.file.writeStepRow("formfinding/step", std::span<const double>(&step, 1));
      return PETSC_SUCCESS;
    });
  };
  bool ok = false;
  PetscCall(analysis.run(ctx.U, onStep, &ok));
  if (ok) PetscCall(ctx.finishStepAnalyses(ctx.U));  // the found shape (form finding may end before formfinding_step)
  const auto& reps = analysis.reports();
  std::vector<double> res, change, normal;
  for (const auto& r : reps) {
    res.push_back(r.residualNorm);
    change.push_back(r.shapeChange);
    normal.push_back(r.shapeChangeNormal);
  }
  PetscErrorCode ierr = PETSC_SUCCESS;
  ctx.guardedWrite([&] {
    ctx.file.writeArray("formfinding/residual", res, {static_cast<long>(res.size())});
    ctx.file.writeArray("formfinding/shape_change", change, {static_cast<long>(change.size())});
    ctx.file.writeArray("formfinding/shape_change_normal", normal, {static_cast<long>(normal.size())});
    // the found shape before the elastic restart, kept for a restart with other loads (app/phases/restart.hpp)
    if (ok && !ctx.status.stopping()) ierr = ctx.writeCheckpoint("checkpoint_formfinding");
    if (!ierr) ctx.file.commit();
  });
  PetscCall(ierr);
  ctx.checkpointState = nullptr;
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
  if (hasFormFound(ctx.model, ElementType::Membrane)) {  // not for a pure cable net (issue 10 item 17)
    std::snprintf(line, sizeof line, "  membrane mesh quality: initial %.4f, found %.4f (1 = equilateral/square)\n",
                  analysis.initialMeshQuality(), reps.empty() ? analysis.initialMeshQuality() : reps.back().meshQuality);
    s += line;
  }
  if (!reps.empty()) {
    const double tff = MPI_Wtime() - t0 - (ctx.times.output - outBefore) - (ctx.times.analyses - anaBefore);
    std::snprintf(line, sizeof line, "  form-finding time %.3f s (%.4f s per step, output excluded)\n", tff,
                  tff / static_cast<double>(reps.size()));
    s += line;
  }
  ctx.summaryLines += s;
  ctx.times.formfinding = MPI_Wtime() - t0 - (ctx.times.output - outBefore) - (ctx.times.analyses - anaBefore);
  ctx.times.formfindingIts = 0;
  for (const auto& r : reps) ctx.times.formfindingIts += r.newtonIterations;
  if (!ok && !ctx.status.stopping()) {
    ctx.status.fail(analysis.failureMessage());
  } else if (ok && !ctx.status.stopping()) {
    PetscCall(analysis.restart(ctx.U));
  }
  PetscCall(PetscLogEventEnd(SinewEvents::get().formfinding, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
