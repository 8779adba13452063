// Reuse between the levels of a -target_error study (docs/accuracy.md, "Reuse between levels"): the
// converged states of a level's load steps (or path points), interpolated onto the next level's nodes,
// are that level's Newton starts (analysis/statics_handover.hpp; the path's predictor,
// ContinuationAnalysis::coarsePathGuess).
#pragma once
#include <vector>

#include "analysis/statics_handover.hpp"
#include "sinew/model.hpp"

namespace sinew::accuracy {

/// The levels of `m` can hand their states on: load-stepped statics or an arc-length path refined by
/// nbeams (not the split of membranes, not displacement control), the load steps or the arc-length path
/// after form finding (also of split membranes; accuracy/found_shape_reuse.hpp), or dynamics whose levels halve
/// dt alone (their time steps, analysis/time_handover.hpp; not with the elements refined too).
bool reusesStates(const Model& m);

/// The states `record` of level `coarse` on the FE nodes of level `fine` (nbeams x2 or equal per scene
/// element): a node both levels have keeps its state; a new midside node of a beam takes the cubic
/// Hermite of the element's deformed shape (the end positions and the tangents R d of the end rotations,
/// d the element's reference direction) and the geodesic mean of the end rotations; of an ANCF cable the
/// cubic Hermite positions and slopes at the midpoint; of a 3D cable the chord's midpoint. Empty when
/// the meshes do not nest that way.
std::vector<LevelState> interpolateStates(const Model& coarse, const Model& fine, const std::vector<LevelState>& record);

}  // namespace sinew::accuracy
