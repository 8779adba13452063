#include "app/runner.hpp"

#include "app/command_line.hpp"
#include "app/phases/run_accuracy.hpp"
#include "app/scene_run.hpp"
#include "parallel/collective_error.hpp"
#include "settings/read_settings.hpp"

namespace sinew {
namespace {

/// `sinew scene.yaml [flags]`: the settings from the options database (the command line was
/// checked by handleCommandLine), the scene's run into its result file.
PetscErrorCode runScene(int argc, char** argv, int* exitCode) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PETSC_COMM_WORLD;
  *exitCode = 0;
  PetscBool help = PETSC_FALSE;
  PetscCall(petscHelpRequested(&help));
  if (argc < 2 || argv[1][0] == '-') {
    if (!help) {
      PetscCall(PetscPrintf(comm, "usage: sinew scene.yaml [-o result.h5] [options]; sinew -help lists the options\n"));
      *exitCode = 2;
    }
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  // every flag's setting, read once (the command line was checked by handleCommandLine)
  Settings settings;
  PetscCall(readSettings(nullptr, &settings));
  SceneRun run(comm, SceneSource::file(argv[1]), settings, true);
  PetscCall(run.setUp());
  if (run.ready()) {
    PetscCall(run.runAnalyses());
    PetscCall(run.finish());
  }
  *exitCode = run.exitCode();
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

PetscErrorCode runFromCommandLine(int argc, char** argv, int* exitCode) {
  PetscFunctionBeginUser;
  // opt.target_error: levels of refinement, each a library run with its own error handler
  bool handled = false;
  PetscCall(runWithTargetError(argc, argv, &handled, exitCode));
  if (handled) PetscFunctionReturn(PETSC_SUCCESS);
  // PETSc/SLEPc errors: recorded with the phase, returned on every rank together, reported once
  // (exit 4; exit 3 for a non-finite element force law). 10 s: how long a failing rank waits for the
  // others before it ends the job alone (they wait in a collective it will never join).
  SolverErrorGuard guard(PETSC_COMM_WORLD, 10.0);
  PetscErrorCode ierr = PETSC_SUCCESS;
  try {
    ierr = runScene(argc, argv, exitCode);
  } catch (const SolverCallError& e) {  // a constructor's PETSc call failed (SinewCallThrow)
    ierr = e.code();
  }
  if (ierr) *exitCode = reportRunFailure(PETSC_COMM_WORLD, ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
