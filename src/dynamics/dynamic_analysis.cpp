#include "dynamics/dynamic_analysis.hpp"
#include "parallel/collective_error.hpp"
#include "solvers/cut_corrected_lu.hpp"
#include "solvers/solver_defaults.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sinew {

LoadState DynamicAnalysis::loadsAt(double t) {
  LoadState ls;
  ls.loadFactor = 1.0;       // loads act from t = 0 (step loads); user functions see t
  ls.gravityRamped = false;
  ls.timeFunctions = true;   // loads and prescribed motions given as functions of time act at t
  ls.time = t;
  return ls;
}

DynamicAnalysis::Scheme DynamicAnalysis::checkScheme(const DistributedMesh& mesh, Scheme scheme) {
  if (scheme == Scheme::TSAlpha2 && mesh.anyRotations)
    throw SceneError("-dynamics_scheme", "tsalpha2 integrates the unknowns as a vector space; beam rotations need the "
                                         "Lie-group form of the default scheme (arnold_bruls)");
  if (scheme == Scheme::EnergyMomentum) {
    // the first set (lowest eprops index, agreed on every rank) whose kernels have no step force
    RunFailure local;
    long key = -1;
    for (const LocalElement& e : mesh.elements) {
      if (e.kernel->hasStepForce() || (key >= 0 && e.set >= key)) continue;
      key = e.set;
      const char* field = e.kernel->stepForceRefusal();
      local = {2, std::string(e.kernel->name()) + " elements of " + (e.set >= 0 ? epropsName(e.set) : "the model") +
                      (field ? " with " + std::string(field) + ": a user force law is not the gradient of a strain energy"
                             : ": no step force")};
    }
    const RunFailure agreed = agreeOnFailure(mesh.comm, local, key);
    if (agreed)
      throw SceneError("-dynamics_scheme", "energy_momentum needs the step force of a strain energy; this model has " +
                                               agreed.message + " (use midpoint or arnold_bruls)");
  }
  return scheme;
}

DynamicAnalysis::DynamicAnalysis(Assembler& assembler, const DynamicsOptions& opts, const Settings& all)
    : asm_(assembler), opts_(opts), damping_(assembler, opts, all.eigen, all.dynamics.stiffnessDamping) {
  const DynamicsSettings& settings = all.dynamics;
  const StaticsSettings& newton = all.statics;
  ls_ = loadsAt(0.0);
  MPI_Comm comm = asm_.mesh().comm;
  SinewCallThrow(comm, asm_.createMatrix(&J_));
  SinewCallThrow(comm, asm_.createVector(&F_));
  const Scheme scheme = checkScheme(asm_.mesh(), settings.scheme);
  maxCuts_ = newton.maxCuts;
  denseMax_ = newton.denseMaxUnknowns;
  growAfter_ = settings.dtGrowAfter;
  if (growAfter_ < 0) throw SceneError("-dt_grow_after", "expected a count >= 0, got " + std::to_string(growAfter_));
  const StepControlSettings sc = stepControl(opts_, settings, scheme);
  control_ = sc.control;
  dtMin_ = sc.dtMin;
  dtMax_ = sc.dtMax;
  adaptTol_ = sc.tol;
  adaptIts_ = sc.its;
  forceRtol_ = newton.forceRtol.value_or(forceRtol_);
  // modified Newton pays where a Jacobian and its factorization cost much more than a residual and
  // a solve; measured (docs/ancf_cable2d.md): A3 with 64 elements (258 unknowns) 1.8x faster, 512
  // elements 1.4x, a 16-element pendulum (66 unknowns) 1.1x slower: auto = from 200 unknowns
  const AutoSwitch mode = settings.modifiedNewton;
  modifiedNewton_ = mode == AutoSwitch::On || (mode == AutoSwitch::Auto && asm_.mesh().numGlobalUnknowns >= 200);
  chain_ = ancfChain(asm_.mesh());
  corotated_ = settings.corotatedJacobian && modifiedNewton_ && scheme == Scheme::ArnoldBruls && chain_;
  if (corotated_) corotatedMatrix_ = std::make_unique<CorotatedNewtonMatrix>(asm_);
  // refined step solves (setRefinements): once (true), never (false), or auto: added while Newton's
  // updates on an unchanged matrix contract by less than kRefineContraction (the LU's accuracy in the
  // smooth modes limits Newton: A1g at 65536 elements 7.5e-3; at 4096 1e-5..1e-4, where a refinement
  // would only cost), see formJacobian; not when the user chose another KSP for the step solves
  // (runArnoldBruls)
  refineAuto_ = corotated_ && settings.refine == AutoSwitch::Auto;
  refinements_ = corotated_ && settings.refine == AutoSwitch::On ? 1 : 0;
  // ANCF chains on several ranks: rank-local LU with the exact correction of the few coupling
  // unknowns (useCutCorrectedLU) instead of every rank factoring the whole chain (PCREDUNDANT); A1g
  // at 65536 elements, 2 ranks: 28 ms against 42 ms per factorization, 2.1 ms against 5.2 ms per
  // solve (docs/performance.md, "The direct solver of a chain")
  // the kept LU turned with the nodes (useNodeRotatedPC): always (true), never (false), or auto: from
  // the first kept matrix that stalled by an element turn below kRotationTurn (A1g: from 16384
  // elements), where turned kept matrices would otherwise be rebuilt and refactored in every step
  // (docs/performance.md)
  const AutoSwitch nr = settings.nodeRotation;
  nodeRotation_ = !corotated_ || nr == AutoSwitch::Off ? NodeRotation::Off
                  : nr == AutoSwitch::On               ? NodeRotation::On
                                                       : NodeRotation::Auto;
  rotating_ = nodeRotation_ == NodeRotation::On;
  const ChainLU lu = settings.chainLU;
  cutLU_ = chain_ && (lu == ChainLU::Cut ||
                      (lu == ChainLU::Auto && couplingUnknowns(asm_.mesh()) <= kCutCorrectedMaxCoupling));
  mumpsWorkspace_ = settings.mumpsWorkspace;
  // Newton with mixed stresses for beams, as in statics (docs/beam.md): a large rotation step moves
  // the nodes along straight lines and stretches axially stiff elements; the displacement-based
  // tangent would carry that spurious axial force (residuals alternating by 1e2 per iteration on a
  // swinging leaf spring at dt = T1/24). Each step's stresses are linearized from q_n.
  asm_.setMixedStressNewton(newton.mixedStresses && asm_.hasMixedStressKernels());
  // the complete consistent beam mass (its kinetic energy's inertia force) in the Arnold-Bruls loop;
  // the midpoint and energy-momentum rules take element masses as M(q_{n+1/2}) (qd_{n+1} - qd_n)/h
  asm_.setCompleteInertia(scheme == Scheme::ArnoldBruls || scheme == Scheme::EnergyMomentum);
  // Newton's start of a step. The extrapolation q_n + h qd_n + h^2/2 a_n carries the algorithmic
  // accelerations of the modes the step does not resolve (h omega >> 1: the axial and the short
  // bending waves of a fine cable, omega ~ 1/l_e resp. 1/l_e^2). Those are noise of amplitude
  // ~ (their displacement error)/(beta h^2), only damped by rho per step; extrapolated, they put
  // each element far off its quasi-static state: A1g at 4096 elements started Newton at a residual
  // of 1e5..5e8 (full Newton diverged to 1e14, modified Newton stalled and refactored: 104 Newton
  // iterations on 49 Jacobians in 20 steps, 61 retried steps in 100 on one process). q_n has a
  // smooth error (the inertia M qd_n/(beta h) of one step's motion): from a residual of 43..1400
  // Newton converges in 2 iterations per step (the update test of convergenceTest), no retries.
  // auto: q_n from 200 unknowns (where modified Newton keeps the Jacobian) and for beams (below); else
  // the extrapolation (A3 with 1 element: 2000 iterations against 2779 from q_n).
  const DynamicsPredictor pr = settings.predictor;
  const bool fine = asm_.mesh().numGlobalUnknowns >= 200;
  // Beams (mixed-stress Newton) start from q_n at any size, as statics has no secant predictor for
  // them: the additive extrapolation of positions and rotation vectors stretches the elements. The
  // leaf spring swinging under its weight (scripts/study_beam_dynamics.py, 16 elements, dt = T1/24)
  // took 303 Newton iterations with 5 retried steps from the extrapolation, 36 from q_n; without the
  // mixed stresses the extrapolation even converged to another root of the step equations (tip
  // -0.318 m at t = 0.3 s against -0.266 m from q_n and from every smaller step: -0.268 m).
  predictor_ = pr == DynamicsPredictor::State || pr == DynamicsPredictor::Rotation ||
                       (pr == DynamicsPredictor::Auto && (fine || asm_.mixedStressNewton()))
                   ? Predictor::State
                   : Predictor::Acceleration;
  // rotation: q_n moved by each node's rigid motion over the step (Assembler::rigidMotionPredictor),
  // which follows a fast rotation that q_n misses by h Omega r (the spin-up at 6 rad/s: 3 Newton
  // iterations per step instead of 4). Not the default: on the leaf swinging under its weight in 12
  // steps (test_beam_dynamics_swing) it took 62 iterations against 36 from q_n (192 steps: 386 against 510).
  followRotation_ = pr == DynamicsPredictor::Rotation;
  coordMax_ = asm_.coordinateScale();
  int mult = 0;
  for (const LocalElement& e : asm_.mesh().elements) mult |= e.firstMultiplier >= 0;
  MPI_Allreduce(MPI_IN_PLACE, &mult, 1, MPI_INT, MPI_LOR, comm);
  if (mult) {
    SinewCallThrow(comm, VecDuplicate(F_, &keep_));
    SinewCallThrow(comm, VecSet(keep_, 1.0));
    PetscScalar* k = nullptr;
    SinewCallThrow(comm, VecGetArray(keep_, &k));
    for (const LocalElement& e : asm_.mesh().elements)
      for (int j = 0; e.firstMultiplier >= 0 && j < e.kernel->numConstraints(); ++j) k[e.firstMultiplier + j] = 0.0;
    SinewCallThrow(comm, VecRestoreArray(keep_, &k));
  }
  if (scheme == Scheme::EnergyMomentum) {
    int state = 0;
    for (const LocalElement& e : asm_.mesh().elements) state |= e.kernel->hasInertia() && e.kernel->massDependsOnState();
    MPI_Allreduce(MPI_IN_PLACE, &state, 1, MPI_INT, MPI_LOR, comm);
    stateMassSteps_ = state != 0;
    if (stateMassSteps_)  // docs/dynamics.md "Energy-momentum scheme": the consistent mass' step is not a discrete gradient
      SinewCallThrow(comm, PetscPrintf(comm, "  warning: -dynamics_scheme energy_momentum with the consistent beam mass: the "
                                             "step does not keep the energy exactly (its inertia is taken at q_n+1) and stiff "
                                             "beams can gain energy; -beam_mass linear (its default) or lumped gives the exact "
                                             "energy-momentum step\n"));
  }
  // the scheme, with the multipliers (no rates) and the rotation unknowns (Lie-group form) of the model
  if (scheme == Scheme::TSAlpha2) {
    auto ts = std::make_unique<TSAlpha2Scheme>(static_cast<MotionEquations&>(*this));
    tsScheme_ = ts.get();
    scheme_ = std::move(ts);
  } else if (scheme == Scheme::EnergyMomentum) {
    auto em = std::make_unique<EnergyMomentumScheme>(settings.energyDecay, F_, keep_, &asm_);
    stepScheme_ = emScheme_ = em.get();
    scheme_ = std::move(em);
  } else if (scheme == Scheme::Midpoint) {
    auto mid = std::make_unique<MidpointScheme>(F_, keep_, &asm_);
    stepScheme_ = midpointScheme_ = mid.get();
    scheme_ = std::move(mid);
    if (keep_) SinewCallThrow(comm, VecDuplicate(F_, &Fend_));
  } else {
    auto alpha = std::make_unique<GeneralizedAlphaScheme>(opts_.spectral_radius, F_, keep_, &asm_);
    stepScheme_ = alphaScheme_ = alpha.get();
    scheme_ = std::move(alpha);
  }
}

DynamicAnalysis::~DynamicAnalysis() {
  scheme_.reset();
  SNESDestroy(&snes_);
  MatDestroy(&J_);
  MatDestroy(&Jop_);
  for (Vec* v : {&F_, &keep_, &U0_, &Fend_}) VecDestroy(v);
}

// ---------------------------------------------------------------- the step schemes' own step loop
// (its Newton step: dynamic_newton.cpp)

PetscErrorCode DynamicAnalysis::formFunction(SNES, Vec U, Vec F, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<DynamicAnalysis*>(ctx);
  PetscCall(self->stepScheme_->rates(U));
  PetscCall(self->stepResidual(U, self->stepScheme_->evaluation(U), F));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// M qdd_0 = f_ext(0) - f_int(q_0, qd_0, 0): one KSP solve (options prefix init_, LU by default).
PetscErrorCode DynamicAnalysis::initialAccelerations(Vec U, Vec V, Vec Qdd, bool* ok) {
  PetscFunctionBeginUser;
  MPI_Comm comm = asm_.mesh().comm;
  Mat M;
  PetscCall(asm_.createMatrix(&M));
  LoadState ls0 = ls_;
  ls0.time = 0.0;
  PetscCall(asm_.mass(U, ls0, M));
  PetscCall(VecSet(Qdd, 0.0));
  PetscCall(asm_.dynamicResidual(U, V, Qdd, ls0, F_));  // f_int - f_ext
  PetscCall(VecScale(F_, -1.0));
  KSP ksp;
  PetscCall(KSPCreate(comm, &ksp));
  PetscCall(KSPSetOptionsPrefix(ksp, "init_"));
  Mat K = nullptr, A = nullptr;
  double s = 1.0;
  if (keep_) {
    // Constraints (index 3): M a0 + G^T lambda0 = r, G a0 = 0 (at rest). The tangent at shiftA = s
    // is A_s = [K + s M, G^T; G, 0]; with x = a0 / s, A_s [x; lambda0] = [r + K x; 0], solved by
    // fixed-point iteration from x = 0 (rate ||K|| / (s ||M||) = 1e-4 with s below).
    PetscCall(asm_.createMatrix(&K));
    PetscCall(asm_.createMatrix(&A));
    PetscCall(asm_.dynamicJacobian(U, V, nullptr, ls0, 0.0, 0.0, K));
    PetscReal nk = 0, nm = 0;
    PetscCall(MatNorm(K, NORM_INFINITY, &nk));
    PetscCall(MatNorm(M, NORM_INFINITY, &nm));
    s = nm > 0 && nk > 0 ? 1e4 * nk / nm : 1.0;
    PetscCall(asm_.dynamicJacobian(U, V, nullptr, ls0, 0.0, s, A));
    PetscCall(KSPSetOperators(ksp, A, A));
  } else {
    PetscCall(KSPSetOperators(ksp, M, M));
  }
  PetscCall(useDirectSolver(ksp));
  if (chain_) PetscCall(useChainLU(ksp, comm));
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(KSPSolve(ksp, F_, Qdd));
  KSPConvergedReason why;
  PetscCall(KSPGetConvergedReason(ksp, &why));
  if (keep_) {
    Vec x, rhs;
    PetscCall(VecDuplicate(Qdd, &x));
    PetscCall(VecDuplicate(Qdd, &rhs));
    for (int it = 0; it < 6 && why >= 0; ++it) {
      PetscCall(VecPointwiseMult(x, keep_, Qdd));
      PetscCall(MatMult(K, x, rhs));
      PetscCall(VecPointwiseMult(rhs, keep_, rhs));  // K x on the coordinate rows, 0 on the constraints
      PetscCall(VecAXPY(rhs, 1.0, F_));
      PetscCall(KSPSolve(ksp, rhs, Qdd));
      PetscCall(KSPGetConvergedReason(ksp, &why));
    }
    // Qdd = [x; lambda0]: a0 = s x on the coordinates; lambda0 goes into U (consistent start)
    PetscCall(VecPointwiseMult(x, keep_, Qdd));
    PetscCall(VecAXPY(U, 1.0, Qdd));
    PetscCall(VecAXPY(U, -1.0, x));
    PetscCall(VecScale(x, s));
    PetscCall(VecCopy(x, Qdd));
    PetscCall(VecDestroy(&x));
    PetscCall(VecDestroy(&rhs));
    PetscCall(MatDestroy(&K));
    PetscCall(MatDestroy(&A));
  }
  PetscReal nrm = 0;
  PetscCall(VecNorm(Qdd, NORM_INFINITY, &nrm));
  *ok = why >= 0 && std::isfinite(nrm);
  if (!*ok)
    failure_ = std::string("opt.dynamics: the initial accelerations M a0 = f_ext - f_int could not be solved (") +
               KSPConvergedReasons[why] +
               "); the mass matrix is singular: every free coordinate needs mass (physicsMassPerLength, dens or nodal mass)";
  PetscCall(KSPDestroy(&ksp));
  PetscCall(MatDestroy(&M));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::step(double t1, bool* ok, int* its, double* fnorm, SNESConvergedReason* why, bool commit) {
  PetscFunctionBeginUser;
  const double h = h_;
  Vec U;
  PetscCall(SNESGetSolution(snes_, &U));
  // a -target_error level in time: Newton starts from the coarser level's state at t1 where it has one
  // (not on a guarded retry), instead of the predictor (level_time_reuse.cpp)
  bool coarseStart = false;
  if (coarse_ && !restPredictor_) PetscCall(startFromCoarseLevel(t1, U, &coarseStart));
  const bool rotated = followRotation_ && !restPredictor_ && !coarseStart;
  if (asm_.mixedStressNewton() && !rotated && !coarseStart) {  // the mixed-stress tangent linearizes from the converged q_n (also on a retry)
    LoadState lsn = ls_;
    lsn.time = t1 - h;
    PetscCall(asm_.setMixedReference(stepScheme_->state().q, lsn));
  }
  if (emScheme_) {  // the step forces start from q_n
    LoadState lsn = ls_;
    lsn.time = t1 - h;
    PetscCall(asm_.setStepStart(stepScheme_->state().q, lsn));
  }
  ls_.time = t1;
  PetscCall(stepScheme_->beginStep(h));
  // Newton starts at the scheme's extrapolation or at q_n; guarded: at q_n (an extrapolation by the
  // accelerations of a step load on a fine mesh lands far outside Newton's reach: stiff axial waves)
  if (coarseStart) {
    // the mixed stresses linearize from the start, near q_{n+1} (as from the rotation predictor's)
    if (asm_.mixedStressNewton()) PetscCall(asm_.setMixedReference(U, ls_));
  } else if (restPredictor_ || predictor_ == Predictor::State) {
    PetscCall(VecCopy(stepScheme_->state().q, U));
  } else {
    PetscCall(stepScheme_->predict(U));
  }
  if (rotated) {
    // q_n moved by each node's rigid motion; the mixed stresses linearize from there (linearized from
    // q_n, the strains of a turn by h Omega are off by ~ (h Omega)^2 / 2 of the element: the spin-up at
    // 6 rad/s took 4 Newton iterations per step instead of 3)
    PetscCall(asm_.rigidMotionPredictor(stepScheme_->state().qd, h, U));
    if (asm_.mixedStressNewton()) PetscCall(asm_.setMixedReference(U, ls_));
  }
  NewtonOutcome out;
  PetscCall(solveNewton(snes_, U, &out));
  *why = out.reason;
  *its = out.iterations;
  *fnorm = out.residualNorm;
  *ok = *why > 0;
  if (!*ok) jacobianValid_ = false;  // a failed solve starts the retry from a fresh Jacobian
  if (*ok) {
    PetscCall(stepScheme_->rates(U));
    if (commit) PetscCall(stepScheme_->commit(U));
    if (coarseStart) {
      ++report_.coarseStarts;
      ++handover_->guessesUsed;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

void DynamicAnalysis::setGuarded(bool on) {
  restPredictor_ = on;
  modifiedNewton_ = on ? false : modifiedDefault_;
}

// A time step t -> t1 of size h for the StepController: solved by step() (committed at once with
// `commit`). Guarded mode: a failed solve is first retried at the same step size with full Newton
// started at q_n instead of the extrapolated predictor, then by halving (still guarded); the next
// time step starts plain again (a diverging extrapolation is caught early: DIVERGED_DTOL).
SteppedProcedure DynamicAnalysis::timeStep(bool commit, SNESConvergedReason* why, double* fnorm) {
  SteppedProcedure p;
  p.solve = [this, commit, why, fnorm](double, double t1, double h, StepAttempt* a) -> PetscErrorCode {
    h_ = h;
    PetscCall(step(t1, &a->converged, &a->iterations, fnorm, why, commit));
    a->reason = SNESConvergedReasons[*why];
    report_.newtonIterations += a->iterations;
    ++report_.substeps;
    return PETSC_SUCCESS;
  };
  p.retry = [this](const StepAttempt&, bool* retry, std::string* how) -> PetscErrorCode {
    *retry = !restPredictor_;
    if (!*retry) return PETSC_SUCCESS;
    setGuarded(true);
    ++report_.guardedSteps;
    *how = "full Newton from the last state";
    return PETSC_SUCCESS;
  };
  MPI_Comm comm = asm_.mesh().comm;
  p.print = [comm](const std::string& m) { PetscPrintf(comm, "%s", m.c_str()); };
  return p;
}

PetscErrorCode DynamicAnalysis::runArnoldBruls(Vec U, const StepCallback& onStep, bool* converged) {
  PetscFunctionBeginUser;
  MPI_Comm comm = asm_.mesh().comm;
  PetscCall(SNESCreate(comm, &snes_));
  PetscCall(SNESSetType(snes_, SNESNEWTONLS));
  PetscCall(SNESSetFunction(snes_, F_, formFunction, this));
  if (refinements_ > 0 || refineAuto_) {
    PetscInt m = 0, n = 0, M = 0, N = 0;
    PetscCall(MatGetLocalSize(J_, &m, &n));
    PetscCall(MatGetSize(J_, &M, &N));
    PetscCall(MatCreateShell(comm, m, n, M, N, this, &Jop_));
    PetscCall(MatShellSetOperation(Jop_, MATOP_MULT, reinterpret_cast<void (*)(void)>(applyNewtonMatrix)));
  }
  PetscCall(SNESSetJacobian(snes_, Jop_ ? Jop_ : J_, J_, formJacobian, this));
  PetscCall(SNESSetTolerances(snes_, 1e-50, 1e-10, 1e-12, 50, 10000));
  // a residual 1e6 times its start is a diverged Newton solve: retried at once, not after 50 iterations
  PetscCall(SNESSetDivergenceTolerance(snes_, 1e6));
  SNESLineSearch lsrch;
  PetscCall(SNESGetLineSearch(snes_, &lsrch));
  PetscCall(SNESLineSearchSetType(lsrch, SNESLINESEARCHBASIC));
  newtonTest_.rules() = newtonRules();
  PetscCall(SNESSetConvergenceTest(snes_, convergenceTest, this, nullptr));
  KSP ksp;
  PetscCall(SNESGetKSP(snes_, &ksp));
  PetscCall(useDynamicsSolver(ksp));
  if (refinements_ > 0) PetscCall(setRefinements(ksp, refinements_));
  PetscCall(SNESSetFromOptions(snes_));
  if (refineAuto_) {  // the step solves' KSP chosen by the user (-ksp_type): auto does not change it
    KSPType type;
    PetscBool preonly = PETSC_FALSE;
    PetscCall(KSPGetType(ksp, &type));
    PetscCall(PetscStrcmp(type, KSPPREONLY, &preonly));
    refineAuto_ = preonly;
  }
  Vec Usol;
  PetscCall(VecDuplicate(U, &Usol));
  PetscCall(SNESSetSolution(snes_, Usol));
  PetscCall(VecDestroy(&Usol));

  bool ok = false;
  const SchemeState state = stepScheme_->state();  // the scheme's step start q_n, qd_n, a_n, qdd_n
  // a resumed run: the damping of the start state (setupResumedDamping), or, from a checkpoint
  // without that state (older files, Restart::resumeDynamics warns), of the resumed state
  if (resumed_ && !dampingReady_) PetscCall(setupDamping(state.q));
  if (!resumed_) {
    PetscCall(VecCopy(U, state.q));
    PetscCall(asm_.absorbRotations(state.q));  // rotation unknowns are increments from R_n (0 at a step start)
    PetscCall(setupDamping(state.q));
    PetscCall(VecSet(state.qd, 0.0));
    PetscCall(initialAccelerations(state.q, state.qd, state.qdd, &ok));
    if (!ok) {
      *converged = false;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    PetscCall(VecCopy(state.qdd, state.a));  // a_0 = qdd_0
    progress_ = {0, 0.0, opts_.dt, 0, 0.0};
    PetscCall(recordLevelStep(0.0, state.q, state.qd));
    if (onStep) PetscCall(onStep(0, 0.0, state.q, state.qd, state.qdd));
  }

  if (adaptive()) {
    PetscCall(runAdaptive(onStep, converged));
    PetscCall(VecCopy(state.q, U));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(useCoarseLevel());
  const double dt = opts_.dt, tend = opts_.tend;
  const int nsteps = std::max(1, static_cast<int>(std::ceil(tend / dt - 1e-9)));
  double t = resumed_ ? progress_.time : 0.0;
  *converged = true;
  // Sub-step size h: halved when Newton fails (at most -max_cuts times per time step), doubled again
  // after growAfter_ successes in a row (never above dt), so one hard moment does not leave the rest
  // of the run at a tiny step. growAfter_ = 0 is the former rule: every time step restarts at dt, no
  // growth inside a step. A remainder below 1e-6 of the sub-step is round-off of the summed
  // sub-steps: the step ends on the target. A resumed run (resume()) continues with the state of its checkpoint.
  StepRules rules;
  rules.maxCuts = maxCuts_;
  rules.growAfter = growAfter_;
  rules.maxStep = dt;
  rules.landing = Landing::Relative;
  rules.landingSlack = 1e-6;
  rules.firstSize = growAfter_ == 0 ? FirstSize::Max : FirstSize::Carried;
  StepController control(rules, {"time step", "time", "dt"});
  control.resume(resumed_ ? progress_.h : dt, resumed_ ? progress_.successes : 0);
  modifiedDefault_ = modifiedNewton_;
  SNESConvergedReason why = SNES_CONVERGED_ITERATING;
  double fnorm = 0;
  bool reduced = false;  // the time step starts below dt
  StepSequence steps;
  steps.first = (resumed_ ? progress_.step : 0) + 1;
  steps.last = nsteps;
  steps.target = [&](int k) { return k == nsteps ? tend : k * dt; };
  steps.begin = [&](int) -> PetscErrorCode {
    reduced = (growAfter_ == 0 ? dt : control.carried()) < dt;
    setGuarded(false);
    return PETSC_SUCCESS;
  };
  steps.reached = [&](int& k, StepStop* stop) -> PetscErrorCode {
    report_.steps = k;
    report_.reducedSteps += reduced || control.cuts() > 0;
    report_.time = t;
    progress_ = {k, t, control.carried(), control.successes(), 0.0};
    PetscCall(recordLevelStep(t, state.q, state.qd));
    if (onStep) PetscCall(onStep(k, t, state.q, state.qd, state.qdd));
    if (stop_ && *stop_) *stop = StepStop::Interrupted;
    return PETSC_SUCCESS;
  };
  StepStop stop;
  PetscCall(control.run(timeStep(true, &why, &fnorm), steps, &t, &stop));
  if (stop == StepStop::CutLimit) {
    std::ostringstream msg;
    msg << "time step " << control.step() << " of " << nsteps << " did not converge: Newton stopped at t = "
        << control.lastEnd() << " (" << SNESConvergedReasons[why] << ", residual norm " << fnorm << ") after " << maxCuts_
        << " halvings of the step (last converged time " << t
        << "). Try a smaller opt.dynamics.dt, a line search (-snes_linesearch_type bt), -snes_monitor, or check "
           "supports and masses.";
    failure_ = msg.str();
    *converged = false;
  }
  PetscCall(VecCopy(state.q, U));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The midpoint rule's momentum balance (MidpointScheme): (p_{n+1} - p_n) / h + f_int(q_{n+1/2}, qd_{n+1/2}) =
// f_ext(t_{n+1/2}), with the momenta p = m qd of nodal masses (M qd for constant element masses) and
// J_s w of rotary inertia (set here: Assembler::setRotaryMomentum). Internal forces of any
// configuration have zero resultant force and moment, so p and H = sum x x p + J_s w change only by
// the external impulse: exactly, for a converged step.
PetscErrorCode DynamicAnalysis::withRotaryMomentum(Vec U, const std::function<PetscErrorCode()>& evaluate, bool cayley) {
  PetscFunctionBeginUser;
  const PetscScalar *u, *w0;
  Vec Vn = stepScheme_->state().qd;
  PetscCall(VecGetArrayRead(U, &u));
  PetscCall(VecGetArrayRead(Vn, &w0));
  asm_.setRotaryMomentum({u, w0, h_, cayley});
  if (cayley) asm_.setStepForces({h_, emScheme_->decay()});
  const PetscErrorCode ierr = evaluate();
  asm_.setRotaryMomentum({});
  asm_.setStepForces({});
  PetscCall(VecRestoreArrayRead(Vn, &w0));
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The loads at the evaluation point's time; the energy-momentum scheme's configuration is the step's
// end q_{n+1}, so its prescribed motions take their values at t_{n+1} (the step force runs from q_n at
// t_n to q_{n+1} at t_{n+1}; at t_{n+1/2} a driven hub's end angle lagged by h Omega / 2).
LoadState DynamicAnalysis::evaluationLoads(const EvaluationPoint& e) const {
  LoadState ls = ls_;
  ls.time += e.timeShift;
  if (e.stepForces) ls.motionTime = ls_.time;
  return ls;
}

PetscErrorCode DynamicAnalysis::stepResidual(Vec U, const EvaluationPoint& e, Vec F) {
  PetscFunctionBeginUser;
  const LoadState ls = evaluationLoads(e);
  if (e.midStep || e.stepForces)
    PetscCall(withRotaryMomentum(U, [&] { return asm_.dynamicResidual(e.q, e.qd, e.qdd, ls, F); }, e.stepForces));
  else PetscCall(asm_.dynamicResidual(e.q, e.qd, e.qdd, ls, F));
  PetscCall(damping_.addForce(e.qd, F));
  if (e.midStep && Fend_) {
    // Rigid elements and rigid deformation modes: their constraints g(q_{n+1}) = 0 hold at the step's
    // end (the rows of the residual at U), while their forces G(q_{n+1/2})^T lambda act at the mid
    // configuration with the other forces. g is invariant under rigid motions, so those forces have
    // no resultant moment there either: the momentum balance stays exact.
    PetscCall(asm_.residual(U, ls_, Fend_));
    PetscCall(VecPointwiseMult(F, keep_, F));
    PetscCall(VecPointwiseMult(Fend_, midpointScheme_->constraintRows(), Fend_));
    PetscCall(VecAXPY(F, 1.0, Fend_));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::stepJacobian(Vec U, const EvaluationPoint& e, Mat P) {
  PetscFunctionBeginUser;
  const LoadState ls = evaluationLoads(e);
  // midpoint: the rotary inertia's block exact (rotaryMomentumStep; the elements' rotation columns are
  // those of the mid state)
  if (e.midStep || e.stepForces)
    PetscCall(withRotaryMomentum(U, [&] { return asm_.dynamicJacobian(e.q, e.qd, e.qdd, ls, e.shiftV, e.shiftA, P); },
                                 e.stepForces));
  else PetscCall(asm_.dynamicJacobian(e.q, e.qd, e.qdd, ls, e.shiftV, e.shiftA, P));
  PetscCall(damping_.addJacobian(e.shiftV, P));
  if (e.jacobianScale != 1.0) PetscCall(MatScale(P, e.jacobianScale));
  if (e.midStep && Fend_) {
    // constraint rows d g(q_{n+1}) / d q_{n+1} ~ G(q_{n+1/2}) (twice the halved mid rows) and
    // multiplier columns G^T (lambda is the mid-step multiplier itself): scale both by 2
    PetscCall(MatDiagonalScale(P, midpointScheme_->constraintScale(), midpointScheme_->constraintScale()));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// ---------------------------------------------------------------- PETSc TSALPHA2 (Chung-Hulbert)

PetscErrorCode DynamicAnalysis::motionResidual(double t, Vec q, Vec qd, Vec qdd, Vec F) {
  PetscFunctionBeginUser;
  LoadState ls = ls_;
  ls.time = t;
  PetscCall(asm_.dynamicResidual(q, qd, qdd, ls, F));
  PetscCall(damping_.addForce(qd, F));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::motionTangent(double t, Vec q, Vec qd, double shiftV, double shiftA, Mat P) {
  PetscFunctionBeginUser;
  LoadState ls = ls_;
  ls.time = t;
  PetscCall(asm_.dynamicJacobian(q, qd, nullptr, ls, shiftV, shiftA, P));
  PetscCall(damping_.addJacobian(shiftV, P));
  // the Newton test's round-off floor (roundoffFloor) scales with the Newton matrix, as formJacobian's
  // (without it the floor was 0 and Newton stalled at the round-off of the residual, 4e-11 on an ANCF cable)
  PetscCall(MatNorm(P, NORM_INFINITY, &jacobianNorm_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::runTSAlpha2(Vec U, const StepCallback& onStep, bool* converged) {
  PetscFunctionBeginUser;
  PetscCall(tsScheme_->create(F_, J_, opts_.spectral_radius, opts_.dt, opts_.tend, maxCuts_));
  SNES snes;
  KSP ksp;
  PetscCall(tsScheme_->snes(&snes));
  PetscCall(SNESSetTolerances(snes, 1e-50, 1e-10, 1e-12, 50, 10000));
  newtonTest_.rules() = newtonRules();
  PetscCall(SNESSetConvergenceTest(snes, convergenceTest, this, nullptr));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(useDirectSolver(ksp));
  Vec V = tsScheme_->state().qd, A;
  PetscCall(VecDuplicate(U, &A));
  PetscCall(VecSet(V, 0.0));
  bool ok = false;
  PetscCall(setupDamping(U));
  PetscCall(initialAccelerations(U, V, A, &ok));
  if (ok) {
    if (onStep) PetscCall(onStep(0, 0.0, U, V, A));
    PetscCall(VecSet(A, 0.0));  // TSALPHA2 does not expose its accelerations: sensors see qdd = 0
    PetscCall(tsScheme_->solve(U, [&](int step, double t, Vec q, Vec qd, bool* stop) -> PetscErrorCode {
      report_.steps = step;
      report_.time = t;
      if (onStep) PetscCall(onStep(step, t, q, qd, A));
      *stop = stop_ && *stop_;
      return PETSC_SUCCESS;
    }));
    int rejected = 0;
    TSConvergedReason why;
    double tfail = 0;
    PetscCall(tsScheme_->statistics(&report_.newtonIterations, &rejected, &why, &tfail));
    report_.jacobians = report_.newtonIterations;  // TS assembles a Jacobian at every Newton iteration
    report_.reducedSteps = rejected;
    ok = why > 0;
    if (!ok) {
      std::ostringstream msg;
      msg << "opt.dynamics with -dynamics_scheme tsalpha2: PETSc's TSALPHA2 stopped at t = " << tfail << " ("
          << TSConvergedReasons[why] << ", after " << report_.steps
          << " time steps): its Newton solves failed even with reduced steps. The default scheme (arnold_bruls) "
             "controls the step itself; else try a smaller opt.dynamics.dt or -snes_linesearch_type bt.";
      failure_ = msg.str();
    }
  }
  *converged = ok;
  PetscCall(VecDestroy(&A));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::setupDamping(Vec U) {
  PetscFunctionBeginUser;
  if (!damping_.active()) PetscFunctionReturn(PETSC_SUCCESS);
  if (!file_) SETERRQ(asm_.mesh().comm, PETSC_ERR_ORDER, "DynamicAnalysis::setResultFile must be called before run() with damping");
  LoadState ls0 = ls_;
  ls0.time = 0.0;
  PetscCall(damping_.setup(U, ls0, keep_, *file_));
  if (!U0_) PetscCall(VecDuplicate(U, &U0_));
  PetscCall(VecCopy(U, U0_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::resume(const DynamicsProgress& p, Vec U, Vec V, Vec A, Vec Qdd) {
  PetscFunctionBeginUser;
  if (!scheme_->restartable())
    SETERRQ(asm_.mesh().comm, PETSC_ERR_SUP, "-dynamics_scheme tsalpha2 keeps its state inside PETSc TS: it cannot resume");
  progress_ = p;
  report_.steps = p.step;
  report_.time = p.time;
  resumed_ = true;
  PetscCall(stepScheme_->restore({U, V, A, Qdd}));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::setupResumedDamping(Vec U0) {
  PetscFunctionBeginUser;
  PetscCall(setupDamping(U0));
  dampingReady_ = true;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::run(Vec U, const StepCallback& onStep, bool* converged) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().dynamics, 0, 0, 0, 0));
  if (tsScheme_) PetscCall(runTSAlpha2(U, onStep, converged));
  else PetscCall(runArnoldBruls(U, onStep, converged));
  PetscCall(PetscLogEventEnd(SinewEvents::get().dynamics, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
