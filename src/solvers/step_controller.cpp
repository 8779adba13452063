#include "solvers/step_controller.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sinew {

namespace {

std::string formatted(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace

#define SINEW_STEP_CALL(expr)     \
  do {                            \
    const int ierr_ = (expr);     \
    if (ierr_ != 0) return ierr_; \
  } while (0)

double IterationTarget::grown(double size, int its) const {
  size *= std::clamp(std::sqrt(static_cast<double>(desired_) / std::max(its, 1)), lo_, hi_);
  if (max_ > 0) size = std::copysign(std::min(std::abs(size), max_), size);
  return size;
}

int IterationTarget::operator()(double, double proposal, const StepAttempt& a, double* next, bool* reject) const {
  *next = grown(proposal, a.iterations);
  *reject = false;
  return 0;
}

int StepController::run(const SteppedProcedure& p, const StepSequence& s, double* x, StepStop* stop) {
  *stop = StepStop::None;
  for (int k = s.first; k <= s.last; ++k) {
    step_ = k;
    cuts_ = 0;
    if (s.begin) SINEW_STEP_CALL(s.begin(k));
    if (s.target) {
      const double target = s.target(k);
      SINEW_STEP_CALL(advance(p, x, &target, s.solveAtTarget && s.solveAtTarget(k), stop));
    } else {
      SINEW_STEP_CALL(advance(p, x, nullptr, false, stop));
    }
    if (*stop != StepStop::None) return 0;
    if (s.reached) SINEW_STEP_CALL(s.reached(k, stop));
    if (*stop != StepStop::None) return 0;
  }
  *stop = s.target ? StepStop::EndReached : StepStop::MaxSteps;
  return 0;
}

int StepController::advance(const SteppedProcedure& p, double* x, const double* target, bool once, StepStop* stop) {
  double dl = carried_;  // the proposed size of the next step
  if (target) {
    switch (rules_.firstSize) {
      case FirstSize::Carried: break;
      case FirstSize::CarriedWithinRest: dl = std::min(carried_, *target - *x); break;
      case FirstSize::Rest: dl = *target - *x; break;
      case FirstSize::Max: dl = rules_.maxStep; break;
    }
  }
  while (!target || *x < *target || once) {
    once = false;
    double to = 0, h = 0;
    land(*x, dl, target, &to, &h);
    lastSize_ = h;
    lastEnd_ = to;
    StepAttempt a;
    SINEW_STEP_CALL(p.solve(*x, to, h, &a));
    last_ = a;
    if (a.converged) {
      double next = dl;
      bool reject = false;
      if (h != 0) SINEW_STEP_CALL(grown(dl, h, a, &next, &reject));  // a step of size 0 adapts nothing
      dl = next;
      if (reject) continue;
      if (p.accept) SINEW_STEP_CALL(p.accept(*x, to, h, a));
      *x = to;
      if (h != 0) carried_ = dl;
      if (!target) return 0;
      continue;
    }
    successes_ = 0;
    if (p.retry) {  // the same step another way first
      bool again = false;
      std::string how;
      SINEW_STEP_CALL(p.retry(a, &again, &how));
      if (again) {
        if (!how.empty()) message(p, a, how);
        continue;
      }
    }
    if (h == 0 || (rules_.maxCuts >= 0 && cuts_ >= rules_.maxCuts)) {
      *stop = StepStop::CutLimit;
      return 0;
    }
    if (rules_.minStep > 0 && std::abs(h) <= rules_.minStep * (1 + 1e-9)) {
      *stop = StepStop::BelowMinimum;
      return 0;
    }
    ++cuts_;
    dl = rules_.cutFactor * (rules_.cutProposal ? dl : h);
    if (rules_.minStep > 0) dl = std::max(dl, rules_.minStep);
    message(p, a, names_.size + " " + formatted("%.3g", dl));
  }
  return 0;
}

void StepController::land(double x, double dl, const double* target, double* to, double* h) const {
  if (!target) {
    *to = x + dl;
    *h = dl;
    return;
  }
  const double end = *target;
  switch (rules_.landing) {
    case Landing::Absolute:
      *to = end - (x + dl) < rules_.landingSlack ? end : x + dl;
      *h = *to - x;
      break;
    case Landing::Relative:
      *h = end - x - dl <= rules_.landingSlack * dl ? end - x : dl;
      *to = *h == end - x ? end : x + *h;
      break;
    case Landing::EqualSplit: {
      const double rest = end - x;
      const int n = std::max(1, static_cast<int>(std::ceil(rest / dl - 1e-6)));
      *h = rest / n;
      *to = n == 1 ? end : x + *h;
      break;
    }
    case Landing::Clamp:
      *to = std::min(end, x + dl);
      *h = *to - x;
      break;
  }
}

int StepController::grown(double dl, double h, const StepAttempt& a, double* next, bool* reject) {
  *next = dl;
  *reject = false;
  if (rules_.strategy) return rules_.strategy(h, dl, a, next, reject);
  if (rules_.growIts >= 0 && a.iterations <= rules_.growIts) *next = std::min(rules_.growFactor * dl, rules_.maxStep);
  if (rules_.growAfter > 0 && dl < rules_.maxStep && ++successes_ >= rules_.growAfter) {
    *next = std::min(rules_.growFactor * dl, rules_.maxStep);
    successes_ = 0;
  }
  return 0;
}

void StepController::message(const SteppedProcedure& p, const StepAttempt& a, const std::string& retrying) const {
  if (!p.print) return;
  const double at = std::isnan(a.at) ? lastEnd_ : a.at;
  p.print("  " + names_.label + " " + std::to_string(step_) + ": Newton failed at " + names_.quantity + " " +
          formatted("%.6g", at) + " (" + a.reason + "); retrying with " + retrying + "\n");
}

}  // namespace sinew
