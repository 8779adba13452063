// A scene given as a YAML tree instead of text (sinew::SceneSource::yamlTree, built by the Python
// module from a dict): the text made from it when a result file needs one, and the checks of the
// text path that read the text.
#pragma once
#include <yaml-cpp/yaml.h>

#include <string>

namespace sinew {

/// The scene text of the tree, as the Python module's emitter writes a dict: maps in block style
/// (flow inside lists), lists in flow style, null as ~, every scalar as its text (the emitter quotes
/// it where a plain scalar would read differently). YAML::Load of it gives the tree back.
std::string sceneTreeText(const YAML::Node& root);

/// Whether `word` occurs in a key or scalar of the tree (as text.find(word) on its text for a word
/// of letters, digits and '_').
bool treeMentions(const YAML::Node& root, const std::string& word);

/// "" when the trees are the same for the scene reader (kinds, scalars, tags, key order, sizes);
/// else the path and what differs first (tests: the tree of a dict against YAML::Load of its text).
std::string treeDifference(const YAML::Node& a, const YAML::Node& b, const std::string& path = "");

}  // namespace sinew
