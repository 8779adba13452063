#include "accuracy/supported_boundary.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sinew::accuracy {

namespace {

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// The point halfway between a and b on the circle through c, a, b (the arc from a to b that does not
/// pass c); the chord's midpoint when the three are collinear.
Vec3 arcMidpoint(const Vec3& c, const Vec3& a, const Vec3& b) {
  const Vec3 chord{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
  const Vec3 u = sub(a, c), v = sub(b, c);
  const Vec3 n = cross(u, v);
  const double nn = dot(n, n);
  if (nn <= 1e-24 * dot(u, u) * dot(v, v)) return chord;
  // circumcentre of c, a, b: c + (|u|^2 (v x n) + |v|^2 (n x u)) / (2 |n|^2)
  const Vec3 vn = cross(v, n), nu = cross(n, u);
  Vec3 o;
  for (int k = 0; k < 3; ++k) o[k] = c[k] + (dot(u, u) * vn[k] + dot(v, v) * nu[k]) / (2 * nn);
  const Vec3 r = sub(a, o), m = sub(chord, o);
  const double mm = std::sqrt(dot(m, m)), radius = std::sqrt(dot(r, r));
  if (mm <= 1e-12 * radius) return chord;
  // the arc's midpoint on the side away from c: along +m when c lies beyond the chord from o
  const double side = dot(sub(c, o), m) < mm * mm ? 1.0 : -1.0;
  Vec3 x;
  for (int k = 0; k < 3; ++k) x[k] = o[k] + side * radius * m[k] / mm;
  return x;
}

}  // namespace

SupportedBoundary::SupportedBoundary(const Model& m) : model_(m) {
  std::map<std::pair<int, int>, int> uses;  // membrane edge -> elements along it
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const std::vector<int>& el = m.elements[e];
    if (m.elementSet[e] < 0 || el.size() < 3) continue;
    for (std::size_t i = 0; i < el.size(); ++i) {
      const int a = el[i], b = el[(i + 1) % el.size()];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  }
  const auto fixed = [&m](int n) {
    const auto it = m.nprops.find(n);
    return it != m.nprops.end() && it->second.fix;
  };
  for (const auto& [edge, count] : uses)
    if (count == 1 && fixed(edge.first) && fixed(edge.second)) {
      neighbours_[edge.first].push_back(edge.second);
      neighbours_[edge.second].push_back(edge.first);
    }
}

std::optional<Vec3> SupportedBoundary::midpoint(int a, int b) const {
  const auto ia = neighbours_.find(a), ib = neighbours_.find(b);
  if (ia == neighbours_.end() || ib == neighbours_.end()) return std::nullopt;
  if (std::find(ia->second.begin(), ia->second.end(), b) == ia->second.end()) return std::nullopt;
  const auto x = [this](int n) { return model_.nodes[static_cast<std::size_t>(n)]; };
  // the boundary goes on through a and b when each has exactly one other supported boundary edge
  std::vector<Vec3> candidates;
  if (ia->second.size() == 2) candidates.push_back(arcMidpoint(x(ia->second[0] == b ? ia->second[1] : ia->second[0]), x(a), x(b)));
  if (ib->second.size() == 2) candidates.push_back(arcMidpoint(x(ib->second[0] == a ? ib->second[1] : ib->second[0]), x(b), x(a)));
  if (candidates.empty()) return std::nullopt;
  Vec3 mean{};
  for (const Vec3& c : candidates)
    for (int k = 0; k < 3; ++k) mean[k] += c[k] / static_cast<double>(candidates.size());
  return mean;
}

}  // namespace sinew::accuracy
