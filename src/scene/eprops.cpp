// eprops: element property sets (beam, cable, membrane, ancf_cable2d) and the per-element
// checks that depend on the element type.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "scene/nearest_name.hpp"
#include "scene/scene_detail.hpp"
#include "scene/time_fields.hpp"

namespace sinew::scene {
namespace {

const std::vector<std::string> kCommonKeys = {"elems", "type", "physical", "color", "opacity", "hide"};
const std::vector<std::string> kBeamKeys = {"flex", "nbeams", "cw", "warping", "emod", "smod", "dens", "cshape", "dim", "orien"};
const std::vector<std::string> kCableKeys = {"area", "emod", "dens", "prestress", "prestress_stress"};
const std::vector<std::string> kMembraneKeys = {"thickness", "emod", "nu", "dens", "prestress", "prestress_dir",
                                                "prestress_radial_axis", "pressure", "pressure_initial"};
const std::vector<std::string> kAncfKeys = {"physicsMassPerLength", "physicsBendingStiffness", "physicsAxialStiffness",
                                            "physicsBendingDamping", "physicsAxialDamping", "physicsReferenceAxialStrain",
                                            "physicsReferenceCurvature", "strainIsRelativeToReference",
                                            "useReducedOrderIntegration", "axialForceUserFunction",
                                            "bendingMomentUserFunction", "nbeams", "massProportionalLoad"};
const std::vector<std::string> kTypes = {"beam", "cable", "membrane", "ancf_cable2d"};

const std::vector<std::string>& typeKeys(ElementType t) {
  switch (t) {
    case ElementType::Cable: return kCableKeys;
    case ElementType::Membrane: return kMembraneKeys;
    case ElementType::AncfCable2D: return kAncfKeys;
    case ElementType::Beam: break;
  }
  return kBeamKeys;
}

bool contains(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

/// Keys of a set: common keys plus those of its type; a key of another type gets a pointed message.
void checkSetKeys(const YAML::Node& n, const std::string& path, ElementType type) {
  std::vector<std::string> allowed = kCommonKeys;
  const auto& own = typeKeys(type);
  allowed.insert(allowed.end(), own.begin(), own.end());
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string k = keyString(it->first, path);
    if (contains(allowed, k)) continue;
    for (ElementType other : {ElementType::Beam, ElementType::Cable, ElementType::Membrane, ElementType::AncfCable2D})
      if (other != type && contains(typeKeys(other), k)) {
        const std::string near = nearestName(k, allowed);
        fail(childPath(path, k), "key '" + k + "' does not apply to type " + elementTypeName(type) + " (it is a " + elementTypeName(other) +
                                     " field)" + (near.empty() ? "" : " (did you mean '" + near + "'?)"));
      }
  }
  checkKeys(n, path, allowed);
}

/// A direction vector: 3 numbers, not all zero.
Vec3 getDirection(const YAML::Node& n, const std::string& path, bool allow2 = false) {
  const Vec3 v = getVec3(n, path, allow2, kLoad);
  if (norm(v) == 0) fail(path, "expected a nonzero direction, got [0, 0, 0]");
  return v;
}

std::string modeList(const std::vector<int>& modes) {
  std::string s;
  for (std::size_t i = 0; i < modes.size(); ++i) s += (i == 0 ? "" : i + 1 == modes.size() ? " and " : ", ") + std::to_string(modes[i]);
  return s;
}

void parseBeam(const YAML::Node& n, const std::string& path, ElementSet& s) {
  BeamProperties& b = s.get<BeamProperties>();
  std::vector<int> flexModes;
  if (const YAML::Node f = n["flex"]; f.IsDefined()) {
    const auto modes = getInts(f, childPath(path, "flex"), true);
    for (std::size_t i = 0; i < modes.size(); ++i) {
      const std::string p = f.IsSequence() ? indexPath(childPath(path, "flex"), i) : childPath(path, "flex");
      if (modes[i] < 1 || modes[i] > 6) fail(p, "expected a deformation mode 1..6, got " + std::to_string(modes[i]));
      if (b.flex[static_cast<std::size_t>(modes[i] - 1)]) fail(p, "mode " + std::to_string(modes[i]) + " is listed twice");
      b.flex[static_cast<std::size_t>(modes[i] - 1)] = true;
      flexModes.push_back(modes[i]);
    }
  }
  std::sort(flexModes.begin(), flexModes.end());
  if (const YAML::Node v = n["nbeams"]; v.IsDefined()) s.nbeams = getIntAtLeast(v, childPath(path, "nbeams"), 1);
  if (const YAML::Node v = n["cw"]; v.IsDefined()) b.cw = getBool(v, childPath(path, "cw"));
  if (const YAML::Node v = n["warping"]; v.IsDefined()) {  // newer SPACAR Light scripts' name of cw
    if (n["cw"].IsDefined()) fail(childPath(path, "warping"), "warping is another name of cw; give one of them");
    b.cw = getBool(v, childPath(path, "warping"));
  }
  const bool hasE = n["emod"].IsDefined(), hasG = n["smod"].IsDefined(), hasRho = n["dens"].IsDefined();
  if (hasE) b.emod = getNonNegative(n["emod"], childPath(path, "emod"), kMaterial);
  if (hasG) b.smod = getNonNegative(n["smod"], childPath(path, "smod"), kMaterial);
  if (hasRho) b.dens = getNonNegative(n["dens"], childPath(path, "dens"), kMaterial);
  if (const YAML::Node v = n["cshape"]; v.IsDefined())
    b.cshape = getChoice(v, childPath(path, "cshape"), {"rect", "circ"}) == "rect" ? CrossSection::Rect : CrossSection::Circ;
  if (const YAML::Node v = n["dim"]; v.IsDefined()) {
    const std::string p = childPath(path, "dim");
    if (b.cshape == CrossSection::None)
      fail(childPath(path, "cshape"), "missing: dim is given, so cshape (rect or circ) is needed to read it");
    const std::size_t want = b.cshape == CrossSection::Rect ? 2 : 1;
    const std::string shape = b.cshape == CrossSection::Rect ? "rect" : "circ";
    if (want == 1 && v.IsScalar()) {  // the seed's double: dim: 0.01 is dim: [0.01]
      b.dim.push_back(getPositive(v, p, kSectionLength));
    } else {
      if (!v.IsSequence()) fail(p, "expected a list of " + std::to_string(want) + (want == 1 ? " number" : " numbers") +
                                       " (or, for circ, one number) for cshape " + shape + ", got " + describe(v));
      if (v.size() != want)
        fail(p, "expected " + std::to_string(want) + (want == 1 ? " number" : " numbers") + " for cshape " + shape + " (" +
                    (want == 2 ? "[width, height]" : "[diameter]") + "), got " + std::to_string(v.size()));
      for (std::size_t i = 0; i < want; ++i) b.dim.push_back(getPositive(v[i], indexPath(p, i), kSectionLength));
    }
  }
  if (const YAML::Node v = n["orien"]; v.IsDefined()) b.orien = getDirection(v, childPath(path, "orien"));

  // The materials the flexible modes need, as the element (beamSection) needs them: emod for
  // elongation (1) and bending (3-6), smod for torsion (2) and for the shear deformation of bending
  // (3-6, Timoshenko); constrained warping (cw) needs both (Poisson's ratio emod / (2 smod) - 1).
  std::vector<int> needE, needG;
  for (int m : flexModes) {
    if (m != 2 || b.cw) needE.push_back(m);
    if (m != 1) needG.push_back(m);
  }
  auto what = [](const std::vector<int>& modes) {
    std::string w;
    for (int m : modes) {
      const char* kind = m == 1 ? "elongation" : m == 2 ? "torsion" : "bending";
      if (w.find(kind) == std::string::npos) w += std::string(w.empty() ? "" : ", ") + kind;
    }
    return w;
  };
  if (!needE.empty() && (!hasE || b.emod == 0))
    fail(childPath(path, "emod"), std::string(hasE ? "expected emod > 0" : "missing") + ": flexible mode" +
                                      (needE.size() > 1 ? "s " : " ") + modeList(needE) + " (" + what(needE) +
                                      (b.cw && b.flex[1] ? "; torsion with cw" : "") + ") need" +
                                      (needE.size() > 1 ? " " : "s ") + "emod (Young's modulus)");
  if (!needG.empty() && (!hasG || b.smod == 0))
    fail(childPath(path, "smod"), std::string(hasG ? "expected smod > 0" : "missing") + ": flexible mode" +
                                      (needG.size() > 1 ? "s " : " ") + modeList(needG) + " (" + what(needG) +
                                      (needG.back() > 2 ? ", with shear deformation" : "") + ") need" +
                                      (needG.size() > 1 ? " " : "s ") + "smod (shear modulus)");
  if (b.cw && b.cshape == CrossSection::Circ && !flexModes.empty())
    fail(childPath(path, n["warping"].IsDefined() ? "warping" : "cw"),
         "constrained warping (cw) applies to rect sections only (cshape is circ)");
  if (!flexModes.empty() || b.dens > 0) {
    const std::string why = flexModes.empty() ? "a beam with dens > 0" : "a flexible beam";
    if (b.cshape == CrossSection::None) fail(childPath(path, "cshape"), "missing: " + why + " needs cshape (rect or circ) and dim");
    if (b.dim.empty())
      fail(childPath(path, "dim"), "missing: " + why + " needs dim (" +
                                       (b.cshape == CrossSection::Rect ? "[width, height] for cshape rect" : "[diameter] for cshape circ") + ")");
  }
}

void parseCable(const YAML::Node& n, const std::string& path, CableProperties& c) {
  if (!n["area"].IsDefined()) fail(childPath(path, "area"), "missing: a cable needs area (cross-section area)");
  c.area = getPositive(n["area"], childPath(path, "area"), kArea);
  if (!n["emod"].IsDefined()) fail(childPath(path, "emod"), "missing: a cable needs emod (Young's modulus)");
  c.emod = getNonNegative(n["emod"], childPath(path, "emod"), kMaterial);
  if (const YAML::Node v = n["dens"]; v.IsDefined()) c.dens = getNonNegative(v, childPath(path, "dens"), kMaterial);
  if (const YAML::Node v = n["prestress"]; v.IsDefined()) c.prestress = getNonNegative(v, childPath(path, "prestress"), kLoad);
  if (const YAML::Node v = n["prestress_stress"]; v.IsDefined()) {
    if (c.prestress)
      fail(childPath(path, "prestress_stress"), "give either prestress (a force) or prestress_stress (a stress), not both");
    c.prestress_stress = getNonNegative(v, childPath(path, "prestress_stress"), kLoad);
  }
}

void parseMembrane(const YAML::Node& n, const std::string& path, MembraneProperties& mp) {
  if (!n["thickness"].IsDefined()) fail(childPath(path, "thickness"), "missing: a membrane needs thickness");
  mp.thickness = getPositive(n["thickness"], childPath(path, "thickness"), kSectionLength);
  if (!n["emod"].IsDefined()) fail(childPath(path, "emod"), "missing: a membrane needs emod (Young's modulus)");
  // emod: 0 for a form-finding-only set (Kratos' form-finding tests use E = 0); checked against the
  // analyses by checkZeroModulusMembranes once the formfinding block is read
  mp.emod = getNonNegative(n["emod"], childPath(path, "emod"), kMaterial);
  if (!n["nu"].IsDefined()) fail(childPath(path, "nu"), "missing: a membrane needs nu (Poisson's ratio, in [0, 0.5))");
  mp.nu = getInRange(n["nu"], childPath(path, "nu"), 0.0, 0.5, true);
  if (const YAML::Node v = n["dens"]; v.IsDefined()) mp.dens = getNonNegative(v, childPath(path, "dens"), kMaterial);
  if (const YAML::Node v = n["prestress"]; v.IsDefined()) {
    const std::string p = childPath(path, "prestress");
    if (!v.IsSequence() || v.size() != 3)
      fail(p, "expected 3 numbers [s11, s22, s12], got " + (v.IsSequence() ? std::to_string(v.size()) : describe(v)));
    const auto x = getNumbers(v, p, 3, kLoad);
    mp.prestress = {x[0], x[1], x[2]};
  }
  if (const YAML::Node v = n["prestress_dir"]; v.IsDefined()) mp.prestress_dir = getDirection(v, childPath(path, "prestress_dir"));
  if (const YAML::Node v = n["prestress_radial_axis"]; v.IsDefined()) {
    if (mp.prestress_dir)
      fail(childPath(path, "prestress_radial_axis"), "give either prestress_dir or prestress_radial_axis, not both");
    mp.prestress_radial_axis = getDirection(v, childPath(path, "prestress_radial_axis"));
  }
  if (const YAML::Node v = n["pressure"]; v.IsDefined())
    mp.pressure = getNumberOrTimeFunction(v, childPath(path, "pressure"), kLoad, &mp.pressure_t);
  if (const YAML::Node v = n["pressure_initial"]; v.IsDefined())
    mp.pressure_initial = getNumber(v, childPath(path, "pressure_initial"), kLoad);
}

void parseAncf(const YAML::Node& n, const std::string& path, ElementSet& s) {
  AncfCable2DProperties& a = s.get<AncfCable2DProperties>();
  auto p = [&](const char* k) { return childPath(path, k); };
  if (const YAML::Node v = n["physicsMassPerLength"]; v.IsDefined()) a.physicsMassPerLength = getNonNegative(v, p("physicsMassPerLength"), kMaterial);
  if (!n["physicsBendingStiffness"].IsDefined())
    fail(p("physicsBendingStiffness"), "missing: ancf_cable2d needs physicsBendingStiffness (EI) > 0");
  a.physicsBendingStiffness = getPositive(n["physicsBendingStiffness"], p("physicsBendingStiffness"), kMaterial);
  if (!n["physicsAxialStiffness"].IsDefined())
    fail(p("physicsAxialStiffness"), "missing: ancf_cable2d needs physicsAxialStiffness (EA) > 0");
  a.physicsAxialStiffness = getPositive(n["physicsAxialStiffness"], p("physicsAxialStiffness"), kMaterial);
  if (const YAML::Node v = n["physicsBendingDamping"]; v.IsDefined()) a.physicsBendingDamping = getNonNegative(v, p("physicsBendingDamping"), kMaterial);
  if (const YAML::Node v = n["physicsAxialDamping"]; v.IsDefined()) a.physicsAxialDamping = getNonNegative(v, p("physicsAxialDamping"), kMaterial);
  if (const YAML::Node v = n["physicsReferenceAxialStrain"]; v.IsDefined())
    a.physicsReferenceAxialStrain = getNumber(v, p("physicsReferenceAxialStrain"), kRatio);
  if (const YAML::Node v = n["physicsReferenceCurvature"]; v.IsDefined())
    a.physicsReferenceCurvature = getNumber(v, p("physicsReferenceCurvature"), kCurvature);
  if (const YAML::Node v = n["strainIsRelativeToReference"]; v.IsDefined())
    a.strainIsRelativeToReference = getInRange(v, p("strainIsRelativeToReference"), 0.0, 1.0);
  if (const YAML::Node v = n["useReducedOrderIntegration"]; v.IsDefined()) {
    a.useReducedOrderIntegration = getInt(v, p("useReducedOrderIntegration"));
    if (a.useReducedOrderIntegration < 0 || a.useReducedOrderIntegration > 2)
      fail(p("useReducedOrderIntegration"), "expected 0, 1 or 2, got " + std::to_string(a.useReducedOrderIntegration));
  }
  for (const char* k : {"axialForceUserFunction", "bendingMomentUserFunction"}) {
    const YAML::Node v = n[k];
    if (!v.IsDefined()) continue;
    const std::string f = getString(v, p(k));
    if (f.find_first_not_of(" \t\n") == std::string::npos) fail(p(k), "expected an expression, got an empty string");
    (std::string(k) == "axialForceUserFunction" ? a.axialForceUserFunction : a.bendingMomentUserFunction) = f;
  }
  if (const YAML::Node v = n["nbeams"]; v.IsDefined()) s.nbeams = getIntAtLeast(v, p("nbeams"), 1);
  if (const YAML::Node v = n["massProportionalLoad"]; v.IsDefined()) a.massProportionalLoad = getVec3(v, p("massProportionalLoad"), true, kLoad);
}

void parseLook(const YAML::Node& n, const std::string& path, ElementSet& s) {
  if (const YAML::Node v = n["color"]; v.IsDefined()) {
    const std::string p = childPath(path, "color");
    // SPACAR Light's forms: [r, g, b] in 0..1, or 0..255 when any value is > 1; a name or a 1-based
    // index of the seed's colour table
    static const std::vector<std::string> names = {"blue", "grey", "darkblue", "darkgrey", "green", "darkgreen"};
    // (the seed's darkblue is (0, 124, 176)/255 and its grey 198/255)
    static const std::array<std::array<double, 3>, 6> table = {{{0.0, 0.447, 0.741},
                                                                 {198 / 255.0, 198 / 255.0, 198 / 255.0},
                                                                 {0.0, 124 / 255.0, 176 / 255.0},
                                                                 {0.4, 0.4, 0.4},
                                                                 {0.466, 0.674, 0.188},
                                                                 {0.1, 0.4, 0.1}}};
    const std::string what = "expected [r, g, b] (0..1 or 0..255), a colour name (blue, grey, darkblue, darkgrey, green, "
                             "darkgreen) or its index 1..6";
    if (v.IsScalar() && !isNumber(v)) {
      const auto it = std::find(names.begin(), names.end(), v.Scalar());
      if (it == names.end()) fail(p, what + ", got '" + v.Scalar() + "'" + suggestion(v.Scalar(), names));
      s.color = table[static_cast<std::size_t>(it - names.begin())];
    } else if (v.IsScalar() || (v.IsSequence() && v.size() == 1)) {
      const int k = getInt(v, p);
      if (k < 1 || k > 6) fail(p, what + ", got the index " + std::to_string(k));
      s.color = table[static_cast<std::size_t>(k - 1)];
    } else {
      if (!v.IsSequence() || v.size() != 3) fail(p, what + ", got " + (v.IsSequence() ? "a list of " + std::to_string(v.size()) : describe(v)));
      std::array<double, 3> c{};
      for (std::size_t i = 0; i < 3; ++i) c[i] = getInRange(v[i], indexPath(p, i), 0.0, 255.0);
      if (std::any_of(c.begin(), c.end(), [](double x) { return x > 1.0; }))
        for (double& x : c) x /= 255.0;
      s.color = c;
    }
  }
  if (const YAML::Node v = n["opacity"]; v.IsDefined()) s.opacity = getInRange(v, childPath(path, "opacity"), 0.0, 1.0);
  if (const YAML::Node v = n["hide"]; v.IsDefined()) s.hide = getBool(v, childPath(path, "hide"));
}

std::string nodeList(const std::vector<int>& nodes) {
  std::string s;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    s += (i == 0 ? "" : i + 1 == nodes.size() ? " and " : ", ") + std::to_string(nodes[i] + 1);
  return s;
}

/// "a beam element (eprops(1))", "a rigid beam (in no eprops set)".
std::string elementKind(const Model& m, int e) {
  const int set = m.elementSet[static_cast<std::size_t>(e)];
  if (set < 0) return "a rigid beam (in no eprops set)";
  return std::string("a ") + elementTypeName(m.eprops[static_cast<std::size_t>(set)].type()) + " element (" + epropsName(set) + ")";
}

/// Two elements of the same type on the same node set (in any order) are one element given twice;
/// an element in no set is a (rigid) beam, so it duplicates a beam on the same nodes too.
void checkDuplicateElements(const SceneContext& ctx) {
  const Model& m = ctx.model;
  std::map<std::pair<int, std::vector<int>>, int> seen;  // (type, sorted nodes) -> element
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const int set = m.elementSet[e];
    const ElementType type = set < 0 ? ElementType::Beam : m.eprops[static_cast<std::size_t>(set)].type();
    std::vector<int> nodes = m.elements[e];
    std::sort(nodes.begin(), nodes.end());
    const int ei = static_cast<int>(e);
    const auto [it, fresh] = seen.emplace(std::make_pair(static_cast<int>(type), nodes), ei);
    if (fresh) continue;
    fail(ctx.elementPath(ei), ctx.elementLabel(ei) + " duplicates " + ctx.elementLabel(it->second) + " on nodes " + nodeList(nodes) +
                                  ": " + elementKind(m, ei) + " and " + elementKind(m, it->second) +
                                  " (remove one, or merge their properties into one set)");
  }
}

/// Elements after nbeams splitting stay within kMaxSplitElements.
void checkSplitCount(const SceneContext& ctx) {
  const Model& m = ctx.model;
  double total = 0;
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const int set = m.elementSet[e];
    total += (set >= 0 && m.elements[e].size() == 2) ? m.eprops[static_cast<std::size_t>(set)].nbeams : 1;
  }
  if (total <= kMaxSplitElements) return;
  if (m.eprops.empty()) fail("elements", "the model has " + fmt(total) + " elements; Sinew takes at most " + fmt(kMaxSplitElements));
  int biggest = 0;
  for (std::size_t i = 1; i < m.eprops.size(); ++i)
    if (m.eprops[i].nbeams > m.eprops[static_cast<std::size_t>(biggest)].nbeams) biggest = static_cast<int>(i);
  fail(childPath(indexPath("eprops", static_cast<std::size_t>(biggest)), "nbeams"),
       "nbeams splits the model into " + fmt(total) + " elements; Sinew takes at most " + fmt(kMaxSplitElements));
}

}  // namespace

std::vector<std::vector<std::string>> scanPhysicalNames(const YAML::Node& eprops) {
  std::vector<std::vector<std::string>> names;
  if (!eprops.IsDefined() || !eprops.IsSequence()) return names;
  for (std::size_t i = 0; i < eprops.size(); ++i) {
    std::vector<std::string> set;
    const YAML::Node item = eprops[i];
    if (item.IsDefined() && item.IsMap()) {
      const YAML::Node ph = item["physical"];
      if (ph.IsDefined() && ph.IsScalar()) set.push_back(ph.Scalar());
      if (ph.IsDefined() && ph.IsSequence())
        for (std::size_t k = 0; k < ph.size(); ++k)
          if (ph[k].IsScalar()) set.push_back(ph[k].Scalar());
    }
    names.push_back(std::move(set));
  }
  return names;
}

void parseEprops(const YAML::Node& eprops, SceneContext& ctx) {
  Model& m = ctx.model;
  m.elementSet.assign(m.elements.size(), -1);
  if (!eprops.IsDefined() || eprops.IsNull()) return;
  if (!eprops.IsSequence()) fail("eprops", "expected a list of property sets (- elems: [...]), got " + describe(eprops));
  std::vector<std::string> where(m.elements.size());  // path that put each element in its set
  for (std::size_t i = 0; i < eprops.size(); ++i) {
    const std::string path = indexPath("eprops", i);
    const YAML::Node n = eprops[i];
    if (!n.IsMap()) fail(path, "expected a map of set properties (elems, type, ...), got " + describe(n));
    ElementSet s;
    if (const YAML::Node t = n["type"]; t.IsDefined()) {
      const std::string type = getChoice(t, childPath(path, "type"), kTypes);
      if (type == "cable") s.props = CableProperties{};
      else if (type == "membrane") s.props = MembraneProperties{};
      else if (type == "ancf_cable2d") s.props = AncfCable2DProperties{};
    }
    checkSetKeys(n, path, s.type());

    std::vector<std::pair<int, std::string>> members;  // element, path naming it
    const YAML::Node elems = n["elems"], physical = n["physical"];
    if (!elems.IsDefined() && !physical.IsDefined())
      fail(childPath(path, "elems"), "missing: the set needs elems (element numbers) or physical (Gmsh group names)");
    std::set<int> inSet;
    if (elems.IsDefined()) {
      const std::string p = childPath(path, "elems");
      if (!elems.IsSequence() && !elems.IsScalar()) fail(p, "expected a list of element numbers, got " + describe(elems));
      for (std::size_t k = 0; k < (elems.IsSequence() ? elems.size() : 1); ++k) {
        const std::string pk = elems.IsSequence() ? indexPath(p, k) : p;
        const int e = checkedIndex(elems.IsSequence() ? elems[k] : elems, pk, "element", m.elements.size());
        if (!inSet.insert(e).second) fail(pk, "element " + std::to_string(e + 1) + " is listed twice in this set");
        members.emplace_back(e, pk);
      }
    }
    std::vector<std::string> physNames;
    if (physical.IsDefined()) {
      const std::string p = childPath(path, "physical");
      physNames = getStrings(physical, p);
      if (!ctx.mesh) fail(p, "physical groups come from a Gmsh file, but the scene has no `mesh:`");
      for (std::size_t k = 0; k < physNames.size(); ++k) {
        const std::string pk = physical.IsSequence() ? indexPath(p, k) : p;
        const GmshPhysicalGroup* g = ctx.mesh->findGroup(physNames[k]);
        if (!g)
          fail(pk, "no physical group '" + physNames[k] + "' in " + ctx.mesh->file + suggestion(physNames[k], ctx.mesh->groupNames()));
        if (g->dim == 0) fail(pk, "physical group '" + physNames[k] + "' holds points, not elements");
        for (int ge : g->elements) {
          const int e = ctx.meshElementToModel[static_cast<std::size_t>(ge)];
          if (e < 0 || !inSet.insert(e).second) continue;
          members.emplace_back(e, pk);
        }
      }
    }
    if (members.empty()) fail(physical.IsDefined() ? childPath(path, "physical") : childPath(path, "elems"), "the set has no elements");
    for (const auto& [e, pk] : members) {
      const int other = m.elementSet[static_cast<std::size_t>(e)];
      if (other >= 0)
        fail(pk, ctx.elementLabel(e) + " is already in " + epropsName(other) + " (" + where[static_cast<std::size_t>(e)] +
                     "); an element belongs to one set");
      m.elementSet[static_cast<std::size_t>(e)] = static_cast<int>(i);
      where[static_cast<std::size_t>(e)] = pk;
      s.elems.push_back(e);
    }

    switch (s.type()) {
      case ElementType::Beam: parseBeam(n, path, s); break;
      case ElementType::Cable: parseCable(n, path, s.get<CableProperties>()); break;
      case ElementType::Membrane: parseMembrane(n, path, s.get<MembraneProperties>()); break;
      case ElementType::AncfCable2D: parseAncf(n, path, s); break;
    }
    parseLook(n, path, s);
    m.eprops.push_back(std::move(s));
    ctx.setPhysical.push_back(std::move(physNames));
  }
}

void checkElementTypes(SceneContext& ctx) {
  Model& m = ctx.model;
  int ancfSet = -1;
  for (std::size_t i = 0; i < m.eprops.size(); ++i)
    if (m.eprops[i].type() == ElementType::AncfCable2D && ancfSet < 0) ancfSet = static_cast<int>(i);
  const std::string ancfPath = epropsName(ancfSet);

  for (std::size_t i = 0; i < m.eprops.size(); ++i) {
    const ElementType t = m.eprops[i].type();
    const std::string p = childPath(indexPath("eprops", i), "type");
    if ((t == ElementType::Cable || t == ElementType::Membrane) && m.dimension == 2)
      fail(p, std::string(elementTypeName(t)) + " elements need a 3D model, but the nodes have 2 coordinates (x, y)");
    if (ancfSet >= 0 && t != ElementType::AncfCable2D)
      fail(p, std::string("cannot mix ") + elementTypeName(t) + " elements with ancf_cable2d (" + ancfPath +
                  "): an ancf_cable2d model is planar and holds only ancf_cable2d elements");
  }
  if (ancfSet >= 0 && m.dimension == 3)
    for (std::size_t k = 0; k < m.nodes.size(); ++k)
      if (m.nodes[k][2] != 0.0)
        fail(childPath(ancfPath, "type"), "ancf_cable2d needs a 2D model (nodes with x, y only, or z = 0), but node " +
                                              std::to_string(k + 1) + " has z = " + fmt(m.nodes[k][2]));

  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const int ei = static_cast<int>(e);
    const int set = m.elementSet[e];
    const std::size_t nn = m.elements[e].size();
    if (set < 0) {
      if (ancfSet >= 0)
        fail(ctx.elementPath(ei), ctx.elementLabel(ei) + " is in no eprops set (a rigid beam), which cannot be mixed with ancf_cable2d (" +
                                      ancfPath + ")");
      if (nn != 2)
        fail(ctx.elementPath(ei), ctx.elementLabel(ei) + " has " + std::to_string(nn) +
                                      " nodes but is in no eprops set: an element without a set is a rigid 2-node beam; "
                                      "3- or 4-node elements need a membrane set");
      continue;
    }
    const ElementType t = m.eprops[static_cast<std::size_t>(set)].type();
    const bool ok = t == ElementType::Membrane ? (nn == 3 || nn == 4) : nn == 2;
    if (!ok)
      fail(ctx.elementPath(ei), ctx.elementLabel(ei) + " has " + std::to_string(nn) + " nodes, but " + epropsName(set) +
                                    " makes it a " + elementTypeName(t) + ", which needs " +
                                    (t == ElementType::Membrane ? "3 or 4" : "2"));
    if (t == ElementType::Membrane) {
      // Zero area: a triangle (or either half of a quad split along 1-3) with collinear nodes.
      const auto& el = m.elements[e];
      auto x = [&](std::size_t k) { return m.nodes[static_cast<std::size_t>(el[k])]; };
      const double l = std::max(norm(x(1) - x(0)), norm(x(2) - x(0)));
      auto area2 = [&](std::size_t a, std::size_t b, std::size_t c) { return norm(cross(x(b) - x(a), x(c) - x(a))); };
      const bool flat = area2(0, 1, 2) <= 1e-12 * l * l || (nn == 4 && area2(0, 2, 3) <= 1e-12 * l * l);
      if (flat) fail(ctx.elementPath(ei), ctx.elementLabel(ei) + " has zero area: its nodes are collinear");
    }
  }
  checkDuplicateElements(ctx);
  checkSplitCount(ctx);
}

}  // namespace sinew::scene
