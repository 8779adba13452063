// Load-stepped nonlinear statics: SNES (Newton, line search, MUMPS by default) on the
// assembler's residual; a failed increment is retried with halved increments, which grow
// back (x2) after quick convergence (-adaptive_increments, -increment_grow_its).
#pragma once
#include <petscsnes.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "analysis/statics_handover.hpp"
#include "assembly/assembler.hpp"
#include "settings/settings.hpp"
#include "solvers/ancf/cable_coarse_space.hpp"
#include "solvers/newton_test.hpp"

namespace sinew {

class StepController;

struct StepReport {
  int step = 0;            ///< 1-based requested load step
  double loadFactor = 0;
  int newtonIterations = 0;
  int increments = 0;      ///< SNES solves used (1 = no cut)
  double residualNorm = 0;
  /// Newton converged on its update (rule 4 of the convergence test): the residual is at the
  /// round-off noise of the stored positions, which can exceed the load itself (fine ANCF cables)
  bool convergedOnUpdate = false;
  double relativeUpdate = 0;  ///< ||dU|| / ||U|| of the last Newton update of the step
};

/// Where a load-stepped run stands after a converged step (checkpoints, -restart).
struct StaticsProgress {
  int step = 0;              ///< load steps done
  double lambda = 0;         ///< load factor reached
  double dlPrev = 0;         ///< last converged increment (secant predictor)
  double dlAdapt = 0;        ///< adaptive increment carried to the next step
  double fintConverged = 0;  ///< ||f_int|| of the last converged state
};

class StaticAnalysis {
 public:
  /// options prefix "" -> -snes_*, -ksp_*, -pc_* act on this solver. `settings`: the Newton and load
  /// stepping settings, `ancf`: the solver of fine ANCF cables.
  StaticAnalysis(Assembler& assembler, int loadsteps, const StaticsSettings& settings, const AncfSettings& ancf);
  ~StaticAnalysis();
  /// Solves the load steps from U (in: start state, out: last converged state): SPACAR Light's
  /// steps by default (step 1 = initial loads and prescribed motions alone, load factor 0; step k
  /// at (k-1)/(loadsteps-1)), Sinew's uniform ramp k/loadsteps after setUniformRamp(true) (see
  /// stepFactor). onStep runs after each converged step. Sets converged and, when it fails,
  /// failureMessage (step, residual, what to try).
  using StepCallback = std::function<PetscErrorCode(const StepReport&, Vec U)>;
  PetscErrorCode run(Vec U, const StepCallback& onStep, bool* converged);
  /// Steps run() goes to (default loadsteps): the load factor of step k stays stepFactor(k), so a
  /// larger last step continues the ramp beyond load factor 1 with the same increment.
  void setLastStep(int last) { lastStep_ = last; }
  /// Continues after step p.step (a checkpoint; U, the reference rotations and the element states
  /// restored by the caller): dU is the last converged increment (copied).
  PetscErrorCode resume(const StaticsProgress& p, Vec dU);
  /// State after the last converged step (valid inside the step callback).
  const StaticsProgress& progress() const { return progress_; }
  /// Last converged increment (nullptr before run()).
  Vec lastIncrement() const { return dU_; }
  const std::vector<StepReport>& reports() const { return reports_; }
  const std::string& failureMessage() const { return failure_; }
  /// True when the last failed increment ended with SNES_DIVERGED_LINEAR_SOLVE on a finite tangent
  /// (a singular one; a tangent with Inf/NaN entries is no model error).
  bool linearSolveFailed() const { return linearFailed_; }
  /// The model has no external load at all: a start residual at the round-off floor
  /// (8 eps ||J||_inf max|X|) is equilibrium without a Newton step (a free-free body has a singular J).
  void setUnloaded(bool u) { unloaded_ = u; }
  /// The loop ends after the step whose onStep set *stop (an interrupt or a failed result file);
  /// the run is then neither converged nor failed here: the caller knows why it stopped.
  void setStopFlag(const bool* stop) { stop_ = stop; }
  /// opt.load_ramp uniform: step k at load factor k/loadsteps (Sinew's former steps).
  void setUniformRamp(bool u) { uniform_ = u; }
  /// Nothing acts at load factor 0 (no initial loads or motions): SPACAR Light's step 1 is the start
  /// state, reported without a solve.
  void setStartIsInitialState(bool s) { startIsInitial_ = s; }
  /// The time the kernels see (ANCF force laws of t): the load factor (default, as before), or
  /// t = 0 at every load step when a time integration continues from the last one (opt.dynamics
  /// start: static), so that its start at t = 0 is the equilibrium found here.
  void setTimeZero(bool z) { timeZero_ = z; }
  /// A -target_error level (analysis/statics_handover.hpp): every accepted increment's state is
  /// recorded in h->record, and an increment that ends at the load factor of one of h->guesses starts
  /// Newton from that state (instead of the last converged state or the predictor); if that Newton
  /// fails, the increment is retried from the last converged state. nullptr: neither.
  void setHandover(StaticsHandover* h) { handover_ = h; }
  /// Load factor of 1-based load step k (SPACAR Light: 0 at step 1, 1 at the last step).
  double stepFactor(int step) const;

  SNES snes() const { return snes_; }
  /// The cable coarse space in use (nullptr when none).
  const CableCoarseSpace* coarseSpace() const { return coarse_.get(); }

 private:
  static PetscErrorCode formFunction(SNES, Vec U, Vec F, void* ctx);
  static PetscErrorCode formJacobian(SNES, Vec U, Mat J, Mat P, void* ctx);
  static PetscErrorCode convergenceTest(SNES, PetscInt it, PetscReal xnorm, PetscReal snorm, PetscReal fnorm,
                                        SNESConvergedReason* reason, void* ctx);
  NewtonRules newtonRules() const;
  PetscErrorCode loadChange(Vec U, double* change);
  PetscErrorCode solveIncrement(Vec U, double lambda, bool* ok, int* its, double* fnorm, SNESConvergedReason* why);
  /// Appends the converged node states (current evaluation, every rank's owned nodes) to the record.
  PetscErrorCode recordState(double lambda);
  /// U <- the guess at load factor lambda on the free DOFs (rotations relative to the reference
  /// rotations); *used: a guess was found (the same on every rank).
  PetscErrorCode startFromGuess(Vec U, double lambda, bool* used);
  /// The load steps after form finding (StaticsHandover::fromStart): U holds the guess; keeps it when its
  /// residual (at ls_) is below that of the extrapolation Ulast + s dU, else U <- Ulast, *guessed = false.
  PetscErrorCode nearerStart(Vec U, Vec Ulast, Vec dU, double s, bool* guessed);
  PetscErrorCode fail(const StepController& control, double lambda, SNESConvergedReason why, double fnorm, bool* converged);

  static PetscErrorCode tangentMult(Mat A, Vec x, Vec y);
  PetscErrorCode setUpElementwiseOperator(OperatorChoice choice, const AncfSettings& ancf);

  Assembler& asm_;
  const bool* stop_ = nullptr;
  int loadsteps_;
  int lastStep_;
  StaticsProgress progress_;
  bool resumed_ = false;
  Vec dU_ = nullptr;  ///< last converged increment (secant predictor)
  bool uniform_ = false;
  bool startIsInitial_ = false;
  bool timeZero_ = false;
  double timeAt(double lambda) const { return timeZero_ ? 0.0 : lambda; }
  SNES snes_ = nullptr;
  Mat J_ = nullptr;
  Mat Jop_ = nullptr;  ///< element-wise tangent operator (MATSHELL) when -tangent_operator elementwise
  std::unique_ptr<CableCoarseSpace> coarse_;  ///< two-level preconditioner of fine ANCF cables
  bool coarsePredictor_ = true;  ///< -ancf_coarse_predictor: nonlinear coarse solve before each increment
  Vec F_ = nullptr;
  LoadState ls_;
  LoadState equilibrium_;   ///< loads of the last converged state (nothing applied before the first)
  Vec Fwork_ = nullptr;     ///< residual at equilibrium_ (loadChange)
  double forceRtol_ = 1e-11;
  static PetscErrorCode tangentNorms(Mat P, PetscReal* inf, PetscReal* frobenius);
  double jacobianNorm_ = 0;  ///< ||J||_inf at the start of the increment (round-off floor of the residual)
  NewtonTest newtonTest_;  ///< the Newton test with the statics rules (newtonRules(), set by run())
  double fintConverged_ = 0;          ///< ||f_int|| at the last converged state
  bool unloaded_ = false;
  double coordMax_ = 0;      ///< largest |node coordinate| (positions carry round-off eps * coordMax_)
  int maxCuts_ = 10;
  bool predictor_ = true;  ///< secant predictor from the last converged increment
  bool adaptive_ = true;   ///< -adaptive_increments: halved increments grow back (x2) after quick convergence
  int growIts_ = 5;        ///< -increment_grow_its: "quick" = at most this many Newton iterations
  int divergedIts_ = 0;    ///< -newton_diverged_its: an increment still above its start residual after this many
                           ///< iterations fails (0: off; default 6 for beams under the mixed-stress Newton)
  StaticsHandover* handover_ = nullptr;
  std::vector<StepReport> reports_;
  std::string failure_;
  bool linearFailed_ = false;
  bool tangentFinite_ = true;  ///< the last assembled tangent's Frobenius norm is finite
};

}  // namespace sinew
