// The one Newton convergence test of Sinew's procedures (statics, path following, form finding,
// dynamics, the cable coarse predictor). Each procedure states which of the rules below fit its
// residual (NewtonRules) and supplies, per iteration, the norms SNES passes to a convergence test
// plus the scale of the forces being balanced and the residual's round-off floor (NewtonIterate).
//
// The rules, with r = ||F|| at iteration k, s = ||dU|| the Newton update, x = ||U||:
//   force     r <= forceRtol * scale                     (the residual at the round-off level of the forces)
//   start     r <= startRtol * r_start                   (relative to the increment's start residual)
//   below-floor  r <= floor (from forceFromIteration on)
//   start-at-floor  k = 0 and r <= startFloorFactor * floor, the loads unchanged since the start state's
//             equilibrium (the start state is in equilibrium to round-off; a residual that is the load
//             increment itself is never converged without a Newton step, however small the load)
//   stalled   k > 0, r <= floor and below 1e-3 of r_0 (or r_0 itself at the floor), and the last
//             iteration no longer reduced r tenfold, dropped it 1000x, or came from just above the floor
//   dropped   k > 0, r <= floor and r <= 1e-3 r_0
//   update    (relative) k > 1, r <= updateFloorFactor * floor: s/x below `tight`, or below `loose`
//             and no longer shrinking tenfold (updateConverged);
//             (contraction) k >= 2, r <= floor, r <= 1.5 r_k-1: the iterate's error estimate
//             theta/(1-theta) s (theta = s_k / s_k-1) below updateRtol * x
//   at rest   k > 0, r <= floor and s <= 1e3 eps max|X| (a model at rest under loads still zero)
//   diverged  k >= divergedIts and r > r_0: the iteration wanders (the increment is cut)
//   final update  (midpoint) every verdict waits for s <= finalUpdateRtol max(x, max|X|); (energy-momentum)
//             or, at k >= 2, for r_k-1 <= floor and r_k <= floor (s_k was J^-1 of round-off)
//   NaN       a non-finite residual always diverges.
// The floor is 8 eps ||J||_inf max|X| (roundoffFloor): positions carry eps max|X|, so a stiffness
// entry k gives residual noise ~ k eps max|X| per row.
#pragma once
#include <petscsnes.h>

#include "sinew/petsc_compat.hpp"

#include <limits>

namespace sinew {

/// Newton has converged on its update: the relative update below `tight`, or below `loose` and no
/// longer shrinking tenfold (round-off has ended quadratic convergence).
inline bool updateConverged(double rel, double relPrev, double tight, double loose) {
  return rel <= tight || (rel <= loose && rel > 0.1 * relPrev);
}

/// The residual's round-off floor 8 eps ||J||_inf max|X|.
double roundoffFloor(double jacobianNorm, double coordMax);

/// The scale of the forces a residual is judged against: max(||f_ext||, ||f_int||), with ||f_int||
/// capped at `internalCap` (statics: 10 max(||f_ext||, ||f_int|| of the last converged state), so
/// that a diverging iterate, whose internal forces are huge, never looks converged).
double forceScale(double external, double internal, double internalCap = std::numeric_limits<double>::infinity());

/// Which rules a procedure's residual admits (see the file comment); zero / None switches a rule off.
struct NewtonRules {
  /// What SNES's default test (SNESConvergedDefault: -snes_atol, -snes_rtol, -snes_stol, max_it)
  /// decides: kept (Keep), kept except its update test (KeepButUpdate: an update below -snes_stol
  /// proves nothing by itself), or only its divergence and -snes_atol verdicts (Own: statics, whose
  /// -snes_rtol is relative to the increment's start residual, rule `start`).
  enum class Snes { Keep, KeepButUpdate, Own } snes = Snes::Keep;
  /// KeepButUpdate: SNES's update verdict stands when r <= this * scale (dynamics: 1e-6; <= 0: never).
  double snesUpdateForceRtol = 0;
  double forceRtol = 0;
  int forceFromIteration = 0;  ///< the force and below-floor rules apply from this iteration on
  bool belowFloor = false;     ///< rule below-floor: r <= floor (path following)
  bool startRelative = false;  ///< rule `start` with SNES's rtol (Snes::Own only)
  double startFloorFactor = 0; ///< rule start-at-floor: r_0 <= this * floor (0: off)
  bool stalledAtFloor = false;
  bool droppedBelowFloor = false;
  enum class Update { None, Relative, Contraction } update = Update::None;
  double updateTight = 1e-8, updateLoose = 1e-6;  ///< Relative
  double updateFloorFactor = 1;  ///< Relative: applies once r <= this * floor (0: at any residual)
  bool updateNeedsStartAtFloor = false;  ///< Relative: only when r_0 <= updateFloorFactor * floor too
  bool updateDividesLineSearch = false;  ///< Relative: s is the full Newton step (SNES line search's lambda divided out)
  double updateRtol = 1e-6;      ///< Contraction
  bool atRest = false;
  int divergedIts = 0;
  /// A verdict stands only when k > 0 and s <= this * max(x, max|X|) (the implicit midpoint rule:
  /// momentum is exact only for a solved step); 0: off.
  double finalUpdateRtol = 0;
  /// finalUpdateRtol also holds at k >= 2 when r_k-1 and r_k are both at their floor (the energy-momentum
  /// scheme): the update s_k was J^-1 of round-off already, and a further one only moves the iterate
  /// within that noise (the spin-up at 6 rad/s: updates 2.9e-3, 2.2e-7, 5.8e-12, 1.0e-15 m at residuals
  /// 1.5e-1, 3e-8, 1e-8, 1e-8 N against a floor of 2e-6 N).
  bool finalUpdateAtFloor = false;
};

/// One Newton iterate: SNES's convergence-test arguments, the force scale and the floor.
struct NewtonIterate {
  NewtonIterate() = default;
  /// The arguments of a SNES convergence test.
  NewtonIterate(PetscInt it_, PetscReal xnorm_, PetscReal snorm_, PetscReal fnorm_)
      : it(it_), xnorm(xnorm_), snorm(snorm_), fnorm(fnorm_) {}
  PetscInt it = 0;
  PetscReal xnorm = 0, snorm = 0, fnorm = 0;
  double scale = 0;   ///< forceScale of the iterate
  double floor = 0;   ///< roundoffFloor of the iterate's Jacobian
  double coordMax = 0;  ///< max |X| (rule at rest)
  /// k = 0: norm of the change of the loads and prescribed motions since the start state was in
  /// equilibrium (R(U, target) - R(U, start loads)); above round-off of the force scale the start
  /// residual is load, not noise, and rule start-at-floor does not hold. 0: unchanged or not known.
  double loadChange = 0;
};

/// The test with its history over one Newton solve (reset at iteration 0).
class NewtonTest {
 public:
  explicit NewtonTest(const NewtonRules& rules = {}) : rules_(rules) {}
  NewtonRules& rules() { return rules_; }
  const NewtonRules& rules() const { return rules_; }
  /// The increment's start residual (rule `start`): set before the solve.
  void setStartResidual(double r) { fnormStart_ = r; }

  /// Judges an iterate of `snes` (after SNESConvergedDefault): *reason as a SNES convergence test sets it.
  PetscErrorCode judge(SNES snes, const NewtonIterate& x, SNESConvergedReason* reason);
  /// Judges an iterate of a Newton loop written by hand (path following): the rules alone.
  SNESConvergedReason judge(const NewtonIterate& x);

  double startResidual() const { return fnorm0_; }       ///< r_0 of the current solve
  bool convergedOnUpdate() const { return onUpdate_; }   ///< the last solve ended on rule `update`
  double relativeUpdate() const { return relUpdate_; }   ///< s/x of the last update (Relative)
  double contraction() const { return theta_; }          ///< s_k / s_k-1 of the last two updates (0 before)

 private:
  void decide(const NewtonIterate& x, double atol, double rtol, double lambda, SNESConvergedReason* reason);
  NewtonRules rules_;
  double fnormStart_ = 0;
  double fnorm0_ = 0, fnormPrev_ = 0;
  double relUpdate_ = 0, relUpdatePrev_ = 0;
  double snormPrev_ = 0, theta_ = 0;
  bool onUpdate_ = false;
};

/// What a Newton solve ended with: SNES's reason, its iterations and the last residual norm.
struct NewtonOutcome {
  SNESConvergedReason reason = SNES_CONVERGED_ITERATING;
  int iterations = 0;
  double residualNorm = 0;
};

/// SNESSolve from U (the initial guess, overwritten by the solution) and its outcome.
PetscErrorCode solveNewton(SNES snes, Vec U, NewtonOutcome* outcome);

}  // namespace sinew
