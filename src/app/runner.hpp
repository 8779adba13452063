// Scene -> plan of analyses -> run -> result file and summary.
#pragma once
#include <petscsys.h>

namespace sinew {

/// Runs the scene named on the command line. exitCode: 0 when every requested analysis
/// converged, 1 for output and other errors, 2 for scene errors, 3 when an analysis failed (or a
/// force law was not finite), 4 for an internal solver error (a PETSc/SLEPc error, caught on every
/// rank), 5 when interrupted. Installs Sinew's PETSc error handler for the run.
PetscErrorCode runFromCommandLine(int argc, char** argv, int* exitCode);

}  // namespace sinew
