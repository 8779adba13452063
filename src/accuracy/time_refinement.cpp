#include "accuracy/time_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace sinew::accuracy {

namespace {

using Kind = QuantityDef::Kind;

/// Fraction of the largest displacement below which a node's history is not watched.
constexpr double kSignificant = 1e-6;

long numNodes(const RunResults& r) {
  const ResultArray* a = r.find("node/p0");
  return a && !a->shape.empty() ? a->shape[0] : 0;
}

/// The largest norm of the rows (3 components each) of a history.
double largestRow(const std::vector<double>& h) {
  double m = 0;
  for (std::size_t i = 0; i + 2 < h.size(); i += 3)
    m = std::max(m, std::sqrt(h[i] * h[i] + h[i + 1] * h[i + 1] + h[i + 2] * h[i + 2]));
  return m;
}

QuantityDef history(long node) { return {Kind::DisplacementHistory, "node " + std::to_string(node + 1) + " p(t)", node, 0}; }

}  // namespace

bool refinesTime(const Model& m) { return m.opt.dynamics.has_value() && m.opt.accuracy_refine != "space"; }

bool refinesSpace(const Model& m) {
  return !m.opt.dynamics || m.opt.accuracy_refine == "space" || m.opt.accuracy_refine == "both";
}

std::string timeRefinementLimit(const Model& m) {
  if (!m.opt.dynamics)
    return m.opt.accuracy_refine == "time" || m.opt.accuracy_refine == "both"
               ? "opt.accuracy_refine: " + m.opt.accuracy_refine +
                     " refines the time step of opt.dynamics; this scene has none (use space, the default)"
               : "";
  if (m.opt.dynamics->adaptive.control != "none")
    return "opt.dynamics.adaptive: -target_error halves a fixed time step level by level; adaptive steps choose "
           "their own (use control: none, or refine -dynamics_adapt_tol by hand)";
  for (const std::string& name : m.opt.accuracy_quantities) {
    std::istringstream words(name);
    std::string first, node, field;
    words >> first >> node >> field;
    if (first != "node" || field != "p")
      return "opt.accuracy_quantities: with opt.dynamics only 'node <n> p' (the node's time history), not '" + name + "'";
  }
  return "";
}

long timeSteps(const Model& m) {
  if (!m.opt.dynamics || m.opt.dynamics->dt <= 0) return 1;
  return std::max(1L, static_cast<long>(std::ceil(m.opt.dynamics->tend / m.opt.dynamics->dt - 1e-9)));
}

Model timeRefinedModel(const Model& base, int level) {
  Model m = base;
  m.opt.target_error = 0;
  m.opt.accuracy_quantities.clear();
  const int f = 1 << level;
  DynamicsOptions& d = *m.opt.dynamics;
  d.dt /= f;  // exact: a power of two
  d.output_every *= f;
  OutputSteps& o = m.opt.output_steps;  // time step k of level 0 is step k 2^L here
  if (o.kind == OutputSteps::Kind::Every) o.every *= f;
  if (o.kind == OutputSteps::Kind::List)
    for (int& s : o.steps) s *= f;
  return m;
}

std::vector<double> displacementHistory(long node, const RunResults& r) {
  const ResultArray* p = r.find("node/p");
  const ResultArray* p0 = r.find("node/p0");
  if (!p || !p0 || p->shape.size() < 2 || p->integer || node < 0 || node >= p->shape[1]) return {};
  const std::size_t rows = static_cast<std::size_t>(p->shape[0]), nn = static_cast<std::size_t>(p->shape[1]);
  const std::size_t n = static_cast<std::size_t>(node);
  if (p0->values.size() < (n + 1) * 3 || p->values.size() < rows * nn * 3) return {};
  std::vector<double> h(rows * 3);
  for (std::size_t row = 0; row < rows; ++row)
    for (std::size_t k = 0; k < 3; ++k) h[row * 3 + k] = p->values[(row * nn + n) * 3 + k] - p0->values[n * 3 + k];
  return h;
}

double largestDisplacementOverRows(const RunResults& r) {
  double m = 0;
  for (long n = 0; n < numNodes(r); ++n) m = std::max(m, largestRow(displacementHistory(n, r)));
  return m;
}

std::vector<QuantityDef> historyQuantities(const Model& model, const RunResults& coarsest,
                                           const std::vector<std::string>& names) {
  std::vector<QuantityDef> out;
  if (!names.empty()) {  // checked by timeRefinementLimit: "node <n> p"
    for (const std::string& name : names) {
      std::istringstream words(name);
      std::string first;
      long node = 0;
      words >> first >> node;
      out.push_back(history(node - 1));
    }
    return out;
  }
  std::vector<long> watched;
  for (const auto& [node, props] : model.nprops)
    if (loadedNode(props)) watched.push_back(node);
  long most = -1;
  double largest = 0;
  // refined elements add nodes: only the scene's nodes are nodes of every level
  const long candidates = refinesSpace(model) ? std::min<long>(numNodes(coarsest), static_cast<long>(model.nodes.size()))
                                              : numNodes(coarsest);
  for (long n = 0; n < candidates; ++n) {
    const double u = largestRow(displacementHistory(n, coarsest));
    if (u > largest) largest = u, most = n;
  }
  if (most >= 0 && std::find(watched.begin(), watched.end(), most) == watched.end()) watched.push_back(most);
  std::sort(watched.begin(), watched.end());
  for (long n : watched)
    if (largestRow(displacementHistory(n, coarsest)) > kSignificant * largest) out.push_back(history(n));
  return out;
}

std::string historyText(const std::vector<double>& v) {
  const std::size_t rows = v.size() / 3;
  if (rows == 0) return "[]";
  char b[160];
  std::snprintf(b, sizeof b, "%zu rows, last [%.10g, %.10g, %.10g]", rows, v[v.size() - 3], v[v.size() - 2], v[v.size() - 1]);
  return b;
}

}  // namespace sinew::accuracy
