// Reuse between the levels of a -target_error study (docs/accuracy.md, "Reuse between levels"): the
// converged states of a level's load steps (or path points, or time steps), interpolated onto the next
// level's nodes, are that level's Newton starts (analysis/statics_handover.hpp; the path's predictor,
// ContinuationAnalysis::coarsePathGuess; dynamics, analysis/time_handover.hpp).
#pragma once
#include <vector>

#include "analysis/statics_handover.hpp"
#include "sinew/element_kernel.hpp"
#include "sinew/linalg3.hpp"
#include "sinew/model.hpp"

namespace sinew::accuracy {

/// The levels of `m` can hand their states on: load-stepped statics or an arc-length path refined by
/// nbeams (not the split of membranes, not displacement control), the load steps or the arc-length path
/// after form finding (also of split membranes; accuracy/found_shape_reuse.hpp), or dynamics (their time
/// steps, analysis/time_handover.hpp; with the elements refined too, the records mapped by LevelNodeMap).
bool reusesStates(const Model& m);

/// How the FE nodes of level `fine` lie on those of level `coarse`, and the map of node states (12 per
/// FE node, LevelState's layout) from the one to the other. Line elements (nbeams x2 or equal per scene
/// element): a node both levels have keeps its state; a new midside node of a beam takes the cubic
/// Hermite of the element's deformed shape (the end positions and the tangents R d of the end rotations,
/// d the element's reference direction) and the geodesic mean of the end rotations (BeamMidRotation); of an ANCF cable the
/// cubic Hermite positions and slopes at the midpoint; of a 3D cable the chord's midpoint. Split
/// membranes (accuracy/membrane_refinement.hpp; positions alone): a new node of an edge or a quad's
/// centre the mean of the coarse nodes it lies between. Invalid when the meshes do not nest that way.
enum class BeamMidRotation {
  GeodesicMean,   ///< the geodesic mean of the end rotations
  HermiteTangent  ///< that mean turned by the least rotation that takes its R d onto the cubic's tangent
};

class LevelNodeMap {
 public:
  LevelNodeMap(const Model& coarse, const Model& fine, BeamMidRotation rotation = BeamMidRotation::GeodesicMean);
  bool valid() const { return valid_; }
  std::size_t coarseNodes() const { return nc_; }
  std::size_t fineNodes() const { return kind_.size(); }
  /// The node states `coarse` (12 x coarse nodes) on the fine nodes (12 x fine nodes); empty when invalid
  /// or of another size.
  std::vector<double> apply(const std::vector<double>& coarse) const;
  /// apply() on every state of a record (load factors kept); empty when any state does not map.
  std::vector<LevelState> apply(const std::vector<LevelState>& record) const;

 private:
  bool valid_ = false;
  BeamMidRotation rotation_;
  std::size_t nc_ = 0;
  std::vector<NodeKind> kind_;            ///< per fine node
  std::vector<int> same_, midA_, midB_;   ///< per fine node: the coarse node it is, or the coarse line element's ends
  std::vector<Vec3> Xc_;                  ///< the coarse nodes' reference positions (the chords of the midpoints)
  std::vector<std::vector<int>> parents_; ///< split membranes: per new node (from nc_) the coarse nodes of its mean
};

/// The states `record` of level `coarse` on the FE nodes of level `fine` (LevelNodeMap, line elements).
/// Empty when the meshes do not nest that way.
std::vector<LevelState> interpolateStates(const Model& coarse, const Model& fine, const std::vector<LevelState>& record);

}  // namespace sinew::accuracy
