// What -target_error leaves behind: the /accuracy group of the result file (docs/results.md), the
// table of the summary, and the read-back of a level's datasets from the result file it wrote.
#pragma once
#include <set>
#include <string>

#include "accuracy/refinement_study.hpp"
#include "sinew/result_store.hpp"

namespace sinew::accuracy {

/// The datasets `names` (float) and the root attribute nunknowns of a closed result file (local:
/// every rank reads it). Throws std::runtime_error naming the file and the dataset.
RunResults readResultDatasets(const std::string& path, const std::set<std::string>& names);

/// Adds /accuracy to the closed result file (local: one rank writes). Per level l and quantity q:
///   level [nl] (0, 1, ...), nbeams_factor [nl], unknowns [nl], wall_time [nl] (s), worst_error [nl]
///   (NaN below level 2), limiting [nl] (quantity index, -1 none), error [nl, nq], order [nl, nq],
///   status [nl, nq] (0 converging, 1 resolved, 2 erratic, -1 no estimate), value [nl, nq, m]
///   (m = the most components of a quantity, NaN-padded), extrapolated [nq, m] (finest level,
///   converging quantities only). Attributes: quantities (one name a line), target, met, level
///   (the reported one), stop_reason, refinement ("elements / 2^level", "dt / 2^level" or "elements and
///   dt / 2^level"). Throws std::runtime_error on an HDF5 failure.
void writeAccuracyGroup(const std::string& path, const StudyResult& study);

/// The same datasets as RunResults (names "accuracy/level", ...) and the attributes as texts of group
/// "accuracy" (target as %.10g, met and level as integers): the in-memory answer of the library.
RunResults accuracyResults(const StudyResult& study);

/// The summary's table: one line per level (unknowns, time, worst estimate, limiting quantity), then
/// per quantity the reported level's value, its estimate, observed order and extrapolated value.
std::string accuracyTable(const StudyResult& study);

}  // namespace sinew::accuracy
