// ContinuationAnalysis on the levels of a -target_error study (docs/accuracy.md, "The coarser level's steps as
// the plan of the finer path"): the step that crosses the path's stop is repeated onto the stop exactly.
#include <algorithm>
#include <cmath>

#include "analysis/continuation_analysis.hpp"

namespace sinew {

PetscErrorCode ContinuationAnalysis::landOnStop(Vec U, double* lambda, Vec U0, double lambda0, Vec dUprev, double dlPrev,
                                                int* its) {
  PetscFunctionBeginUser;
  // the stops the step crossed, each at the fraction t of the step (linear in its stop variable); the first
  StopLanding on = StopLanding::None;
  double first = 2, increment = 0;  // the landing step's control: u_control - u_control(U0), or lambda - lambda0
  if (haveControl_ && opt_.stop_displacement) {
    const double stop = *opt_.stop_displacement;
    double v = 0, v0 = 0;
    PetscCall(controlDisplacement(U, *lambda, &v));
    PetscCall(controlDisplacement(U0, lambda0, &v0));
    if (std::abs(v) >= std::abs(stop) && std::abs(v0) < std::abs(stop)) {
      on = StopLanding::Displacement, increment = stop - v0;
      first = v != v0 ? std::clamp((stop - v0) / (v - v0), 0.0, 1.0) : 0.0;
    }
  }
  if (opt_.stop_load_factor) {
    const double stop = *opt_.stop_load_factor;
    const double t = (stop - lambda0) / (*lambda - lambda0);  // lambda0 < stop <= *lambda: t in (0, 1]
    if (*lambda >= stop && lambda0 < stop && t < first) on = StopLanding::LoadFactor, increment = stop - lambda0, landingLambda_ = stop;
  }
  if (on == StopLanding::None) PetscFunctionReturn(PETSC_SUCCESS);
  Vec Ukeep;
  PetscCall(VecDuplicate(U, &Ukeep));
  PetscCall(VecCopy(U, Ukeep));
  const double lambdaKeep = *lambda;
  PetscCall(VecCopy(U0, U));
  *lambda = lambda0;
  bool ok = false;
  int landingIts = 0;
  landing_ = on;
  PetscCall(step(U, lambda, increment, dUprev, dlPrev, false, &ok, &landingIts));
  landing_ = StopLanding::None;
  *its += landingIts;
  if (ok) {  // the step's arc length in the constraint's metric (the limit point locator's parameter)
    const double w = opt_.constraint == "spherical" ? opt_.psi * opt_.psi * lastQnorm_ * lastQnorm_ : 0.0;
    PetscCall(VecWAXPY(work_, -1.0, U0, U));
    PetscReal n2;
    PetscCall(VecDot(work_, work_, &n2));
    landedDs_ = std::sqrt(n2 + w * (*lambda - lambda0) * (*lambda - lambda0));
  } else {
    PetscCall(VecCopy(Ukeep, U));
    *lambda = lambdaKeep;
  }
  PetscCall(VecDestroy(&Ukeep));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
