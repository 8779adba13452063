#include "accuracy/richardson.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew::accuracy {

const char* statusName(EstimateStatus s) {
  switch (s) {
    case EstimateStatus::Converging: return "converging";
    case EstimateStatus::Resolved: return "resolved";
    case EstimateStatus::Erratic: return "erratic";
  }
  return "erratic";
}

namespace {

/// |a - b|: Euclidean over all components (rowSize 0) or the largest over rows of rowSize components.
double distance(const std::vector<double>& a, const std::vector<double>& b, std::size_t rowSize) {
  const std::size_t n = std::min(a.size(), b.size()), row = rowSize > 0 ? rowSize : std::max<std::size_t>(n, 1);
  double largest = 0;
  for (std::size_t start = 0; start < n; start += row) {
    double s = 0;
    for (std::size_t i = start; i < n && i < start + row; ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
    largest = std::max(largest, std::sqrt(s));
  }
  return largest;
}

}  // namespace

Estimate richardson(const std::vector<double>& q0, const std::vector<double>& q1, const std::vector<double>& q2,
                    double scale, double theoreticalOrder, double target, std::size_t rowSize, double upperOrder) {
  Estimate e;
  const double d1 = distance(q1, q0, rowSize), d2 = distance(q2, q1, rowSize);
  e.order = (d1 > 0 && d2 > 0) ? std::log2(d1 / d2) : std::numeric_limits<double>::quiet_NaN();
  const bool sane = std::isfinite(e.order) && e.order >= theoreticalOrder - kOrderBelow &&
                    e.order <= std::max(theoreticalOrder, upperOrder) + kOrderAbove;
  if (sane) {
    const double f = 1.0 / (std::pow(2.0, e.order) - 1.0);  // q* - q2 = f (q2 - q1)
    e.status = EstimateStatus::Converging;
    e.error = f * d2 / scale;
    e.extrapolated = q2;
    for (std::size_t i = 0; i < q2.size() && i < q1.size(); ++i) e.extrapolated[i] += f * (q2[i] - q1[i]);
    return e;
  }
  const double largest = std::max(d1, d2);
  e.status = largest <= kResolvedFraction * target * scale ? EstimateStatus::Resolved : EstimateStatus::Erratic;
  e.error = (e.status == EstimateStatus::Resolved ? largest : d2) / scale;
  return e;
}

}  // namespace sinew::accuracy
