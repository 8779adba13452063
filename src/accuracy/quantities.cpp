#include "accuracy/quantities.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "accuracy/path_quantities.hpp"
#include "accuracy/time_refinement.hpp"

namespace sinew::accuracy {

namespace {

using Kind = QuantityDef::Kind;

/// Fraction of its scale below which a quantity of the coarsest level is not watched.
constexpr double kSignificant = 1e-6;

/// The last row of a step-indexed dataset, as a flat array of its values ([] when missing or empty).
std::vector<double> lastRow(const RunResults& r, const std::string& name) {
  const ResultArray* a = r.find(name);
  if (!a || a->shape.empty() || a->shape[0] == 0 || a->integer) return {};
  const std::size_t row = a->values.size() / static_cast<std::size_t>(a->shape[0]);
  return std::vector<double>(a->values.end() - static_cast<long>(row), a->values.end());
}

/// Values `count` of node `node` in a node dataset's last row ([ns, nn, count...]).
std::vector<double> nodeValues(const RunResults& r, const std::string& name, long node, std::size_t count) {
  const std::vector<double> row = lastRow(r, name);
  const std::size_t at = static_cast<std::size_t>(node) * count;
  if (row.size() < at + count) return {};
  return std::vector<double>(row.begin() + static_cast<long>(at), row.begin() + static_cast<long>(at + count));
}

/// Rotation vector (angle times axis) of a unit quaternion [q0, q1, q2, q3], q0 >= 0.
std::vector<double> rotationVector(const std::vector<double>& q) {
  if (q.size() != 4) return {};
  const double s = std::sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (s == 0) return {0, 0, 0};
  const double angle = 2 * std::atan2(s, q[0]);
  return {angle * q[1] / s, angle * q[2] / s, angle * q[3] / s};
}

double norm(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

long numNodes(const RunResults& r) {
  const ResultArray* a = r.find("node/p0");
  return a && !a->shape.empty() ? a->shape[0] : 0;
}

/// Row/column of a 3x3 diagonal block of a 6x6 compliance matrix: offset 0 (tt) or 3 (rr).
std::vector<double> complianceBlock(const std::vector<double>& cm, int offset) {
  if (cm.size() != 36) return {};
  std::vector<double> b;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) b.push_back(cm[static_cast<std::size_t>((offset + i) * 6 + offset + j)]);
  return b;
}

/// The largest per-node norm of a node quantity over every scene node (the quantity's scale).
double largestOverNodes(const RunResults& r, Kind kind) {
  double best = 0;
  QuantityDef q;
  q.kind = kind;
  for (long n = 0; n < numNodes(r); ++n) {
    q.node = n;
    const std::vector<double> v = readQuantity(q, r);
    if (!v.empty() && std::isfinite(norm(v))) best = std::max(best, norm(v));
  }
  return best;
}

/// Diagonal of the scene nodes' bounding box (1 for a single point).
double modelSize(const RunResults& r) {
  const ResultArray* p0 = r.find("node/p0");
  if (!p0 || p0->values.size() < 3) return 1.0;
  Vec3 lo{p0->values[0], p0->values[1], p0->values[2]}, hi = lo;
  for (std::size_t i = 0; i + 2 < p0->values.size(); i += 3)
    for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p0->values[i + k]), hi[k] = std::max(hi[k], p0->values[i + k]);
  const double d = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
  return d > 0 ? d : 1.0;
}

/// A quantity worth watching: finite and above 1e-6 of its scale on the coarsest level (a node that
/// does not move, a reaction at round-off are not).
bool significant(const QuantityDef& q, const RunResults& coarsest) {
  const std::vector<double> v = readQuantity(q, coarsest);
  return !v.empty() && std::isfinite(norm(v)) && norm(v) > kSignificant * quantityScale(q, coarsest);
}

std::string nodeName(long node, const char* field) { return "node " + std::to_string(node + 1) + " " + field; }

/// Node quantities of one field word ("p", "r", "Freac", "Mreac", "CMglob").
std::vector<QuantityDef> nodeQuantities(long node, const std::string& field) {
  if (field == "p") return {{Kind::Displacement, nodeName(node, "p"), node, 0}};
  if (field == "r") return {{Kind::Rotation, nodeName(node, "r"), node, 0}};
  if (field == "Freac") return {{Kind::Force, nodeName(node, "Freac"), node, 0}};
  if (field == "Mreac") return {{Kind::Moment, nodeName(node, "Mreac"), node, 0}};
  return {{Kind::ComplianceTT, nodeName(node, "CMglob tt"), node, 0}, {Kind::ComplianceRR, nodeName(node, "CMglob rr"), node, 0}};
}

/// Every column of /freq or /buck with a finite value on the coarsest level.
void addColumns(std::vector<QuantityDef>& out, const RunResults& r, const char* dataset, Kind kind) {
  const std::vector<double> row = lastRow(r, dataset);
  for (std::size_t k = 0; k < row.size(); ++k)
    if (std::isfinite(row[k]) && row[k] != 0)
      out.push_back({kind, std::string(dataset) + " " + std::to_string(k + 1), -1, static_cast<long>(k)});
}

}  // namespace

bool loadedNode(const NodeProps& p) {
  auto any = [](const Vec3& v) { return v[0] != 0 || v[1] != 0 || v[2] != 0; };
  bool displaced = p.rot.has_value() || p.rot_initial.has_value();
  for (int k = 0; k < 3; ++k) displaced |= (p.displ[k] && *p.displ[k] != 0) || (p.displ_initial[k] && *p.displ_initial[k] != 0);
  return any(p.force) || any(p.force_initial) || any(p.moment) || any(p.moment_initial) || displaced;
}

namespace {

bool supported(const NodeProps& p) {
  bool held = p.fix || p.fix_pos || p.fix_orien || p.fix_x || p.fix_y || p.fix_z || p.fix_coords.has_value();
  for (int k = 0; k < 3; ++k) held |= p.displ[k].has_value();
  return held || p.rot.has_value();
}

}  // namespace

double theoreticalOrder(const QuantityDef& q, bool lumpedMass, bool membranes, const ElementOrders& orders) {
  if (membranes) return 2.0;
  if (q.kind == Kind::Buckling || (q.kind == Kind::Frequency && !lumpedMass)) return orders.modal;
  if (q.kind == Kind::Frequency || q.kind == Kind::StressMax) return 2.0;
  return orders.nodal;
}

std::vector<double> readQuantity(const QuantityDef& q, const RunResults& r) {
  switch (q.kind) {
    case Kind::Frequency:
    case Kind::Buckling: {
      const std::vector<double> row = lastRow(r, q.kind == Kind::Frequency ? "freq" : "buck");
      if (static_cast<std::size_t>(q.index) >= row.size()) return {};
      return {row[static_cast<std::size_t>(q.index)]};
    }
    case Kind::StressMax: {
      const std::vector<double> row = lastRow(r, "stressmax");
      return row.empty() ? row : std::vector<double>{row.back()};
    }
    case Kind::Displacement: {
      std::vector<double> p = nodeValues(r, "node/p", q.node, 3);
      const ResultArray* p0 = r.find("node/p0");
      if (p.empty() || !p0 || p0->values.size() < static_cast<std::size_t>(q.node + 1) * 3) return {};
      for (std::size_t k = 0; k < 3; ++k) p[k] -= p0->values[static_cast<std::size_t>(q.node) * 3 + k];
      return p;
    }
    case Kind::Rotation: return rotationVector(nodeValues(r, "node/r_quat", q.node, 4));
    case Kind::Force: return nodeValues(r, "node/Freac", q.node, 3);
    case Kind::Moment: return nodeValues(r, "node/Mreac", q.node, 3);
    case Kind::ComplianceTT: return complianceBlock(nodeValues(r, "node/CMglob", q.node, 36), 0);
    case Kind::ComplianceRR: return complianceBlock(nodeValues(r, "node/CMglob", q.node, 36), 3);
    case Kind::LimitLoad: return criticalLoadFactor(r, 1, q.index);
    case Kind::BifurcationLoad: return criticalLoadFactor(r, 2, q.index);
    case Kind::Shape: return formFoundShape(r, q.index);
    case Kind::DisplacementHistory: return displacementHistory(q.node, r);
  }
  return {};
}

double quantityScale(const QuantityDef& q, const RunResults& r) {
  double s = 0;
  switch (q.kind) {
    case Kind::Frequency:
    case Kind::Buckling:
    case Kind::StressMax:
    case Kind::ComplianceTT:
    case Kind::ComplianceRR:
    case Kind::LimitLoad:
    case Kind::BifurcationLoad: {
      for (double v : readQuantity(q, r))
        if (std::isfinite(v)) s = std::max(s, std::abs(v));
      break;
    }
    case Kind::Displacement:
    case Kind::Rotation: s = largestOverNodes(r, q.kind); break;
    // reactions relative to the loads the supports carry: the larger of the force and the moment
    // over the model size (a reaction that is zero in theory stays at round-off against that)
    case Kind::Force: s = std::max(largestOverNodes(r, Kind::Force), largestOverNodes(r, Kind::Moment) / modelSize(r)); break;
    case Kind::Moment: s = std::max(largestOverNodes(r, Kind::Moment), largestOverNodes(r, Kind::Force) * modelSize(r)); break;
    case Kind::Shape: s = shapeScale(r, q.index); break;
    case Kind::DisplacementHistory: s = largestDisplacementOverRows(r); break;
  }
  return s > 0 ? s : 1.0;
}

std::set<std::string> datasetsUsed(const std::vector<QuantityDef>& qs) {
  std::set<std::string> names;
  for (const QuantityDef& q : qs) {
    switch (q.kind) {
      case Kind::Frequency: names.insert("freq"); break;
      case Kind::Buckling: names.insert("buck"); break;
      case Kind::StressMax: names.insert("stressmax"); break;
      case Kind::Displacement: names.insert({"node/p", "node/p0"}); break;
      case Kind::Rotation: names.insert({"node/r_quat", "node/p0"}); break;
      case Kind::Force: names.insert({"node/Freac", "node/p0"}); break;
      case Kind::Moment: names.insert({"node/Mreac", "node/p0"}); break;
      case Kind::ComplianceTT:
      case Kind::ComplianceRR: names.insert("node/CMglob"); break;
      case Kind::LimitLoad:
      case Kind::BifurcationLoad: names.insert("path/critical_points"); break;
      case Kind::Shape: names.insert({"node/p", "node/p0", "formfinding/step"}); break;
      case Kind::DisplacementHistory: names.insert({"node/p", "node/p0"}); break;
    }
  }
  return names;
}

std::vector<QuantityDef> selectQuantities(const Model& model, const RunResults& coarsest,
                                          const std::vector<std::string>& names) {
  if (model.opt.dynamics) return historyQuantities(model, coarsest, names);
  std::vector<QuantityDef> out;
  if (!names.empty()) {  // opt.accuracy_quantities (checked by the scene reader)
    for (const std::string& name : names) {
      std::istringstream words(name);
      std::string first, node, field;
      words >> first >> node >> field;
      if (first == "freq") addColumns(out, coarsest, "freq", Kind::Frequency);
      else if (first == "buck") addColumns(out, coarsest, "buck", Kind::Buckling);
      else if (first == "stressmax" && coarsest.find("stressmax")) out.push_back({Kind::StressMax, "stressmax", -1, 0});
      else if (first == "limit" || first == "bifurcation") {
        std::vector<QuantityDef> path;
        addCriticalPoints(path, coarsest);
        for (const QuantityDef& q : path)
          if ((q.kind == Kind::LimitLoad) == (first == "limit")) out.push_back(q);
      } else if (first == "shape" && model.formfinding) out.push_back({Kind::Shape, "shape", -1, numNodes(coarsest)});
      else if (first == "node")
        for (const QuantityDef& q : nodeQuantities(std::stol(node) - 1, field)) out.push_back(q);
    }
    return out;
  }
  addCriticalPoints(out, coarsest);  // a path's limit and bifurcation points (none without continuation)
  if (model.formfinding) out.push_back({Kind::Shape, "shape", -1, numNodes(coarsest)});
  // the nodes the scene loads, and the one that moves most on the coarsest level
  std::vector<long> watched;
  for (const auto& [node, props] : model.nprops)
    if (loadedNode(props)) watched.push_back(node);
  long most = -1;
  double largest = 0;
  for (long n = 0; n < numNodes(coarsest); ++n) {
    const double u = norm(readQuantity({Kind::Displacement, "", n, 0}, coarsest));
    if (u > largest) largest = u, most = n;
  }
  if (most >= 0 && std::find(watched.begin(), watched.end(), most) == watched.end()) watched.push_back(most);
  std::sort(watched.begin(), watched.end());
  // membranes: a nodal reaction is the traction over the node's share of the edge, which halves with
  // h, and a point load's compliance grows as log(1/h): neither converges, neither is watched
  bool membranes = false;
  for (std::size_t e = 0; e < model.elements.size(); ++e) membranes |= model.elementSet[e] >= 0 && model.elements[e].size() > 2;
  const bool compliance = coarsest.find("node/CMglob") != nullptr && !membranes;
  for (long n : watched) {
    std::vector<QuantityDef> qs = nodeQuantities(n, "p");
    qs.push_back(nodeQuantities(n, "r")[0]);
    if (compliance)
      for (const QuantityDef& q : nodeQuantities(n, "CMglob")) qs.push_back(q);
    for (const QuantityDef& q : qs)
      if (significant(q, coarsest)) out.push_back(q);
  }
  for (const auto& [node, props] : model.nprops) {
    if (!supported(props) || membranes) continue;
    for (const char* field : {"Freac", "Mreac"})
      for (const QuantityDef& q : nodeQuantities(node, field))
        if (significant(q, coarsest)) out.push_back(q);
  }
  if (const QuantityDef stress{Kind::StressMax, "stressmax", -1, 0}; significant(stress, coarsest)) out.push_back(stress);
  addColumns(out, coarsest, "freq", Kind::Frequency);
  addColumns(out, coarsest, "buck", Kind::Buckling);
  return out;
}

}  // namespace sinew::accuracy
