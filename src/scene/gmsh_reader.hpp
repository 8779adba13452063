// Reader for Gmsh 4 ASCII meshes (format 4.0 and 4.1): nodes, first-order line / triangle /
// quad elements, point elements (for physical point groups) and named physical groups.
// Errors throw sinew::SceneError("mesh", "<file>:<line>: <what>").
#pragma once
#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "sinew/model.hpp"

namespace sinew {

struct GmshElement {
  int type = 0;        ///< Gmsh type: 1 line, 2 triangle, 3 quad, 15 point
  int dim = 0;         ///< dimension of the entity it is classified on
  int entityTag = 0;
  std::size_t tag = 0;            ///< Gmsh element tag
  std::vector<int> nodes;         ///< 0-based indices into GmshMesh::nodes
  std::vector<int> groups;        ///< indices into GmshMesh::groups
  int line = 0;                   ///< line in the file (for messages)
};

struct GmshPhysicalGroup {
  int dim = 0, tag = 0;
  std::string name;               ///< from $PhysicalNames; the tag as text when unnamed
  std::vector<int> elements;      ///< indices into GmshMesh::elements
  std::vector<int> nodes;         ///< sorted unique 0-based node indices of those elements
};

struct GmshMesh {
  std::string file;               ///< as given, for messages
  std::string version;            ///< "4.1" or "4"/"4.0"
  std::vector<Vec3> nodes;        ///< in file order
  std::vector<std::size_t> nodeTags;
  std::vector<int> nodeLines;     ///< line of each node's coordinates (for messages)
  std::vector<GmshElement> elements;  ///< in file order
  std::vector<GmshPhysicalGroup> groups;

  /// Group by name (any dimension, the first with that name), or nullptr.
  const GmshPhysicalGroup* findGroup(const std::string& name) const;
  std::vector<std::string> groupNames() const;
};

/// Nodes per element for the supported types (1, 2, 3, 15); 0 for others.
int gmshNodesPerElement(int type);

/// Parse Gmsh 4 ASCII text; `file` names the source in messages.
GmshMesh parseGmsh(std::istream& in, const std::string& file);
GmshMesh readGmsh(const std::string& path);

}  // namespace sinew
