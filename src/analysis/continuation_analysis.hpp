// Path following past limit points (opt.continuation): arc-length (Crisfield's cylindrical
// constraint, or spherical with a load scale) or displacement control at one node DOF, on the
// assembler's residual R(U, lambda) = f_int(U) - f_ext(lambda). Each corrector iteration solves the
// tangent twice with one factorization (bordering: K du_R = -R, K du_q = q, q = -dR/dlambda) and
// closes the constraint for the load-factor correction. At every converged point the inertia of the
// tangent (negative pivots of a symmetric MUMPS factorization, less one per rigid-mode multiplier)
// says how many unstable directions the state has; a change between two points is a critical point:
// a limit point where the load factor turns back, a bifurcation otherwise.
#pragma once
#include <petscksp.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "analysis/statics_handover.hpp"
#include "assembly/assembler.hpp"
#include "settings/settings.hpp"
#include "sinew/model.hpp"
#include "solvers/newton_test.hpp"

namespace sinew {

struct PathPoint {
  int step = 0;
  double loadFactor = 0;
  double arcLength = 0;        ///< the arc length (or displacement increment) of the step
  int iterations = 0;          ///< corrector iterations of the last (successful) attempt
  int cuts = 0;                ///< failed attempts before it (step halved)
  double residualNorm = 0;     ///< |R(U, lambda)| at the converged point [N, N m]
  int negativeEigenvalues = -1;  ///< of the tangent, rigid-mode multipliers discounted; -1 when not computed
  double controlValue = 0;     ///< the displacement of the control DOF (when a node is given)
  double slopeLoad = 0, slopeControl = 0;  ///< d lambda / ds and d u_control / ds along the path there
  double lowestEigenvalue = 0;  ///< SLEPc: lowest eigenvalue of the tangent (-continuation_lowest_eigenvalue)
  /// SLEPc: the tangent's eigenvalues nearest to 0 from below and from above (NaN when none converged on
  /// that side). With k negative eigenvalues they are the k-th and (k+1)-th smallest: the ones that
  /// change sign when the count changes by one, whatever the lowest eigenvalue does.
  double nearestNegative = std::numeric_limits<double>::quiet_NaN();
  double nearestPositive = std::numeric_limits<double>::quiet_NaN();
};

struct CriticalPoint {
  enum Kind { Limit = 1, Bifurcation = 2 };
  Kind kind = Limit;
  bool interpolated = false;  ///< a bifurcation located by the zero of the eigenvalue changing sign (else the midpoint)
  int afterStep = 0;    ///< between path points afterStep and afterStep + 1
  double loadFactor = 0;  ///< located load factor (parabola through three points for a limit point)
  double controlValue = 0;
};

class ContinuationAnalysis {
 public:
  /// maxCuts: halvings of a failing step (-max_cuts, StaticsSettings::maxCuts).
  ContinuationAnalysis(Assembler& assembler, const ContinuationOptions& opt, const ContinuationSettings& settings,
                       int maxCuts);
  ~ContinuationAnalysis();
  using PointCallback = std::function<PetscErrorCode(const PathPoint&, Vec U)>;
  /// Follows the path from U (load factor 0) until a stop criterion; onPoint after each converged point.
  PetscErrorCode run(Vec U, const PointCallback& onPoint, bool* converged);
  const std::vector<PathPoint>& points() const { return points_; }
  const std::vector<CriticalPoint>& criticalPoints() const { return critical_; }
  const std::string& failureMessage() const { return failure_; }
  bool computesLowestEigenvalue() const { return lowest_; }
  std::string summary() const;
  /// The path ends after the current point when *stop is set (an interrupt; equal on every rank).
  void setStopFlag(const bool* stop) { stop_ = stop; }
  /// The start state already carries the initial loads (a form-found shape: form finding applied the
  /// prescribed initial motions): equilibrium under them is found from it in one increment, not ramped.
  void setStartCarriesInitialLoads(bool v) { startCarriesInitial_ = v; }
  /// A -target_error level (docs/accuracy.md "Reuse between levels"): the path records its start state
  /// and every converged point into h->record, and an arc-length step predicts from the coarser level's
  /// path h->guesses (interpolated onto this level's nodes) where it reaches the step's constraint. Its steps
  /// follow the coarser level's accepted steps as their plan (the same number of steps, from the coarser
  /// point k - 1 to point k as the predictor) until one fails or the plan ends; then its own step control.
  /// plan false: the own step control throughout, and no landing on the stop (-accuracy_path_plan).
  void setHandover(StaticsHandover* h, bool plan = true) {
    handover_ = h;
    plan_ = plan;
  }

  /// Checkpoint (-restart): the path's state after the last reported point as a fixed-size row of
  /// checkpointSize() values (header, the points so far, the critical points), and the last increment
  /// (the predictor's direction; valid during the point callback).
  static constexpr int kCkHeader = 9, kCkPointCols = 12, kCkLegacyPointCols = 10, kCkCritCols = 5;
  static long checkpointSize(int maxSteps) { return kCkHeader + static_cast<long>(maxSteps) * (kCkPointCols + kCkCritCols); }
  /// The row of checkpoints written before the points carried their nearest eigenvalues (10 columns
  /// per point), and that row in the current layout (those eigenvalues unknown: NaN; another row as is).
  static long legacyCheckpointSize(int maxSteps) { return kCkHeader + static_cast<long>(maxSteps) * (kCkLegacyPointCols + kCkCritCols); }
  static std::vector<double> currentCheckpointLayout(const std::vector<double>& state, int maxSteps);
  std::vector<double> checkpointState() const;
  Vec lastIncrement() const { return dUprev_; }
  /// Continues the path from a checkpoint: U is the state of its last point (reference rotations
  /// restored), dU its last increment; run() then goes on after that point.
  PetscErrorCode resume(const std::vector<double>& state, Vec dU);

 private:
  PetscErrorCode loadDerivative(Vec U, double lambda, Vec q);
  /// The start state: equilibrium under the initial loads alone (load factor 0), reached by ramping them
  /// (LoadState::initialFactor 0 -> 1 in -continuation_initial_steps Newton-solved increments).
  PetscErrorCode equilibrateInitial(Vec U, bool* ok);
  PetscErrorCode factor(Vec U, double lambda);
  /// The inertia count; with SLEPc on (lowest_ or branchSwitch_) and p given, also p's lowest and nearest
  /// eigenvalues.
  PetscErrorCode negativeEigenvalues(Vec U, double lambda, int* count, PathPoint* p);
  /// Lowest eigenvalue of K_ (assembled true tangent) by SLEPc: shift-and-invert about 0, a few pairs;
  /// its eigenvector into phi when given; the converged eigenvalues nearest to 0 below and above it
  /// into below/above when given (NaN if none on that side).
  PetscErrorCode lowestEigenvalue(double* value, Vec phi = nullptr, double* below = nullptr, double* above = nullptr);
  PetscErrorCode stabilityMatrix();
  /// Newton at a fixed load factor from U (the branch switch); ok when the residual meets the tolerance.
  PetscErrorCode solveFixedLoad(Vec U, double lambda, double scale, bool* ok);
  PetscErrorCode newton(Vec U, const LoadState& ls, double tol, int maxIts, bool* ok);
  /// -branch_switch: from the point just past a bifurcation, onto the branch along the critical
  /// eigenvector (orthogonal to the path tangent dUprev), by tau = |ds|; ok when it left the primary path.
  PetscErrorCode switchBranch(Vec U, double lambda, double tau, Vec dUprev, bool* ok);
  PetscErrorCode controlDisplacement(Vec U, double lambda, double* value);
  /// Path tangent at a converged point, oriented along dUlast: d lambda / ds and d u_control / ds.
  PetscErrorCode pathSlopes(Vec U, double lambda, Vec dUlast, double dlLast, PathPoint* p);
  PetscErrorCode step(Vec U, double* lambda, double ds, Vec dUprev, double dlPrev, bool first, bool* ok, int* its);
  /// The corrector from the predicted (U, lambda) of a step from (U0, lambda0) of size ds.
  PetscErrorCode correct(Vec U, double* lambda, Vec U0, double lambda0, double ds, double qnorm, double jnorm,
                         KSPConvergedReason* kr, bool* ok, int* its);
  /// The start of the corrector of a step of size ds from (U0, lambda0) from the coarser level's path
  /// (handover_->guesses, linear between its points): (U0, lambda0) plus the path's increment from C0,
  /// its point nearest to U0, to C1, where it leaves the ball |P - C0|^2 + w (lambda_P - lambda_C0)^2 =
  /// ds^2; into (G, *lambdaG) when found (the same on every rank).
  PetscErrorCode coarsePathGuess(Vec U0, double lambda0, double ds, double w, Vec G, double* lambdaG, bool* found);
  /// The coarser level's step k (k >= 1; handover_->guesses[k - 1] to [k], on this level's unknowns about the
  /// current reference rotations) as a step from (U, lambda): its size in the constraint's metric into *ds;
  /// with G given, the step's start G = U + (C_k - C_k-1), *lambdaG = lambda + (lambda_k - lambda_k-1).
  PetscErrorCode plannedStep(std::size_t k, Vec U, double lambda, double* ds, Vec G = nullptr, double* lambdaG = nullptr);
  /// A -target_error level's step from (U0, lambda0) to (U, *lambda) that crossed a stop is repeated from
  /// its start onto the stop: by displacement control onto stop_displacement, by load control onto
  /// stop_load_factor (the one the step crossed first, linear in the step, when it crossed both); the end
  /// state then carries no interpolation between path points, whose error would not shrink from level to
  /// level with the plan's steps. On success landedDs_ is the repeated step's arc length and *its grows by
  /// its corrector iterations, else the step stays as it was (src/analysis/continuation_landing.cpp).
  PetscErrorCode landOnStop(Vec U, double* lambda, Vec U0, double lambda0, Vec dUprev, double dlPrev, int* its);
  /// After form finding (StaticsHandover::fromStart): the corrector starts from the tangent predictor
  /// (Upred, lambdaPred) instead of the coarser path's (U, *lambda) where its residual is smaller (a coarse
  /// membrane's path can be far from the finer one's); then *guessed is false.
  PetscErrorCode nearerPredictor(Vec U, double* lambda, Vec Upred, double lambdaPred, bool* guessed);
  /// Appends the state at (U, lambda) to handover_->record.
  PetscErrorCode recordPoint(Vec U, double lambda);
  /// The path's start (U, lambda) into handover_->record; after form finding (StaticsHandover::fromStart)
  /// also into handover_->start, and the coarser path becomes this start plus the coarser level's
  /// displacements from its own start (handover_->guesses) in coarsePath_.
  PetscErrorCode recordStart(Vec U, double lambda);
  /// The coarser level's path on this level's nodes: states (handover_->guesses, or coarsePath_ after form
  /// finding).
  const std::vector<LevelState>& coarsePath() const { return handover_->fromStart ? coarsePath_ : handover_->guesses; }
  /// The model's size in the arc-length metric: |s| with s = D (bounding-box diagonal of the nodes) at
  /// every free translation and 1 at every free rotation or ANCF slope (collective).
  double modelPathSize() const;
  /// Angle [rad] between the step just taken, (U - Uprev, dl), and the one before, (dUprev, dlPrev), in the
  /// metric |dU|^2 + w dl^2 (w = psi^2 |q|^2 with the spherical constraint, else that of the first step:
  /// its tangent at 45 degrees); 0 without a step before.
  PetscErrorCode turnAngle(Vec U, Vec Uprev, double dl, Vec dUprev, double dlPrev, double* angle);
  void classify();

  Assembler& asm_;
  ContinuationOptions opt_;
  Vec dUprev_ = nullptr;  ///< increment of the last converged step
  bool resumed_ = false;   ///< run() continues after points_.back() (resume)
  double resumeLambda_ = 0, resumeDs_ = 0, resumeDlPrev_ = 0;
  int resumePrevNeg_ = -1, resumeIts_ = 0;
  double ckDs_ = 0, ckDlPrev_ = 0;  ///< step state at the reported point (checkpointState)
  int ckIts_ = 0;
  double lastResidual_ = 0;  ///< |R| of the last converged corrector (the path point's residual)
  double lastQnorm_ = 0;     ///< |q| at the start of the last step (the spherical constraint's load scale)
  /// The largest step: ds_max, or (arclength without ds_max) kAutoFraction of modelPathSize(), at least
  /// |ds|; then the turn of the path from step to step is bounded too (angleControl_).
  double dsMax_ = 0;
  bool angleControl_ = false;
  static constexpr double kAutoFraction = 0.02;  ///< default ds_max / model size in the arc-length metric
  static constexpr double kTargetAngle = 0.1;    ///< the turn per step aimed at [rad]
  static constexpr double kMaxAngle = 0.25;      ///< a step that turns the path more is repeated shorter [rad]
  Mat K_ = nullptr;
  Mat Ks_ = nullptr;   ///< symmetric part of K_ (follower pressure makes K_ unsymmetric); see stabilityMatrix
  Mat stab_ = nullptr; ///< the matrix whose inertia / lowest eigenvalue is taken: K_ or Ks_
  KSP ksp_ = nullptr;
  Vec R_ = nullptr, q_ = nullptr, duR_ = nullptr, duq_ = nullptr, dU_ = nullptr, e_ = nullptr, work_ = nullptr;
  long multipliers_ = 0;      ///< global number of rigid-mode multipliers (each adds one negative pivot)
  bool haveControl_ = false;  ///< e_ selects the control DOF among the unknowns
  double rtol_ = 1e-9;
  static NewtonRules newtonRules();
  NewtonIterate iterate(int k, double rnorm, double tol, double jnorm) const;
  NewtonTest newtonTest_{newtonRules()};  ///< the corrector's Newton test
  int maxIts_ = 15, maxCuts_ = 10, desiredIts_ = 5, initialSteps_ = 10;
  bool startCarriesInitial_ = false;
  bool inertia_ = true;
  bool lowest_ = false;  ///< -continuation_lowest_eigenvalue
  bool branchSwitch_ = false, switched_ = false;  ///< -branch_switch; done once
  int switchedAt_ = 0;   ///< the path point reached on the new branch (0: none)
  std::vector<PathPoint> points_;
  std::vector<CriticalPoint> critical_;
  std::string failure_;
  const bool* stop_ = nullptr;
  StaticsHandover* handover_ = nullptr;
  std::vector<LevelState> coarsePath_;  ///< after form finding: the found shape plus the coarser displacements
  std::size_t guessCursor_ = 0;  ///< the coarser path's point nearest to the last step's start
  /// The coarser level's steps as this level's plan (run()): path step n is the coarser step planStep_ of
  /// size planSize_ while planActive_; planned_: the current attempt is one.
  bool plan_ = true, planActive_ = false, planned_ = false;
  std::size_t planStep_ = 0;
  double planSize_ = 0;
  int repeated_ = 0;  ///< steps repeated shorter because they turned the path too far (summary)
  /// The step is solved by displacement control or by load control at landingLambda_ (landOnStop).
  enum class StopLanding { None, Displacement, LoadFactor };
  StopLanding landing_ = StopLanding::None;
  double landingLambda_ = 0;
  double landedDs_ = 0;   ///< arc length of the step landed on the stop (0: none)
};

}  // namespace sinew
