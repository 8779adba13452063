// -target_error through the library entry (sinew::run, the Python module; docs/accuracy.md "From
// the library and Python"): the same levels as the command line (src/app/phases/run_accuracy.cpp),
// the answer the reported level's RunOutput with the study added.
#pragma once
#include <mpi.h>

#include <optional>

#include "settings/settings.hpp"
#include "sinew/simulation.hpp"

namespace sinew {

/// nullopt when the scene asks for no target_error (or cannot be read: the ordinary run reports
/// that). Else the study's answer: the reported level's results in memory with /accuracy as datasets
/// "accuracy/..." and the group texts "accuracy" (or, with settings.output.file, that level's result
/// file with /accuracy added); its output is the levels' lines, the level's own output and the
/// accuracy table; exitCode 3 with a message when the target was not reached within
/// -accuracy_max_unknowns. Throws RunError for a scene -target_error cannot refine (exit 2) or a
/// failing level (its exit code). Collective.
std::optional<RunOutput> runTargetErrorInLibrary(MPI_Comm comm, const SceneSource& scene, const Settings& settings,
                                                 bool echo);

}  // namespace sinew
