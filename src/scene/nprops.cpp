// nprops: node properties keyed by node number, or by the name of a Gmsh physical group
// (applied to every node of the group; node-number entries are applied after groups).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>

#include "scene/nearest_name.hpp"
#include "scene/scene_detail.hpp"
#include "scene/time_fields.hpp"

namespace sinew::scene {
namespace {

const std::vector<std::string> kNpropsKeys = {
    "fix",         "fix_pos",       "fix_orien",   "fix_x",          "fix_y",          "fix_z",
    "fix_coords",  "mass",          "mominertia",  "displ_x",        "displ_y",        "displ_z",
    "displ_initial_x", "displ_initial_y", "displ_initial_z", "rot", "rot_initial", "force",
    "force_initial", "moment",      "moment_initial", "transfer_in", "transfer_out", "slope"};
const std::vector<std::string> kTransferIn = {"force_x", "force_y", "force_z", "moment_x", "moment_y", "moment_z"};
const std::vector<std::string> kTransferOut = {"displ_x", "displ_y", "displ_z", "veloc_x", "veloc_y", "veloc_z"};
const char* kAxis[3] = {"x", "y", "z"};

bool isNodeNumber(const std::string& key) {
  long long v = 0;
  auto res = std::from_chars(key.data(), key.data() + key.size(), v);
  return !key.empty() && res.ec == std::errc() && res.ptr == key.data() + key.size();
}

/// Paths of the entries that gave loads, per node (for conflict messages).
struct LoadSources {
  std::string force, force_initial, moment, moment_initial, transfer_in, transfer_out;
};

std::array<double, 6> getMominertia(const YAML::Node& v, const std::string& p) {
  const std::string what = "expected 6 numbers [Ixx, Ixy, Ixz, Iyy, Iyz, Izz] or a symmetric 3x3 matrix";
  if (!v.IsSequence()) fail(p, what + ", got " + describe(v));
  std::array<double, 6> I{};
  if (v.size() == 6) {
    const auto x = getNumbers(v, p, 6, kInertia);
    std::copy(x.begin(), x.end(), I.begin());
  } else if (v.size() == 3) {
    double a[3][3];
    double scale = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      if (!v[i].IsSequence()) fail(indexPath(p, i), what + ": expected a row of 3 numbers, got " + describe(v[i]));
      const auto row = getNumbers(v[i], indexPath(p, i), 3, kInertia);
      for (std::size_t j = 0; j < 3; ++j) {
        a[i][j] = row[j];
        scale = std::max(scale, std::abs(row[j]));
      }
    }
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = i + 1; j < 3; ++j)
        if (std::abs(a[i][j] - a[j][i]) > 1e-12 * scale)
          fail(p, "expected a symmetric matrix, but (" + std::to_string(i + 1) + "," + std::to_string(j + 1) + ") = " + fmt(a[i][j]) +
                      " and (" + std::to_string(j + 1) + "," + std::to_string(i + 1) + ") = " + fmt(a[j][i]));
    I = {a[0][0], a[0][1], a[0][2], a[1][1], a[1][2], a[2][2]};
  } else {
    fail(p, what + ", got a list of " + std::to_string(v.size()));
  }
  for (std::size_t k : {0u, 3u, 5u})
    if (I[k] < 0) fail(p, "expected nonnegative moments of inertia on the diagonal, got " + fmt(I[k]));
  return I;
}

/// Prescribed rotation: SPACAR Light's 1x4 [angle, axis_x, axis_y, axis_z] (axis normalized, a zero
/// axis is an error), or a rotation vector [rx, ry, rz] = angle * unit axis. Returns the rotation vector.
/// With `text` (rot only): the angle may be a function of time, [angle(t), axis_x, axis_y, axis_z]
/// (its text goes to *text, the unit axis to *axis; the rotation vector returned is its value at t = 0).
Vec3 getRotation(const YAML::Node& v, const std::string& p, std::string* text = nullptr, Vec3* unitAxis = nullptr) {
  const std::string what = "expected [angle, axis_x, axis_y, axis_z] (SPACAR Light) or a rotation vector [rx, ry, rz]";
  if (!v.IsSequence() || (v.size() != 3 && v.size() != 4))
    fail(p, what + ", got " + (v.IsSequence() ? "a list of " + std::to_string(v.size()) : describe(v)));
  if (v.size() == 3) {
    for (std::size_t k = 0; k < 3; ++k)
      if (double x = 0; text && v[k].IsScalar() && !YAML::convert<double>::decode(v[k], x))
        fail(indexPath(p, k), "a rotation as a function of time is [angle(t), axis_x, axis_y, axis_z] (a fixed axis), got '" +
                                  v[k].Scalar() + "' in a rotation vector");
    return getVec3(v, p, false, kRotation);
  }
  std::string fn;
  const double angle = text ? getNumberOrTimeFunction(v[0], indexPath(p, 0), kRotation, &fn) : getNumber(v[0], indexPath(p, 0), kRotation);
  Vec3 axis{};
  for (std::size_t k = 0; k < 3; ++k) axis[k] = getNumber(v[k + 1], indexPath(p, k + 1), kLoad);
  const double a = norm(axis);
  if (a == 0.0) fail(p, "the rotation axis [" + fmt(axis[0]) + ", " + fmt(axis[1]) + ", " + fmt(axis[2]) + "] is zero; " + what);
  if (text) {
    *text = fn;
    *unitAxis = {axis[0] / a, axis[1] / a, axis[2] / a};
  }
  return {angle * axis[0] / a, angle * axis[1] / a, angle * axis[2] / a};
}

/// Moment: 3 numbers; a 2D model also takes one number (about z).
/// With `texts` (moment only), entries may be functions of time.
Vec3 getMoment(const YAML::Node& v, const std::string& p, bool twoD, std::array<std::string, 3>* texts = nullptr) {
  if (twoD && (v.IsScalar() || (v.IsSequence() && v.size() == 1))) {
    const YAML::Node m = v.IsSequence() ? v[0] : v;
    const std::string mp = v.IsSequence() ? indexPath(p, 0) : p;
    return {0, 0, texts ? getNumberOrTimeFunction(m, mp, kLoad, &(*texts)[2]) : getNumber(m, mp, kLoad)};
  }
  if (twoD && (!v.IsSequence() || v.size() != 3))
    fail(p, "expected 3 numbers (or 1, about z, in a 2D model), got " + (v.IsSequence() ? std::to_string(v.size()) : describe(v)));
  return texts ? getVec3OrTimeFunctions(v, p, false, kLoad, *texts) : getVec3(v, p, false, kLoad);
}

std::vector<std::string> getTransfer(const YAML::Node& v, const std::string& p, const std::vector<std::string>& valid) {
  const auto names = getStrings(v, p);
  std::set<std::string> seen;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string pi = v.IsSequence() ? indexPath(p, i) : p;
    if (std::find(valid.begin(), valid.end(), names[i]) == valid.end()) {
      std::string list;
      for (const auto& s : valid) list += (list.empty() ? "" : ", ") + s;
      const std::string near = nearestName(names[i], valid);
      fail(pi, "expected one of " + list + ", got '" + names[i] + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)"));
    }
    if (!seen.insert(names[i]).second) fail(pi, "'" + names[i] + "' is listed twice");
  }
  return names;
}

void applyProps(NodeProps& np, LoadSources& src, const YAML::Node& n, const std::string& path, const SceneContext& ctx) {
  const bool twoD = ctx.model.dimension == 2;
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string k = it->first.Scalar();
    const YAML::Node v = it->second;
    const std::string p = childPath(path, k);
    if (k == "fix") np.fix = getBool(v, p);
    else if (k == "fix_pos") np.fix_pos = getBool(v, p);
    else if (k == "fix_orien") np.fix_orien = getBool(v, p);
    else if (k == "fix_x") np.fix_x = getBool(v, p);
    else if (k == "fix_y") np.fix_y = getBool(v, p);
    else if (k == "fix_z") np.fix_z = getBool(v, p);
    else if (k == "fix_coords") {
      const std::string what = "expected 4 entries of 0 or 1 (x, y, slope_x, slope_y)";
      if (!v.IsSequence()) fail(p, what + ", got " + describe(v));
      if (v.size() != 4) fail(p, what + ", got " + std::to_string(v.size()));
      std::array<int, 4> fc{};
      for (std::size_t i = 0; i < 4; ++i) {
        const YAML::Node c = v[i];
        if (!c.IsScalar() || (c.Scalar() != "0" && c.Scalar() != "1" && c.Scalar() != "true" && c.Scalar() != "false"))
          fail(indexPath(p, i), "expected 0 or 1, got " + describe(c));
        fc[i] = (c.Scalar() == "1" || c.Scalar() == "true") ? 1 : 0;
      }
      np.fix_coords = fc;
    } else if (k == "slope") {
      const auto sv = getNumbers(v, p, 2, kLoad);
      if (!std::isfinite(sv[0]) || !std::isfinite(sv[1]) || std::hypot(sv[0], sv[1]) == 0.0)
        fail(p, "expected a nonzero reference slope [slope_x, slope_y], got [" + fmt(sv[0]) + ", " + fmt(sv[1]) + "]");
      np.slope = std::array<double, 2>{sv[0], sv[1]};
    } else if (k == "mass") np.mass = getNonNegative(v, p, kMaterial);
    else if (k == "mominertia") np.mominertia = getMominertia(v, p);
    else if (k.rfind("displ_initial_", 0) == 0) np.displ_initial[static_cast<std::size_t>(k.back() - 'x')] = getNumber(v, p, kCoordinate);
    else if (k.rfind("displ_", 0) == 0) {
      const auto a = static_cast<std::size_t>(k.back() - 'x');
      np.displ[a] = getNumberOrTimeFunction(v, p, kCoordinate, &np.displ_t[a]);
    } else if (k == "rot") np.rot = getRotation(v, p, &np.rot_t, &np.rot_axis);
    else if (k == "rot_initial") np.rot_initial = getRotation(v, p);
    else if (k == "force") { np.force = getVec3OrTimeFunctions(v, p, twoD, kLoad, np.force_t); src.force = p; }
    else if (k == "force_initial") { np.force_initial = getVec3(v, p, twoD, kLoad); src.force_initial = p; }
    else if (k == "moment") { np.moment = getMoment(v, p, twoD, &np.moment_t); src.moment = p; }
    else if (k == "moment_initial") { np.moment_initial = getMoment(v, p, twoD); src.moment_initial = p; }
    else if (k == "transfer_in") { np.transfer_in = getTransfer(v, p, kTransferIn); src.transfer_in = p; }
    else if (k == "transfer_out") { np.transfer_out = getTransfer(v, p, kTransferOut); src.transfer_out = p; }
  }
}

/// Why direction k (0..2) of node np is held, or "" when it is free.
std::string heldBy(const NodeProps& np, std::size_t k) {
  if (np.fix) return "fix";
  if (np.fix_pos) return "fix_pos";
  if ((k == 0 && np.fix_x) || (k == 1 && np.fix_y) || (k == 2 && np.fix_z)) return std::string("fix_") + kAxis[k];
  if (np.displ[k]) return std::string("displ_") + kAxis[k];
  if (np.displ_initial[k]) return std::string("displ_initial_") + kAxis[k];
  if (np.fix_coords && k < 2 && (*np.fix_coords)[k]) return "fix_coords";
  return "";
}

std::string rotationHeldBy(const NodeProps& np) {
  if (np.fix) return "fix";
  if (np.fix_orien) return "fix_orien";
  if (np.rot) return "rot";
  if (np.rot_initial) return "rot_initial";
  return "";
}

void checkConflicts(int node, const NodeProps& np, const LoadSources& src) {
  const std::string label = "node " + std::to_string(node + 1);
  for (std::size_t k = 0; k < 3; ++k) {
    const std::string held = heldBy(np, k);
    if (held.empty()) continue;
    const std::string msg = " in " + std::string(kAxis[k]) + ", but " + label + " is held in " + kAxis[k] + " by " + held +
                            " (a load on a held direction only changes the reaction; remove it or free the direction)";
    if (np.force[k] != 0 || !np.force_t[k].empty()) fail(src.force, "force" + msg);
    if (np.force_initial[k] != 0) fail(src.force_initial, "force_initial" + msg);
    for (const char* kind : {"displ_", "veloc_"}) {
      const std::string out = kind + std::string(kAxis[k]);
      if (std::find(np.transfer_out.begin(), np.transfer_out.end(), out) != np.transfer_out.end())
        fail(src.transfer_out, "transfer output " + out + ", but " + label + " is held in " + kAxis[k] + " by " + held +
                                   " (a held direction does not move: the output would be zero; remove it or free the direction)");
    }
    const std::string in = std::string("force_") + kAxis[k];
    if (std::find(np.transfer_in.begin(), np.transfer_in.end(), in) != np.transfer_in.end())
      fail(src.transfer_in, "transfer input " + in + ", but " + label + " is held in " + kAxis[k] + " by " + held);
  }
  const std::string held = rotationHeldBy(np);
  if (!held.empty()) {
    const std::string msg = " on " + label + ", whose rotation is held by " + held +
                            " (a moment on a held rotation only changes the reaction; remove it or free the rotation)";
    if (norm(np.moment) != 0 || !np.moment_t[0].empty() || !np.moment_t[1].empty() || !np.moment_t[2].empty())
      fail(src.moment, "moment" + msg);
    if (norm(np.moment_initial) != 0) fail(src.moment_initial, "moment_initial" + msg);
    for (const auto& in : np.transfer_in)
      if (in.rfind("moment_", 0) == 0) fail(src.transfer_in, "transfer input " + in + msg);
  }
}

}  // namespace

std::vector<std::string> scanNodeGroupKeys(const YAML::Node& nprops) {
  std::vector<std::string> keys;
  if (!nprops.IsDefined() || !nprops.IsMap()) return keys;
  for (auto it = nprops.begin(); it != nprops.end(); ++it)
    if (it->first.IsScalar() && !isNodeNumber(it->first.Scalar())) keys.push_back(it->first.Scalar());
  return keys;
}

void parseNprops(const YAML::Node& nprops, SceneContext& ctx) {
  Model& m = ctx.model;
  if (!nprops.IsDefined() || nprops.IsNull()) return;
  if (!nprops.IsMap()) fail("nprops", "expected a map from node numbers to properties ({1: {fix: true}}), got " + describe(nprops));

  struct Entry {
    std::string path;
    YAML::Node props;
    std::vector<int> nodes;
  };
  std::vector<Entry> groups, numbered;
  std::map<int, std::string> seen;
  for (auto it = nprops.begin(); it != nprops.end(); ++it) {
    const std::string key = keyString(it->first, "nprops");
    const std::string path = numberedPath("nprops", key);
    Entry e{path, it->second, {}};
    if (isNodeNumber(key)) {
      const int node = checkedKeyIndex(it->first, path, "node", m.nodes.size());
      if (!seen.emplace(node, path).second)
        fail(path, "node " + std::to_string(node + 1) + " is given twice (also at " + seen[node] + ")");
      e.nodes = {node};
    } else {
      if (!ctx.mesh)
        fail(path, "expected a node number, got '" + key + "' (names of Gmsh physical groups need a `mesh:` file)");
      const GmshPhysicalGroup* g = ctx.mesh->findGroup(key);
      if (!g) fail(path, "no node number or physical group '" + key + "' in " + ctx.mesh->file + suggestion(key, ctx.mesh->groupNames()));
      for (int n : g->nodes) e.nodes.push_back(static_cast<int>(ctx.sceneNodes) + n);
    }
    if (e.props.IsNull()) continue;
    checkKeys(e.props, path, kNpropsKeys);
    (e.nodes.size() == 1 && isNodeNumber(key) ? numbered : groups).push_back(std::move(e));
  }

  // Nodes on ancf_cable2d elements (fix_coords applies to them only).
  std::vector<bool> ancfNode(m.nodes.size(), false);
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const int s = m.elementSet[e];
    if (s >= 0 && m.eprops[static_cast<std::size_t>(s)].type() == ElementType::AncfCable2D)
      for (int n : m.elements[e]) ancfNode[static_cast<std::size_t>(n)] = true;
  }

  std::map<int, LoadSources> sources;
  for (const auto* list : {&groups, &numbered})
    for (const Entry& e : *list)
      for (int node : e.nodes) {
        applyProps(m.nprops[node], sources[node], e.props, e.path, ctx);
        if (e.props["fix_coords"].IsDefined() && !ancfNode[static_cast<std::size_t>(node)])
          fail(childPath(e.path, "fix_coords"), "fix_coords applies to nodes of ancf_cable2d elements; node " +
                                                    std::to_string(node + 1) + " is not on one");
        if (e.props["slope"].IsDefined() && !ancfNode[static_cast<std::size_t>(node)])
          fail(childPath(e.path, "slope"), "slope (ANCF reference slope) applies to nodes of ancf_cable2d elements; node " +
                                               std::to_string(node + 1) + " is not on one");
      }
  for (const auto& [node, np] : m.nprops) checkConflicts(node, np, sources[node]);
}

}  // namespace sinew::scene
