// Scene reader (design.md section 2): YAML scene (+ optional Gmsh 4 mesh) -> validated Model.
// Every problem throws sinew::SceneError(path, message). Paths join map keys with '.' and give
// list positions 0-based in brackets: `nodes[3]`, `elements[2][1]`, `nprops.7.force`,
// `eprops[2].dim`, `opt.loadsteps`; messages use the 1-based node/element numbers of the scene
// and end with the scene line ("(line 12)", or "(file.yaml line 12)" from readScene).
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sinew/model.hpp"

namespace YAML {
class Node;
}

namespace sinew {

/// overrides(name) returns the command-line value for opt field `name` (e.g. "40", "true",
/// "0,0,-9.81", "{3: [2,3]}") or nullopt. Values are YAML scalars or flow sequences/maps; a bare
/// comma list "0,0,-9.81" means [0,0,-9.81]; an empty value means true (a flag given alone).
using OptionOverride = std::function<std::optional<std::string>(const std::string& optName)>;

/// Parse scene text. baseDir resolves `mesh:`. Model.sceneText = text. `restart`: the run continues
/// a checkpoint (-restart), whose plan may end later than opt.loadsteps: a list in opt.output_steps
/// is then checked by the caller (checkOutputSteps with the restart's last load step).
Model parseScene(const std::string& text, const std::string& baseDir, const OptionOverride& overrides = {},
                 bool restart = false);
/// Parse a scene given as its YAML tree (as YAML::Load makes it from the text; the Python module
/// builds it from a dict without text). Model.sceneText stays empty (sceneTreeText, scene_tree.hpp,
/// makes the text when a result file needs it). The tree is not changed. Messages name the field's
/// path, without a line.
Model parseSceneTree(const YAML::Node& root, const std::string& baseDir, const OptionOverride& overrides = {},
                     bool restart = false);
/// Read a scene file; messages name the file. opt.filename defaults to the file's stem.
Model readScene(const std::string& path, const OptionOverride& overrides = {}, bool restart = false);

/// A Model built in code (sinew::run's SceneSource::fromModel) gets the reader's checks that work on
/// the model itself: numbers in range (node, element and set indices of elements, eprops elems,
/// nprops, opt, sensors, formfinding), element lengths and kinds, trailing nodes (sets
/// connectedNodes), membranes without modulus, dynamics without mass; elementSet is derived from the
/// sets' elems when empty. SceneError with SPACAR Light's 1-based numbers in the field paths.
void checkBuiltModel(Model& m);

/// A list in opt.output_steps holds only steps the run has: load steps 1..lastLoadStep (statics,
/// also before a time loop with start: static), time steps 0..tend/dt that are multiples of
/// output_every; else SceneError("opt.output_steps", ...).
void checkOutputSteps(const Options& o, int lastLoadStep);

/// Every opt field with its type and default, for -help.
struct OptionDoc {
  std::string name, type, defaultValue, help;
};
const std::vector<OptionDoc>& sceneOptionDocs();

}  // namespace sinew
