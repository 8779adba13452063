// Path following's load vector q = -dR/dlambda (continuation_analysis.hpp): the predictor's tangent,
// the arc-length constraint's load term and the path slopes.
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "analysis/continuation_analysis.hpp"
#include "solvers/newton_test.hpp"

namespace sinew {

// q = (R(lambda - h) - R(lambda + h)) / 2h, a central difference: exact (to round-off) for loads,
// gravity and pressure that scale with the load factor, second order for prescribed motions.
// The difference carries the residual's round-off, eps times its force scale (forceScale of the two
// evaluations: initial loads, internal forces): a path load below it vanishes from the difference (a
// 1e-12 N force beside a 20 N initial load on the same node: 20 + 1e-4 x 1e-12 = 20 exactly, q = 0).
// Then h grows until the difference stands kResolved times above that round-off (q to about 1e-6);
// loads are linear in the load factor, so any h is exact for them. A difference resolved at the first
// h (every path with loads above the round-off) is the plain central difference.
PetscErrorCode ContinuationAnalysis::loadDerivative(Vec U, double lambda, Vec q) {
  PetscFunctionBeginUser;
  constexpr double kResolved = 1e6;
  constexpr int kMaxGrowths = 6;
  double h = 1e-4 * std::max(1.0, std::abs(lambda));
  for (int growth = 0;; ++growth) {
    LoadState ls;
    ls.loadFactor = ls.time = lambda + h;
    PetscCall(asm_.residual(U, ls, work_));
    double scale = forceScale(asm_.externalForceNorm(), asm_.internalForceNorm());
    ls.loadFactor = ls.time = lambda - h;
    PetscCall(asm_.residual(U, ls, q));
    scale = std::max(scale, forceScale(asm_.externalForceNorm(), asm_.internalForceNorm()));
    PetscCall(VecAXPY(q, -1.0, work_));
    PetscReal d;
    PetscCall(VecNorm(q, NORM_2, &d));
    const double noise = DBL_EPSILON * scale;
    if (d > kResolved * noise || growth == kMaxGrowths) break;
    // the difference grows with h (loads are linear in it): aim 100 times above the bound
    h *= std::clamp(d > 0 ? 100.0 * kResolved * noise / d : 1e8, 10.0, 1e8);
  }
  PetscCall(VecScale(q, 0.5 / h));  // q = (R(-h) - R(+h)) / 2h = -dR/dlambda
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
