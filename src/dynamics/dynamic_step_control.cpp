// Optional time-step control of the Arnold-Brüls loop (opt.dynamics.adaptive, -dynamics_adapt):
// the settings and their checks, the local error estimate and the adaptive time loop
// (docs/dynamics.md, "Time-step control").
#include "dynamics/dynamic_analysis.hpp"
#include "parallel/collective_error.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sinew {

DynamicAnalysis::StepControlSettings DynamicAnalysis::stepControl(const DynamicsOptions& opts,
                                                                  const DynamicsSettings& settings, Scheme scheme) {
  // time-step control: opt.dynamics.adaptive, each field overridden by its flag
  const AdaptiveStepOptions& ad = opts.adaptive;
  StepControlSettings r;
  const std::string& control = ad.control;
  r.control = settings.adapt ? *settings.adapt
              : control == "newton" ? StepControl::Newton
              : control == "error"  ? StepControl::Error
                                    : StepControl::None;
  r.dtMin = settings.dtMin.value_or(ad.dt_min > 0 ? ad.dt_min : 1e-4 * opts.dt);
  r.dtMax = settings.dtMax.value_or(ad.dt_max > 0 ? ad.dt_max : opts.dt * opts.output_every);
  r.tol = settings.adaptTol.value_or(ad.tolerance);
  r.its = settings.adaptIts.value_or(ad.target_iterations);
  if (r.control != StepControl::None && r.dtMin > r.dtMax) {
    std::ostringstream msg;
    msg << "the smallest adaptive step " << r.dtMin << " exceeds the largest (dt_max " << r.dtMax << ")";
    throw SceneError("-dynamics_dt_min", msg.str());
  }
  if (r.control != StepControl::None && scheme == Scheme::TSAlpha2)
    throw SceneError("-dynamics_adapt", "adaptive steps are Sinew's Arnold-Brüls loop; -dynamics_scheme tsalpha2 takes a fixed dt");
  if (r.control != StepControl::None && scheme == Scheme::Midpoint)
    throw SceneError("-dynamics_adapt", "adaptive steps are Sinew's Arnold-Brüls loop (its error estimate and step "
                                        "restart); -dynamics_scheme midpoint takes a fixed dt");
  if (r.control != StepControl::None && scheme == Scheme::EnergyMomentum)
    throw SceneError("-dynamics_adapt", "adaptive steps are Sinew's Arnold-Brüls loop (its error estimate and step "
                                        "restart); -dynamics_scheme energy_momentum takes a fixed dt");
  return r;
}

void DynamicAnalysis::checkStepControl(const DistributedMesh& mesh, const DynamicsOptions& opts,
                                       const DynamicsSettings& settings) {
  stepControl(opts, settings, checkScheme(mesh, settings.scheme));
}

// The local error of q_{n+1} (GeneralizedAlphaScheme::localError: h^2 |beta - 1/6| ||a_{n+1} - a_n||,
// algorithmic accelerations; spatial angular accelerations for rotations; multipliers masked) is
// compared with tolerance times the largest displacement of the unknowns (inf-norm over translations,
// rotation increments, ANCF coordinates: mixed units, meant for models whose rotations and
// displacements/size are of one order).
PetscErrorCode DynamicAnalysis::errorRatio(Vec U, double* eta, double* scale) {
  PetscFunctionBeginUser;
  double err = 0;
  PetscCall(alphaScheme_->localError(F_, &err));  // F_ is free here: the residual of the solve is not needed
  PetscReal u = 0;
  if (keep_) {  // the displacement scale without the multipliers
    PetscCall(VecPointwiseMult(F_, keep_, U));
    PetscCall(VecNorm(F_, NORM_INFINITY, &u));
  } else {
    PetscCall(VecNorm(U, NORM_INFINITY, &u));
  }
  // the largest displacement so far (not the current one: it passes 0 twice per oscillation), and at
  // least 1e-3 of the model size (at rest under a load that rises from 0 the error and the motion of
  // the first step are of the same order at any h: relative to |U| alone the step would go to dt_min)
  *scale = std::max({static_cast<double>(u), adaptScale_, 1e-3 * coordMax_});
  *eta = err > 0 ? err / (adaptTol_ * *scale) : 0.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Adaptive steps: output rows stay at k dt (k a multiple of output_every, and tend); the steps
// between them are chosen by the controller and land on each row time exactly (the remaining
// interval is split into equal steps no longer than the proposed h), so rows need no interpolation.
PetscErrorCode DynamicAnalysis::runAdaptive(const StepCallback& onStep, bool* converged) {
  PetscFunctionBeginUser;
  const double dt = opts_.dt, tend = opts_.tend;
  const int nsteps = std::max(1, static_cast<int>(std::ceil(tend / dt - 1e-9)));
  const int every = opts_.output_every;
  double t = resumed_ ? progress_.time : 0.0;
  report_.acceptedSteps = resumed_ ? progress_.successes : 0;
  adaptScale_ = resumed_ ? progress_.scale : 0.0;
  *converged = true;
  modifiedDefault_ = modifiedNewton_;
  Vec U;
  PetscCall(SNESGetSolution(snes_, &U));
  // a failed step: as with a fixed dt, full Newton from q_n at the same step, then halving down to dt_min
  StepRules rules;
  rules.maxCuts = -1;
  rules.minStep = dtMin_;
  rules.landing = Landing::EqualSplit;
  // proposed change of the step: newton aims at adaptIts_ iterations, error at eta = 1 (safety 0.9,
  // local error ~ h^3); within [0.2, 2] per step, and no growth below 1.2 (keeps a factored Jacobian);
  // error: a step with eta > 1 is rejected and repeated from q_n with the smaller step
  double stepScale = adaptScale_;  // errorRatio's displacement scale of the step
  rules.strategy = [&](double h, double proposal, const StepAttempt& a, double* next, bool* reject) -> PetscErrorCode {
    double factor = 1.0, eta = 0.0;
    stepScale = adaptScale_;
    if (control_ == StepControl::Newton) {
      factor = std::sqrt(static_cast<double>(adaptIts_) / std::max(a.iterations, 1));
    } else {
      PetscCall(errorRatio(U, &eta, &stepScale));
      factor = eta > 0 ? 0.9 * std::cbrt(1.0 / eta) : 2.0;
    }
    factor = std::clamp(factor, 0.2, 2.0);
    if (factor >= 1.0 && factor < 1.2) factor = 1.0;
    *reject = control_ == StepControl::Error && eta > 1.0 && h > dtMin_ * (1 + 1e-9);
    if (*reject) {
      *next = std::max(h * std::min(factor, 0.9), dtMin_);
      ++report_.rejectedSteps;
      return PETSC_SUCCESS;
    }
    *next = h * factor;
    if (h < proposal && factor >= 1.0) *next = std::max(*next, proposal);  // a step shortened to land on a row time
    *next = std::clamp(*next, dtMin_, dtMax_);
    return PETSC_SUCCESS;
  };
  StepController control(rules, {"output step", "time", "dt"});
  control.resume(std::clamp(resumed_ ? progress_.h : dt, dtMin_, dtMax_));
  SNESConvergedReason why = SNES_CONVERGED_ITERATING;
  double fnorm = 0;
  SteppedProcedure timeSteps = timeStep(false, &why, &fnorm);
  timeSteps.accept = [&](double, double t1, double h, const StepAttempt&) -> PetscErrorCode {
    PetscCall(stepScheme_->commit(U));
    setGuarded(false);
    adaptScale_ = stepScale;
    lastH_ = h;
    ++report_.acceptedSteps;
    report_.hMin = report_.hMin > 0 ? std::min(report_.hMin, h) : h;
    report_.hMax = std::max(report_.hMax, h);
    if (onSubstep_) PetscCall(onSubstep_(t1, stepScheme_->state().q, stepScheme_->state().qd));
    return PETSC_SUCCESS;
  };
  // output rows r at step krow(r) = min(nsteps, r every), time krow dt (tend at the last)
  auto krow = [&](int r) { return std::min(nsteps, r * every); };
  const int done = resumed_ ? progress_.step : 0;
  StepSequence rows;
  rows.last = (nsteps + every - 1) / every;
  rows.first = done >= nsteps ? rows.last + 1 : done / every + 1;
  rows.target = [&](int r) { return krow(r) == nsteps ? tend : krow(r) * dt; };
  rows.begin = [&](int) -> PetscErrorCode {
    setGuarded(false);
    return PETSC_SUCCESS;
  };
  rows.reached = [&](int& r, StepStop* stop) -> PetscErrorCode {
    const int k = krow(r);
    report_.reducedSteps += control.cuts();
    report_.steps = k;
    report_.time = t;
    progress_ = {k, t, control.carried(), report_.acceptedSteps, adaptScale_};
    const SchemeState s = stepScheme_->state();
    if (onStep) PetscCall(onStep(k, t, s.q, s.qd, s.qdd));
    if (stop_ && *stop_) *stop = StepStop::Interrupted;
    return PETSC_SUCCESS;
  };
  StepStop stop;
  PetscCall(control.run(timeSteps, rows, &t, &stop));
  if (stop == StepStop::BelowMinimum) {
    report_.reducedSteps += control.cuts();
    std::ostringstream msg;
    msg << "adaptive time steps: Newton did not converge at t = " << control.lastEnd() << " (" << SNESConvergedReasons[why]
        << ", residual norm " << fnorm << ") with the smallest step dt_min = " << dtMin_ << " (last converged time " << t
        << "). Try a smaller opt.dynamics.adaptive.dt_min, a line search (-snes_linesearch_type bt), or check "
           "supports and masses.";
    failure_ = msg.str();
    *converged = false;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
