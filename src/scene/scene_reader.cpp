// Scene reader: top level, nodes, elements, the Gmsh mesh merge and command-line overrides.
// The blocks nprops, eprops, opt, formfinding and sensors are read in their own files.
#include "scene/scene_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include "elements/element_kinds.hpp"
#include "scene/nearest_name.hpp"
#include "scene/scene_detail.hpp"

namespace sinew {
namespace scene {

std::string SceneContext::elementPath(int e) const {
  return isMeshElement(e) ? std::string("mesh") : indexPath("elements", static_cast<std::size_t>(e));
}

std::string SceneContext::elementLabel(int e) const {
  std::string s = "element " + std::to_string(e + 1);
  if (isMeshElement(e) && mesh) {
    const auto& g = mesh->elements[static_cast<std::size_t>(modelElementToMesh[static_cast<std::size_t>(e) - sceneElements])];
    s += " (Gmsh element " + std::to_string(g.tag) + ", " + mesh->file + ":" + std::to_string(g.line) + ")";
  }
  return s;
}

double elementLength(const Model& m, int e) {
  const auto& el = m.elements[static_cast<std::size_t>(e)];
  return norm(m.nodes[static_cast<std::size_t>(el[1])] - m.nodes[static_cast<std::size_t>(el[0])]);
}

int checkedIndex(const YAML::Node& n, const std::string& path, const std::string& what, std::size_t count) {
  const int v = getInt(n, path);
  if (v < 1 || static_cast<std::size_t>(v) > count)
    fail(path, what + " " + std::to_string(v) + " does not exist (the model has " + std::to_string(count) + " " + what +
                   "s, numbered from 1)");
  return v - 1;
}

int checkedKeyIndex(const YAML::Node& key, const std::string& path, const std::string& what, std::size_t count) {
  // JSON object keys are strings: {"1": {...}} is node 1 as much as YAML's {1: {...}}
  const std::string t = key.IsScalar() ? key.Scalar() : std::string();
  const bool digits = !t.empty() && t.size() < 10 && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (digits && key.Tag() == "!") return checkedIndex(YAML::Load(t), path, what, count);
  return checkedIndex(key, path, what, count);
}

namespace {

const std::vector<std::string> kTopKeys = {"title", "nodes", "elements", "mesh", "nprops",
                                           "eprops", "opt", "formfinding", "sensors"};

/// `nodes:` rows of 2 or 3 numbers, all of the same length. Returns the row length (0 if none).
int parseNodes(const YAML::Node& nodes, Model& m) {
  if (!nodes.IsDefined() || nodes.IsNull()) return 0;
  if (!nodes.IsSequence()) fail("nodes", "expected a list of [x, y, z] rows, got " + describe(nodes));
  int dim = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const std::string path = indexPath("nodes", i);
    const YAML::Node row = nodes[i];
    if (!row.IsSequence()) fail(path, "expected a row [x, y, z] or [x, y] for node " + std::to_string(i + 1) + ", got " + describe(row));
    const int n = static_cast<int>(row.size());
    if (n != 2 && n != 3) fail(path, "expected 2 or 3 numbers (x, y[, z]) for node " + std::to_string(i + 1) + ", got " + std::to_string(n));
    if (dim == 0) dim = n;
    if (n != dim)
      fail(path, "expected " + std::to_string(dim) + " numbers like nodes(1) (all nodes have the same dimension), got " + std::to_string(n));
    const auto x = getNumbers(row, path, kCoordinate);
    m.nodes.push_back({x[0], x[1], n == 3 ? x[2] : 0.0});
  }
  return dim;
}

/// `elements:` rows of 2 to 4 node numbers (ranges are checked once mesh nodes are known).
void parseElementRows(const YAML::Node& elements, std::vector<std::vector<YAML::Node>>& rows) {
  if (!elements.IsDefined() || elements.IsNull()) return;
  if (!elements.IsSequence()) fail("elements", "expected a list of rows of node numbers, got " + describe(elements));
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const std::string path = indexPath("elements", i);
    const YAML::Node row = elements[i];
    if (!row.IsSequence())
      fail(path, "expected a row of node numbers for element " + std::to_string(i + 1) + ", got " + describe(row));
    if (row.size() < 2 || row.size() > 4)
      fail(path, "expected 2 node numbers (beam, cable) or 3 to 4 (membrane) for element " + std::to_string(i + 1) +
                     ", got " + std::to_string(row.size()));
    std::vector<YAML::Node> r;
    for (std::size_t j = 0; j < row.size(); ++j) r.push_back(row[j]);
    rows.push_back(std::move(r));
  }
}

int elementDim(int gmshType) { return gmshType == 1 ? 1 : (gmshType == 2 || gmshType == 3) ? 2 : 0; }

/// Add the Gmsh nodes and the elements that are not mere node selectors: an element is added
/// unless every physical group it belongs to is used only as an nprops node group. Without any
/// physical group, only elements of the highest dimension are added (Gmsh saves the boundary too).
void mergeMesh(const YAML::Node& root, int sceneDim, SceneContext& ctx) {
  Model& m = ctx.model;
  const GmshMesh& mesh = *ctx.mesh;
  std::set<std::string> epNames, npNames;
  for (const auto& names : scanPhysicalNames(root["eprops"])) epNames.insert(names.begin(), names.end());
  for (const auto& k : scanNodeGroupKeys(root["nprops"])) npNames.insert(k);

  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const Vec3& x = mesh.nodes[i];
    const std::string where = mesh.file + ":" + std::to_string(mesh.nodeLines[i]) + ": node tag " + std::to_string(mesh.nodeTags[i]) + ": ";
    for (double c : x) checkMagnitude(c, "mesh", kCoordinate, where);
    if (sceneDim == 2 && x[2] != 0.0)
      fail("mesh", mesh.file + ":" + std::to_string(mesh.nodeLines[i]) + ": node tag " + std::to_string(mesh.nodeTags[i]) +
                       " has z = " + fmt(x[2]) + ", but the scene's nodes are 2D (x, y)");
    m.nodes.push_back(x);
  }

  int maxDim = 0;
  for (const auto& e : mesh.elements) maxDim = std::max(maxDim, elementDim(e.type));
  ctx.meshElementToModel.assign(mesh.elements.size(), -1);
  for (std::size_t i = 0; i < mesh.elements.size(); ++i) {
    const auto& e = mesh.elements[i];
    if (elementDim(e.type) == 0) continue;
    bool add = false;
    if (e.groups.empty()) {
      add = mesh.groups.empty() && elementDim(e.type) == maxDim;
    } else {
      bool inEprops = false, onlyNodeGroup = true;
      for (int g : e.groups) {
        const std::string& name = mesh.groups[static_cast<std::size_t>(g)].name;
        if (epNames.count(name)) inEprops = true;
        if (!npNames.count(name)) onlyNodeGroup = false;
      }
      add = inEprops || !onlyNodeGroup;
    }
    if (!add) continue;
    ctx.meshElementToModel[i] = static_cast<int>(m.elements.size());
    ctx.modelElementToMesh.push_back(static_cast<int>(i));
    std::vector<int> el;
    for (int n : e.nodes) el.push_back(static_cast<int>(ctx.sceneNodes) + n);
    m.elements.push_back(std::move(el));
  }
}

/// Makes the node order of the Gmsh surface elements (triangles, quads) consistent across each
/// connected surface (issue 10 item 15): two elements sharing an edge must run along it in
/// opposite directions. Elements are grouped into connected surfaces through their edges shared
/// by exactly two surface elements; in each surface the orientation of the majority is kept (a tie:
/// that of the lowest element) and the others are reversed. Returns how many were reversed.
long orientMeshSurfaces(Model& m, const std::vector<int>& surface) {
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edges;  // edge -> (surface index, +1/-1)
  for (std::size_t i = 0; i < surface.size(); ++i) {
    const auto& el = m.elements[static_cast<std::size_t>(surface[i])];
    for (std::size_t j = 0; j < el.size(); ++j) {
      const int a = el[j], b = el[(j + 1) % el.size()];
      edges[{std::min(a, b), std::max(a, b)}].push_back({static_cast<int>(i), a < b ? 1 : -1});
    }
  }
  std::vector<std::vector<std::pair<int, int>>> nb(surface.size());  // neighbour, 1 = must differ in flip
  for (const auto& [e, uses] : edges) {
    if (uses.size() != 2) continue;  // boundary or non-manifold edge
    const int same = uses[0].second == uses[1].second ? 1 : 0;
    nb[static_cast<std::size_t>(uses[0].first)].push_back({uses[1].first, same});
    nb[static_cast<std::size_t>(uses[1].first)].push_back({uses[0].first, same});
  }
  std::vector<int> flip(surface.size(), -1);
  long reversed = 0;
  for (std::size_t seed = 0; seed < surface.size(); ++seed) {
    if (flip[seed] >= 0) continue;
    std::vector<int> comp{static_cast<int>(seed)};
    flip[seed] = 0;
    for (std::size_t k = 0; k < comp.size(); ++k)
      for (const auto& [f, differ] : nb[static_cast<std::size_t>(comp[k])])
        if (flip[static_cast<std::size_t>(f)] < 0) {
          flip[static_cast<std::size_t>(f)] = flip[static_cast<std::size_t>(comp[k])] ^ differ;
          comp.push_back(f);
        }
    long ones = 0;
    for (int i : comp) ones += flip[static_cast<std::size_t>(i)];
    const int reverse = 2 * ones > static_cast<long>(comp.size()) ? 0 : 1;  // reverse the minority
    for (int i : comp) {
      if (flip[static_cast<std::size_t>(i)] != reverse) continue;
      auto& el = m.elements[static_cast<std::size_t>(surface[static_cast<std::size_t>(i)])];
      std::reverse(el.begin() + 1, el.end());  // [a, b, c] -> [a, c, b], [a, b, c, d] -> [a, d, c, b]
      ++reversed;
    }
  }
  return reversed;
}

/// Membrane sets with emod: 0 (issue 10 item 16): allowed for form-finding-only sets, i.e. sets that
/// are form-found and keep their prestress as their only stiffness afterwards (FORCE restart) in a
/// run whose load analysis carries no load (frequencies, buckling, compliance about the found shape
/// use the prestress stiffness). Refused where the membrane would have to carry load elastically.
void checkZeroModulusMembranes(const Model& m) {
  bool loaded = (m.opt.gravity && norm(*m.opt.gravity) > 0.0) || m.opt.dynamics.has_value();
  for (const auto& [node, np] : m.nprops) {
    loaded |= norm(np.force) > 0.0 || norm(np.moment) > 0.0 || np.rot.has_value();
    for (const auto& d : np.displ) loaded |= d.has_value() && *d != 0.0;
  }
  for (const ElementSet& s : m.eprops) {
    if (const auto* mp = s.as<MembraneProperties>()) loaded |= mp->pressure != 0.0;
    if (const auto* a = s.as<AncfCable2DProperties>()) loaded |= a->massProportionalLoad && norm(*a->massProportionalLoad) > 0.0;
  }
  for (std::size_t i = 0; i < m.eprops.size(); ++i) {
    const MembraneProperties* mp = m.eprops[i].as<MembraneProperties>();
    if (!mp || mp->emod != 0.0) continue;
    const std::string path = childPath(indexPath("eprops", i), "emod");
    if (!m.formfinding)
      fail(path, "emod: 0 is only for membranes that are form-found (a formfinding block); an elastic membrane needs emod > 0");
    const auto& ffe = m.formfinding->formfinding_elements;
    if (!ffe.empty() && std::find(ffe.begin(), ffe.end(), static_cast<int>(i)) == ffe.end())
      fail(path, "emod: 0 is only for form-found membranes; this set is not in formfinding.formfinding_elements");
    if (m.formfinding->elastic_restart_method != "FORCE")
      fail(path, "emod: 0 with elastic_restart_method " + m.formfinding->elastic_restart_method +
                     ": the membrane would have no stiffness at all after form finding (use FORCE, or emod > 0)");
    if (loaded)
      fail(path, "emod: 0 (a form-finding-only membrane) cannot carry the loads of the analysis after form finding "
                 "(nprops force/moment/displ/rot, gravity, pressure, massProportionalLoad or opt.dynamics): give emod > 0");
  }
}

void checkElementGeometry(SceneContext& ctx);

/// Element rows: node numbers in range, no node twice, no two nodes at the same place.
void checkElementNodes(const std::vector<std::vector<YAML::Node>>& rows, SceneContext& ctx) {
  Model& m = ctx.model;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::vector<int> el;
    for (std::size_t j = 0; j < rows[i].size(); ++j) {
      const std::string path = indexPath(indexPath("elements", i), j);
      const YAML::Node& n = rows[i][j];
      if (!isNumber(n)) fail(path, "expected a node number, got " + describe(n));
      el.push_back(checkedIndex(n, path, "node", m.nodes.size()));
    }
    m.elements[i] = std::move(el);
  }
  checkElementGeometry(ctx);
}

/// Element rows with node numbers in range: no node twice, no zero or tiny length.
void checkElementGeometry(SceneContext& ctx) {
  Model& m = ctx.model;
  Vec3 lo = m.nodes[0], hi = m.nodes[0];
  for (const auto& x : m.nodes)
    for (std::size_t k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], x[k]);
      hi[k] = std::max(hi[k], x[k]);
    }
  // Coordinates are bounded (kCoordinate), so the size and lengths below are finite.
  const double size = norm(hi - lo);
  const double minLength = std::max(kMinElementLength, kMinElementLengthRelative * size);
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const auto& el = m.elements[e];
    const int ei = static_cast<int>(e);
    for (std::size_t a = 0; a < el.size(); ++a)
      for (std::size_t b = a + 1; b < el.size(); ++b) {
        if (el[a] == el[b])
          fail(ctx.elementPath(ei), ctx.elementLabel(ei) + " lists node " + std::to_string(el[a] + 1) + " twice");
        const double d = norm(m.nodes[static_cast<std::size_t>(el[a])] - m.nodes[static_cast<std::size_t>(el[b])]);
        if (d == 0)
          fail(ctx.elementPath(ei), ctx.elementLabel(ei) + " has zero length: nodes " + std::to_string(el[a] + 1) + " and " +
                                        std::to_string(el[b] + 1) + " coincide");
        if (d < minLength)
          fail(ctx.elementPath(ei), ctx.elementLabel(ei) + " is too short: nodes " + std::to_string(el[a] + 1) + " and " +
                                        std::to_string(el[b] + 1) + " are " + fmt(d) + " apart, below " + fmt(minLength) +
                                        " (the larger of " + fmt(kMinElementLength) + " and " + fmt(kMinElementLengthRelative) +
                                        " times the model size " + fmt(size) + ")");
      }
  }
}

/// SPACAR Light allows unconnected nodes after the last node an element connects (trailing nodes):
/// they are held fixed (no unknowns; the run warns). An unconnected node before it is an error, so is
/// anything but a support given to a trailing node, or a trailing node chosen for path following.
void checkConnectivity(SceneContext& ctx) {
  Model& m = ctx.model;
  std::vector<char> connected(m.nodes.size(), 0);
  for (const auto& el : m.elements)
    for (int n : el) connected[static_cast<std::size_t>(n)] = 1;
  std::size_t last = 0;
  for (std::size_t n = 0; n < connected.size(); ++n)
    if (connected[n]) last = n;
  m.connectedNodes = last + 1;
  for (std::size_t n = 0; n < last; ++n)
    if (!connected[n])
      fail(indexPath("nodes", n), "node " + std::to_string(n + 1) + " is not connected to any element (only nodes after " +
                                      "the last connected node " + std::to_string(last + 1) +
                                      ", trailing nodes, may be unconnected, as in SPACAR Light)");
  for (const auto& [node, np] : m.nprops) {
    if (static_cast<std::size_t>(node) <= last) continue;
    std::string field;
    if (np.mass != 0.0 || np.mominertia != std::array<double, 6>{}) field = np.mass != 0.0 ? "mass" : "mominertia";
    else if (norm(np.force) != 0.0 || norm(np.force_initial) != 0.0) field = norm(np.force) != 0.0 ? "force" : "force_initial";
    else if (norm(np.moment) != 0.0 || norm(np.moment_initial) != 0.0) field = norm(np.moment) != 0.0 ? "moment" : "moment_initial";
    else if (np.rot || np.rot_initial) field = np.rot ? "rot" : "rot_initial";
    else if (!np.transfer_in.empty() || !np.transfer_out.empty()) field = np.transfer_in.empty() ? "transfer_out" : "transfer_in";
    else if (np.slope) field = "slope";
    for (int k = 2; k >= 0; --k)
      if (np.displ[k] || np.displ_initial[k]) field = std::string(np.displ[k] ? "displ_" : "displ_initial_") + "xyz"[k];
    if (!field.empty())
      fail(npropsPath(node, field),
           "node " + std::to_string(node + 1) + " is not connected to any element (a trailing node, held fixed): " + field +
               " has nothing to act on");
  }
  if (m.opt.continuation && m.opt.continuation->node >= 0 && static_cast<std::size_t>(m.opt.continuation->node) > last)
    fail("opt.continuation.node", "node " + std::to_string(m.opt.continuation->node + 1) +
                                      " is not connected to any element (a trailing node, held fixed)");
}

/// opt.dynamics solves M qdd = f: a model without any mass (no eprops dens or physicsMassPerLength,
/// no nprops mass or mominertia) cannot start its time loop. Found here, before form finding or any
/// other analysis runs (it used to fail only after them, issue 24).
void checkDynamicsMass(const Model& m) {
  if (!m.opt.dynamics) return;
  for (const ElementSet& s : m.eprops)
    if (elementKind(s.type()).hasInertia(s)) return;
  for (const auto& [node, np] : m.nprops) {
    if (np.mass > 0.0) return;
    for (double i : np.mominertia)
      if (i != 0.0) return;
  }
  fail("opt.dynamics", "the model has no mass: time integration needs mass at every free coordinate (eprops dens, "
                       "physicsMassPerLength for ancf_cable2d, or nprops mass)");
}

void parseRoot(const YAML::Node& root, const std::string& baseDir, Model& m, bool restart) {
  if (!root.IsDefined() || root.IsNull()) fail("", "the scene is empty: expected a map with at least nodes and elements");
  if (!root.IsMap()) fail("", "expected a map of top-level keys (title, nodes, elements, ...), got " + describe(root));
  checkKeys(root, "", kTopKeys);
  SceneContext ctx{m};
  ctx.restart = restart;

  const YAML::Node title = root["title"];
  if (title.IsDefined() && !title.IsNull()) m.title = getString(title, "title");

  const bool hasMesh = root["mesh"].IsDefined();
  if (!root["nodes"].IsDefined() && !hasMesh) fail("nodes", "missing: the scene needs a list of node coordinates");
  if (!root["elements"].IsDefined() && !hasMesh) fail("elements", "missing: the scene needs a list of elements (rows of node numbers)");
  const int sceneDim = parseNodes(root["nodes"], m);
  std::vector<std::vector<YAML::Node>> rows;
  parseElementRows(root["elements"], rows);
  ctx.sceneNodes = m.nodes.size();
  ctx.sceneElements = rows.size();
  m.elements.resize(rows.size());

  if (hasMesh) {
    const std::string rel = getString(root["mesh"], "mesh");
    if (rel.empty()) fail("mesh", "expected the path of a Gmsh 4 .msh file, got an empty string");
    std::filesystem::path p(rel);
    if (p.is_relative() && !baseDir.empty()) p = std::filesystem::path(baseDir) / p;
    ctx.mesh = readGmsh(p.lexically_normal().string());
    mergeMesh(root, sceneDim, ctx);
    std::vector<int> surface;
    for (int e : ctx.meshElementToModel)
      if (e >= 0 && m.elements[static_cast<std::size_t>(e)].size() >= 3) surface.push_back(e);
    if (const long n = orientMeshSurfaces(m, surface); n > 0)
      m.warnings.push_back("mesh " + ctx.mesh->file + ": " + std::to_string(n) + " of " + std::to_string(surface.size()) +
                           " triangles/quadrangles were inverted against their neighbours (inconsistent node order); "
                           "reversed them so that each connected surface has one orientation (that of the majority), "
                           "which pressure loads follow (right-hand rule)");
  }
  m.dimension = (ctx.sceneNodes > 0 && sceneDim == 2) ? 2 : 3;
  if (m.nodes.empty()) fail("nodes", "the model has no nodes");
  if (m.elements.empty()) fail("elements", "the model has no elements");
  checkElementNodes(rows, ctx);

  parseEprops(root["eprops"], ctx);
  checkElementTypes(ctx);
  parseNprops(root["nprops"], ctx);
  parseOptions(root["opt"], ctx);
  if (!m.opt.dynamics)
    for (const auto& [node, np] : m.nprops)
      if (np.hasTimeFunctions()) {
        m.warnings.push_back(indexedPath("nprops", static_cast<std::size_t>(node)) +
                             ": loads or prescribed motions given as functions of time act in statics with their value "
                             "at t = 0 (ramped by the load factor); they follow t only in a time integration (opt.dynamics)");
        break;
      }
  if (!m.opt.dynamics)
    for (std::size_t set = 0; set < m.eprops.size(); ++set)
      if (const auto* mp = m.eprops[set].as<MembraneProperties>(); mp && !mp->pressure_t.empty()) {
        m.warnings.push_back(indexedPath("eprops", set) +
                             ".pressure: a pressure given as a function of time acts in statics with its value at t = 0 "
                             "(ramped by the load factor); it follows t only in a time integration (opt.dynamics)");
        break;
      }
  const YAML::Node ff = root["formfinding"];
  if (ff.IsDefined()) parseFormfinding(ff, ctx);
  parseSensors(root["sensors"], ctx);
  checkZeroModulusMembranes(m);
  checkDynamicsMass(m);
  checkConnectivity(ctx);
}

/// A command-line value as a YAML node: "0,0,-9.81" -> [0, 0, -9.81]; "" -> true.
YAML::Node overrideNode(const std::string& name, const std::string& value) {
  std::string text = value;
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return YAML::Node(true);
  const char c = text[first];
  if (text.find(',') != std::string::npos && c != '[' && c != '{' && c != '"' && c != '\'') text = "[" + text + "]";
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    fail(childPath("opt", name), "cannot read the command-line value '" + value + "' of -" + name + ": " + e.msg);
  }
}

/// The command-line values of opt fields (name, value), in the order of optionNames().
std::vector<std::pair<std::string, std::string>> givenOverrides(const OptionOverride& overrides) {
  std::vector<std::pair<std::string, std::string>> given;
  if (!overrides) return given;
  for (const auto& name : optionNames())
    if (const std::optional<std::string> v = overrides(name)) given.emplace_back(name, *v);
  return given;
}

void applyOverrides(YAML::Node& root, const std::vector<std::pair<std::string, std::string>>& given,
                    std::vector<std::pair<std::string, std::string>>& applied) {
  if (given.empty()) return;
  if (!root.IsDefined() || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  if (!root.IsMap()) return;
  for (const auto& [name, v] : given) {
    const YAML::Node value = overrideNode(name, v);
    if (!root["opt"].IsDefined() || root["opt"].IsNull()) root["opt"] = YAML::Node(YAML::NodeType::Map);
    if (!root["opt"].IsMap()) return;  // reported by the opt reader
    root["opt"][name] = value;
    applied.emplace_back(name, v);
  }
}

/// Scene line of the deepest node along `path` (1-based), 0 when unknown.
int lineOf(const YAML::Node& root, const std::string& path) {
  YAML::Node cur;
  cur.reset(root);
  int line = 0;
  // one step down: the map entry `key`, or list entry `key` (1-based) of a sequence
  const auto step = [&](const std::string& key, bool numbered) {
    if (numbered && cur.IsSequence()) {
      const std::size_t k = std::stoul(key);
      if (k < 1 || k > cur.size()) return false;
      const YAML::Node& seq = cur;
      YAML::Node next = seq[k - 1];
      cur.reset(next);
      if (cur.Mark().line >= 0) line = cur.Mark().line + 1;
      return true;
    }
    if (!cur.IsMap()) return false;
    for (auto it = cur.begin(); it != cur.end(); ++it) {
      if (it->first.IsScalar() && it->first.Scalar() == key) {
        if (it->first.Mark().line >= 0) line = it->first.Mark().line + 1;
        YAML::Node next = it->second;
        cur.reset(next);
        return true;
      }
    }
    return false;
  };
  std::size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '.') ++i;
    if (i < path.size() && path[i] == '(') {  // (k) or (k,l): 1-based list entries or numbered map keys
      const std::size_t close = path.find(')', i);
      if (close == std::string::npos) break;
      std::istringstream parts(path.substr(i + 1, close - i - 1));
      i = close + 1;
      bool ok = true;
      for (std::string part; ok && std::getline(parts, part, ',');)
        ok = !part.empty() && part.find_first_not_of("0123456789") == std::string::npos && step(part, true);
      if (!ok) break;
      continue;
    }
    std::size_t end = path.find_first_of(".(", i);
    if (end == std::string::npos) end = path.size();
    const std::string key = path.substr(i, end - i);
    i = end;
    if (!step(key, false)) break;
  }
  return line;
}

/// The error with its origin: a command-line value, else the scene line (when the tree was read
/// from text: `lines`; a tree built in code, or its copy, has no lines).
SceneError locate(const SceneError& e, const YAML::Node& root, const std::vector<std::pair<std::string, std::string>>& overridden,
                  const std::string& fileLabel, bool lines) {
  const std::string& path = e.path();
  std::string message = e.what();
  if (!path.empty() && message.rfind(path + ": ", 0) == 0) message = message.substr(path.size() + 2);
  if (path == "mesh" && message.find(".msh") != std::string::npos) return SceneError(path, message);
  for (const auto& [name, value] : overridden) {
    const std::string p = "opt." + name;
    if (path == p || path.rfind(p + ".", 0) == 0 || path.rfind(p + "(", 0) == 0)
      return SceneError(path, message + " (from the command line: -" + name + " " + value + ")");
  }
  const int line = lines ? lineOf(root, path) : 0;
  if (line > 0) message += " (" + (fileLabel.empty() ? std::string() : fileLabel + " ") + "line " + std::to_string(line) + ")";
  else if (!fileLabel.empty()) message += " (" + fileLabel + ")";
  return SceneError(path, message);
}

/// "line L, column C" of a byte offset (1-based).
std::string positionOf(const std::string& text, std::size_t offset) {
  const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
  const std::size_t lineStart = text.rfind('\n', offset == 0 ? 0 : offset - 1);
  const std::size_t column = offset - (lineStart == std::string::npos || offset == 0 ? 0 : lineStart + 1) + 1;
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

/// A scene is UTF-8 text: no NUL or other control bytes (tab, newline and carriage return aside).
void checkText(const std::string& text, const std::string& prefix) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 || c == '\t' || c == '\n' || c == '\r') continue;
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02x", static_cast<unsigned>(c));
    throw SceneError("", prefix + "not a text file: control byte " + hex + " at " + positionOf(text, i) +
                             " (a scene is a YAML text file in UTF-8)");
  }
}

/// Records where a YAML document starts (Parser events; the content is not kept).
class DocumentStart : public YAML::EventHandler {
 public:
  YAML::Mark mark;
  void OnDocumentStart(const YAML::Mark& m) override { mark = m; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

std::string at(const YAML::Mark& m) {
  return "line " + std::to_string(m.line + 1) + ", column " + std::to_string(m.column + 1);
}

/// Runs a yaml-cpp call; its exceptions become SceneErrors with the position.
template <class F>
auto yamlCall(const std::string& prefix, F&& f) {
  try {
    return f();
  } catch (const YAML::DeepRecursion& e) {
    throw SceneError("", prefix + "the nesting is too deep: more than " + std::to_string(e.depth()) +
                             " levels of lists or maps at " + at(e.mark) + " (a scene nests a few levels)");
  } catch (const YAML::Exception& e) {
    throw SceneError("", prefix + "YAML syntax error at " + at(e.mark) + ": " + e.msg);
  }
}

/// Counts the documents of the text with the event parser (yaml-cpp's LoadAll loops forever on
/// some malformed input: a document that does not advance the parser is reported as an error).
void checkOneDocument(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  int count = 0, previous = -1;
  YAML::Mark second;
  for (;;) {
    DocumentStart doc;
    if (!yamlCall(prefix, [&] { return parser.HandleNextDocument(doc); })) break;
    if (doc.mark.pos <= previous)
      throw SceneError("", prefix + "YAML syntax error at " + at(doc.mark) +
                               ": unexpected text after the end of a complete value (a stray ']', '}' or ',')");
    previous = doc.mark.pos;
    if (++count == 2) second = doc.mark;
  }
  if (count > 1)
    throw SceneError("", prefix + "the file holds " + std::to_string(count) + " YAML documents (the second starts at line " +
                             std::to_string(second.line + 1) + "); Sinew reads one");
}

/// The one YAML document of the scene (null when the text holds none).
YAML::Node loadOneDocument(const std::string& text, const std::string& prefix) {
  checkOneDocument(text, prefix);
  return yamlCall(prefix, [&] { return YAML::Load(text); });
}

/// The scene's tree (a map) -> Model, errors located in it. fromText: the tree was loaded here from
/// the text (errors name its lines); else it is the caller's (errors name the field alone; it is not
/// changed: command-line values go into a copy).
Model parseTree(const YAML::Node& tree, bool fromText, const std::string& baseDir, const OptionOverride& overrides,
                const std::string& fileLabel, bool restart) {
  const std::string prefix = fileLabel.empty() ? std::string() : fileLabel + ": ";
  if (!tree.IsDefined() || tree.IsNull())
    throw SceneError("", prefix + "the scene is empty: expected a map with at least nodes and elements");
  Model m;
  std::vector<std::pair<std::string, std::string>> overridden;
  const std::vector<std::pair<std::string, std::string>> given = givenOverrides(overrides);
  YAML::Node root = given.empty() || fromText ? tree : YAML::Clone(tree);
  try {
    applyOverrides(root, given, overridden);
    parseRoot(root, baseDir, m, restart);
  } catch (const SceneError& e) {
    throw locate(e, root, overridden, fileLabel, fromText);
  } catch (const YAML::Exception& e) {
    throw SceneError("", prefix + "cannot read the scene: " + e.what());
  }
  return m;
}

Model parseSceneImpl(const std::string& text, const std::string& baseDir, const OptionOverride& overrides,
                     const std::string& fileLabel, bool restart) {
  const std::string prefix = fileLabel.empty() ? std::string() : fileLabel + ": ";
  checkText(text, prefix);
  Model m = parseTree(loadOneDocument(text, prefix), true, baseDir, overrides, fileLabel, restart);
  m.sceneText = text;
  return m;
}

/// 0-based index `i` of a model built in code in 0..count-1, else a SceneError at `path` naming the
/// 1-based number and the range.
void checkIndex(long i, std::size_t count, const std::string& path, const std::string& what) {
  if (i < 0 || static_cast<std::size_t>(i) >= count)
    fail(path, "expected a " + what + " number 1.." + std::to_string(count) + " (0-based " + std::to_string(i) +
                   " in the Model built in code), got " + std::to_string(i + 1));
}

void checkBuiltModelImpl(Model& m) {
  if (m.nodes.empty()) fail("nodes", "the model has no nodes");
  if (m.elements.empty()) fail("elements", "the model has no elements");
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    for (double c : m.nodes[i]) checkMagnitude(c, indexPath("nodes", i), kCoordinate);
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const auto& el = m.elements[e];
    if (el.size() < 2 || el.size() > 4)
      fail(indexPath("elements", e), "expected 2 node numbers (beam, cable) or 3 to 4 (membrane) for element " +
                                         std::to_string(e + 1) + ", got " + std::to_string(el.size()));
    for (std::size_t j = 0; j < el.size(); ++j) checkIndex(el[j], m.nodes.size(), indexPath(indexPath("elements", e), j), "node");
  }
  // each element's set (derived from the sets' elems when not given; -1: a rigid element)
  std::vector<int> sets(m.elements.size(), -1);
  for (std::size_t i = 0; i < m.eprops.size(); ++i)
    for (std::size_t j = 0; j < m.eprops[i].elems.size(); ++j) {
      const int e = m.eprops[i].elems[j];
      const std::string path = indexPath(childPath(indexPath("eprops", i), "elems"), j);
      checkIndex(e, m.elements.size(), path, "element");
      if (sets[static_cast<std::size_t>(e)] >= 0)
        fail(path, "element " + std::to_string(e + 1) + " is already in eprops(" + std::to_string(sets[static_cast<std::size_t>(e)] + 1) + ")");
      sets[static_cast<std::size_t>(e)] = static_cast<int>(i);
    }
  if (m.elementSet.empty()) m.elementSet = sets;
  if (m.elementSet != sets)
    fail("elementSet", "the Model's elementSet does not match the eprops sets' elems (leave it empty to derive it)");
  for (const auto& [node, np] : m.nprops) checkIndex(node, m.nodes.size(), indexPath("nprops", static_cast<std::size_t>(std::max(node, 0))), "node");
  for (const auto& [e, modes] : m.opt.rls) checkIndex(e, m.elements.size(), "opt.rls", "element");
  for (std::size_t i = 0; i < m.opt.compliance_nodes.size(); ++i)
    checkIndex(m.opt.compliance_nodes[i], m.nodes.size(), indexPath("opt.compliance_nodes", i), "node");
  if (m.opt.continuation && m.opt.continuation->node >= 0)
    checkIndex(m.opt.continuation->node, m.nodes.size(), "opt.continuation.node", "node");
  for (std::size_t i = 0; i < m.sensors.size(); ++i) {
    const Sensor& s = m.sensors[i];
    if (s.node >= 0) checkIndex(s.node, m.nodes.size(), childPath(indexPath("sensors", i), "node"), "node");
    else checkIndex(s.element, m.elements.size(), childPath(indexPath("sensors", i), "element"), "element");
  }
  if (m.formfinding) {
    for (std::size_t i = 0; i < m.formfinding->formfinding_elements.size(); ++i)
      checkIndex(m.formfinding->formfinding_elements[i], m.eprops.size(), indexPath("formfinding.formfinding_elements", i), "eprops set");
    for (std::size_t i = 0; i < m.formfinding->stress_adaption.size(); ++i)
      checkIndex(m.formfinding->stress_adaption[i], m.eprops.size(), indexPath("formfinding.stress_adaption", i), "eprops set");
  }
  SceneContext ctx{m};
  ctx.sceneNodes = m.nodes.size();
  ctx.sceneElements = m.elements.size();
  checkElementGeometry(ctx);
  checkElementTypes(ctx);
  checkZeroModulusMembranes(m);
  checkDynamicsMass(m);
  checkConnectivity(ctx);  // also the trailing unconnected nodes (m.connectedNodes)
}

}  // namespace
}  // namespace scene

void checkBuiltModel(Model& m) { scene::checkBuiltModelImpl(m); }

Model parseScene(const std::string& text, const std::string& baseDir, const OptionOverride& overrides, bool restart) {
  return scene::parseSceneImpl(text, baseDir, overrides, "", restart);
}

Model parseSceneTree(const YAML::Node& root, const std::string& baseDir, const OptionOverride& overrides, bool restart) {
  return scene::parseTree(root, false, baseDir, overrides, "", restart);
}

Model readScene(const std::string& path, const OptionOverride& overrides, bool restart) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw SceneError("", "'" + path + "' is a directory, not a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError("", "cannot open scene file '" + path + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw SceneError("", "cannot read scene file '" + path + "'");
  if (ss.str().empty()) throw SceneError("", "scene file '" + path + "' is empty: expected a map with at least nodes and elements");
  const std::filesystem::path p(path);
  Model m = scene::parseSceneImpl(ss.str(), p.parent_path().string(), overrides, p.filename().string(), restart);
  if (m.opt.filename.empty()) m.opt.filename = p.stem().string();
  return m;
}

}  // namespace sinew
