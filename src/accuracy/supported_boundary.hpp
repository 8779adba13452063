// The supported boundary of a form-finding membrane (docs/accuracy.md "Form finding"): the fixed
// nodes along the membrane's free edges are the shape's boundary curve (the rings of a catenoid), so a
// level's new node on such an edge goes on that curve, not on the chord. The curve through an edge
// (a, b) is the circle through a, b and the next supported boundary node beyond a (and beyond b: the
// mean of the two midpoints), which keeps circles and straight lines exact at every level.
#pragma once
#include <map>
#include <optional>
#include <vector>

#include "sinew/model.hpp"

namespace sinew::accuracy {

class SupportedBoundary {
 public:
  /// The boundary edges (used by one membrane element) between two `fix` nodes of `m`.
  explicit SupportedBoundary(const Model& m);
  /// The midpoint of edge (a, b) on the boundary curve, or nothing when (a, b) is no such edge or
  /// neither end has a supported boundary neighbour.
  std::optional<Vec3> midpoint(int a, int b) const;

 private:
  const Model& model_;
  std::map<int, std::vector<int>> neighbours_;  ///< node -> the other ends of its supported boundary edges
};

}  // namespace sinew::accuracy
