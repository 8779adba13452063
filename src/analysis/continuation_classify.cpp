// Path following's critical points: a change of the tangent's inertia between two path points
// classified and located (continuation_analysis.hpp).
#include <algorithm>
#include <cmath>

#include "analysis/continuation_analysis.hpp"

namespace sinew {

// The last two points differ in their negative-eigenvalue count: a limit point when the load factor
// turned back between them (located by the cubic Hermite interpolant of the load factor over the step),
// a bifurcation otherwise, located at the zero of the eigenvalue that changes sign (linear over the step)
// when SLEPc gave it at both points, else at the midpoint.
void ContinuationAnalysis::classify() {
  const size_t n = points_.size();
  const PathPoint& b = points_[n - 1];
  const PathPoint a = n >= 2 ? points_[n - 2] : PathPoint{};
  // a limit point when the load factor turned back between the two points (path slopes of opposite
  // sign), a bifurcation otherwise
  const bool turned = n >= 2 && a.slopeLoad * b.slopeLoad < 0;
  CriticalPoint c;
  c.afterStep = static_cast<int>(n) - 1;
  c.kind = turned ? CriticalPoint::Limit : CriticalPoint::Bifurcation;
  if (turned) {
    // cubic Hermite lambda(t), t in [0, 1] over the step's arc length h, from the values and the path
    // slopes at both ends; the limit point is where d lambda / dt = 0
    const double h = b.arcLength, la = a.loadFactor, lb = b.loadFactor, ma = h * a.slopeLoad, mb = h * b.slopeLoad;
    const double A2 = 6 * la + 3 * ma - 6 * lb + 3 * mb, A1 = -6 * la - 4 * ma + 6 * lb - 2 * mb, A0 = ma;
    double t = 0.5;
    if (std::abs(A2) > 1e-300) {
      const double disc = std::max(A1 * A1 - 4 * A2 * A0, 0.0);
      const double t1 = (-A1 + std::sqrt(disc)) / (2 * A2), t2 = (-A1 - std::sqrt(disc)) / (2 * A2);
      t = (t1 >= 0 && t1 <= 1) ? t1 : std::clamp(t2, 0.0, 1.0);
    } else if (A1 != 0.0) {
      t = std::clamp(-A0 / A1, 0.0, 1.0);
    }
    auto hermite = [t](double ya, double yb, double sa, double sb) {
      const double t2 = t * t, t3 = t2 * t;
      return (2 * t3 - 3 * t2 + 1) * ya + (t3 - 2 * t2 + t) * sa + (-2 * t3 + 3 * t2) * yb + (t3 - t2) * sb;
    };
    c.loadFactor = hermite(la, lb, ma, mb);
    c.controlValue = hermite(a.controlValue, b.controlValue, h * a.slopeControl, h * b.slopeControl);
  } else if (const double ma = b.negativeEigenvalues > a.negativeEigenvalues ? a.nearestPositive : a.nearestNegative,
             mb = b.negativeEigenvalues > a.negativeEigenvalues ? b.nearestNegative : b.nearestPositive;
             n >= 2 && (lowest_ || branchSwitch_) && std::isfinite(ma) && std::isfinite(mb) && ma * mb < 0) {
    // With k negative eigenvalues at a and k + 1 at b, the (k+1)-th smallest crosses zero: at a it is the
    // smallest positive one, at b the largest negative one (k + 1 -> k: the other way round). For k = 0
    // that is the lowest eigenvalue at both points; at a second bifurcation (1 -> 2) the lowest is
    // already negative at both and says nothing. Linear interpolation of it over the step. (A count
    // jumping by more than one: the nearest ones, exact for a multiple eigenvalue.)
    const double t = ma / (ma - mb);
    c.loadFactor = a.loadFactor + t * (b.loadFactor - a.loadFactor);
    c.controlValue = a.controlValue + t * (b.controlValue - a.controlValue);
    c.interpolated = true;
  } else {
    c.loadFactor = 0.5 * (a.loadFactor + b.loadFactor);
    c.controlValue = 0.5 * (a.controlValue + b.controlValue);
  }
  critical_.push_back(c);
}

}  // namespace sinew
