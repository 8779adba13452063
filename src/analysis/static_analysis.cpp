#include "analysis/static_analysis.hpp"
#include "parallel/collective_error.hpp"
#include "solvers/newton_test.hpp"
#include "solvers/solver_defaults.hpp"
#include "solvers/step_controller.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sinew {

StaticAnalysis::StaticAnalysis(Assembler& assembler, int loadsteps, const StaticsSettings& settings, const AncfSettings& ancf)
    : asm_(assembler), loadsteps_(loadsteps), lastStep_(loadsteps) {
  MPI_Comm comm = asm_.mesh().comm;
  SinewCallThrow(comm, asm_.createMatrix(&J_));
  {  // rigid-body modes as near-null space: used by algebraic multigrid (-pc_type gamg), ignored by LU
    MatNullSpace nsp;
    SinewCallThrow(comm, asm_.rigidBodyModes(&nsp));
    SinewCallThrow(comm, MatSetNearNullSpace(J_, nsp));
    SinewCallThrow(comm, MatNullSpaceDestroy(&nsp));
  }
  SinewCallThrow(comm, asm_.createVector(&F_));
  SinewCallThrow(comm, SNESCreate(comm, &snes_));
  SinewCallThrow(comm, SNESSetType(snes_, SNESNEWTONLS));
  SinewCallThrow(comm, SNESSetFunction(snes_, F_, formFunction, this));
  SinewCallThrow(comm, SNESSetJacobian(snes_, J_, J_, formJacobian, this));
  SinewCallThrow(comm, SNESSetTolerances(snes_, 1e-50, 1e-10, 1e-9, 50, 10000));
  SinewCallThrow(comm, SNESSetDivergenceTolerance(snes_, -1.0));  // stiff axial modes make the first residual jump
  SNESLineSearch ls;
  SinewCallThrow(comm, SNESGetLineSearch(snes_, &ls));
  SinewCallThrow(comm, SNESLineSearchSetType(ls, SNESLINESEARCHBASIC));
  SinewCallThrow(comm, SNESSetConvergenceTest(snes_, convergenceTest, this, nullptr));
  KSP ksp;
  SinewCallThrow(comm, SNESGetKSP(snes_, &ksp));
  SinewCallThrow(comm, useDirectSolver(ksp, asm_.mesh(), settings.denseMaxUnknowns));
  SinewCallThrow(comm, setUpElementwiseOperator(settings.tangentOperator, ancf));
  SinewCallThrow(comm, SNESSetFromOptions(snes_));
  forceRtol_ = settings.forceRtol.value_or(forceRtol_);
  maxCuts_ = settings.maxCuts;
  adaptive_ = settings.adaptiveIncrements;
  growIts_ = settings.incrementGrowIts;
  coordMax_ = asm_.coordinateScale();
  // Newton with mixed stresses (beams): see Assembler::setMixedStressNewton; -newton_mixed_stresses false
  // restores the displacement-based tangent
  asm_.setMixedStressNewton(settings.mixedStresses);
  // The secant predictor extrapolates positions and rotation vectors additively: for beams that
  // stretches the elements (the spurious axial force the mixed-stress tangent keeps out of the
  // tangent, but not out of the residual), and every roll-up measured converged in fewer
  // iterations without it (docs/beam.md). Default: off for models with beams under the
  // mixed-stress Newton, on otherwise.
  const bool beamsMixed = settings.mixedStresses && asm_.hasMixedStressKernels();
  predictor_ = settings.predictor.value_or(!beamsMixed);
  divergedIts_ = settings.divergedIts.value_or(beamsMixed ? 6 : 0);
}

// -tangent_operator elementwise|assembled (default: elementwise for models with ANCF cables).
// Fine ANCF cables have a tangent with condition number ~ n^4 (7e16 at 16384 elements): the LU
// factors of the assembled matrix alone give Newton increments with O(1) error in the softest
// modes. Elementwise, the Newton system is solved by GMRES (right preconditioned, so it measures
// the true residual) on the element-wise operator of Assembler::applyTangent, preconditioned by the
// LU factorization of the assembled tangent; the few modes the LU gets wrong take a few GMRES
// iterations. -ksp_* / -pc_* options still act on this solver.
PetscErrorCode StaticAnalysis::setUpElementwiseOperator(OperatorChoice choice, const AncfSettings& ancf) {
  PetscFunctionBeginUser;
  MPI_Comm comm = asm_.mesh().comm;
  const bool available = asm_.elementwiseTangentAvailable();
  if (choice == OperatorChoice::Elementwise && !available)
    SETERRQ(comm, PETSC_ERR_ARG_INCOMP,
            "-tangent_operator elementwise: not available for models with cables or surface pressure");
  const bool use = available && (choice == OperatorChoice::Elementwise ||
                                 (choice == OperatorChoice::Auto && asm_.mesh().anyAncf));
  if (!use) PetscFunctionReturn(PETSC_SUCCESS);
  asm_.keepTangentBlocks(true);
  const PetscInt nloc = asm_.mesh().numOwnedUnknowns, N = static_cast<PetscInt>(asm_.mesh().numGlobalUnknowns);
  PetscCall(MatCreateShell(comm, nloc, nloc, N, N, this, &Jop_));
  PetscCall(MatShellSetOperation(Jop_, MATOP_MULT, reinterpret_cast<void (*)(void)>(tangentMult)));
  PetscCall(SNESSetJacobian(snes_, Jop_, J_, formJacobian, this));
  KSP ksp;
  PetscCall(SNESGetKSP(snes_, &ksp));
  PetscCall(KSPSetType(ksp, KSPGMRES));
  PetscCall(KSPSetPCSide(ksp, PC_RIGHT));
  PetscCall(KSPGMRESSetRestart(ksp, 30));
  // fine cables: a coarse space of cubic Hermite functions along the split scene elements takes
  // the soft modes the LU gets wrong (cable_coarse_space.hpp); -ancf_coarse_ratio r sets the fine
  // elements per coarse element (0: none; default ~2 sqrt(ANCF elements) once a scene element is
  // split into at least 1024 elements)
  const int ratio = ancf.coarseRatio ? *ancf.coarseRatio : CableCoarseSpace::defaultRatio(asm_.mesh(), 1024);
  coarsePredictor_ = ancf.coarsePredictor;
  // rtol 1e-10 (one level) or 1e-6 (with the coarse space): the residual of a fine cable is mostly
  // round-off noise, and the element-wise products are accurate to eps |J_e| |dU_e - t|; at
  // 1,048,576 A1 elements GMRES broke down at rtol 1e-8 (Newton converges on its update whatever
  // the inexactness of each increment). Without the coarse space the LU's soft modes need the
  // tighter solve: at 16384 elements rtol 1e-6 cost cut increments (44 Newton iterations) where
  // 1e-10 converged in one load step (9 iterations).
  PetscCall(KSPSetTolerances(ksp, ratio > 0 ? 1e-6 : 1e-10, 1e-300, PETSC_DEFAULT, 200));
  if (ratio > 0) {
    coarse_ = std::make_unique<CableCoarseSpace>(asm_, ratio);
    PC pc;
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(coarse_->install(pc));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode StaticAnalysis::tangentMult(Mat A, Vec x, Vec y) {
  PetscFunctionBeginUser;
  void* ctx;
  PetscCall(MatShellGetContext(A, &ctx));
  PetscCall(static_cast<StaticAnalysis*>(ctx)->asm_.applyTangent(x, y));
  PetscFunctionReturn(PETSC_SUCCESS);
}

StaticAnalysis::~StaticAnalysis() {
  SNESDestroy(&snes_);
  MatDestroy(&Jop_);
  MatDestroy(&J_);
  VecDestroy(&F_);
  VecDestroy(&dU_);
  VecDestroy(&Fwork_);
}

PetscErrorCode StaticAnalysis::resume(const StaticsProgress& p, Vec dU) {
  PetscFunctionBeginUser;
  progress_ = p;
  fintConverged_ = p.fintConverged;
  resumed_ = true;
  if (!dU_) PetscCall(VecDuplicate(dU, &dU_));
  PetscCall(VecCopy(dU, dU_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode StaticAnalysis::formFunction(SNES, Vec U, Vec F, void* ctx) {
  auto* self = static_cast<StaticAnalysis*>(ctx);
  return self->asm_.residual(U, self->ls_, F);
}

PetscErrorCode StaticAnalysis::formJacobian(SNES snes, Vec U, Mat, Mat P, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<StaticAnalysis*>(ctx);
  PetscCall(self->asm_.jacobian(U, self->ls_, P));
  PetscInt it = 0;
  PetscCall(SNESGetIterationNumber(snes, &it));
  PetscReal norm = 0, frobenius = 0;
  PetscCall(tangentNorms(P, &norm, &frobenius));
  if (it == 0) self->jacobianNorm_ = norm;  // at the start state
  // Inf/NaN entries, or entries whose squares overflow (above ~1e154: no factorization handles them)
  self->tangentFinite_ = std::isfinite(frobenius);
  PetscFunctionReturn(PETSC_SUCCESS);
}

// ||P||_inf and ||P||_F as MatNorm gives them; a one-process AIJ matrix in one pass over its values
// (the same sums in the same order: each row's |entries| by column, the squares in storage order).
PetscErrorCode StaticAnalysis::tangentNorms(Mat P, PetscReal* inf, PetscReal* frobenius) {
  PetscFunctionBeginUser;
  PetscBool seq = PETSC_FALSE;
  PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(P), MATSEQAIJ, &seq));
  PetscInt m = 0;
  const PetscInt *ia = nullptr, *ja = nullptr;
  PetscBool done = PETSC_FALSE;
  if (seq) PetscCall(MatGetRowIJ(P, 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
  if (!done) {
    PetscCall(MatNorm(P, NORM_INFINITY, inf));
    PetscCall(MatNorm(P, NORM_FROBENIUS, frobenius));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  const PetscScalar* a;
  PetscCall(MatSeqAIJGetArrayRead(P, &a));
  PetscReal rowMax = 0.0, squares = 0.0;
  for (PetscInt i = 0; i < m; ++i) {
    PetscReal sum = 0.0;
    for (PetscInt k = ia[i]; k < ia[i + 1]; ++k) {
      sum += std::abs(a[k]);
      squares += a[k] * a[k];
    }
    if (sum > rowMax) rowMax = sum;
  }
  PetscCall(MatSeqAIJRestoreArrayRead(P, &a));
  PetscCall(MatRestoreRowIJ(P, 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
  *inf = rowMax;
  *frobenius = std::sqrt(squares);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode StaticAnalysis::convergenceTest(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm,
                                               PetscReal fnorm, SNESConvergedReason* reason, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<StaticAnalysis*>(ctx);
  if (it == 0 && self->unloaded_ && self->jacobianNorm_ == 0.0) {  // no load: the start state may be equilibrium
    Vec U;
    PetscCall(SNESGetSolution(snes, &U));
    PetscCall(self->asm_.jacobian(U, self->ls_, self->J_));
    PetscCall(MatNorm(self->J_, NORM_INFINITY, &self->jacobianNorm_));
  }
  const double fext = self->asm_.externalForceNorm();
  NewtonIterate x(it, xnorm, snorm, fnorm);
  x.scale = forceScale(fext, self->asm_.internalForceNorm(), 10.0 * std::max(fext, self->fintConverged_));
  x.floor = roundoffFloor(self->jacobianNorm_, self->coordMax_);
  x.coordMax = self->coordMax_;
  const NewtonRules& rules = self->newtonTest_.rules();
  if (it == 0 && rules.startFloorFactor > 0 && fnorm <= rules.startFloorFactor * x.floor) {
    // a start residual at the round-off floor: round-off, or a load increment below it (a tiny load)?
    Vec U;
    PetscCall(SNESGetSolution(snes, &U));
    PetscCall(self->loadChange(U, &x.loadChange));
  }
  PetscCall(self->newtonTest_.judge(snes, x, reason));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// ||R(U, target loads) - R(U, loads of the start state's equilibrium)||: the load and prescribed-motion
// increment the start residual holds (the internal forces of U cancel). The assembler's force norms are
// those of the target again afterwards (the test's force scale).
PetscErrorCode StaticAnalysis::loadChange(Vec U, double* change) {
  PetscFunctionBeginUser;
  if (!Fwork_) PetscCall(VecDuplicate(F_, &Fwork_));
  PetscCall(asm_.residual(U, equilibrium_, Fwork_));
  PetscCall(asm_.residual(U, ls_, F_));
  PetscCall(VecAXPY(Fwork_, -1.0, F_));
  PetscReal n = 0;
  PetscCall(VecNorm(Fwork_, NORM_2, &n));
  *change = n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The statics rules of the Newton test (solvers/newton_test.hpp):
//   (1) start: below -snes_rtol times the residual of the increment at its start state (before the predictor);
//   (2) force: below -force_rtol times the force scale (external loads, converged internal forces);
//   (3) start-at-floor and stalled: at the round-off floor 8 eps ||J||_inf max|X|, a start residual below
//       1e-2 of it (no load: below it), or a residual below it and 1e-3 of the start that no longer
//       drops tenfold per iteration;
//   (4) converged on the update: with fine ANCF cables the round-off noise of the stored positions
//       (eps |x| in each coordinate, amplified by the bending stiffness EI/h^3) can exceed the load
//       itself, so no residual test can pass. The noise is a pattern of self-equilibrated element
//       moments that moves the solution by almost nothing; the Newton update measures the distance
//       to the solution. Newton stops when the update is below 1e-8 of |U| (or below 1e-6 and no
//       longer shrinking tenfold) while the residual is below the 2-norm floor
//       8 eps ||J||_inf max|X| sqrt(unknowns). Only with an accurate linear solve (the element-wise
//       operator, -tangent_operator) or when no residual test can pass (start residual below that floor).
//       The update is the full Newton step (a line search's fraction lambda divided out). With the
//       element-wise operator rules (3) are off: the floor estimate, dominated by EI/h^3, can exceed a
//       fine cable's whole load, so a stalled residual below it proves nothing there.
//   A Newton that converges does so within a few iterations (mixed-stress tangent: 3-6 on the
//   roll-ups); one still above its start residual after -newton_diverged_its iterations is wandering
//   (a too large increment): it is given up early so the increment is halved.
// A Newton update below -snes_stol * |x| alone proves nothing and does not end the iteration.
NewtonRules StaticAnalysis::newtonRules() const {
  NewtonRules r;
  r.snes = NewtonRules::Snes::Own;
  r.startRelative = true;
  r.forceRtol = forceRtol_;
  const bool elementwise = Jop_ != nullptr;
  if (unloaded_ || !elementwise) r.startFloorFactor = unloaded_ ? 1.0 : 1e-2;
  r.stalledAtFloor = !elementwise;
  r.divergedIts = elementwise ? 0 : divergedIts_;
  r.update = NewtonRules::Update::Relative;
  r.updateTight = 1e-8;
  r.updateLoose = 1e-6;
  r.updateFloorFactor = std::sqrt(static_cast<double>(asm_.mesh().numGlobalUnknowns));
  r.updateNeedsStartAtFloor = !elementwise;
  r.updateDividesLineSearch = true;
  return r;
}

PetscErrorCode StaticAnalysis::solveIncrement(Vec U, double lambda, bool* ok, int* its, double* fnorm,
                                              SNESConvergedReason* why) {
  PetscFunctionBeginUser;
  ls_.loadFactor = lambda;
  ls_.time = timeAt(lambda);
  NewtonOutcome out;
  PetscCall(solveNewton(snes_, U, &out));
  *why = out.reason;
  *its = out.iterations;
  *fnorm = out.residualNorm;
  const double f = out.residualNorm;
  // a reported convergence with a residual above its start value (a line search ending on a wild
  // trial point) is a failure, whatever the reason code says; not so when both are at the round-off
  // floor (a load below it: the Newton step is the solution, its residual round-off)
  const double floor = roundoffFloor(jacobianNorm_, coordMax_);
  const bool atFloor = newtonTest_.startResidual() <= floor && f <= floor;
  *ok = *why > 0 && (f <= newtonTest_.startResidual() || newtonTest_.convergedOnUpdate() || atFloor);
  if (*why > 0 && !*ok) *why = SNES_DIVERGED_LINE_SEARCH;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// SPACAR Light's load steps: step 1 is the state under the initial loads (`force_initial`,
// `moment_initial`, `pressure_initial`) and initial prescribed motions (`displ_initial_*`,
// `rot_initial`) alone; the standard loads and motions ramp linearly over the remaining steps and
// reach their value at the last one: lambda_k = (k - 1) / (n - 1). One step is the full load.
// opt.load_ramp uniform: lambda_k = k / n (initial loads and the first increment solved together).
double StaticAnalysis::stepFactor(int step) const {
  if (uniform_ || loadsteps_ == 1) return static_cast<double>(step) / loadsteps_;
  return static_cast<double>(step - 1) / (loadsteps_ - 1);
}

PetscErrorCode StaticAnalysis::run(Vec U, const StepCallback& onStep, bool* converged) {
  PetscFunctionBeginUser;
  MPI_Comm comm = asm_.mesh().comm;
  newtonTest_.rules() = newtonRules();
  Vec Usave;  // state before the increment; dU_: last converged increment (secant predictor)
  PetscCall(VecDuplicate(U, &Usave));
  if (!dU_) PetscCall(VecDuplicate(U, &dU_));
  Vec dU = dU_;
  // a resumed run (resume()) continues with the step-size state of its checkpoint
  double dlPrev = resumed_ ? progress_.dlPrev : 0.0;
  // adaptive increments: a halved increment grows back (x2 after an increment that converged in at
  // most -increment_grow_its Newton iterations), never beyond the user's load step; the size carries
  // over to the next load step, so a hard stretch is not retried at full size step after step.
  // Fixed increments: each load step starts with its whole increment, halved on failure.
  const double dlMax = loadsteps_ == 1 ? 1.0 : stepFactor(2) - stepFactor(1);
  const double dlAdaptStart = resumed_ ? progress_.dlAdapt : dlMax;
  StepRules rules;
  rules.maxCuts = maxCuts_;
  rules.cutProposal = !adaptive_;
  rules.growIts = adaptive_ ? growIts_ : -1;
  rules.maxStep = dlMax;
  rules.landing = Landing::Absolute;
  rules.landingSlack = 1e-9 * dlMax;  // no sliver increments
  rules.firstSize = adaptive_ ? FirstSize::CarriedWithinRest : FirstSize::Rest;
  StepController control(rules, {"load step", "load factor", "increment"});
  control.resume(dlAdaptStart);
  *converged = true;
  double lambda = resumed_ ? progress_.lambda : 0.0;
  // loads of the start state's equilibrium: nothing applied (the reference state), or those of the resumed step
  equilibrium_ = LoadState{};
  equilibrium_.initialFactor = resumed_ ? 1.0 : 0.0;
  equilibrium_.loadFactor = lambda;
  equilibrium_.time = timeAt(lambda);
  {
    LoadState start;  // the converged state the run starts from
    start.loadFactor = lambda;
    start.time = timeAt(lambda);
    PetscCall(asm_.setMixedReference(U, start));
  }
  StepReport rep;
  bool predictNext = true, predicted = false;
  std::vector<Mat3> Rsave;
  SNESConvergedReason why = SNES_CONVERGED_ITERATING;
  double fnorm = 0;

  SteppedProcedure increment;
  increment.solve = [&](double from, double next, double, StepAttempt* a) -> PetscErrorCode {
    PetscCall(VecCopy(U, Usave));
    Rsave = asm_.referenceRotations();
    // residual of the load increment at the start state: -snes_rtol is relative to it (not to
    // the residual of the predicted state, which the stiff axial modes can make much larger)
    ls_.loadFactor = next;
    ls_.time = timeAt(next);
    PetscCall(asm_.residual(U, ls_, F_));
    PetscReal fnormStart = 0;
    PetscCall(VecNorm(F_, NORM_2, &fnormStart));
    newtonTest_.setStartResidual(fnormStart);
    // predictor: extrapolate the last increment (rotation increments included)
    bool guessed = false;  // a coarser level's state at this load factor (-target_error levels)
    if (handover_ && handover_->fromStart && handover_->start.nodes.empty())  // U: the start state (the residual above)
      PetscCall(gatherLevelState(asm_, from, &handover_->start));
    if (handover_ && predictNext) PetscCall(startFromGuess(U, next, &guessed));
    const bool extrapolate = dlPrev > 0 && predictor_ && predictNext;
    if (guessed && extrapolate && handover_->fromStart)  // after form finding: the nearer of the two starts
      PetscCall(nearerStart(U, Usave, dU, (next - from) / dlPrev, &guessed));
    predicted = guessed || extrapolate;
    if (predicted && !guessed) PetscCall(VecAXPY(U, (next - from) / dlPrev, dU));
    if (coarse_ && coarsePredictor_) PetscCall(coarse_->predict(U, ls_));  // nonlinear coarse solve first
    PetscCall(solveIncrement(U, next, &a->converged, &a->iterations, &fnorm, &why));
    a->reason = SNESConvergedReasons[why];
    rep.newtonIterations += a->iterations;
    ++rep.increments;
    rep.residualNorm = fnorm;
    rep.convergedOnUpdate = rep.convergedOnUpdate || newtonTest_.convergedOnUpdate();
    rep.relativeUpdate = newtonTest_.relativeUpdate();
    if (a->converged) return PETSC_SUCCESS;
    PetscCall(VecCopy(Usave, U));
    asm_.setReferenceRotations(Rsave);
    LoadState last = ls_;
    last.loadFactor = from;
    last.time = timeAt(from);
    PetscCall(asm_.setMixedReference(U, last));
    // a failed LU factorization (MUMPS) must not be reused by the retry: refactor from scratch
    KSP ksp;
    PC pc;
    PetscCall(SNESGetKSP(snes_, &ksp));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCReset(pc));
    return PETSC_SUCCESS;
  };
  increment.accept = [&](double from, double next, double h, const StepAttempt&) -> PetscErrorCode {
    predictNext = true;
    PetscCall(VecWAXPY(dU, -1.0, Usave, U));
    PetscCall(asm_.residual(U, ls_, F_));  // line searches may end on a trial evaluation
    fintConverged_ = asm_.internalForceNorm();
    PetscCall(asm_.setMixedReference(U, ls_));  // the next increment's stresses start from this state
    if (h != 0) dlPrev = next - from;  // step 1 of SPACAR Light's steps (size 0): no increment for the predictor
    if (handover_) PetscCall(recordState(next));  // the states are those of U (the residual above)
    PetscCall(asm_.absorbRotations(U));
    equilibrium_ = ls_;  // the loads of the state just converged (tiny-load rule of the Newton test)
    return PETSC_SUCCESS;
  };
  // the extrapolation (or a coarser level's state) can overshoot a sharply bending path: the same
  // increment from the last state
  increment.retry = [&](const StepAttempt&, bool* retry, std::string*) -> PetscErrorCode {
    *retry = predicted;
    if (predicted) predictNext = false;
    return PETSC_SUCCESS;
  };
  increment.print = [comm](const std::string& m) { PetscPrintf(comm, "%s", m.c_str()); };

  StepSequence steps;
  steps.first = (resumed_ ? progress_.step : 0) + 1;
  steps.last = lastStep_;
  steps.target = [this](int k) { return stepFactor(k); };
  // SPACAR Light's step 1 (target 0): one solve under the initial loads and motions alone
  steps.solveAtTarget = [this](int k) { return stepFactor(k) == 0.0 && !startIsInitial_; };
  steps.begin = [&](int k) -> PetscErrorCode {
    rep = StepReport{};
    rep.step = k;
    predictNext = true;
    return PETSC_SUCCESS;
  };
  steps.reached = [&](int& k, StepStop* stop) -> PetscErrorCode {
    rep.loadFactor = lambda;
    reports_.push_back(rep);
    progress_ = {k, lambda, dlPrev, adaptive_ ? control.carried() : dlAdaptStart, fintConverged_};
    if (onStep) PetscCall(onStep(rep, U));
    if (stop_ && *stop_) *stop = StepStop::Interrupted;
    return PETSC_SUCCESS;
  };
  StepStop stop;
  PetscCall(control.run(increment, steps, &lambda, &stop));
  if (stop == StepStop::CutLimit) PetscCall(fail(control, lambda, why, fnorm, converged));
  PetscCall(VecDestroy(&Usave));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The failure of load step control.step(): its last increment to control.lastEnd() did not
// converge (SNES reason `why`, residual `fnorm`), after -max_cuts halvings or, at the initial loads
// alone (an increment of size 0), at once.
PetscErrorCode StaticAnalysis::fail(const StepController& control, double lambda, SNESConvergedReason why, double fnorm,
                                    bool* converged) {
  PetscFunctionBeginUser;
  const bool initial = control.lastSize() == 0;
  std::ostringstream msg;
  msg << "load step " << control.step() << " of " << lastStep_ << " did not converge: Newton stopped at load factor "
      << control.lastEnd() << " (" << SNESConvergedReasons[why] << ", residual norm " << fnorm << ")";
  if (initial)
    msg << " under the initial loads and prescribed motions alone (SPACAR Light's step 1: they act in full, "
           "in one increment that cannot be cut). Try moving part of them to the ramped loads and motions "
           "(force, moment, displ_*, rot instead of *_initial), a line search (-snes_linesearch_type bt|l2), "
           "-snes_monitor to watch the residual, or check supports and rigid modes for a mechanism.";
  else
    msg << " after " << maxCuts_ << " halvings of the increment (last converged load factor " << lambda
        << "). Try more load steps (-loadsteps), a line search (-snes_linesearch_type bt|l2), "
           "-snes_monitor to watch the residual, or check supports and rigid modes for a mechanism.";
  // a tangent with Inf/NaN entries is no singular model: MUMPS refuses it, PETSc's LU may not, so
  // the constraint check it would trigger could name a mechanism on some rank counts only
  linearFailed_ = why == SNES_DIVERGED_LINEAR_SOLVE && tangentFinite_;
  if (!tangentFinite_ || why == SNES_DIVERGED_FNORM_NAN)
    msg << (tangentFinite_ ? " The residual is not finite (Inf/NaN)."
                           : " The tangent stiffness is not finite (Inf/NaN, or entries above 1e154).");
  failure_ = msg.str();
  *converged = false;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
