// Gmsh 4 reader tests: the meshes/square_tri.msh fixture (4.1), a hand-written 4.0 file, error
// locations, and a scene that maps physical groups to eprops sets and nprops node groups.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/gmsh_reader.hpp"
#include "scene/scene_reader.hpp"

#ifndef SINEW_SOURCE_DIR
#define SINEW_SOURCE_DIR "/work/main"
#endif

namespace {

using sinew::GmshMesh;
using sinew::SceneError;

std::string sourceDir() { return SINEW_SOURCE_DIR; }

std::size_t countType(const GmshMesh& m, int type) {
  return static_cast<std::size_t>(std::count_if(m.elements.begin(), m.elements.end(), [&](const auto& e) { return e.type == type; }));
}

TEST(GmshReader, SquareFixture) {
  const GmshMesh m = sinew::readGmsh(sourceDir() + "/meshes/square_tri.msh");
  EXPECT_EQ(m.version, "4.1");
  ASSERT_EQ(m.nodes.size(), 9u);
  EXPECT_DOUBLE_EQ(m.nodes[2][0], 1.0);
  EXPECT_DOUBLE_EQ(m.nodes[2][1], 1.0);
  ASSERT_EQ(m.elements.size(), 13u);
  EXPECT_EQ(countType(m, 15), 1u);
  EXPECT_EQ(countType(m, 1), 4u);
  EXPECT_EQ(countType(m, 2), 8u);
  ASSERT_EQ(m.groups.size(), 4u);

  const auto* sail = m.findGroup("sail");
  ASSERT_NE(sail, nullptr);
  EXPECT_EQ(sail->dim, 2);
  EXPECT_EQ(sail->elements.size(), 8u);
  EXPECT_EQ(sail->nodes.size(), 9u);
  const auto* edge = m.findGroup("edge_fixed");
  ASSERT_NE(edge, nullptr);
  EXPECT_EQ(edge->dim, 1);
  EXPECT_EQ(edge->elements.size(), 2u);
  ASSERT_EQ(edge->nodes.size(), 3u);
  for (int n : edge->nodes) EXPECT_DOUBLE_EQ(m.nodes[static_cast<std::size_t>(n)][0], 0.0);
  const auto* corner = m.findGroup("corner");
  ASSERT_NE(corner, nullptr);
  EXPECT_EQ(corner->dim, 0);
  ASSERT_EQ(corner->nodes.size(), 1u);
  EXPECT_DOUBLE_EQ(m.nodes[static_cast<std::size_t>(corner->nodes[0])][0], 1.0);
  EXPECT_DOUBLE_EQ(m.nodes[static_cast<std::size_t>(corner->nodes[0])][1], 1.0);
  EXPECT_EQ(m.findGroup("nothing"), nullptr);
}

// Two triangles on a unit square, written in format 4.0 (entity tag before dimension,
// node tag and coordinates on one line, points with a bounding box).
const char* kFormat40 = R"($MeshFormat
4 0 8
$EndMeshFormat
$PhysicalNames
2
1 7 "left edge"
2 8 "skin"
$EndPhysicalNames
$Entities
0 1 1 0
4 0 0 0 0 1 0 1 7 0
1 0 0 0 1 1 0 1 8 0
$EndEntities
$Nodes
2 4
4 1 0 2
1 0 0 0
4 0 1 0
1 2 0 2
2 1 0 0
3 1 1 0
$EndNodes
$Elements
2 3
4 1 1 1
1 1 4
1 2 2 2
2 1 2 3
3 1 3 4
$EndElements
)";

TEST(GmshReader, Format40) {
  std::istringstream in(kFormat40);
  const GmshMesh m = sinew::parseGmsh(in, "two.msh");
  ASSERT_EQ(m.nodes.size(), 4u);
  ASSERT_EQ(m.elements.size(), 3u);
  const auto* skin = m.findGroup("skin");
  ASSERT_NE(skin, nullptr);
  EXPECT_EQ(skin->elements.size(), 2u);
  const auto* left = m.findGroup("left edge");
  ASSERT_NE(left, nullptr);
  EXPECT_EQ(left->nodes.size(), 2u);
  EXPECT_EQ(m.elements[2].nodes, (std::vector<int>{0, 3, 1}));  // node tags 1, 3, 4
  EXPECT_EQ(m.elements[2].line, 29);
}

SceneError gmshError(const std::string& text) {
  std::istringstream in(text);
  try {
    sinew::parseGmsh(in, "bad.msh");
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "no error";
  return SceneError("", "");
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return s.replace(pos, from.size(), to);
}

TEST(GmshReader, ErrorsNameFileAndLine) {
  SceneError e = gmshError(replaced(kFormat40, "3 1 3 4\n", "3 1 3 9\n"));
  EXPECT_EQ(e.path(), "mesh");
  EXPECT_NE(std::string(e.what()).find("bad.msh:29: element 3 refers to node tag 9"), std::string::npos) << e.what();

  e = gmshError(replaced(kFormat40, "4 0 1 0\n", "4 0 one 0\n"));
  EXPECT_NE(std::string(e.what()).find("bad.msh:18: expected a node coordinate, got 'one'"), std::string::npos) << e.what();

  e = gmshError(replaced(kFormat40, "1 2 2 2\n", "1 2 9 2\n"));
  EXPECT_NE(std::string(e.what()).find("bad.msh:27: element type 9 (6-node triangle) is not supported"), std::string::npos)
      << e.what();

  e = gmshError(replaced(kFormat40, "4 0 8", "2.2 0 8"));
  EXPECT_NE(std::string(e.what()).find("bad.msh:2: Gmsh format 2.2 is not supported"), std::string::npos) << e.what();

  e = gmshError(replaced(kFormat40, "4 0 8", "4.1 1 8"));
  EXPECT_NE(std::string(e.what()).find("binary"), std::string::npos) << e.what();

  e = gmshError(replaced(kFormat40, "$EndNodes\n", ""));
  EXPECT_NE(std::string(e.what()).find("expected $EndNodes"), std::string::npos) << e.what();

  EXPECT_THROW(sinew::readGmsh("/nonexistent/none.msh"), SceneError);
}

TEST(GmshReader, SceneMapsPhysicalGroups) {
  const sinew::Model m = sinew::readScene(sourceDir() + "/tests/scenes/good/sail_mesh.yaml");
  // the CARAT++ formfinding block, every field
  ASSERT_TRUE(m.formfinding.has_value());
  EXPECT_EQ(m.formfinding->formfinding_step, 10);
  EXPECT_EQ(m.formfinding->formfinding_elements, (std::vector<int>{0, 1}));
  EXPECT_EQ(m.formfinding->stress_adaption, (std::vector<int>{0}));
  EXPECT_EQ(m.formfinding->homotopy_curve, (std::vector<double>{0, 0, 0.5}));
  EXPECT_DOUBLE_EQ(m.formfinding->equilibrium_accuracy, 1e-6);
  EXPECT_EQ(m.formfinding->elastic_restart_method, "DISPLACEMENT");

  EXPECT_EQ(m.dimension, 3);
  ASSERT_EQ(m.nodes.size(), 10u);       // 1 scene node + 9 mesh nodes
  ASSERT_EQ(m.elements.size(), 11u);    // 1 scene element + 2 edge cables + 8 triangles (edge_fixed lines only select nodes)
  EXPECT_EQ(m.elements[0], (std::vector<int>{0, 9}));
  ASSERT_EQ(m.eprops.size(), 3u);
  EXPECT_EQ(m.eprops[0].type(), sinew::ElementType::Membrane);
  EXPECT_EQ(m.eprops[0].elems.size(), 8u);
  for (int e : m.eprops[0].elems) EXPECT_EQ(m.elements[static_cast<std::size_t>(e)].size(), 3u);
  EXPECT_EQ(m.eprops[0].get<sinew::MembraneProperties>().prestress[0], 1e6);
  EXPECT_EQ(m.eprops[1].type(), sinew::ElementType::Cable);
  EXPECT_EQ(m.eprops[1].elems, (std::vector<int>{1, 2}));
  for (int e : m.eprops[1].elems)
    for (int n : m.elements[static_cast<std::size_t>(e)]) EXPECT_DOUBLE_EQ(m.nodes[static_cast<std::size_t>(n)][1], 1.0);
  EXPECT_EQ(m.eprops[2].elems, (std::vector<int>{0}));
  ASSERT_TRUE(m.eprops[2].get<sinew::CableProperties>().prestress_stress.has_value());
  for (std::size_t e = 0; e < m.elements.size(); ++e) EXPECT_GE(m.elementSet[e], 0) << e;

  // edge_fixed: the three mesh nodes at x = 0; corner: the node at (1, 1).
  int fixedCount = 0;
  for (const auto& [node, np] : m.nprops) {
    if (np.fix_pos) {
      ++fixedCount;
      EXPECT_DOUBLE_EQ(m.nodes[static_cast<std::size_t>(node)][0], 0.0);
    }
    if (np.force[2] != 0) {
      EXPECT_DOUBLE_EQ(m.nodes[static_cast<std::size_t>(node)][0], 1.0);
      EXPECT_DOUBLE_EQ(m.nodes[static_cast<std::size_t>(node)][1], 1.0);
    }
  }
  EXPECT_EQ(fixedCount, 3);
  EXPECT_TRUE(m.nprops.at(0).fix);
  ASSERT_TRUE(m.formfinding.has_value());
  EXPECT_EQ(m.formfinding->formfinding_elements, (std::vector<int>{0, 1}));
}

std::string writeScene(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "sinew_gmsh_test";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

SceneError sceneError(const std::string& text) {
  try {
    sinew::parseScene(text, sourceDir() + "/tests/scenes/good");
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for\n" << text;
  return SceneError("", "");
}

TEST(GmshReader, SceneErrors) {
  const std::string base = "mesh: ../../../meshes/square_tri.msh\n";
  SceneError e = sceneError(base + "eprops:\n  - {physical: sial, type: membrane, thickness: 0.001, emod: 1e9, nu: 0.3}\n");
  EXPECT_EQ(e.path(), "eprops(1).physical");
  EXPECT_NE(std::string(e.what()).find("no physical group 'sial'"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("did you mean 'sail'?"), std::string::npos) << e.what();

  e = sceneError(base + "nprops:\n  edge_fixd: {fix: true}\neprops:\n  - {physical: sail, type: membrane, thickness: 0.001, emod: 1e9, nu: 0.3}\n");
  EXPECT_EQ(e.path(), "nprops.edge_fixd");
  EXPECT_NE(std::string(e.what()).find("did you mean 'edge_fixed'?"), std::string::npos) << e.what();

  // Triangles without a membrane set.
  e = sceneError(base);
  EXPECT_EQ(e.path(), "mesh");
  EXPECT_NE(std::string(e.what()).find("square_tri.msh:"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("is in no eprops set"), std::string::npos) << e.what();

  // A 2D scene with a mesh off the plane z = 0 is caught node by node; here the mesh is planar.
  e = sceneError("nodes: [[0, 0]]\n" + base + "eprops:\n  - {physical: sail, type: membrane, thickness: 0.001, emod: 1e9, nu: 0.3}\n");
  EXPECT_EQ(e.path(), "eprops(1).type");
  EXPECT_NE(std::string(e.what()).find("membrane elements need a 3D model"), std::string::npos) << e.what();

  // A missing mesh file, through readScene.
  const std::string scene = writeScene("missing_mesh.yaml", "mesh: nothing_here.msh\n");
  try {
    sinew::readScene(scene);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& err) {
    EXPECT_EQ(err.path(), "mesh");
    EXPECT_NE(std::string(err.what()).find("cannot open mesh file"), std::string::npos) << err.what();
  }
}

}  // namespace
