// Implicit time integration of M qdd + f_int(q, qd, t) = f_ext(t) with one of the schemes of
// time_scheme.hpp (-dynamics_scheme), which own their parameters and state:
//   arnold_bruls: generalized alpha as Exudyn uses it (GeneralizedAlphaScheme, the default)
//   midpoint: the implicit midpoint rule, keeps linear and angular momentum exactly (MidpointScheme)
//   energy_momentum: keeps energy and momenta exactly, or lets the energy decay (EnergyMomentumScheme)
//   tsalpha2: PETSc's TSALPHA2, the Chung-Hulbert variant (TSAlpha2Scheme; docs/ancf_cable2d.md
//   compares it with the default)
// DynamicAnalysis orchestrates: the start (a_0 = qdd_0 from M qdd_0 = f_ext(0) - f_int(q_0, qd_0, 0)),
// the Newton solve of each step of the first two for q_{n+1} (one SNES solve; options without prefix:
// -snes_*, -ksp_*, -pc_*; modified Newton, the ANCF solver choices: dynamic_newton.cpp), damping, the
// step loop through the StepController (a failed step is retried with halved steps, -max_cuts;
// adaptive steps: dynamic_step_control.cpp) and the output rows.
// Beams (docs/dynamics.md): Frame6 rotation unknowns are spatial increments from R_n, absorbed into
// R_ref after every converged step (Lie-group form; V and A hold spatial angular velocities and
// accelerations); Lagrange multipliers of rigid modes are index-3 unknowns without rates.
#pragma once
#include <petscsnes.h>
#include <petscts.h>

#include <functional>
#include <memory>
#include <string>

#include "analysis/statics_handover.hpp"
#include "assembly/assembler.hpp"
#include "dynamics/damping.hpp"
#include "dynamics/energy_momentum_scheme.hpp"
#include "dynamics/generalized_alpha_scheme.hpp"
#include "dynamics/midpoint_scheme.hpp"
#include "dynamics/time_scheme.hpp"
#include "dynamics/tsalpha2_scheme.hpp"
#include "settings/settings.hpp"
#include "sinew/model.hpp"
#include "solvers/ancf/corotated_newton_matrix.hpp"
#include "solvers/newton_test.hpp"
#include "solvers/step_controller.hpp"

namespace sinew {

struct DynamicsReport {
  int steps = 0;             ///< time steps of size dt completed
  int reducedSteps = 0;      ///< steps that needed halved sub-steps
  int guardedSteps = 0;      ///< steps retried with full Newton from the last state (guarded)
  int substeps = 0;          ///< SNES solves (1 per step without cuts)
  int newtonIterations = 0;
  int jacobians = 0;         ///< Jacobians assembled and factored (modified Newton keeps one for many iterations)
  int corotatedJacobians = 0;  ///< of those, rebuilt from rotated kept element blocks (ANCF cables, no kernel)
  int refinements = 0;       ///< refinements per step solve at the end (-dynamics_refine)
  int refinedSolves = 0;     ///< step solves that were refined
  int coarseStarts = 0;      ///< step solves that started from the coarser level's record and converged (-target_error)
  double time = 0;           ///< last converged time
  // adaptive time steps (opt.dynamics.adaptive; 0 with a fixed dt)
  int acceptedSteps = 0;     ///< accepted steps (time steps taken) since t = 0
  int rejectedSteps = 0;     ///< steps rejected by the error estimate (solved, then repeated smaller)
  double hMin = 0, hMax = 0; ///< smallest and largest accepted step of this run
};

/// Where a time integration stands after a converged time step (checkpoints, -restart).
struct DynamicsProgress {
  int step = 0;        ///< time steps of size dt done
  double time = 0;     ///< time reached
  double h = 0;        ///< current sub-step size (halved after a failure, grows back; adaptive: the next step)
  int successes = 0;   ///< successful sub-steps in a row since the last change of h (adaptive: accepted steps)
  double scale = 0;    ///< adaptive steps (error): largest displacement |U|_inf so far (errorRatio)
};

class DynamicAnalysis : private MotionEquations {
 public:
  /// settings.dynamics: the flags of the time loop; settings.statics: the Newton settings shared with
  /// statics (-max_cuts, -force_rtol, -newton_mixed_stresses); settings.eigen: modal damping's
  /// frequency analysis.
  DynamicAnalysis(Assembler& assembler, const DynamicsOptions& opts, const Settings& settings);
  ~DynamicAnalysis() override;
  DynamicAnalysis(const DynamicAnalysis&) = delete;
  DynamicAnalysis& operator=(const DynamicAnalysis&) = delete;

  /// Called at t = 0 (step 0, after the initial accelerations) and after every time step:
  /// U, V and the accelerations Qdd at time t.
  using StepCallback = std::function<PetscErrorCode(int step, double t, Vec U, Vec V, Vec Qdd)>;
  /// Adaptive steps: called after every accepted step (t, U, V), written or not (external work).
  using SubstepCallback = std::function<PetscErrorCode(double t, Vec U, Vec V)>;
  void setSubstepCallback(SubstepCallback cb) { onSubstep_ = std::move(cb); }
  /// True with opt.dynamics.adaptive / -dynamics_adapt newton|error.
  bool adaptive() const { return control_ != StepControl::None; }
  /// The last accepted step size (adaptive runs: /dynamics/dt).
  double lastStep() const { return lastH_; }
  /// The loads of the time loop at t: in full from t = 0, functions of time evaluated at t.
  static LoadState loadsAt(double t);
  using Scheme = DynamicsScheme;
  /// Checks -dynamics_scheme against the model (SceneError; called at setup, where scene errors exit 2):
  /// tsalpha2 (a vector space) cannot integrate rotation unknowns; energy_momentum needs a step force
  /// of every element and no element mass matrix (beams with -beam_mass lumped, rigid elements). Collective.
  static Scheme checkScheme(const DistributedMesh& mesh, Scheme scheme);
  /// Checks opt.dynamics.adaptive with its flags (-dynamics_adapt, -dynamics_dt_min/max, ...): SceneError
  /// (exit 2) for dt_min > dt_max or adaptive steps with tsalpha2 or midpoint. Called at setup, after checkScheme.
  static void checkStepControl(const DistributedMesh& mesh, const DynamicsOptions& opts, const DynamicsSettings& settings);
  /// Integrates from U (in: initial state, at rest; out: state at the last converged time).
  PetscErrorCode run(Vec U, const StepCallback& onStep, bool* converged);
  /// With opt.dynamics damping: the frequency analysis of the start state (modal damping) sees
  /// this file (it writes nothing into it). Call before run().
  void setResultFile(ResultFile* file) { file_ = file; }
  const Damping& damping() const { return damping_; }
  /// The loop ends after the step whose onStep set *stop (an interrupt or a failed result file);
  /// the run is then neither converged nor failed here: the caller knows why it stopped.
  void setStopFlag(const bool* stop) { stop_ = stop; }
  /// A -target_error level in time (analysis/time_handover.hpp; -accuracy_reuse): the fixed-step loop
  /// records its converged time steps in h->history (when set) and starts Newton at each step's end
  /// time from h->coarseHistory (when its layout is this run's on every rank), counted in
  /// h->guessesUsed. Call before run(); null: neither.
  void setLevelHandover(StaticsHandover* h) { handover_ = h; }

  const DynamicsReport& report() const { return report_; }
  /// Continues after time step p.step (a checkpoint; Arnold-Brüls scheme only): U, V, the
  /// generalized-alpha auxiliary accelerations A and the accelerations Qdd at p.time (copied).
  PetscErrorCode resume(const DynamicsProgress& p, Vec U, Vec V, Vec A, Vec Qdd);
  /// A resumed run's damping, built from the start state of the interrupted run: U0 (rotations
  /// absorbed) with the assembler holding that state's reference rotations and element states
  /// (Restart::resumeDynamics loads them from /checkpoint_dynamics_start, then restores the resumed
  /// ones). Without this call a resumed run rebuilds the damping from the resumed state.
  PetscErrorCode setupResumedDamping(Vec U0);
  /// Some damping (Rayleigh or modal) is asked for.
  bool damped() const { return damping_.active(); }
  /// The state the damping was built at (rotations absorbed; the multipliers as they were then,
  /// before the initial accelerations set lambda0); null before run() or without damping.
  Vec dampingState() const { return U0_; }
  /// State after the last converged time step (valid inside the step callback).
  const DynamicsProgress& progress() const { return progress_; }
  /// The time-integration scheme (-dynamics_scheme) with its state.
  const TimeScheme& scheme() const { return *scheme_; }
  /// Auxiliary (algorithmic) accelerations a_n of the last converged step (null with tsalpha2).
  Vec auxiliaryAccelerations() const { return scheme_->state().a; }
  /// True for -dynamics_scheme tsalpha2 (PETSc TS; it cannot be resumed from a checkpoint).
  bool usesPetscTS() const { return tsScheme_ != nullptr; }
  const std::string& failureMessage() const { return failure_; }
  bool midpoint() const { return midpointScheme_ != nullptr; }
  bool energyMomentum() const { return emScheme_ != nullptr; }
  double energyDecay() const { return emScheme_ ? emScheme_->decay() : 0.0; }
  /// alpha_m and alpha_f of the Arnold-Brüls scheme at opt.dynamics.spectral_radius (the summary line).
  double alphaM() const { return GeneralizedAlphaParameters::fromSpectralRadius(opts_.spectral_radius).alphaM; }
  double alphaF() const { return GeneralizedAlphaParameters::fromSpectralRadius(opts_.spectral_radius).alphaF; }

 private:
  static PetscErrorCode formFunction(SNES, Vec U, Vec F, void* ctx);
  static PetscErrorCode formJacobian(SNES, Vec U, Mat J, Mat P, void* ctx);
  static PetscErrorCode convergenceTest(SNES, PetscInt it, PetscReal xnorm, PetscReal snorm, PetscReal fnorm,
                                        SNESConvergedReason* reason, void* ctx);
  /// MotionEquations (TSAlpha2Scheme): M qdd + f_int(q, qd, t) - f_ext(t) + C qd and K + shiftV C + shiftA M.
  PetscErrorCode motionResidual(double t, Vec q, Vec qd, Vec qdd, Vec F) override;
  PetscErrorCode motionTangent(double t, Vec q, Vec qd, double shiftV, double shiftA, Mat P) override;
  /// The step equation of the step scheme at the iterate U (rates computed): the equations of motion
  /// at its evaluation point e; the midpoint rule's rotary inertia as the momentum change over the
  /// step and, with multipliers, their constraints at the step's end.
  PetscErrorCode stepResidual(Vec U, const EvaluationPoint& e, Vec F);
  /// The loads of the step's evaluation point e (time t_{n+1} + e.timeShift; see the definition).
  LoadState evaluationLoads(const EvaluationPoint& e) const;
  /// Its derivative by U: e.jacobianScale (K + e.shiftV C + e.shiftA M) at e (midpoint: constraint rows
  /// and multiplier columns scaled by 2).
  PetscErrorCode stepJacobian(Vec U, const EvaluationPoint& e, Mat P);
  /// Runs `evaluate` with the midpoint rule's rotary momentum of the iterate U set in the assembler
  /// (cayley and the step forces: the energy-momentum scheme).
  PetscErrorCode withRotaryMomentum(Vec U, const std::function<PetscErrorCode()>& evaluate, bool cayley = false);
  PetscErrorCode useDynamicsSolver(KSP ksp);
  PetscErrorCode initialAccelerations(Vec U, Vec V, Vec Qdd, bool* ok);
  /// Solves the step to t1 (size h_); with commit, a converged step becomes the new step start.
  PetscErrorCode step(double t1, bool* ok, int* its, double* fnorm, SNESConvergedReason* why, bool commit = true);
  /// Local error of the converged step (rates of U computed), relative to tolerance * largest displacement:
  /// eta = h^2 |beta - 1/6| ||a_{n+1} - a_n||_inf / (tol * scale); accepted at eta <= 1. scale: the
  /// largest ||U||_inf of the run so far and of U, at least 1e-3 of the model size; *scale out.
  PetscErrorCode errorRatio(Vec U, double* eta, double* scale);
  /// The time loop with adaptive steps (after the start of runArnoldBruls).
  PetscErrorCode runAdaptive(const StepCallback& onStep, bool* converged);
  PetscErrorCode runArnoldBruls(Vec U, const StepCallback& onStep, bool* converged);
  PetscErrorCode runTSAlpha2(Vec U, const StepCallback& onStep, bool* converged);
  /// Builds the damping matrix from the start state U (rotations absorbed).
  PetscErrorCode setupDamping(Vec U);
  // a -target_error level in time (level_time_reuse.cpp)
  /// coarse_ <- the coarser level's record when its layout is this run's on every rank (collective).
  PetscErrorCode useCoarseLevel();
  /// Appends the converged state (t, q, qd; rotations absorbed) to handover_->history, if set.
  PetscErrorCode recordLevelStep(double t, Vec q, Vec qd);
  /// U <- the coarser level's state at t1 (exact at its times, cubic Hermite between); *found false
  /// (U unchanged) when t1 is outside its record. The same answer on every rank.
  PetscErrorCode startFromCoarseLevel(double t1, Vec U, bool* found);
  // levels that refine the elements too: the record by FE node (level_space_time_reuse.cpp)
  /// Appends the converged state of every FE node at t (states of q, rates qd) to handover_->history.
  PetscErrorCode recordNodeStep(double t, Vec q, Vec qd);
  /// coarse_ <- c when the coarser level's nodes map onto this level's (handover_->coarseNodeMap) and
  /// Newton builds its Jacobian at every iteration.
  PetscErrorCode useCoarseNodes(const TimeHandover& c);
  /// U <- q_n plus the coarser level's motion from t1 - h to t1 on this level's nodes; *found false when
  /// either time is outside its record.
  PetscErrorCode startFromCoarseNodes(double t1, Vec U, bool* found);

  Assembler& asm_;
  const bool* stop_ = nullptr;
  StaticsHandover* handover_ = nullptr;     ///< setLevelHandover
  const TimeHandover* coarse_ = nullptr;    ///< the coarser level's record in use (useCoarseLevel)
  bool resumed_ = false;
  bool dampingReady_ = false;  ///< setupResumedDamping was called
  DynamicsProgress progress_;
  DynamicsOptions opts_;
  std::unique_ptr<TimeScheme> scheme_;  ///< the scheme of -dynamics_scheme; one of:
  StepScheme* stepScheme_ = nullptr;    ///< arnold_bruls or midpoint (Sinew's Newton per step)
  GeneralizedAlphaScheme* alphaScheme_ = nullptr;
  MidpointScheme* midpointScheme_ = nullptr;
  EnergyMomentumScheme* emScheme_ = nullptr;
  TSAlpha2Scheme* tsScheme_ = nullptr;
  double h_ = 0;
  LoadState ls_;
  SNES snes_ = nullptr;
  Mat J_ = nullptr;
  Mat Jop_ = nullptr;  ///< refined step solves: the Newton matrix applied element by element (CorotatedNewtonMatrix::apply)
  bool refineAuto_ = false;  ///< -dynamics_refine auto: refinements added from the first slow contraction on
  static constexpr double kRefineContraction = 1e-3;
  static constexpr int kMaxRefinements = 3;
  int refinements_ = 0;      ///< refinements per step solve (0: the LU alone; -dynamics_refine true: 1)
  bool refineCheck_ = false;  ///< auto: the next contraction on one matrix judges the last added refinement
  double refineTheta_ = 0;    ///< the contraction that added it
  int refineIt_ = -100;       ///< Newton iteration of this solve that added it (-100: an earlier solve)
  PetscErrorCode setRefinements(KSP ksp, int n);
  /// -dynamics_node_rotation: the kept LU preconditions turned with the nodes (useNodeRotatedPC)
  enum class NodeRotation { Off, On, Auto } nodeRotation_ = NodeRotation::Off;
  bool rotating_ = false;  ///< node rotation in use (On; Auto: when the first kept matrix stalled at a turn below kRotationTurn)
  /// With node rotation, a kept matrix is rebuilt at the first iteration of a step whose first update
  /// reduced the residual by less than this (A1g at 65536 elements, 20 steps: 0.5: 51 Newton
  /// iterations on 7 matrices; 0.2: 47 on 7; 0.1: 41 on 8; 0.05: 41 on 17).
  static constexpr double kRotatedContractivity = 0.1;
  /// -dynamics_node_rotation auto: on when the first kept matrix that stalled did so at an element turn
  /// below this (rad).
  /// Measured stall turns: A1g (20 steps, 2 ranks) 5.1e-4 at 65536 elements, 5.3e-4 at 32768, 1.1e-3 at
  /// 16384, where it saves rebuilds and factorizations in every step; A1g at 4096 elements (100 steps,
  /// one process) 3.1e-3 and A3 at 512 elements 1.1e-2, where node rotation cost CPU time (0.95 against
  /// 0.85 s, 1.70 against 1.50 s, the fastest of 5 interleaved runs each) by replacing cheap rebuilds
  /// with fresh matrices. Later stalls (A3 at 512 elements: below 2e-3) do not switch it on.
  static constexpr double kRotationTurn = 2e-3;
  bool cutLU_ = false;  ///< ANCF chain with few coupling unknowns: useCutCorrectedLU on several ranks
  int mumpsWorkspace_ = 100;  ///< -mat_mumps_icntl_14 of the MUMPS step solver (DynamicsSettings::mumpsWorkspace)
  int denseMax_ = 200;        ///< -dense_max_unknowns: the small models' dense step LU (useDynamicsSolver)
  static PetscErrorCode applyNewtonMatrix(Mat A, Vec x, Vec y);
  Vec F_ = nullptr;
  /// 1 on coordinates, 0 on Lagrange multipliers (index-3 constraints: no rates); null without multipliers
  Vec keep_ = nullptr;
  Vec U0_ = nullptr;  ///< dampingState()
  double forceRtol_ = 1e-10;
  int maxCuts_ = 10;
  int growAfter_ = 3;  ///< after a halving, double the sub-step after this many successes (0: never)
  double jacobianNorm_ = 0, coordMax_ = 0;  ///< round-off floor of the residual (convergenceTest)
  NewtonTest newtonTest_;  ///< the Newton test with the dynamics rules (newtonRules(), set with the SNES)
  NewtonRules newtonRules() const;
  static constexpr double kUpdateRtol = 1e-6;  ///< update test: estimated error <= this * |U|
  static constexpr double kMidpointUpdateRtol = 1e-14;  ///< midpoint: a step ends at an update <= this * |U|
  Vec Fend_ = nullptr;  ///< midpoint with multipliers: the residual at the step's end (their constraint rows)
  // Modified Newton (as Exudyn's): the factored Jacobian is kept across iterations and time steps
  // while Newton contracts by at least kContractivity: measured on the residual with the
  // acceleration predictor; with the state predictor on the residual at the first iteration and on
  // the Newton updates after it (the residual is at its round-off noise there), and a residual that
  // grows 1.5x also refactors. A new step size (beyond 1e-9 relative) or kMaxReuse iterations on
  // one Jacobian make the next iteration assemble a fresh one (DynamicAnalysis::formJacobian).
  bool modifiedNewton_ = true;
  bool jacobianValid_ = false;
  /// -dynamics_corotated_jacobian (ANCF cables under modified Newton): a kept Jacobian that stops
  /// contracting is first rebuilt from its element blocks rotated with the elements
  /// (CorotatedNewtonMatrix::assemble); a fresh one only when that does not help either.
  bool corotated_ = false;
  std::unique_ptr<CorotatedNewtonMatrix> corotatedMatrix_;  ///< the kept blocks (corotated_ only)
  bool chain_ = false;  ///< ancfChain(mesh): an ANCF cable model (its LU: useChainLU)
  /// energy-momentum scheme with element masses that depend on the state (the consistent beam mass):
  /// its inertia is not a discrete gradient, so Newton ends at the round-off floor (newtonRules)
  bool stateMassSteps_ = false;
  bool lastCorotated_ = false;  ///< the current Newton matrix is a corotated rebuild
  double staleTurn_ = HUGE_VAL;  ///< smallest element turn (rad) at which a kept Newton matrix stalled
  int matrixIt_ = -100;          ///< Newton iteration of this solve that built the current matrix (-100: an earlier solve)
  bool restPredictor_ = false;  ///< guarded retry: Newton starts at q_n
  bool modifiedDefault_ = true;  ///< modifiedNewton_ outside guarded retries (set at the start of a time loop)
  /// Guarded mode: a failed solve is retried at the same step with full Newton started at q_n (on);
  /// the next step starts plain again (off).
  void setGuarded(bool on);
  /// setGuarded(true), counted and reported: "Newton failed at t1 (why); retrying ...".
  /// The time step t -> t1 for the StepController (solve, guarded retry, messages); `commit`: a
  /// converged step becomes the step start at once.
  SteppedProcedure timeStep(bool commit, SNESConvergedReason* why, double* fnorm);
  /// Newton's start of a time step (-dynamics_predictor): q_n + h qd_n + h^2/2 a_n or q_n
  enum class Predictor { Acceleration, State } predictor_ = Predictor::Acceleration;
  bool followRotation_ = false;  ///< -dynamics_predictor rotation: q_n moved by the nodes' rigid motion
  double jacobianH_ = 0;       ///< step size the kept Jacobian was built for
  int reuseCount_ = 0;         ///< iterations on the kept Jacobian since it was built
  double prevFnorm_ = 0;       ///< residual norm at the previous Jacobian call of this solve
  // time-step control (opt.dynamics.adaptive, -dynamics_adapt; docs/dynamics.md "Time-step control")
  using StepControl = TimeStepControl;
  StepControl control_ = StepControl::None;
  struct StepControlSettings {
    StepControl control = StepControl::None;
    double dtMin = 0, dtMax = 0, tol = 0;
    int its = 0;
  };
  /// The scene's opt.dynamics.adaptive overridden by the flags, checked (SceneError).
  static StepControlSettings stepControl(const DynamicsOptions& opts, const DynamicsSettings& settings, Scheme scheme);
  double dtMin_ = 0, dtMax_ = 0, adaptTol_ = 1e-4;
  int adaptIts_ = 4;
  double lastH_ = 0;
  double adaptScale_ = 0;  ///< largest ||U||_inf of the accepted steps so far (errorRatio)
  SubstepCallback onSubstep_;
  DynamicsReport report_;
  std::string failure_;
  Damping damping_;
  ResultFile* file_ = nullptr;
};

}  // namespace sinew
