// Scene reader tests: a full good scene, command-line overrides, and every fixture in
// tests/scenes/bad (each names the expected error path and a phrase of the message).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include "scene/scene_reader.hpp"

#ifndef SINEW_SOURCE_DIR
#define SINEW_SOURCE_DIR "/work/main"
#endif

namespace {

using sinew::ElementType;
using sinew::Model;
using sinew::SceneError;

std::string sourceDir() { return SINEW_SOURCE_DIR; }
std::string goodScene(const std::string& name) { return sourceDir() + "/tests/scenes/good/" + name; }

const char* kSmallScene = R"(
nodes:
  - [0, 0, 0]
  - [1, 0, 0]
elements:
  - [1, 2]
nprops:
  1: {fix: true}
opt:
  loadsteps: 3
)";

/// Error thrown by parseScene, or a failure when none is thrown.
SceneError parseError(const std::string& text, const sinew::OptionOverride& ov = {}) {
  try {
    sinew::parseScene(text, sourceDir(), ov);
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "no SceneError for:\n" << text;
  return SceneError("<none>", "<none>");
}

sinew::OptionOverride overridesFrom(std::map<std::string, std::string> values) {
  return [values](const std::string& name) -> std::optional<std::string> {
    auto it = values.find(name);
    if (it == values.end()) return std::nullopt;
    return it->second;
  };
}

TEST(SceneReader, CrossHingeScene) {
  const Model m = sinew::readScene(goodScene("crosshinge.yaml"));
  EXPECT_EQ(m.title, "Cross-flexure hinge");
  EXPECT_EQ(m.dimension, 3);
  ASSERT_EQ(m.nodes.size(), 5u);
  EXPECT_DOUBLE_EQ(m.nodes[1][0], 0.1);
  EXPECT_DOUBLE_EQ(m.nodes[4][1], 0.2);
  ASSERT_EQ(m.elements.size(), 4u);
  EXPECT_EQ(m.elements[1], (std::vector<int>{2, 3}));
  EXPECT_NE(m.sceneText.find("Cross-flexure hinge"), std::string::npos);

  ASSERT_EQ(m.eprops.size(), 2u);
  const auto& flexSet = m.eprops[0];
  EXPECT_EQ(flexSet.type(), ElementType::Beam);
  EXPECT_EQ(flexSet.elems, (std::vector<int>{0, 1}));
  const auto& flex = flexSet.get<sinew::BeamProperties>();
  for (bool f : flex.flex) EXPECT_TRUE(f);
  EXPECT_DOUBLE_EQ(flex.emod, 210e9);
  EXPECT_DOUBLE_EQ(flex.smod, 70e9);
  EXPECT_DOUBLE_EQ(flex.dens, 7800);
  EXPECT_EQ(flex.cshape, sinew::CrossSection::Rect);
  EXPECT_EQ(flex.dim, (std::vector<double>{0.05, 0.0002}));
  ASSERT_TRUE(flex.orien.has_value());
  EXPECT_DOUBLE_EQ((*flex.orien)[2], 1.0);
  EXPECT_EQ(flexSet.nbeams, 3);
  EXPECT_TRUE(flex.cw);
  ASSERT_TRUE(flexSet.color.has_value());
  EXPECT_DOUBLE_EQ((*flexSet.color)[1], 0.4);
  EXPECT_DOUBLE_EQ(flexSet.opacity, 0.5);
  const auto& arm = m.eprops[1];
  EXPECT_EQ(arm.elems, (std::vector<int>{3}));
  for (bool f : arm.get<sinew::BeamProperties>().flex) EXPECT_FALSE(f);
  EXPECT_EQ(arm.get<sinew::BeamProperties>().cshape, sinew::CrossSection::Circ);
  EXPECT_TRUE(arm.hide);
  EXPECT_EQ(m.elementSet, (std::vector<int>{0, 0, -1, 1}));

  ASSERT_EQ(m.nprops.size(), 4u);
  EXPECT_TRUE(m.nprops.at(0).fix);
  EXPECT_TRUE(m.nprops.at(2).fix);
  const auto& tip = m.nprops.at(4);
  EXPECT_DOUBLE_EQ(tip.force[1], 1.0);
  EXPECT_DOUBLE_EQ(tip.moment_initial[2], -0.025);
  EXPECT_DOUBLE_EQ(tip.moment[2], 0.05);
  EXPECT_DOUBLE_EQ(tip.mass, 0.1);
  EXPECT_DOUBLE_EQ(tip.mominertia[3], 2e-4);
  EXPECT_EQ(tip.transfer_in, (std::vector<std::string>{"force_x"}));
  EXPECT_EQ(tip.transfer_out, (std::vector<std::string>{"displ_x", "veloc_y"}));
  const auto& n4 = m.nprops.at(3);
  EXPECT_TRUE(n4.fix_z);
  ASSERT_TRUE(n4.displ[2].has_value());
  EXPECT_DOUBLE_EQ(*n4.displ[2], 0.001);
  EXPECT_FALSE(n4.displ[0].has_value());

  EXPECT_EQ(m.opt.loadsteps, 10);
  EXPECT_TRUE(m.opt.calcbuck);
  EXPECT_TRUE(m.opt.calccompl);
  EXPECT_FALSE(m.opt.calcfreq.has_value());
  ASSERT_TRUE(m.opt.gravity.has_value());
  EXPECT_DOUBLE_EQ((*m.opt.gravity)[2], -9.81);
  ASSERT_EQ(m.opt.rls.size(), 1u);
  EXPECT_EQ(m.opt.rls.at(2), (std::vector<int>{2, 3, 4}));
  EXPECT_TRUE(m.opt.transfer);
  EXPECT_DOUBLE_EQ(m.opt.transfer_zeta, 0.01);
  EXPECT_EQ(m.opt.filename, "crosshinge");
  EXPECT_EQ(m.opt.compliance_nodes, (std::vector<int>{4, 1}));
  ASSERT_TRUE(m.opt.dynamics.has_value());
  EXPECT_DOUBLE_EQ(m.opt.dynamics->tend, 1.0);
  EXPECT_DOUBLE_EQ(m.opt.dynamics->dt, 0.01);
  EXPECT_DOUBLE_EQ(m.opt.dynamics->spectral_radius, 0.9);
  EXPECT_EQ(m.opt.nfreq, 4);
  EXPECT_EQ(m.opt.nbuck, 3);

  EXPECT_FALSE(m.formfinding.has_value());

  ASSERT_EQ(m.sensors.size(), 2u);
  EXPECT_EQ(m.sensors[0].element, 0);
  EXPECT_DOUBLE_EQ(m.sensors[0].x, 0.07);
  EXPECT_EQ(m.sensors[0].variable, "Position");
  EXPECT_EQ(m.sensors[0].name, "flexure_mid");
  EXPECT_EQ(m.sensors[1].element, 3);
  EXPECT_DOUBLE_EQ(m.sensors[1].x, 0.0);
}

TEST(SceneReader, Ancf2DScene) {
  const Model m = sinew::readScene(goodScene("ancf_2d.yaml"));
  EXPECT_EQ(m.dimension, 2);
  EXPECT_DOUBLE_EQ(m.nodes[2][2], 0.0);
  ASSERT_EQ(m.eprops.size(), 1u);
  EXPECT_EQ(m.eprops[0].type(), ElementType::AncfCable2D);
  EXPECT_EQ(m.eprops[0].nbeams, 4);
  const auto& s = m.eprops[0].get<sinew::AncfCable2DProperties>();
  EXPECT_DOUBLE_EQ(s.physicsBendingStiffness, 2.5);
  EXPECT_DOUBLE_EQ(s.strainIsRelativeToReference, 1.0);
  EXPECT_EQ(s.useReducedOrderIntegration, 2);
  EXPECT_EQ(s.axialForceUserFunction, "physicsAxialStiffness*(axialStrain-axialStrainRef)");
  ASSERT_TRUE(s.massProportionalLoad.has_value());
  EXPECT_DOUBLE_EQ((*s.massProportionalLoad)[1], -9.81);
  ASSERT_TRUE(m.nprops.at(0).fix_coords.has_value());
  EXPECT_EQ(*m.nprops.at(0).fix_coords, (std::array<int, 4>{1, 1, 0, 1}));
  EXPECT_DOUBLE_EQ(m.nprops.at(2).force[1], -1.0);
  EXPECT_DOUBLE_EQ((*m.opt.gravity)[1], -9.81);
  EXPECT_DOUBLE_EQ(m.opt.dynamics->spectral_radius, 0.8);
  EXPECT_EQ(m.opt.filename, "ancf_2d");  // readScene: the scene file's stem
}

TEST(SceneReader, OverridesChangeOptions) {
  const Model m = sinew::parseScene(kSmallScene, "", overridesFrom({{"loadsteps", "40"}, {"gravity", "0,0,-9.81"},
                                                                     {"calcbuck", "true"}, {"rls", "{1: [2,3]}"},
                                                                     {"transfer", "[true, 0.05]"}, {"silent", ""}}));
  EXPECT_EQ(m.opt.loadsteps, 40);
  ASSERT_TRUE(m.opt.gravity.has_value());
  EXPECT_DOUBLE_EQ((*m.opt.gravity)[0], 0.0);
  EXPECT_DOUBLE_EQ((*m.opt.gravity)[2], -9.81);
  EXPECT_TRUE(m.opt.calcbuck);
  EXPECT_EQ(m.opt.rls.at(0), (std::vector<int>{2, 3}));
  EXPECT_TRUE(m.opt.transfer);
  EXPECT_DOUBLE_EQ(m.opt.transfer_zeta, 0.05);
  EXPECT_TRUE(m.opt.silent);  // a flag given without a value
  EXPECT_EQ(m.sceneText, kSmallScene);
}

TEST(SceneReader, OverrideAddsOptBlock) {
  const std::string text = "nodes: [[0, 0], [1, 0]]\nelements: [[1, 2]]\nnprops: {2: {mass: 1}}\n";  // dynamics needs mass
  const Model m = sinew::parseScene(text, "", overridesFrom({{"nfreq", "12"}, {"dynamics", "{tend: 2, dt: 0.1}"}}));
  EXPECT_EQ(m.opt.nfreq, 12);
  ASSERT_TRUE(m.opt.dynamics.has_value());
  EXPECT_DOUBLE_EQ(m.opt.dynamics->tend, 2.0);
  EXPECT_EQ(m.dimension, 2);
}

TEST(SceneReader, BadOverrideNamesTheFlag) {
  const SceneError e = parseError(kSmallScene, overridesFrom({{"loadsteps", "zero"}}));
  EXPECT_EQ(e.path(), "opt.loadsteps");
  EXPECT_NE(std::string(e.what()).find("expected an integer, got 'zero'"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("from the command line: -loadsteps zero"), std::string::npos) << e.what();
  const SceneError g = parseError(kSmallScene, overridesFrom({{"gravity", "0,1"}}));
  EXPECT_EQ(g.path(), "opt.gravity");
  EXPECT_NE(std::string(g.what()).find("expected 3 numbers, got 2"), std::string::npos) << g.what();
}

TEST(SceneReader, MessagesCarryTheLine) {
  const SceneError e = parseError(std::string(kSmallScene) + "  calcbuck: 3\n");
  EXPECT_EQ(e.path(), "opt.calcbuck");
  EXPECT_NE(std::string(e.what()).find("(line 11)"), std::string::npos) << e.what();
}

TEST(SceneReader, MominertiaMatrixAndTwoDMoment) {
  const Model m = sinew::parseScene(R"(
nodes: [[0, 0], [1, 0]]
elements: [[1, 2]]
nprops:
  1: {fix: true}
  2: {mominertia: [[1, 0.1, 0.2], [0.1, 2, 0.3], [0.2, 0.3, 3]], moment: 5, force: [1, 2]}
)",
                                    "");
  const auto& np = m.nprops.at(1);
  EXPECT_EQ(np.mominertia, (std::array<double, 6>{1, 0.1, 0.2, 2, 0.3, 3}));
  EXPECT_DOUBLE_EQ(np.moment[2], 5.0);
  EXPECT_DOUBLE_EQ(np.force[1], 2.0);
  EXPECT_DOUBLE_EQ(np.force[2], 0.0);
}

TEST(SceneReader, PrescribedDisplacementOnFixedNodeIsFine) {
  const Model m = sinew::parseScene(R"(
nodes: [[0, 0, 0], [1, 0, 0]]
elements: [[1, 2]]
nprops:
  1: {fix: true, displ_x: 0.01, rot_initial: [0, 0, 0.1]}
  2: {force: [0, 1, 0]}
)",
                                    "");
  EXPECT_DOUBLE_EQ(*m.nprops.at(0).displ[0], 0.01);
  EXPECT_DOUBLE_EQ((*m.nprops.at(0).rot_initial)[2], 0.1);
}

TEST(SceneReader, OptionDocsListEveryOptField) {
  const auto& docs = sinew::sceneOptionDocs();
  for (const char* name : {"loadsteps", "calcbuck", "calccompl", "calcfreq", "gravity", "rls", "transfer", "filename",
                           "stressperelement", "rigidstress", "showinputonly", "silent", "compliance_nodes", "dynamics",
                           "nfreq", "nbuck"}) {
    auto it = std::find_if(docs.begin(), docs.end(), [&](const sinew::OptionDoc& d) { return d.name == name; });
    ASSERT_NE(it, docs.end()) << name;
    EXPECT_FALSE(it->type.empty());
    EXPECT_FALSE(it->defaultValue.empty());
    EXPECT_FALSE(it->help.empty());
  }
  const Model m = sinew::parseScene(kSmallScene, "");
  auto loadsteps = std::find_if(docs.begin(), docs.end(), [](const sinew::OptionDoc& d) { return d.name == "loadsteps"; });
  EXPECT_EQ(loadsteps->defaultValue, std::to_string(sinew::Options{}.loadsteps));
}

/// Every tests/scenes/bad/*.yaml starts with "# path: <path>" and "# message: <phrase>".
TEST(SceneReader, BadScenes) {
  const std::filesystem::path dir = sourceDir() + "/tests/scenes/bad";
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  EXPECT_GE(files.size(), 30u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    std::ifstream in(file);
    std::string pathLine, messageLine;
    std::getline(in, pathLine);
    std::getline(in, messageLine);
    ASSERT_EQ(pathLine.rfind("# path:", 0), 0u);
    ASSERT_EQ(messageLine.rfind("# message: ", 0), 0u);
    std::string path = pathLine.substr(7);
    path.erase(0, path.find_first_not_of(' '));
    const std::string message = messageLine.substr(11);
    try {
      sinew::readScene(file.string());
      ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
      EXPECT_EQ(e.path(), path) << e.what();
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << "message: " << e.what();
    }
  }
}

}  // namespace

// A membrane pressure given as a function of time: kept as text with its value at t = 0; a malformed
// one names the field.
TEST(SceneReader, MembranePressureOfTime) {
  const std::string head = R"(
nodes: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]
elements: [[1, 2, 3, 4]]
nprops: {1: {fix: true}, 2: {fix: true}, 3: {fix: true}, 4: {fix: true}}
opt: {calcfreq: false, dynamics: {tend: 0.01, dt: 0.001}}
eprops:
  - {elems: [1], type: membrane, thickness: 1e-3, emod: 1e9, nu: 0.3, dens: 1000, prestress: [1e6, 1e6, 0], )";
  const Model m = sinew::parseScene(head + "pressure: \"5 + 100*t\"}\n", sourceDir());
  const auto* mp = m.eprops.at(0).as<sinew::MembraneProperties>();
  ASSERT_NE(mp, nullptr);
  EXPECT_EQ(mp->pressure_t, "5 + 100*t");
  EXPECT_DOUBLE_EQ(mp->pressure, 5.0);
  const SceneError e = parseError(head + "pressure: \"t < ? 2\"}\n");
  EXPECT_EQ(e.path(), "eprops(1).pressure");
}
