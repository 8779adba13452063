// The levels of -target_error for scenes with membranes (docs/accuracy.md "Membranes"): each level
// splits every membrane element in four (a triangle into its corner triangles and the middle one, a
// quad into four quads) and every 2-node element (cable, beam) in two, at one midpoint node per edge
// shared by everything on that edge, so edge cables stay connected to the membrane. The scene's nodes
// keep their numbers; the new nodes follow them.
#pragma once
#include <string>
#include <vector>

#include "sinew/model.hpp"

namespace sinew::accuracy {

/// Whether the model has membrane elements (elements of more than 2 nodes in a set).
bool hasMembranes(const Model& m);

/// What the membrane refinement cannot split: "" or the reason.
std::string membraneRefinementLimit(const Model& m);

/// The model split `times` times (element length h / 2^times). Nodal properties stay on the scene's
/// nodes; a midpoint node is held in a translation component (or fixed) when both nodes of its edge
/// are, and gets the mean of their prescribed displacements where both prescribe a component by number.
Model splitMembraneModel(const Model& base, int times);

/// The nodes one split of `coarse` adds (numbered from coarse.nodes.size(), in order): per new node the
/// coarse nodes it lies between, the two ends of an edge or the four corners of a quad.
std::vector<std::vector<int>> splitParents(const Model& coarse);

}  // namespace sinew::accuracy
