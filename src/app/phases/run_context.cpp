#include "app/phases/run_context.hpp"

#include <algorithm>
#include <array>

#include "app/interrupt.hpp"
#include "parallel/collective_error.hpp"

namespace sinew {

namespace {

const char* phaseRowsName(StepPhase p) {
  switch (p) {
    case StepPhase::FormFinding: return "form finding";
    case StepPhase::Statics: return "load steps";
    case StepPhase::Continuation: return "path following";
    default: return "dynamics";
  }
}

std::string rowsText(const StepAnalysisRows& r) {
  switch (r.kind) {
    case StepAnalysisRows::Kind::All: return "all";
    case StepAnalysisRows::Kind::Last: return "last";
    case StepAnalysisRows::Kind::None: return "none";
    default: return "every:" + std::to_string(r.every);
  }
}

}  // namespace

void RunContext::startPhase(StepPhase phase, const char* stepName, int steps) {
  progress.startPhase(stepName, steps);
  status.enterPhase(stepName);
  StepAnalysisRows byDefault;  // SPACAR Light: out.freq, out.CMglob per load step
  if (phase != StepPhase::Statics) byDefault.kind = StepAnalysisRows::Kind::Last;
  rows_ = model.opt.step_analyses.value_or(byDefault);
  phaseFirstRow_ = nextStep;
  phases_.emplace_back(phase, rows_);
}

bool RunContext::selectsAnalysisRow(bool last) const {
  const std::vector<long>& done = file.analysisRows();
  switch (rows_.kind) {
    case StepAnalysisRows::Kind::All: return true;
    case StepAnalysisRows::Kind::None: return false;
    case StepAnalysisRows::Kind::Last: return last;
    default: return last || done.empty() || nextStep - done.back() >= rows_.every;
  }
}

PetscErrorCode RunContext::runStepAnalyses(Vec Ustate, const LoadState& ls, bool everyRow) {
  PetscFunctionBeginUser;
  bool open = false;
  for (auto& a : stepAnalyses) {
    if (a->everyRow() != everyRow) continue;
    if (!everyRow && !open) {
      file.beginAnalysisRow();
      open = true;
    }
    const double ta = MPI_Wtime();
    bool ok = true;
    PhaseScope analysisPhase(a->name());
    PetscCall(a->atStep(Ustate, ls, file, &ok));
    times.analyses += MPI_Wtime() - ta;
    if (!ok) status.fail(a->failure());
  }
  if (open) file.endAnalysisRow();
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RunContext::writeStep(double stepValue, Vec Ustate, const LoadState& ls, bool analyses) {
  PetscFunctionBeginUser;
  const double tOut = MPI_Wtime();
  file.beginStep(nextStep++, stepValue);
  lastLoads_ = ls;
  PhaseScope phase("the output of the results");
  PetscCall(results.write(file, Ustate, ls));
  times.output += MPI_Wtime() - tOut;
  if (analyses) PetscCall(runStepAnalyses(Ustate, ls, false));
  PetscCall(runStepAnalyses(Ustate, ls, true));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RunContext::finishStepAnalyses(Vec Ustate) {
  PetscFunctionBeginUser;
  const std::vector<long>& done = file.analysisRows();
  const bool wanted = rows_.kind == StepAnalysisRows::Kind::Last || rows_.kind == StepAnalysisRows::Kind::Every;
  const bool any = std::any_of(stepAnalyses.begin(), stepAnalyses.end(), [](const auto& a) { return !a->everyRow(); });
  if (!wanted || !any || status.stopping() || nextStep <= phaseFirstRow_) PetscFunctionReturn(PETSC_SUCCESS);
  if (!done.empty() && done.back() == nextStep - 1) PetscFunctionReturn(PETSC_SUCCESS);  // the last row has them
  PetscErrorCode ierr = PETSC_SUCCESS;
  guardedWrite([&] {
    ierr = runStepAnalyses(Ustate, lastLoads_, false);
    if (!ierr) {
      const double t = MPI_Wtime();
      file.commit();
      times.output += MPI_Wtime() - t;
    }
  });
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::string RunContext::stepAnalysisLine() const {
  std::string names;
  for (const auto& a : stepAnalyses)
    if (!a->everyRow()) names += (names.empty() ? "" : ", ") + std::string(a->name());
  if (names.empty() || phases_.empty()) return {};
  const long m = static_cast<long>(file.analysisRows().size()), ns = file.stepsWritten();
  std::string where;
  if (m == ns) where = ns == 1 ? "at the one row" : "at all " + std::to_string(ns) + " rows";
  else if (m == 0) where = "at none of the " + std::to_string(ns) + " rows";
  else if (m == 1 && file.analysisRows().back() == ns - 1) where = "at the last of " + std::to_string(ns) + " rows";
  else where = "at " + std::to_string(m) + " of " + std::to_string(ns) + " rows";
  std::string why;
  bool everyRow = true;
  if (model.opt.step_analyses) {
    why = "opt.step_analyses: " + rowsText(*model.opt.step_analyses);
    everyRow = model.opt.step_analyses->kind == StepAnalysisRows::Kind::All;
  } else {
    for (const auto& [phase, rows] : phases_) {
      why += (why.empty() ? "" : ", ") + std::string(phaseRowsName(phase)) + ": " + rowsText(rows);
      everyRow = everyRow && rows.kind == StepAnalysisRows::Kind::All;
    }
    why = "opt.step_analyses default, " + why;
  }
  if (!everyRow) why += "; -step_analyses all for every row";
  return "\n step analyses: " + names + " " + where + " (" + why + ")\n";
}

PetscErrorCode RunContext::writeCheckpoint(const std::string& group) {
  PetscFunctionBeginUser;
  if (!checkpoint || !checkpointState) PetscFunctionReturn(PETSC_SUCCESS);
  const double t = MPI_Wtime();
  CheckpointData d;
  PetscCall(checkpointState(d));
  d.scalars[kCkRows] = nextStep;
  d.scalars[kCkFormFinding] = plan.formfinding ? 1.0 : 0.0;
  if (model.formfinding && d.formfindingRows == 0) d.formfindingRows = model.formfinding->formfinding_step;
  checkpoint->write(file, d, group);
  times.checkpoint += MPI_Wtime() - t;
  times.output += MPI_Wtime() - t;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RunContext::writeLoadFactorRow(const std::optional<double>& loadFactor) {
  PetscFunctionBeginUser;
  if (loadFactor) file.writeStepRow("load_factor", std::array<double, 1>{*loadFactor});
  PetscFunctionReturn(PETSC_SUCCESS);
}

bool RunContext::guardedWrite(const std::function<void()>& write) {
  if (!status.writeOk()) return false;
  try {
    write();
    return true;
  } catch (const std::exception& e) {  // thrown on every rank together (ResultFile agrees on failures)
    status.writeFailed(e.what());
    return false;
  }
}

PetscErrorCode RunContext::convergedStep(const Step& s, Vec Ustate, const LoadState& ls,
                                         const std::function<PetscErrorCode()>& afterWrite) {
  PetscFunctionBeginUser;
  if (status.stopping()) PetscFunctionReturn(PETSC_SUCCESS);  // a step a solver finished after the stop: abandoned
  if (const int sig = agreedInterrupt(comm)) status.interrupt(sig);
  // -stop_after_step k (a testing aid): stop as on SIGTERM once the file holds k step rows (equal on every rank)
  const int stopAfterRows = settings.output.stopAfterStep;
  if (!status.stopping() && stopAfterRows > 0 && nextStep + 1 >= stopAfterRows)
    status.interrupt(RunStatus::kStopAfterStep);
  status.reached(s.index);
  const bool write =
      !s.selectable || s.last || status.stopping() || model.opt.output_steps.selects(s.index, s.last);
  if (write) {
    PetscErrorCode ierr = PETSC_SUCCESS;
    guardedWrite([&] {
      ierr = writeStep(s.value, Ustate, ls, selectsAnalysisRow(s.last));
      if (!ierr) ierr = writeLoadFactorRow(s.loadFactorRow);
      if (!ierr && afterWrite) ierr = afterWrite();
      if (!ierr) ierr = writeCheckpoint();  // same commit as the step: no flush of its own
      if (!ierr) {
        const double t = MPI_Wtime();
        file.commit();
        times.output += MPI_Wtime() - t;
      }
    });
    PetscCall(ierr);
    skipped_.any = false;
  } else {
    skipped_ = {true, s.value, ls, s.loadFactorRow};
  }
  if (status.writeOk()) progress.step(s.index, s.detail);  // a step whose write failed is not reported as done
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RunContext::writeSkippedLast(Vec Ustate) {
  PetscFunctionBeginUser;
  if (!skipped_.any || !status.writeOk()) PetscFunctionReturn(PETSC_SUCCESS);
  skipped_.any = false;
  PetscErrorCode ierr = PETSC_SUCCESS;
  guardedWrite([&] {
    ierr = writeStep(skipped_.value, Ustate, skipped_.ls, selectsAnalysisRow(false));
    if (!ierr) ierr = writeLoadFactorRow(skipped_.loadFactorRow);
    if (!ierr) ierr = writeCheckpoint();
    if (!ierr) file.commit();
  });
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
