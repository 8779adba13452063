#include "accuracy/path_quantities.hpp"

#include <algorithm>
#include <cmath>

namespace sinew::accuracy {

namespace {

/// The most path points a scene may ask for (opt.continuation.max_steps).
constexpr long kMaxPathSteps = 100000;

/// The stop variable of each row: the control displacement (stop_displacement) or the load factor.
const char* stopVariable(const ContinuationOptions& c) {
  return c.stop_displacement ? "path/control_displacement" : "load_factor";
}

/// The step datasets of the end state: the load factor, the control displacement and the node
/// results and stress of every path point (step analyses, which run at chosen rows, are not among them).
const char* const kEndState[] = {"load_factor", "path/control_displacement", "node/p", "node/r_quat",
                                 "node/Freac", "node/Mreac", "stressmax"};

/// Whether `a` is an end-state dataset of `rows` rows of reals.
bool isEndStateDataset(const std::string& name, const ResultArray& a, long rows) {
  return std::find(std::begin(kEndState), std::end(kEndState), name) != std::end(kEndState) && !a.integer &&
         !a.shape.empty() && a.shape[0] == rows && a.rows.empty() && !a.values.empty();
}

double modelSizeOf(const RunResults& r) {
  const ResultArray* p0 = r.find("node/p0");
  if (!p0 || p0->values.size() < 3) return 1.0;
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = p0->values[static_cast<std::size_t>(k)];
  for (std::size_t i = 0; i + 2 < p0->values.size(); i += 3)
    for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p0->values[i + k]), hi[k] = std::max(hi[k], p0->values[i + k]);
  const double d = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
  return d > 0 ? d : 1.0;
}

/// Row index of the found shape: the last row with a finite /formfinding/step (-1: none).
long foundShapeRow(const RunResults& r) {
  const ResultArray* s = r.find("formfinding/step");
  if (!s) return -1;
  for (long i = static_cast<long>(s->values.size()) - 1; i >= 0; --i)
    if (std::isfinite(s->values[static_cast<std::size_t>(i)])) return i;
  return -1;
}

}  // namespace

std::string pathRefinementLimit(const Model& m) {
  if (!m.opt.continuation) return "";
  const ContinuationOptions& c = *m.opt.continuation;
  if (!c.stop_displacement && !c.stop_load_factor)
    return "opt.continuation: the levels compare the same path only up to a stop criterion; give stop_displacement or "
           "stop_load_factor (max_steps ends the path at a different point on every level)";
  if (c.stop_displacement && c.node < 0) return "opt.continuation: stop_displacement needs the control node";
  return "";
}

void adaptPathLevel(Model& m, int level) {
  if (!m.opt.continuation || level <= 0) return;
  ContinuationOptions& c = *m.opt.continuation;
  c.max_steps = static_cast<int>(std::min(kMaxPathSteps, static_cast<long>(c.max_steps) << std::min(level, 16)));
}

std::vector<std::string> pathStopDatasets(const Model& m) {
  if (!m.opt.continuation) return {};
  return {"load_factor", "path/control_displacement"};
}

RunResults atPathStop(const Model& m, RunResults r) {
  if (!m.opt.continuation) return r;
  const ContinuationOptions& c = *m.opt.continuation;
  if (!c.stop_displacement && !c.stop_load_factor) return r;
  const ResultArray* var = r.find(stopVariable(c));
  if (!var || var->values.size() < 2) return r;
  const long rows = static_cast<long>(var->values.size());
  const double stop = c.stop_displacement ? *c.stop_displacement : *c.stop_load_factor;
  const auto at = [&](long i) { return var->values[static_cast<std::size_t>(i)]; };
  const double a = at(rows - 2), b = at(rows - 1);
  if (!(std::isfinite(a) && std::isfinite(b)) || a == b || (stop - a) * (stop - b) > 0) return r;  // the last step crossed it
  // cubic Lagrange interpolation in the stop variable over the last points (up to 4) along which it
  // runs one way: error O(ds^4), so the end state converges as fast as the levels' h^2 (ds shrinks as
  // 2^(-L/2)); a linear one, O(ds^2), would converge only as 2^-L
  long first = rows - 2;
  while (first > 0 && rows - first < 4 && std::isfinite(at(first - 1)) && (at(first) - at(first - 1)) * (b - a) > 0) --first;
  std::vector<double> w(static_cast<std::size_t>(rows - first), 1.0);
  for (long j = first; j < rows; ++j)
    for (long k = first; k < rows; ++k)
      if (k != j) w[static_cast<std::size_t>(j - first)] *= (stop - at(k)) / (at(j) - at(k));
  for (auto& [name, d] : r.datasets) {
    if (!isEndStateDataset(name, d, rows)) continue;
    const std::size_t row = d.values.size() / static_cast<std::size_t>(rows);
    std::vector<double> value(row, 0.0);
    for (long j = first; j < rows; ++j)
      for (std::size_t i = 0; i < row; ++i) value[i] += w[static_cast<std::size_t>(j - first)] * d.values[static_cast<std::size_t>(j) * row + i];
    double* last = d.values.data() + (rows - 1) * static_cast<long>(row);
    std::copy(value.begin(), value.end(), last);
    if (name == "node/r_quat")  // the interpolated quaternions back to unit length (same hemisphere: small steps)
      for (std::size_t i = 0; i + 3 < row; i += 4) {
        const double n = std::sqrt(last[i] * last[i] + last[i + 1] * last[i + 1] + last[i + 2] * last[i + 2] + last[i + 3] * last[i + 3]);
        if (n > 0)
          for (std::size_t k = 0; k < 4; ++k) last[i + k] /= n;
      }
  }
  return r;
}

std::vector<double> criticalLoadFactor(const RunResults& r, int kind, long index) {
  const ResultArray* a = r.find("path/critical_points");
  if (!a || a->shape.size() != 2 || a->shape[1] < 3) return {};
  long seen = 0;
  for (long i = 0; i < a->shape[0]; ++i) {
    const double* row = a->values.data() + i * a->shape[1];
    if (static_cast<int>(row[0]) != kind) continue;
    if (seen++ == index) return {row[2]};
  }
  return {};
}

void addCriticalPoints(std::vector<QuantityDef>& out, const RunResults& coarsest) {
  for (int kind : {1, 2}) {
    for (long k = 0;; ++k) {
      const std::vector<double> v = criticalLoadFactor(coarsest, kind, k);
      if (v.empty()) break;
      if (!std::isfinite(v[0]) || v[0] == 0) continue;
      out.push_back({kind == 1 ? QuantityDef::Kind::LimitLoad : QuantityDef::Kind::BifurcationLoad,
                     std::string(kind == 1 ? "limit " : "bifurcation ") + std::to_string(k + 1), -1, k});
    }
  }
}

std::vector<double> formFoundShape(const RunResults& r, long count) {
  const long row = foundShapeRow(r);
  const ResultArray* p = r.find("node/p");
  if (row < 0 || !p || p->shape.size() != 3 || row >= p->shape[0] || p->shape[1] < count) return {};
  const double* at = p->values.data() + row * p->shape[1] * 3;
  return std::vector<double>(at, at + count * 3);
}

double shapeScale(const RunResults& r, long count) {
  const std::vector<double> x = formFoundShape(r, count);
  const ResultArray* p0 = r.find("node/p0");
  const double size = modelSizeOf(r);
  long moving = 0;  // nodes that form finding moved (the supported ones stay)
  for (long n = 0; p0 && n < count && static_cast<std::size_t>(3 * n + 2) < x.size(); ++n) {
    double d = 0;
    for (long k = 0; k < 3; ++k) d += std::pow(x[static_cast<std::size_t>(3 * n + k)] - p0->values[static_cast<std::size_t>(3 * n + k)], 2);
    if (std::sqrt(d) > 1e-12 * size) ++moving;
  }
  return size * std::sqrt(static_cast<double>(std::max(moving, 1L)));
}

}  // namespace sinew::accuracy
