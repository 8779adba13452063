// The element-kind registry (src/elements/element_kinds.*): one entry per ElementType, in its
// order; what the plan and the runner ask of a set comes from its kind's properties.
#include <gtest/gtest.h>

#include "elements/element_kinds.hpp"

using namespace sinew;

namespace {
ElementSet setOf(ElementSet::Properties props, std::vector<int> elems = {0}) {
  ElementSet s;
  s.elems = std::move(elems);
  s.props = std::move(props);
  return s;
}
}  // namespace

TEST(ElementKinds, OneEntryPerTypeInVariantOrder) {
  ASSERT_EQ(elementKinds().size(), std::variant_size_v<ElementSet::Properties>);
  for (std::size_t i = 0; i < elementKinds().size(); ++i) {
    const ElementKind& k = elementKinds()[i];
    EXPECT_EQ(static_cast<std::size_t>(k.type), i);
    EXPECT_NE(k.hasInertia, nullptr);
    EXPECT_NE(k.initiallyLoaded, nullptr);
    EXPECT_NE(k.bodyLoaded, nullptr);
    EXPECT_NE(k.stressOutput, nullptr);
    EXPECT_EQ(k.counters == nullptr, k.countersLine == nullptr);
  }
  EXPECT_EQ(setOf(CableProperties{}).type(), ElementType::Cable);
  EXPECT_EQ(ElementSet{}.type(), ElementType::Beam);  // a set without type is a beam
}

TEST(ElementKinds, PropertiesOfTheKind) {
  CableProperties c;
  c.dens = 7800;
  c.prestress = 10.0;
  const ElementSet cable = setOf(c);
  EXPECT_TRUE(elementKind(ElementType::Cable).hasInertia(cable));
  EXPECT_TRUE(elementKind(ElementType::Cable).initiallyLoaded(cable));
  EXPECT_EQ(elementKind(ElementType::Cable).missingPrestress(cable), nullptr);
  EXPECT_STREQ(elementKind(ElementType::Cable).missingPrestress(setOf(CableProperties{})), "prestress / prestress_stress");
  MembraneProperties m;
  m.pressure_initial = 1.0;
  EXPECT_TRUE(elementKind(ElementType::Membrane).initiallyLoaded(setOf(m)));
  EXPECT_STREQ(elementKind(ElementType::Membrane).missingPrestress(setOf(m)), "prestress [s11, s22, s12]");
  AncfCable2DProperties a;
  EXPECT_FALSE(elementKind(ElementType::AncfCable2D).bodyLoaded(setOf(a)));
  a.massProportionalLoad = Vec3{0, -9.81, 0};
  a.physicsMassPerLength = 2.0;
  EXPECT_TRUE(elementKind(ElementType::AncfCable2D).bodyLoaded(setOf(a)));
  EXPECT_TRUE(elementKind(ElementType::AncfCable2D).hasInertia(setOf(a)));
  BeamProperties b;
  b.flex[0] = true;
  EXPECT_FALSE(elementKind(ElementType::Beam).stressOutput(setOf(b)));
  b.cshape = CrossSection::Circ;
  EXPECT_TRUE(elementKind(ElementType::Beam).stressOutput(setOf(b)));
  EXPECT_TRUE(elementKind(ElementType::Beam).elementSensors && elementKind(ElementType::AncfCable2D).elementSensors);
  EXPECT_FALSE(elementKind(ElementType::Cable).elementSensors || elementKind(ElementType::Membrane).elementSensors);
}

TEST(ElementKinds, FormFoundSetsDefaultToTheFormFindableKinds) {
  const std::vector<ElementSet> eprops = {setOf(BeamProperties{}), setOf(MembraneProperties{}), setOf(AncfCable2DProperties{}),
                                          setOf(CableProperties{})};
  FormFinding ff;
  EXPECT_EQ(formFoundSets(ff, eprops), (std::vector<int>{1, 3}));
  ff.formfinding_elements = {3};
  EXPECT_EQ(formFoundSets(ff, eprops), (std::vector<int>{3}));
}

TEST(ElementKinds, BeamWarnings) {
  Model m;
  m.nodes = {{0, 0, 0}, {0.1, 0, 0}, {0.2, 0, 0}};
  m.elements = {{0, 1}, {1, 2}};
  BeamProperties b;
  b.flex = {true, true, true, true, true, true};
  b.cshape = CrossSection::Rect;
  b.dim = {0.05, 0.001};
  m.eprops = {setOf(b, {0, 1})};
  const std::vector<std::string> w = elementKind(ElementType::Beam).warnings(m, 0);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0], "eprops(1) elements 1, 2: cshape rect without orien (SPACAR Light requires it); the width dim(1) is taken "
                  "along the global z axis (global y for an element along z): give orien");
  // every short element is named (issue 24 item 13), with the smallest ratio
  EXPECT_EQ(w[1], "eprops(1) elements 1, 2: L/w down to 2 < 3 without cw; constrained warping stiffens torsion (set cw: true)");
  b.orien = Vec3{0, 0, 1};
  b.cw = true;
  m.eprops = {setOf(b, {0, 1})};
  EXPECT_TRUE(elementKind(ElementType::Beam).warnings(m, 0).empty());
}
