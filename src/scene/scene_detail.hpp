// Internal pieces of the scene reader, shared by scene_reader.cpp, eprops.cpp, nprops.cpp and
// options.cpp. Each parse* function reads one top-level block of the scene into the Model.
#pragma once
#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

#include "scene/gmsh_reader.hpp"
#include "scene/yaml_fields.hpp"
#include "sinew/model.hpp"

namespace sinew::scene {

struct SceneContext {
  explicit SceneContext(Model& m) : model(m) {}
  Model& model;
  std::size_t sceneNodes = 0;     ///< nodes given in `nodes:` (mesh nodes follow)
  std::size_t sceneElements = 0;  ///< elements given in `elements:` (mesh elements follow)
  std::optional<GmshMesh> mesh;
  std::vector<int> meshElementToModel;  ///< Gmsh element index -> 0-based model element, -1 = not added
  std::vector<int> modelElementToMesh;  ///< model element - sceneElements -> Gmsh element index
  std::vector<std::vector<std::string>> setPhysical;  ///< per eprops set: its `physical:` names
  bool restart = false;  ///< the run continues a checkpoint: opt.output_steps is checked against its plan later

  /// "elements[i]" for scene elements, "mesh" for elements from the Gmsh file.
  std::string elementPath(int e) const;
  /// "element 12" plus, for mesh elements, " (file.msh:40)".
  std::string elementLabel(int e) const;
  bool isMeshElement(int e) const { return static_cast<std::size_t>(e) >= sceneElements; }
};

double elementLength(const Model& m, int e);

/// 1-based number -> 0-based index, checked against count ("node"/"element"/"eprops set").
int checkedIndex(const YAML::Node& n, const std::string& path, const std::string& what, std::size_t count);

/// The same for a map key; a quoted integer ("1", a JSON object key) is the number.
int checkedKeyIndex(const YAML::Node& key, const std::string& path, const std::string& what, std::size_t count);

/// Pre-scan of `eprops` for `physical:` names (needed before adding mesh elements).
std::vector<std::vector<std::string>> scanPhysicalNames(const YAML::Node& eprops);
/// Pre-scan of `nprops` for node-group keys (keys that are not node numbers).
std::vector<std::string> scanNodeGroupKeys(const YAML::Node& nprops);

void parseEprops(const YAML::Node& eprops, SceneContext& ctx);
void checkElementTypes(SceneContext& ctx);
void parseNprops(const YAML::Node& nprops, SceneContext& ctx);
void parseOptions(const YAML::Node& opt, SceneContext& ctx);
void parseFormfinding(const YAML::Node& ff, SceneContext& ctx);
void parseSensors(const YAML::Node& sensors, SceneContext& ctx);

/// Names of all opt fields (for command-line overrides).
std::vector<std::string> optionNames();

}  // namespace sinew::scene
