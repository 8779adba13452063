// Reuse between the levels of a -target_error study for the load analysis after form finding
// (docs/accuracy.md, "Reuse between levels"): each level's reference is its own found shape, so what a
// coarser level hands on is its displacement from that shape at each load step, interpolated onto the
// finer level's nodes; the finer level starts each load step's Newton from its own found shape plus that
// displacement, and an arc-length path takes its own found shape plus the coarser path's displacements as
// the coarser path (predictor and step plan; analysis/statics_handover.hpp, StaticsHandover::fromStart).
#pragma once
#include <vector>

#include "analysis/statics_handover.hpp"
#include "sinew/model.hpp"

namespace sinew::accuracy {

/// The displacements record - start (positions; the other entries 0) of level `coarse` on the FE nodes of
/// level `fine`: a node both levels have keeps its displacement; a new node of a split cable, of a membrane
/// edge (accuracy/membrane_refinement.hpp) or a quad's centre the mean of the displacements of the coarse
/// nodes it lies between. Empty when a level has nodes other than positions alone (beams, ANCF cables), or
/// the meshes do not nest that way.
std::vector<LevelState> interpolateDisplacements(const Model& coarse, const Model& fine, const std::vector<LevelState>& record,
                                                 const LevelState& start);

}  // namespace sinew::accuracy
