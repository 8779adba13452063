// Scene reader robustness (issue 13): value bounds, duplicated elements, one YAML document, deep
// nesting, and scene/mesh paths that are directories, empty, binary or truncated. Each case
// checks the field path and the phrase of the message.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scene/gmsh_reader.hpp"
#include "scene/scene_reader.hpp"

#ifndef SINEW_SOURCE_DIR
#define SINEW_SOURCE_DIR "/work/main"
#endif

namespace {

using sinew::Model;
using sinew::SceneError;

const char* kBeam = R"(nodes:
  - [0, 0, 0]
  - [1, 0, 0]
elements:
  - [1, 2]
eprops:
  - elems: [1]
    flex: [1, 2, 3, 4, 5, 6]
    emod: 210e9
    smod: 70e9
    dens: 7800
    cshape: rect
    dim: [0.05, 0.001]
nprops:
  1: {fix: true}
  2: {force: [0, 0, 1]}
)";

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return pos == std::string::npos ? s : s.replace(pos, from.size(), to);
}

/// The SceneError of parsing `text`; checks its path and that the message holds `phrase`.
void expectError(const std::string& text, const std::string& path, const std::string& phrase,
                 const sinew::OptionOverride& ov = {}) {
  try {
    sinew::parseScene(text, SINEW_SOURCE_DIR, ov);
    ADD_FAILURE() << "no SceneError for:\n" << text.substr(0, 400);
  } catch (const SceneError& e) {
    EXPECT_EQ(e.path(), path) << e.what();
    EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
  }
}

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "sinew_scene_robustness";
  std::filesystem::create_directories(dir);
  return dir / name;
}

TEST(SceneRobustness, ExtremeNumbersNameTheField) {
  for (const char* v : {"1e308", "-1e308", "1e-308", "-1e-308"}) {
    SCOPED_TRACE(v);
    expectError(replaced(kBeam, "dens: 7800", std::string("dens: ") + v), "eprops(1).dens", v[0] == '-' ? ">= 0" : "in [1e-20, 1e+20]");
    expectError(replaced(kBeam, "emod: 210e9", std::string("emod: ") + v), "eprops(1).emod", v[0] == '-' ? ">= 0" : "in [1e-20, 1e+20]");
    expectError(replaced(kBeam, "[1, 0, 0]", std::string("[1, ") + v + ", 0]"), "nodes(2,2)", "coordinate of magnitude in [1e-30, 1e+08]");
    expectError(replaced(kBeam, "force: [0, 0, 1]", std::string("force: [0, 0, ") + v + "]"), "nprops(2).force(3)",
                "load of magnitude in [1e-30, 1e+20]");
    expectError(replaced(kBeam, "dim: [0.05, 0.001]", std::string("dim: [0.05, ") + v + "]"), "eprops(1).dim(2)",
                v[0] == '-' ? "> 0" : "cross-section length in [1e-10, 1e+08]");
  }
  for (const char* v : {".nan", ".inf", "-.inf"}) {
    SCOPED_TRACE(v);
    expectError(replaced(kBeam, "smod: 70e9", std::string("smod: ") + v), "eprops(1).smod", "expected a finite number");
  }
  expectError(replaced(kBeam, "smod: 70e9", "smod: 1e999"), "eprops(1).smod", "1e999 is beyond the range of a double");
  expectError(replaced(kBeam, "smod: 70e9", "smod: 1e-999"), "eprops(1).smod", "1e-999 underflows a double");
}

TEST(SceneRobustness, FarNodeIsNotCoincident) {
  try {
    sinew::parseScene(replaced(kBeam, "[1, 0, 0]", "[1e308, 0, 0]"), "");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.path(), "nodes(2,1)");
    EXPECT_EQ(std::string(e.what()).find("coincide"), std::string::npos) << e.what();
  }
}

TEST(SceneRobustness, CommandLineValuesAreBounded) {
  auto ov = [](const std::string& name) -> std::optional<std::string> {
    if (name == "gravity") return std::string("0,0,1e308");
    return std::nullopt;
  };
  expectError(kBeam, "opt.gravity(3)", "(from the command line: -gravity 0,0,1e308)", ov);
}

TEST(SceneRobustness, EngineeringUnitsAreAccepted) {
  // kN, mm, t: E = 210 kN/mm^2, rho = 7.85e-9 t/mm^3, a 1000 mm beam with a 50 x 1 mm section.
  std::string text = replaced(kBeam, "emod: 210e9", "emod: 210");
  text = replaced(text, "smod: 70e9", "smod: 80.77");
  text = replaced(text, "dens: 7800", "dens: 7.85e-9");
  text = replaced(text, "[1, 0, 0]", "[1000, 0, 0]");
  text = replaced(text, "dim: [0.05, 0.001]", "dim: [50, 1]");
  const Model m = sinew::parseScene(text, "");
  EXPECT_DOUBLE_EQ(m.eprops[0].get<sinew::BeamProperties>().dens, 7.85e-9);
  EXPECT_DOUBLE_EQ(m.nodes[1][0], 1000.0);
}

TEST(SceneRobustness, DuplicatedElements) {
  const std::string text = replaced(kBeam, "  - [1, 2]\neprops", "  - [1, 2]\n  - [2, 1]\neprops");
  expectError(replaced(text, "elems: [1]", "elems: [1, 2]"), "elements(2)",
              "element 2 duplicates element 1 on nodes 1 and 2: a beam element (eprops(1)) and a beam element (eprops(1))");
  // An element in no set is a rigid beam: on the nodes of a beam it is a duplicate too.
  expectError(text, "elements(2)",
              "element 2 duplicates element 1 on nodes 1 and 2: a rigid beam (in no eprops set) and a beam element (eprops(1))");
  // The same nodes as two different types (a beam and a cable in parallel) are two elements.
  const Model m = sinew::parseScene(replaced(text, "nprops:", "  - {elems: [2], type: cable, area: 1e-4, emod: 2e11}\nnprops:"), "");
  EXPECT_EQ(m.elements.size(), 2u);
}

TEST(SceneRobustness, OneYamlDocument) {
  expectError(std::string(kBeam) + "---\ntitle: two\n", "", "the file holds 2 YAML documents (the second starts at line 17); Sinew reads one");
  expectError(std::string(kBeam) + "---\n---\n", "", "the file holds 3 YAML documents");
  const Model m = sinew::parseScene(std::string("---\n") + kBeam + "...\n", "");  // explicit markers around one document
  EXPECT_EQ(m.nodes.size(), 2u);
}

TEST(SceneRobustness, DeepNestingIsAnErrorNotACrash) {
  const std::size_t levels = 100000;
  expectError("nodes: " + std::string(levels, '[') + std::string(levels, ']') + "\n", "", "the nesting is too deep");
  expectError("nodes: " + std::string(levels, '{'), "", "the nesting is too deep");
  std::string block = "nodes:\n";
  for (int i = 0; i < 3000; ++i) block += std::string(static_cast<std::size_t>(i + 1), ' ') + "- \n";
  try {
    sinew::parseScene(block, "");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    SUCCEED() << e.what();
  }
}

TEST(SceneRobustness, EmptyAndBinaryText) {
  expectError("", "", "the scene is empty");
  expectError("# only a comment\n", "", "the scene is empty");
  expectError(std::string("nodes: [[0, 0]]\n\0\x01\x02", 19), "", "not a text file: control byte 0x00 at line 2, column 1");
}

TEST(SceneRobustness, SceneFilePaths) {
  const auto dir = scratch("a_directory.yaml");
  std::filesystem::create_directories(dir);
  try {
    sinew::readScene(dir.string());
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory, not a scene file"), std::string::npos) << e.what();
  }
  const auto empty = scratch("empty.yaml");
  std::ofstream(empty).close();
  try {
    sinew::readScene(empty.string());
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("is empty"), std::string::npos) << e.what();
  }
}

TEST(SceneRobustness, MeshPaths) {
  const std::string meshDir = scratch("mesh_dir.msh").string();
  std::filesystem::create_directories(meshDir);
  expectError("mesh: " + meshDir + "\n", "mesh", "is a directory, not a Gmsh mesh file");
  expectError("mesh: /dev/null\n", "mesh", "is not a regular file");

  std::ifstream in(std::string(SINEW_SOURCE_DIR) + "/meshes/square_tri.msh");
  std::string full((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(full.size(), 400u);
  const auto truncated = scratch("truncated.msh");
  for (std::size_t cut : {full.size() / 3, full.size() / 2, full.size() - 12}) {
    SCOPED_TRACE(cut);
    std::ofstream(truncated) << full.substr(0, cut);
    expectError("mesh: " + truncated.string() + "\n", "mesh", "truncated.msh:");
  }
}

TEST(SceneRobustness, MeshCoordinatesAreBounded) {
  std::ifstream in(std::string(SINEW_SOURCE_DIR) + "/meshes/square_tri.msh");
  std::string full((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto nodes = full.find("$Nodes");
  ASSERT_NE(nodes, std::string::npos);
  // The first coordinate line of the first node block: replace its x by 1e308.
  std::istringstream lines(full.substr(nodes));
  std::string line, target;
  while (std::getline(lines, line))
    if (std::count(line.begin(), line.end(), ' ') == 2 && line.find('.') != std::string::npos) {
      target = line;
      break;
    }
  ASSERT_FALSE(target.empty());
  const auto far = scratch("far.msh");
  std::ofstream(far) << replaced(full, target + "\n", "1e308" + target.substr(target.find(' ')) + "\n");
  expectError("mesh: " + far.string() + "\n", "mesh", "coordinate of magnitude in [1e-30, 1e+08], got 1e+308");
}

}  // namespace
