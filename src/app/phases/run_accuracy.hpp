// -target_error on the command line: the scene solved on levels of refinement through the library
// entry (sinew::run), in memory, the reported level into the result file, then /accuracy and the
// accuracy table (src/accuracy/refinement_study.hpp, docs/accuracy.md).
#pragma once
#include <petscsys.h>

#include <set>
#include <string>

#include "accuracy/refinement_study.hpp"
#include "parallel/collective_error.hpp"
#include "settings/settings.hpp"

namespace sinew {

/// Runs `sinew scene.yaml` with opt.target_error (from the scene or -target_error); *handled =
/// false when the scene does not ask for it (the caller runs it as usual). exitCode: 0 when the
/// target was met and the reported level converged; 3 when the target was not reached within
/// -accuracy_max_unknowns (the file holds the best level); 2 for a scene error or a scene whose
/// refinement -target_error cannot do yet; else the failing level's exit code. Collective. Installs
/// no error handler of its own: every level is a library run with its own.
PetscErrorCode runWithTargetError(int argc, char** argv, bool* handled, int* exitCode);

/// What -target_error cannot refine in `model` with `settings`: "" or the reason (a scene error).
std::string targetErrorLimit(const Model& model, const Settings& settings);
/// One level through the library entry (sinew::run, its own error handler): in memory (every dataset
/// in the results), or into `h5` with `datasets` read back. scenePath names the scene in messages.
accuracy::LevelRun runAccuracyLevel(MPI_Comm comm, const Settings& settings, const std::string& scenePath,
                                    const std::string& h5, const Model& model, bool toFile,
                                    const std::set<std::string>& datasets,
                                    const std::shared_ptr<StaticsHandover>& handover);

/// Adds /accuracy of `study` to the closed result file `h5` (rank 0 writes) and agrees on the outcome:
/// a failure (exit code 1, "error: writing /accuracy: ...") on every rank, or none. Collective.
RunFailure writeAccuracyToFile(MPI_Comm comm, const std::string& h5, const accuracy::StudyResult& study);

}  // namespace sinew
