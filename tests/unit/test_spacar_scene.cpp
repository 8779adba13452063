// SPACAR Light's scene vocabulary (issue 10): what a scene written in the seed's own terms reads as.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "elements/beam_section.hpp"
#include "elements/element_kinds.hpp"
#include "scene/scene_reader.hpp"

#ifndef SINEW_SOURCE_DIR
#define SINEW_SOURCE_DIR "/work/main"
#endif

namespace {

using sinew::Model;
using sinew::SceneError;

Model parse(const std::string& text) { return sinew::parseScene(text, SINEW_SOURCE_DIR, {}); }

SceneError parseError(const std::string& text) {
  try {
    parse(text);
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "no SceneError for:\n" << text;
  return SceneError("<none>", "<none>");
}

std::string beam(const std::string& nprops, const std::string& set, const std::string& opt = "") {
  return "nodes: [[0, 0, 0], [1, 0, 0]]\nelements: [[1, 2]]\nnprops: {" + nprops + "}\neprops:\n  - {elems: [1], " + set +
         "}\nopt: {" + opt + "}\n";
}

// item 4: dim for circ as the seed's double; generally a 1-element list and a scalar are the same
TEST(SpacarScene, ScalarAndOneElementListAreTheSame) {
  const std::string set = "flex: [1, 2, 3, 4, 5, 6], emod: 210e9, smod: 80e9, cshape: circ, dim: ";
  const Model a = parse(beam("1: {fix: true}", set + "0.01"));
  const Model b = parse(beam("1: {fix: true}", set + "[0.01]"));
  ASSERT_EQ(a.eprops[0].get<sinew::BeamProperties>().dim.size(), 1u);
  EXPECT_EQ(a.eprops[0].get<sinew::BeamProperties>().dim, b.eprops[0].get<sinew::BeamProperties>().dim);
  // [x] where a number is expected, x where a 1-element list is expected
  const Model c = parse(beam("1: {fix: true}, 2: {mass: [0.5]}", "flex: 1, emod: [210e9], cshape: circ, dim: [0.01]",
                             "loadsteps: [3], nfreq: [2]"));
  EXPECT_EQ(c.eprops[0].get<sinew::BeamProperties>().emod, 210e9);
  EXPECT_TRUE(c.eprops[0].get<sinew::BeamProperties>().flex[0]);
  EXPECT_EQ(c.nprops.at(1).mass, 0.5);
  EXPECT_EQ(c.opt.loadsteps, 3);
  EXPECT_EQ(c.opt.nfreq, 2);
  // rect still needs its two numbers
  EXPECT_EQ(parseError(beam("1: {fix: true}", "flex: [1], emod: 1e9, cshape: rect, dim: 0.01")).path(), "eprops(1).dim");
}

// item 16 (JSON): object keys are strings, "1" is node 1
TEST(SpacarScene, QuotedNodeKeys) {
  const Model m = parse(R"({"nodes": [[0,0,0],[1,0,0]], "elements": [[1,2]], "nprops": {"1": {"fix": true}, "2": {"mass": 1}},
                            "opt": {"rls": {"1": [1]}}})");
  EXPECT_TRUE(m.nprops.at(0).fix);
  EXPECT_EQ(m.nprops.at(1).mass, 1.0);
  EXPECT_EQ(m.opt.rls.count(0), 1u);
}

// item 1: SPACAR Light's load steps by default, Sinew's former ramp behind opt.load_ramp
TEST(SpacarScene, LoadRamp) {
  EXPECT_EQ(parse(beam("1: {fix: true}", "flex: []")).opt.load_ramp, "spacar");
  EXPECT_EQ(parse(beam("1: {fix: true}", "flex: []", "load_ramp: uniform")).opt.load_ramp, "uniform");
  EXPECT_EQ(parseError(beam("1: {fix: true}", "flex: []", "load_ramp: linear")).path(), "opt.load_ramp");
}

}  // namespace

namespace {

// item 2: rot / rot_initial as [angle, axis] (axis normalized), or a rotation vector
TEST(SpacarScene, RotationAngleAxis) {
  const sinew::Model m = parse(beam("1: {fix_pos: true, rot_initial: [0.5, 0, 3, 4], rot: [0.1, 0.2, 0.3]}", "flex: []"));
  const auto& np = m.nprops.at(0);
  ASSERT_TRUE(np.rot_initial && np.rot);
  EXPECT_DOUBLE_EQ((*np.rot_initial)[0], 0.0);
  EXPECT_DOUBLE_EQ((*np.rot_initial)[1], 0.3);
  EXPECT_DOUBLE_EQ((*np.rot_initial)[2], 0.4);
  EXPECT_DOUBLE_EQ((*np.rot)[2], 0.3);
  EXPECT_EQ(parseError(beam("1: {fix_pos: true, rot: [0.5, 0, 0, 0]}", "flex: []")).path(), "nprops(1).rot");
  EXPECT_EQ(parseError(beam("1: {fix_pos: true, rot: [0.5, 0]}", "flex: []")).path(), "nprops(1).rot");
}

}  // namespace

namespace {

// item 5: colour forms, opacity, hide, warping = cw, opt.customvis / opt.spavisual accepted
TEST(SpacarScene, VisualizationVocabulary) {
  const std::string rigid = "color: ";
  auto color = [&](const std::string& c) { return *parse(beam("1: {fix: true}", "flex: [], color: " + c)).eprops[0].color; };
  EXPECT_DOUBLE_EQ(color("[0.2, 0.4, 0.6]")[1], 0.4);
  EXPECT_DOUBLE_EQ(color("[51, 102, 255]")[2], 1.0);
  EXPECT_DOUBLE_EQ(color("[51, 102, 255]")[0], 0.2);
  EXPECT_EQ(color("darkgreen"), color("6"));
  EXPECT_EQ(color("blue"), color("[1]"));
  EXPECT_NE(color("grey"), color("darkgrey"));
  // the seed's colour table (issue 24 item 15): darkblue (0, 124, 176)/255, grey 198/255
  EXPECT_EQ(color("darkblue"), color("[0, 124, 176]"));
  EXPECT_EQ(color("grey"), color("[198, 198, 198]"));
  EXPECT_EQ(parseError(beam("1: {fix: true}", "flex: [], color: purple")).path(), "eprops(1).color");
  EXPECT_EQ(parseError(beam("1: {fix: true}", "flex: [], color: 7")).path(), "eprops(1).color");
  const Model m = parse(beam("1: {fix: true}", "flex: [1, 2], emod: 1e9, smod: 4e8, cshape: rect, dim: [0.01, 0.001], "
                                               "warping: true, opacity: 0.5, hide: true",
                             "spavisual: false, customvis: {file: part.stl}"));
  EXPECT_TRUE(m.eprops[0].get<sinew::BeamProperties>().cw);
  EXPECT_EQ(m.eprops[0].opacity, 0.5);
  EXPECT_TRUE(m.eprops[0].hide);
  EXPECT_TRUE(m.opt.customvis);
  EXPECT_EQ(parseError(beam("1: {fix: true}", "flex: [2], smod: 4e8, cshape: rect, dim: [0.01, 0.001], cw: true, warping: true"))
                .path(),
            "eprops(1).warping");
}

}  // namespace

namespace {

// item 13: the scene check (src/scene/eprops.cpp) and the element check (beamSection) agree on when
// emod and smod are required, for every set of flexible modes, with and without each modulus and cw
TEST(SpacarScene, ModulusRequirementsAgree) {
  int cases = 0;
  for (int mask = 0; mask < 64; ++mask)
    for (int materials = 0; materials < 4; ++materials)
      for (int cw = 0; cw < 2; ++cw) {
        const bool hasE = materials & 1, hasG = materials & 2;
        std::string flex = "[";
        sinew::BeamProperties set;
        set.cshape = sinew::CrossSection::Rect;
        set.dim = {0.01, 0.001};
        set.orien = sinew::Vec3{0, 0, 1};
        set.cw = cw;
        for (int m = 0; m < 6; ++m)
          if (mask & (1 << m)) {
            flex += (flex.size() > 1 ? ", " : "") + std::to_string(m + 1);
            set.flex[static_cast<std::size_t>(m)] = true;
          }
        flex += "]";
        if (hasE) set.emod = 210e9;
        if (hasG) set.smod = 80e9;
        const std::string text = beam("1: {fix: true}", "flex: " + flex + (hasE ? ", emod: 210e9" : "") +
                                                            (hasG ? ", smod: 80e9" : "") +
                                                            ", cshape: rect, dim: [0.01, 0.001], orien: [0, 0, 1]" +
                                                            (cw ? ", cw: true" : ""));
        bool sceneOk = true, elementOk = true;
        std::string sceneMsg, elementMsg;
        try {
          parse(text);
        } catch (const SceneError& e) {
          sceneOk = false;
          sceneMsg = e.what();
        }
        try {
          sinew::beamSection(set, 1.0);
        } catch (const SceneError& e) {
          elementOk = false;
          elementMsg = e.what();
        }
        EXPECT_EQ(sceneOk, elementOk) << "flex " << flex << (hasE ? " emod" : "") << (hasG ? " smod" : "")
                                      << (cw ? " cw" : "") << ": scene '" << sceneMsg << "', element '" << elementMsg << "'";
        ++cases;
      }
  EXPECT_EQ(cases, 512);
  // flex [3, 4] without smod: the error names the set's smod and says why
  const SceneError e = parseError(beam("1: {fix: true}", "flex: [3, 4], emod: 210e9, cshape: rect, dim: [0.01, 0.001], orien: [0, 0, 1]"));
  EXPECT_EQ(e.path(), "eprops(1).smod");
  EXPECT_NE(std::string(e.what()).find("modes 3 and 4 (bending, with shear deformation) need smod"), std::string::npos) << e.what();
}

}  // namespace

namespace {

/// Two beams, two property sets; `second` is the second set's fields (elems included).
std::string twoSets(const std::string& second, const std::string& nodes = "[[0, 0, 0], [1, 0, 0], [2, 0, 0]]") {
  return "nodes: " + nodes + "\nelements: [[1, 2], [2, 3]]\nnprops: {1: {fix: true}, 3: {force: [0, 1, 0]}}\neprops:\n"
         "  - {elems: [1], flex: [1, 2, 3, 4, 5, 6], emod: 210e9, smod: 80e9, cshape: circ, dim: [0.01]}\n"
         "  - {" + second + "}\n";
}

}  // namespace

// issue 24 item 13: set, list and matrix numbers in field paths and messages are 1-based as in SPACAR
// Light (eprops(2) is the second set): each of these was 0-based (eprops[1], dim[1], nodes[2][0]).
TEST(SpacarScene, FieldPathsAreOneBased) {
  const std::string beam2 = "elems: [2], flex: [1, 2, 3, 4, 5, 6], emod: 210e9, smod: 80e9, cshape: rect, orien: [0, 0, 1], dim: ";
  EXPECT_EQ(parseError(twoSets(beam2 + "[0.01, -1]")).path(), "eprops(2).dim(2)");
  EXPECT_EQ(parseError(twoSets(beam2 + "[0.01, 0.01]", "[[0, 0, 0], [1, 0, 0], [1e300, 0, 0]]")).path(), "nodes(3,1)");
  const SceneError again = parseError(twoSets("elems: [1], flex: [], cshape: circ, dim: [0.01]"));
  EXPECT_EQ(again.path(), "eprops(2).elems(1)");
  EXPECT_NE(std::string(again.what()).find("already in eprops(1)"), std::string::npos) << again.what();
  EXPECT_EQ(parseError(twoSets(beam2 + "[0.01, 0.01]") + "opt: {rls: {2: [1]}}").path(), "opt.rls(2,1)");
  // warnings: the second set, by its 1-based number
  const Model m = parse(twoSets("elems: [2], flex: [1, 2, 3, 4, 5, 6], emod: 210e9, smod: 80e9, cshape: rect, dim: [0.5, 0.01]"));
  ASSERT_EQ(m.eprops.size(), 2u);
  const auto w = sinew::elementKind(m.eprops[1].type()).warnings(m, 1);
  ASSERT_FALSE(w.empty());
  EXPECT_EQ(w[0].rfind("eprops(2) element 2: cshape rect without orien", 0), 0u) << w[0];
}
