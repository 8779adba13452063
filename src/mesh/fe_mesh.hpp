// The finite element mesh derived from a scene: scene elements split into `nbeams` finite
// elements, node kinds chosen from the elements that meet at each node. Built on every rank
// during set-up only (it holds global arrays); the solve uses the distributed LocalMesh.
#pragma once
#include <array>
#include <vector>

#include "sinew/element_kernel.hpp"
#include "sinew/model.hpp"

namespace sinew {

struct FeElement {
  int sceneElement = 0;  ///< 0-based scene element
  int set = -1;          ///< eprops set, -1 = rigid massless beam
  int numNodes = 0;
  std::array<int, 4> nodes{};  ///< FE node ids
};

struct FeMesh {
  int numSceneNodes = 0;
  std::vector<Vec3> X;                     ///< reference positions; scene nodes first
  std::vector<NodeKind> kind;              ///< per FE node
  std::vector<std::array<double, 2>> slope;  ///< ANCF reference slope per node (unit), {1,0} otherwise
  std::vector<FeElement> elements;
  /// Per FE node: 0 for a trailing scene node no element connects (held fixed, no unknowns).
  std::vector<char> connected;
  /// First FE element and count of each scene element (nbeams split).
  std::vector<int> sceneElementFirst, sceneElementCount;
};

ElementType elementTypeOf(const Model& model, int sceneElement);
/// Splits scene elements, assigns node kinds and ANCF slopes. Throws SceneError for nodes that
/// no element connects, except trailing ones (after the last connected node, as SPACAR Light allows).
FeMesh discretize(const Model& model);

}  // namespace sinew
