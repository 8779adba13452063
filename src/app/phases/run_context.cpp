#include "app/phases/run_context.hpp"

#include <array>

#include "app/interrupt.hpp"
#include "parallel/collective_error.hpp"

namespace sinew {

PetscErrorCode RunContext::writeStep(double stepValue, Vec Ustate, const LoadState& ls) {
  PetscFunctionBeginUser;
  const double tOut = MPI_Wtime();
  file.beginStep(nextStep++, stepValue);
  PhaseScope phase("the output of the results");
  PetscCall(results.write(file, Ustate, ls));
  times.output += MPI_Wtime() - tOut;
  for (auto& a : stepAnalyses) {
    const double ta = MPI_Wtime();
    bool ok = true;
    PhaseScope analysisPhase(a->name());
    PetscCall(a->atStep(Ustate, ls, file, &ok));
    times.analyses += MPI_Wtime() - ta;
    if (!ok && converged) {
      converged = false;
      failure = a->failure();
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
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
  if (!ioError.empty()) return false;
  try {
    write();
    return true;
  } catch (const std::exception& e) {  // thrown on every rank together (ResultFile agrees on failures)
    ioError = e.what();
    stop = true;
    return false;
  }
}

PetscErrorCode RunContext::convergedStep(const Step& s, Vec Ustate, const LoadState& ls,
                                         const std::function<PetscErrorCode()>& afterWrite) {
  PetscFunctionBeginUser;
  if (stop) PetscFunctionReturn(PETSC_SUCCESS);  // a step a solver finished after the stop: abandoned
  if (const int sig = agreedInterrupt(comm)) {
    interruptSignal = sig;
    stop = true;
  }
  if (!stop && stopAfterRows > 0 && nextStep + 1 >= stopAfterRows) {  // equal on every rank
    interruptSignal = kStopAfterStep;
    stop = true;
  }
  lastStepIndex = s.index;
  const bool write = !s.selectable || s.last || stop || model.opt.output_steps.selects(s.index, s.last);
  if (write) {
    PetscErrorCode ierr = PETSC_SUCCESS;
    guardedWrite([&] {
      ierr = writeStep(s.value, Ustate, ls);
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
  if (ioError.empty()) progress.step(s.index, s.detail);  // a step whose write failed is not reported as done
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RunContext::writeSkippedLast(Vec Ustate) {
  PetscFunctionBeginUser;
  if (!skipped_.any || !ioError.empty()) PetscFunctionReturn(PETSC_SUCCESS);
  skipped_.any = false;
  PetscErrorCode ierr = PETSC_SUCCESS;
  guardedWrite([&] {
    ierr = writeStep(skipped_.value, Ustate, skipped_.ls);
    if (!ierr) ierr = writeLoadFactorRow(skipped_.loadFactorRow);
    if (!ierr) ierr = writeCheckpoint();
    if (!ierr) file.commit();
  });
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
