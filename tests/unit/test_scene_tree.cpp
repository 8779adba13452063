// The scene reader's tree entry (parseSceneTree, issue 25: sinew._core hands a dict's YAML tree to
// the reader without text): every scene fixture and runs/ scene read from a tree without marks (as
// the Python module builds it) gives what the text gives, errors with the same message less the
// line; treeDifference, the Python tests' check of the built tree, finds a dropped field, a changed
// kind, tag or scalar; command-line values leave the tree. (The tree of a dict against its text:
// tests/python/test_scene_tree.py.)
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "scene/scene_reader.hpp"
#include "scene/scene_tree.hpp"

#ifndef SINEW_SOURCE_DIR
#define SINEW_SOURCE_DIR "/work/main"
#endif

namespace {

namespace fs = std::filesystem;

/// A copy of the tree through the public node API, without marks (as python_scene.cpp builds it).
YAML::Node withoutMarks(const YAML::Node& n) {
  YAML::Node c;
  if (n.IsMap()) {
    c = YAML::Node(YAML::NodeType::Map);
    for (auto it = n.begin(); it != n.end(); ++it) c.force_insert(withoutMarks(it->first), withoutMarks(it->second));
  } else if (n.IsSequence()) {
    c = YAML::Node(YAML::NodeType::Sequence);
    for (auto it = n.begin(); it != n.end(); ++it) c.push_back(withoutMarks(*it));
  } else if (n.IsScalar()) {
    c = YAML::Node(n.Scalar());
  } else {
    return YAML::Node(YAML::NodeType::Null);
  }
  c.SetTag(n.Tag());
  c.SetStyle(n.Style());
  return c;
}

std::string readText(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> scenes() {
  std::vector<fs::path> out;
  for (const char* dir : {"/tests/scenes/bad", "/tests/scenes/good", "/runs"})
    for (const auto& e : fs::directory_iterator(std::string(SINEW_SOURCE_DIR) + dir))
      if (e.path().extension() == ".yaml") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

/// "" when read without error, else the message.
template <class F>
std::string errorOf(F&& read, sinew::Model* m) {
  try {
    *m = read();
    return "";
  } catch (const sinew::SceneError& e) {
    return e.what();
  }
}

TEST(SceneTree, EverySceneReadsAsFromItsText) {
  int trees = 0, errors = 0;
  for (const fs::path& p : scenes()) {
    const std::string text = readText(p), dir = p.parent_path().string();
    YAML::Node root;
    try {
      root = YAML::Load(text);
    } catch (const YAML::Exception&) {
      continue;  // a syntax fixture: no tree
    }
    const YAML::Node tree = withoutMarks(root);
    ASSERT_EQ(sinew::treeDifference(tree, root), "") << p;
    sinew::Model fromText, fromTree;
    const std::string textError = errorOf([&] { return sinew::parseScene(text, dir); }, &fromText);
    const std::string treeError = errorOf([&] { return sinew::parseSceneTree(tree, dir); }, &fromTree);
    // checks of the text itself (one document, nothing after a complete value): no tree has them
    if (textError.rfind("YAML syntax error", 0) == 0 || textError.rfind("the file holds", 0) == 0) continue;
    EXPECT_EQ(treeError, std::regex_replace(textError, std::regex(" \\(line [0-9]+\\)"), "")) << p;
    if (!textError.empty()) {
      ++errors;
      continue;
    }
    ++trees;
    EXPECT_TRUE(fromTree.sceneText.empty());
    EXPECT_EQ(fromTree.nodes, fromText.nodes) << p;
    EXPECT_EQ(fromTree.elements, fromText.elements) << p;
    EXPECT_EQ(fromTree.elementSet, fromText.elementSet) << p;
    EXPECT_EQ(fromTree.eprops.size(), fromText.eprops.size()) << p;
    EXPECT_EQ(fromTree.nprops.size(), fromText.nprops.size()) << p;
    EXPECT_EQ(fromTree.opt.loadsteps, fromText.opt.loadsteps) << p;
    EXPECT_EQ(fromTree.warnings, fromText.warnings) << p;
  }
  EXPECT_GT(trees, 15);
  EXPECT_GT(errors, 50);
}

TEST(SceneTree, DifferenceFindsChanges) {
  const YAML::Node text = YAML::Load("nodes: [[0, 0, 0], [1, 0, 0]]\nopt: {loadsteps: 5, title: 'x'}\n");
  const auto changed = [&](const std::function<void(YAML::Node&)>& change) {
    YAML::Node t = withoutMarks(text);
    change(t);
    return sinew::treeDifference(t, text);
  };
  EXPECT_EQ(changed([](YAML::Node&) {}), "");
  EXPECT_NE(changed([](YAML::Node& t) { t.remove("opt"); }), "");                     // a dropped field
  EXPECT_NE(changed([](YAML::Node& t) { t["opt"]["loadsteps"] = std::vector<int>{5}; }), "");  // a kind
  EXPECT_NE(changed([](YAML::Node& t) { t["opt"]["loadsteps"].SetTag("!"); }), "");   // quoted "5"
  EXPECT_NE(changed([](YAML::Node& t) { t["opt"]["title"].SetTag("?"); }), "");       // plain x
  EXPECT_NE(changed([](YAML::Node& t) { t["opt"]["loadsteps"] = "5.0"; }), "");      // a scalar
  EXPECT_NE(changed([](YAML::Node& t) { t["nodes"][1].push_back(0); }), "");          // a size
  EXPECT_NE(changed([](YAML::Node& t) { t["opt"]["loadsteps"] = YAML::Node(YAML::NodeType::Null); }), "");
}

TEST(SceneTree, CommandLineValuesLeaveTheTree) {
  const YAML::Node tree = withoutMarks(YAML::Load("nodes: [[0, 0, 0], [1, 0, 0]]\nelements: [[1, 2]]\nopt: {loadsteps: 5}\n"));
  const std::string before = sinew::sceneTreeText(tree);
  const sinew::Model m = sinew::parseSceneTree(tree, ".", [](const std::string& name) {
    return name == "loadsteps" ? std::optional<std::string>("7") : std::nullopt;
  });
  EXPECT_EQ(m.opt.loadsteps, 7);
  EXPECT_EQ(sinew::sceneTreeText(tree), before);
  EXPECT_EQ(sinew::parseSceneTree(tree, ".").opt.loadsteps, 5);
}

}  // namespace
