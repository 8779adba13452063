// Scene -> plan of analyses -> run -> result file and summary.
#pragma once
#include <petscsys.h>

namespace sinew {

/// Runs the scene named on the command line. exitCode: 0 when every requested analysis
/// converged, 2 for scene errors, 3 when an analysis failed, 1 for other errors.
PetscErrorCode runFromCommandLine(int argc, char** argv, int* exitCode);

}  // namespace sinew
