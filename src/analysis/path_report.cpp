#include "analysis/path_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sinew {

PathEnd pathEnd(const ContinuationOptions& c, int points, double lambda, double u, bool failed, bool interrupted) {
  std::ostringstream s;
  PathEnd end;
  if (failed) {
    s << "corrector failed after path point " << points;
  } else if (interrupted) {
    s << "interrupted after path point " << points;
  } else if (c.stop_load_factor && lambda >= *c.stop_load_factor) {
    s << "stop_load_factor " << *c.stop_load_factor << " reached (load factor " << lambda << ")";
  } else if (c.stop_displacement && std::abs(u) >= std::abs(*c.stop_displacement)) {
    s << "stop_displacement " << *c.stop_displacement << " reached (control displacement " << u << ")";
  } else {
    s << "max_steps " << c.max_steps << " reached";
    if (c.stop_load_factor || c.stop_displacement) {  // the scene asked for another end
      end.endedShort = true;
      s << " before";
      if (c.stop_load_factor) s << " stop_load_factor " << *c.stop_load_factor;
      if (c.stop_load_factor && c.stop_displacement) s << " and";
      if (c.stop_displacement) s << " stop_displacement " << *c.stop_displacement;
      s << " (load factor " << lambda;
      if (c.node >= 0) s << ", control displacement " << u;
      s << ")";
    }
  }
  end.reason = s.str();
  return end;
}

namespace {

struct P {
  double x, y;
};
double dot(P a, P b) { return a.x * b.x + a.y * b.y; }
P sub(P a, P b) { return {a.x - b.x, a.y - b.y}; }

/// Distance of p from the segment a-b.
double segmentDistance(P p, P a, P b) {
  const P d = sub(b, a);
  const double dd = dot(d, d);
  const double t = dd > 0 ? std::clamp(dot(sub(p, a), d) / dd, 0.0, 1.0) : 0.0;
  const P q{a.x + t * d.x, a.y + t * d.y};
  return std::sqrt(dot(sub(p, q), sub(p, q)));
}

}  // namespace

PathRetrace pathRetrace(const std::vector<double>& lambda, const std::vector<double>& u) {
  PathRetrace r;
  const size_t n = std::min(lambda.size(), u.size());
  double L = 0, D = 0;
  for (size_t i = 0; i < n; ++i) {
    L = std::max(L, std::abs(lambda[i]));
    D = std::max(D, std::abs(u[i]));
  }
  if (n < 4 || !(L > 0) || !(D > 0)) return r;
  std::vector<P> p(n);
  for (size_t i = 0; i < n; ++i) p[i] = {lambda[i] / L, u[i] / D};
  // step k runs from p[k-1] to p[k]; it retraces step j < k when it ends close to it going back
  auto retraces = [&](size_t k, size_t* along) {
    const P dk = sub(p[k], p[k - 1]);
    const double lk = std::sqrt(dot(dk, dk));
    if (!(lk > 0)) return false;
    // a path that turns back runs along the steps just before its turn: the last 50 steps are enough
    for (size_t j = k - 1; j >= 1 && j + 50 >= k; --j) {  // the nearest first
      const P dj = sub(p[j], p[j - 1]);
      const double lj = std::sqrt(dot(dj, dj));
      if (!(lj > 0) || dot(dk, dj) > -0.95 * lk * lj) continue;
      if (segmentDistance(p[k], p[j - 1], p[j]) <= 0.2 * lk) {
        *along = j - 1;
        return true;
      }
    }
    return false;
  };
  for (size_t k = 2; k + 1 < n; ++k) {
    size_t a = 0, b = 0;
    if (retraces(k, &a) && retraces(k + 1, &b)) {
      r.point = static_cast<int>(k);
      r.earlier = static_cast<int>(a);
      return r;
    }
  }
  return r;
}

PathTurnBack pathTurnBack(const std::vector<double>& lambda, const std::vector<double>& u) {
  PathTurnBack r;
  const size_t n = std::min(lambda.size(), u.size());
  size_t limit = 0;  // the load factor's first maximum
  while (limit + 1 < n && lambda[limit + 1] >= lambda[limit]) ++limit;
  if (limit == 0 || limit + 1 >= n) return r;
  // the way there: the largest distance |u - u_0| so far (at `far`); the way back: how much of it the
  // displacement has given up again since
  size_t far = 0;
  for (size_t i = 1; i < n; ++i) {
    const double there = std::abs(u[far] - u[0]), now = std::abs(u[i] - u[0]);
    if (now >= there) {
      far = i;
      continue;
    }
    if (far < limit || !(there - now > 0.5 * there)) continue;
    size_t back = i;  // follow the way back to its end
    while (back + 1 < n && std::abs(u[back + 1] - u[0]) <= std::abs(u[back] - u[0])) ++back;
    // a way back on another branch (other load factors at the same displacements: the symmetric path
    // of a pinned shallow arch loops so) revisits no state: the way back must run along the way there
    // in the plane of the scaled load factor and displacement (median distance below 0.05)
    double L = 0, D = 0;
    for (size_t j = 0; j <= back; ++j) {
      L = std::max(L, std::abs(lambda[j]));
      D = std::max(D, std::abs(u[j]));
    }
    if (!(L > 0) || !(D > 0)) return r;
    std::vector<double> dist;
    for (size_t j = far + 1; j <= back; ++j) {
      double d = 1e300;
      for (size_t m = limit + 1; m <= far; ++m)
        d = std::min(d, segmentDistance({lambda[j] / L, u[j] / D}, {lambda[m - 1] / L, u[m - 1] / D}, {lambda[m] / L, u[m] / D}));
      dist.push_back(d);
    }
    std::nth_element(dist.begin(), dist.begin() + static_cast<long>(dist.size() / 2), dist.end());
    if (dist.empty() || dist[dist.size() / 2] > 0.05) return r;
    r.limit = static_cast<int>(limit);
    r.turn = static_cast<int>(far);
    r.back = static_cast<int>(back);
    r.fraction = (there - std::abs(u[back] - u[0])) / there;
    return r;
  }
  return r;
}

}  // namespace sinew
