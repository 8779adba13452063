// The discretization error of a quantity from three levels of refinement (h, h/2, h/4): Richardson
// extrapolation with the observed order, checked against the element's theoretical order.
//
//   d1 = |q1 - q0|, d2 = |q2 - q1|            (Euclidean norm over the quantity's components, or for a
//                                               time history the largest over its rows)
//   p  = log2(d1 / d2)                         observed order
//   e2 = d2 / (2^p - 1) / scale                estimated relative error of the finest level q2
//   q* = q2 + (q2 - q1) / (2^p - 1)            extrapolated value (reported beside q2, never instead)
//
// The estimate is trusted when p lies within kOrderBelow below and kOrderAbove above the theoretical
// order (the errors shrink as the element's error term says: the levels are in the asymptotic range).
// Otherwise it is Erratic (pre-asymptotic levels, a mode that swapped places), unless the changes
// between the levels are below a tenth of the target (Resolved: the quantity does not depend on the
// mesh at this accuracy, e.g. the reactions of a statically determinate structure, or it is at the
// solver's round-off); then the estimate is the larger change.
#pragma once
#include <string>
#include <vector>

namespace sinew::accuracy {

enum class EstimateStatus { Converging, Resolved, Erratic };
const char* statusName(EstimateStatus s);

struct Estimate {
  EstimateStatus status = EstimateStatus::Erratic;
  double order = 0;   ///< observed order p (NaN when a change is zero)
  double error = 0;   ///< estimated relative error of the finest level
  std::vector<double> extrapolated;  ///< q* (Converging only; else empty)
  bool trusted() const { return status != EstimateStatus::Erratic; }
};

/// Orders accepted around the theoretical order p_th: [p_th - kOrderBelow, p_th + kOrderAbove].
constexpr double kOrderBelow = 0.6;
constexpr double kOrderAbove = 1.5;
/// Changes below this fraction of target * scale between every pair of levels count as resolved.
constexpr double kResolvedFraction = 0.1;

/// The estimate of q2 from q0 (coarsest), q1, q2 (finest) of one quantity with `scale` (> 0). rowSize
/// > 0: the quantity is rows of rowSize components (a time history) and |.| the largest Euclidean
/// norm of a row; 0: the Euclidean norm of all components. upperOrder > theoreticalOrder: a quantity
/// that may converge as either, orders up to upperOrder + kOrderAbove are trusted too.
Estimate richardson(const std::vector<double>& q0, const std::vector<double>& q1, const std::vector<double>& q2,
                    double scale, double theoreticalOrder, double target, std::size_t rowSize = 0,
                    double upperOrder = 0);

}  // namespace sinew::accuracy
