// The one step loop of Sinew's procedures (statics, path following, form finding, dynamics). The
// controller owns the step sequence: it proposes the size of the next step, lets the procedure
// solve it, then accepts it (the procedure commits the state and the position advances), cuts it
// (after a failure: smaller size, a limited number of times, the one retry message) or grows the
// size (after an easy step, within bounds), and says why it stopped. A procedure supplies only its
// step: what a step of size h from position x means, how it is solved and how a failure rolls back.
//
// Positions and sizes are numbers in the procedure's own unit: a load factor (statics), an arc
// length (path following), a form-finding step (form finding), a time (dynamics). The sequence is
// made of report steps k = first..last; report step k either reaches a target position (load step,
// time step: possibly in several steps) or is one converged step (path point, form-finding step).
// Plain C++ (no PETSc): callbacks return an error code, 0 for success, passed on at once.
#pragma once
#include <functional>
#include <limits>
#include <string>

namespace sinew {

/// What one attempt of a step did; the procedure's solve fills it.
struct StepAttempt {
  bool converged = false;
  int iterations = 0;  ///< Newton iterations of the attempt
  std::string reason;  ///< why it failed (SNES's reason name), for the retry message
  double at = std::numeric_limits<double>::quiet_NaN();  ///< the value the retry message names (NaN: the step's end)
};

/// Why the controller stopped.
enum class StepStop {
  None,           ///< still running
  EndReached,     ///< the last report step's target reached
  StopCondition,  ///< the procedure's stop condition met
  MaxSteps,       ///< report steps without a target used up (path points, form-finding steps)
  CutLimit,       ///< a failed step that may not be cut again (max cuts, or a step of size 0)
  BelowMinimum,   ///< a failed step at the smallest size
  Interrupted,    ///< the batch stop flag (SIGTERM)
};

/// What a step is, for the one retry message
///   "  <label> <k>: Newton failed at <quantity> <value> (<reason>); retrying with <size> <h>".
struct StepNames {
  std::string label;     ///< "load step", "path step", "time step"
  std::string quantity;  ///< the position named: "load factor", "time"
  std::string size;      ///< the step size named: "increment", "arc length", "dt"
};

/// Where a step ends near the target: on it exactly, without overshoot and without a sliver left.
enum class Landing {
  Absolute,    ///< on the target when less than `landingSlack` (a size) would remain (statics)
  Relative,    ///< on the target when at most landingSlack * h would remain (dynamics, fixed dt)
  EqualSplit,  ///< the rest split into equal steps no longer than h (dynamics, adaptive dt)
  Clamp,       ///< at min(target, x + h) (the start state under the initial loads)
};

/// The size of a target's first step.
enum class FirstSize {
  Carried,            ///< the size carried over from the last target
  CarriedWithinRest,  ///< the carried size, at most the rest to the target (statics, adaptive increments)
  Rest,               ///< the rest to the target (statics, fixed increments)
  Max,                ///< maxStep (dynamics with -dt_grow_after 0)
};

/// A step-size policy beyond cut-and-grow (aim at a number of Newton iterations, an error estimate):
/// after the converged step of size h, with proposal `proposal`, sets *next, the next proposal, and
/// *reject: the step is refused and repeated from its start with size *next.
using StepSizeStrategy = std::function<int(double h, double proposal, const StepAttempt& a, double* next, bool* reject)>;

/// Aim at `desired` Newton iterations per step: size *= clamp(sqrt(desired / its), lo, hi), then
/// |size| <= maxSize (when > 0). Path following's arc length.
class IterationTarget {
 public:
  IterationTarget(int desired, double lo, double hi, double maxSize) : desired_(desired), lo_(lo), hi_(hi), max_(maxSize) {}
  double grown(double size, int its) const;
  /// As a StepSizeStrategy: the proposal grown by the attempt's iterations, never a rejection.
  int operator()(double h, double proposal, const StepAttempt& a, double* next, bool* reject) const;

 private:
  int desired_;
  double lo_, hi_, max_;
};

/// The step-size rules of a procedure. As used: statics halves a failed increment (at most -max_cuts
/// times per load step), doubles it after at most -increment_grow_its iterations up to the user's
/// load step, carries it within the rest of the next load step and leaves no sliver; dynamics with a
/// fixed dt retries guarded, halves (-max_cuts) and doubles after -dt_grow_after successes up to dt;
/// adaptive dynamics retries guarded, halves down to dt_min and sizes by its error or iteration
/// strategy, rows split into equal steps; path following halves (-max_cuts) and aims at a number of
/// corrector iterations (IterationTarget); form finding never cuts (a failed step ends it).
struct StepRules {
  // cut: a failed step is retried cutFactor times smaller
  double cutFactor = 0.5;
  int maxCuts = 10;          ///< cuts per report step; one more failure stops (< 0: no limit)
  double minStep = 0;        ///< > 0: a failed step of this size is not cut, and no cut goes below it
  bool cutProposal = false;  ///< cut the proposed size, not the step taken (shortened when landing)
  // grow: after an easy step, growFactor times larger, never above maxStep
  int growIts = -1;          ///< after a step of at most this many Newton iterations (< 0: off)
  int growAfter = 0;         ///< after this many converged steps in a row below maxStep (0: off)
  double growFactor = 2.0;
  double maxStep = std::numeric_limits<double>::infinity();
  StepSizeStrategy strategy;  ///< replaces growIts/growAfter when set
  // targets
  Landing landing = Landing::Absolute;
  double landingSlack = 0;
  FirstSize firstSize = FirstSize::Carried;
};

/// The procedure's step.
struct SteppedProcedure {
  /// Attempts the step x -> to of size h; on failure the procedure restores the state at x.
  std::function<int(double x, double to, double h, StepAttempt*)> solve;
  /// Takes the converged step x -> to (optional).
  std::function<int(double x, double to, double h, const StepAttempt&)> accept;
  /// After a failure, before any cut: *retry to repeat the same step another way; *how names it for
  /// the retry message (empty: silent). Optional.
  std::function<int(const StepAttempt&, bool* retry, std::string* how)> retry;
  /// Prints a retry message (optional: silent).
  std::function<void(const std::string&)> print;
};

/// The report steps first..last.
struct StepSequence {
  int first = 1, last = 1;
  /// Report step k begins (optional).
  std::function<int(int k)> begin;
  /// The target of report step k; empty: a report step is one converged step.
  std::function<double(int k)> target;
  /// Whether report step k is solved (as a step of size 0) although its target is reached already
  /// (statics' step 1: the initial loads alone). Optional.
  std::function<bool(int k)> solveAtTarget;
  /// Report step k done: report it; set *stop to end the sequence (StopCondition, Interrupted). A
  /// procedure that made report steps of its own (a branch switch) advances k past them.
  std::function<int(int& k, StepStop* stop)> reached;
};

class StepController {
 public:
  StepController(const StepRules& rules, const StepNames& names) : rules_(rules), names_(names) {}
  /// The size carried into the next target and the converged steps in a row (a resumed run: from its checkpoint).
  void resume(double size, int successes = 0) {
    carried_ = size;
    successes_ = successes;
  }
  /// Runs the sequence from position *x; *stop says why it ended.
  int run(const SteppedProcedure& p, const StepSequence& s, double* x, StepStop* stop);

  double carried() const { return carried_; }        ///< size carried to the next target
  int successes() const { return successes_; }       ///< converged steps in a row (growAfter)
  int cuts() const { return cuts_; }                  ///< cuts in the current report step
  int step() const { return step_; }                  ///< the current report step
  double lastSize() const { return lastSize_; }      ///< size of the last step attempted
  double lastEnd() const { return lastEnd_; }        ///< end of the last step attempted
  const StepAttempt& lastAttempt() const { return last_; }

 private:
  /// Reaches the target from *x (one converged step when there is none).
  int advance(const SteppedProcedure& p, double* x, const double* target, bool once, StepStop* stop);
  /// The end and size of the next step from x with proposal dl.
  void land(double x, double dl, const double* target, double* to, double* h) const;
  /// The next proposal after a converged step of size h; *reject: repeat it.
  int grown(double dl, double h, const StepAttempt& a, double* next, bool* reject);
  void message(const SteppedProcedure& p, const StepAttempt& a, const std::string& retrying) const;

  StepRules rules_;
  StepNames names_;
  double carried_ = std::numeric_limits<double>::infinity();
  int successes_ = 0, cuts_ = 0, step_ = 0;
  double lastSize_ = 0, lastEnd_ = 0;
  StepAttempt last_;
};

}  // namespace sinew
