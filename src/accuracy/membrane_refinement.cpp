#include "accuracy/membrane_refinement.hpp"

#include <map>
#include <utility>

#include "accuracy/supported_boundary.hpp"

namespace sinew::accuracy {

namespace {

/// Translation components a node holds: fix, fix_pos or fix_x/y/z.
std::array<bool, 3> heldTranslations(const NodeProps& p) {
  const bool all = p.fix || p.fix_pos;
  return {all || p.fix_x, all || p.fix_y, all || p.fix_z};
}

/// Supports of the midpoint node of edge (a, b), or nothing: a component held at both ends is held
/// (a clamped or pinned boundary edge stays one), a node between two fixed nodes is fixed; a
/// component prescribed by number at both ends gets their mean (the edge's linear trace).
std::optional<NodeProps> midpointProps(const std::map<int, NodeProps>& nprops, int a, int b) {
  const auto ia = nprops.find(a), ib = nprops.find(b);
  if (ia == nprops.end() || ib == nprops.end()) return std::nullopt;
  const NodeProps &pa = ia->second, &pb = ib->second;
  NodeProps m;
  bool any = false;
  if (pa.fix && pb.fix) {
    m.fix = any = true;
  } else {
    const std::array<bool, 3> ha = heldTranslations(pa), hb = heldTranslations(pb);
    const bool held[3] = {ha[0] && hb[0], ha[1] && hb[1], ha[2] && hb[2]};
    if (held[0] && held[1] && held[2]) {
      m.fix_pos = any = true;
    } else {
      m.fix_x = held[0], m.fix_y = held[1], m.fix_z = held[2];
      any = held[0] || held[1] || held[2];
    }
  }
  for (int k = 0; k < 3; ++k) {
    if (!pa.displ_t[k].empty() || !pb.displ_t[k].empty()) continue;
    if (pa.displ[k] && pb.displ[k]) m.displ[k] = 0.5 * (*pa.displ[k] + *pb.displ[k]), any = true;
    if (pa.displ_initial[k] && pb.displ_initial[k])
      m.displ_initial[k] = 0.5 * (*pa.displ_initial[k] + *pb.displ_initial[k]), any = true;
  }
  return any ? std::optional<NodeProps>(m) : std::nullopt;
}

/// One split: every edge gets its midpoint node (shared by the elements along it), every quad its centre.
/// parents (if given): per new node (numbered from base.nodes.size()) the base nodes it is the mean of.
Model splitOnce(const Model& base, std::vector<std::vector<int>>* parents = nullptr) {
  Model m = base;
  std::map<std::pair<int, int>, int> midpoints;  // sorted node pair -> midpoint node
  // form finding: a supported boundary edge's midpoint goes on the boundary curve (supported_boundary.hpp)
  const std::optional<SupportedBoundary> boundary =
      base.formfinding ? std::optional<SupportedBoundary>(std::in_place, base) : std::nullopt;
  const auto newNode = [&m](const Vec3& x) {
    m.nodes.push_back(x);
    return static_cast<int>(m.nodes.size()) - 1;
  };
  const auto mid = [&](int a, int b) {
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    const auto it = midpoints.find(key);
    if (it != midpoints.end()) return it->second;
    const Vec3& xa = base.nodes[static_cast<std::size_t>(a)];
    const Vec3& xb = base.nodes[static_cast<std::size_t>(b)];
    const std::optional<Vec3> curved = boundary ? boundary->midpoint(a, b) : std::nullopt;
    const int n = newNode(curved ? *curved : Vec3{0.5 * (xa[0] + xb[0]), 0.5 * (xa[1] + xb[1]), 0.5 * (xa[2] + xb[2])});
    if (std::optional<NodeProps> p = midpointProps(base.nprops, a, b)) m.nprops[n] = *p;
    if (parents) parents->push_back({a, b});
    midpoints.emplace(key, n);
    return n;
  };
  const std::size_t nElements = base.elements.size();
  for (std::size_t e = 0; e < nElements; ++e) {
    const int set = base.elementSet[e];
    if (set < 0) continue;  // rigid elements (no set) are not split
    const std::vector<int>& el = base.elements[e];
    std::vector<std::vector<int>> children;
    if (el.size() == 2) {
      const int c = mid(el[0], el[1]);
      children = {{el[0], c}, {c, el[1]}};
    } else if (el.size() == 3) {  // corners a b c; the middle child is the parent turned by 180 degrees in its plane
      const int ab = mid(el[0], el[1]), bc = mid(el[1], el[2]), ca = mid(el[2], el[0]);
      children = {{el[0], ab, ca}, {ab, el[1], bc}, {ca, bc, el[2]}, {bc, ca, ab}};
    } else {  // quad a b c d: the centre is the mean of the corners (the bilinear map's centre)
      const int ab = mid(el[0], el[1]), bc = mid(el[1], el[2]), cd = mid(el[2], el[3]), da = mid(el[3], el[0]);
      Vec3 x{};
      for (int v : el)
        for (int k = 0; k < 3; ++k) x[k] += 0.25 * base.nodes[static_cast<std::size_t>(v)][k];
      const int o = newNode(x);
      if (parents) parents->push_back(el);
      children = {{el[0], ab, o, da}, {ab, el[1], bc, o}, {o, bc, el[2], cd}, {da, o, cd, el[3]}};
    }
    m.elements[e] = children[0];  // the first child keeps the parent's number, the others follow
    for (std::size_t c = 1; c < children.size(); ++c) {
      m.eprops[static_cast<std::size_t>(set)].elems.push_back(static_cast<int>(m.elements.size()));
      m.elements.push_back(children[c]);
      m.elementSet.push_back(set);
    }
  }
  m.connectedNodes = m.nodes.size();
  return m;
}

}  // namespace

bool hasMembranes(const Model& m) {
  for (std::size_t e = 0; e < m.elements.size(); ++e)
    if (m.elementSet[e] >= 0 && m.elements[e].size() > 2) return true;
  return false;
}

std::string membraneRefinementLimit(const Model& m) {
  if (m.nodes.size() > m.connectedNodes)
    return "membranes are refined by splitting their elements, which numbers new nodes after the scene's: a scene with "
           "trailing unconnected nodes is not refined";
  if (!m.opt.rls.empty()) return "opt.rls in a scene with membranes: released elements are not split by the refinement";
  if (!m.sensors.empty()) return "sensors in a scene with membranes: their elements are not split by the refinement";
  for (const ElementSet& s : m.eprops)
    if (s.type() == ElementType::AncfCable2D)
      return "ANCF cables beside membranes are not split by the refinement (their slopes are nodal)";
  return "";
}

std::vector<std::vector<int>> splitParents(const Model& coarse) {
  std::vector<std::vector<int>> parents;
  splitOnce(coarse, &parents);
  return parents;
}

Model splitMembraneModel(const Model& base, int times) {
  Model m = base;
  for (int t = 0; t < times; ++t) m = splitOnce(m);
  return m;
}

}  // namespace sinew::accuracy
