#include "analysis/continuation_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <petscmat.h>
#include <slepceps.h>

#include "parallel/collective_error.hpp"
#include "solvers/newton_test.hpp"
#include "solvers/solver_defaults.hpp"
#include "solvers/step_controller.hpp"

namespace sinew {

ContinuationAnalysis::ContinuationAnalysis(Assembler& assembler, const ContinuationOptions& opt,
                                           const ContinuationSettings& settings, int maxCuts)
    : asm_(assembler), opt_(opt) {
  MPI_Comm comm = asm_.mesh().comm;
  SinewCallThrow(comm, asm_.createMatrix(&K_));
  for (Vec* v : {&R_, &q_, &duR_, &duq_, &dU_, &e_, &work_, &dUprev_}) SinewCallThrow(comm, asm_.createVector(v));
  SinewCallThrow(comm, VecSet(dUprev_, 0.0));
  SinewCallThrow(comm, KSPCreate(comm, &ksp_));
  SinewCallThrow(comm, KSPSetOptionsPrefix(ksp_, "continuation_"));
  SinewCallThrow(comm, useDirectSolver(ksp_));
  SinewCallThrow(comm, KSPSetFromOptions(ksp_));
  rtol_ = settings.rtol;
  maxIts_ = settings.maxIt;
  maxCuts_ = maxCuts;
  desiredIts_ = std::max(settings.desiredIts, 1);
  initialSteps_ = std::max(settings.initialSteps, 1);
  inertia_ = settings.inertia;
  lowest_ = settings.lowestEigenvalue;
  branchSwitch_ = settings.branchSwitch;
  // the largest step: the scene's ds_max; else, in arc length, a fraction of the model's size in the
  // arc-length metric (the step grows from ds by the corrector's iteration count, and the turn of the
  // path per step bounds it where the path curves); displacement control keeps |ds|
  if (opt_.ds_max > 0) {
    dsMax_ = opt_.ds_max;
  } else if (opt_.method != "displacement") {
    dsMax_ = std::max(std::abs(opt_.ds), kAutoFraction * modelPathSize());
    angleControl_ = true;
  } else {
    dsMax_ = std::abs(opt_.ds);
  }
  // the control DOF: a unit vector over the unknowns (the node's owner sets its entry)
  long local = 0;
  for (const LocalElement& el : asm_.mesh().elements) local += el.kernel->numConstraints();
  MPI_Allreduce(&local, &multipliers_, 1, MPI_LONG, MPI_SUM, comm);
  SinewCallThrow(comm, VecSet(e_, 0.0));
  if (opt_.node >= 0) {
    const DistributedMesh& m = asm_.mesh();
    int found = 0;
    for (int i = 0; i < m.numOwnedNodes; ++i) {
      const LocalNode& n = m.nodes[i];
      if (n.sceneNode != opt_.node) continue;
      const int d = n.dof[opt_.direction];
      if (d >= 0) {
        SinewCallThrow(comm, VecSetValue(e_, m.localToGlobalUnknown(d), 1.0, INSERT_VALUES));
        found = 1;
      } else {
        found = -1;
      }
    }
    SinewCallThrow(comm, VecAssemblyBegin(e_));
    SinewCallThrow(comm, VecAssemblyEnd(e_));
    int any[2] = {found > 0, found < 0};
    MPI_Allreduce(MPI_IN_PLACE, any, 2, MPI_INT, MPI_MAX, comm);
    if (any[1] && !any[0])
      throw SceneError("opt.continuation.node", "the control DOF of node " + std::to_string(opt_.node + 1) +
                                                    " is supported or prescribed; choose a free translation");
    haveControl_ = any[0] != 0;
  }
}

ContinuationAnalysis::~ContinuationAnalysis() {
  KSPDestroy(&ksp_);
  MatDestroy(&K_);
  MatDestroy(&Ks_);
  for (Vec* v : {&R_, &q_, &duR_, &duq_, &dU_, &e_, &work_, &dUprev_}) VecDestroy(v);
}

// Initial loads (force_initial, moment_initial, displ_initial, rot_initial) act at every load factor,
// so the path starts from their equilibrium: Newton at load factor 0 with the initial loads ramped in
// equal increments (a cut increment is halved), rotations absorbed after each. A start state that already
// carries them (form finding's found shape with the corners lifted) is equilibrated in one increment:
// ramping from load factor 0 would first pull the prescribed motions back to zero.
PetscErrorCode ContinuationAnalysis::equilibrateInitial(Vec U, bool* ok) {
  PetscFunctionBeginUser;
  LoadState ls;
  *ok = true;
  PetscCall(asm_.residual(U, ls, R_));
  PetscReal r0, fint;
  PetscCall(VecNorm(R_, NORM_2, &r0));
  ls.initialFactor = 0.0;
  PetscCall(asm_.residual(U, ls, work_));
  PetscCall(VecAXPY(work_, -1.0, R_));  // the initial loads' share of the residual
  PetscCall(VecNorm(work_, NORM_2, &fint));
  if (fint == 0.0 && r0 == 0.0) PetscFunctionReturn(PETSC_SUCCESS);
  // the initial loads ramped from 0 to 1 in increments, halved (at most -max_cuts times in all) on failure
  Vec U0;
  PetscCall(VecDuplicate(U, &U0));
  StepRules rules;
  rules.maxCuts = maxCuts_;
  rules.cutProposal = true;
  rules.landing = Landing::Clamp;
  StepController control(rules, {"start state", "initial load factor", "increment"});
  control.resume(startCarriesInitial_ ? 1.0 : 1.0 / initialSteps_);
  std::vector<Mat3> Rsave;
  SteppedProcedure ramp;
  ramp.solve = [&](double, double next, double, StepAttempt* a) -> PetscErrorCode {
    PetscCall(VecCopy(U, U0));
    Rsave = asm_.referenceRotations();
    ls.initialFactor = next;
    PetscCall(newton(U, ls, rtol_ * fint, 3 * maxIts_, &a->converged));
    if (a->converged) return PETSC_SUCCESS;
    PetscCall(VecCopy(U0, U));
    asm_.setReferenceRotations(Rsave);
    return PETSC_SUCCESS;
  };
  ramp.accept = [&](double, double, double, const StepAttempt&) -> PetscErrorCode {
    PetscCall(asm_.setMixedReference(U, ls));
    PetscCall(asm_.absorbRotations(U));
    return PETSC_SUCCESS;
  };
  StepSequence once;
  once.target = [](int) { return 1.0; };
  double mu = 0.0;
  StepStop stop;
  PetscCall(control.run(ramp, once, &mu, &stop));
  *ok = stop == StepStop::EndReached;
  PetscCall(VecDestroy(&U0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContinuationAnalysis::solveFixedLoad(Vec U, double lambda, double scale, bool* ok) {
  PetscFunctionBeginUser;
  LoadState ls;
  ls.loadFactor = ls.time = lambda;
  PetscCall(newton(U, ls, rtol_ * scale, 2 * maxIts_, ok));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The path-following rules of the Newton test (solvers/newton_test.hpp): from the first update on,
// the residual below the tolerance or below its round-off floor 8 eps ||K||_inf max(|X|, 1).
NewtonRules ContinuationAnalysis::newtonRules() {
  NewtonRules r;
  r.forceRtol = 1.0;  // the iterate's scale is the tolerance itself
  r.forceFromIteration = 1;
  r.belowFloor = true;
  return r;
}

NewtonIterate ContinuationAnalysis::iterate(int k, double rnorm, double tol, double jnorm) const {
  NewtonIterate x;
  x.it = k;
  x.fnorm = rnorm;
  x.scale = tol;
  x.floor = roundoffFloor(jnorm, std::max(asm_.coordinateScale(), 1.0));
  return x;
}

// Newton at a fixed load state (a Jacobian per iteration, MUMPS): converged when the residual is
// below tol or its round-off floor (newtonRules); at most maxIts iterations.
PetscErrorCode ContinuationAnalysis::newton(Vec U, const LoadState& ls, double tol, int maxIts, bool* ok) {
  PetscFunctionBeginUser;
  *ok = false;
  PetscReal jnorm = 0;
  for (int k = 0; k <= maxIts; ++k) {
    PetscCall(asm_.residual(U, ls, R_));
    PetscReal rn;
    PetscCall(VecNorm(R_, NORM_2, &rn));
    if (!std::isfinite(rn)) break;
    if (newtonTest_.judge(iterate(k, rn, tol, jnorm)) > 0) {
      *ok = true;
      break;
    }
    if (k == maxIts) break;
    PetscCall(asm_.jacobian(U, ls, K_));
    PetscCall(MatNorm(K_, NORM_INFINITY, &jnorm));
    PetscCall(KSPSetOperators(ksp_, K_, K_));
    PetscCall(KSPSetUp(ksp_));
    PetscCall(VecScale(R_, -1.0));
    PetscCall(KSPSolve(ksp_, R_, duR_));
    KSPConvergedReason kr;
    PetscCall(KSPGetConvergedReason(ksp_, &kr));
    if (kr < 0) break;
    PetscCall(VecAXPY(U, 1.0, duR_));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Branch switching at a symmetric bifurcation (e.g. Wagner & Wriggers 1988): at the first point past it
// (one more negative eigenvalue, the buckled branch exists at this load for a supercritical
// bifurcation) the state is perturbed by tau phi, phi the eigenvector of the lowest eigenvalue made
// orthogonal to the primary path's last increment, and equilibrium found at the same load factor
// (perturbations doubled from tau until Newton does not return to the primary path). The switch counts
// when the result kept at least a tenth of tau along phi.
PetscErrorCode ContinuationAnalysis::switchBranch(Vec U, double lambda, double tau, Vec dUprev, bool* ok) {
  PetscFunctionBeginUser;
  *ok = false;
  LoadState ls;
  ls.loadFactor = ls.time = lambda;
  const bool mixed = asm_.mixedStressNewton();
  asm_.setMixedStressNewton(false);
  PetscCall(asm_.jacobian(U, ls, K_));
  asm_.setMixedStressNewton(mixed);
  PetscCall(stabilityMatrix());
  Vec phi, Ub;
  PetscCall(VecDuplicate(U, &phi));
  PetscCall(VecDuplicate(U, &Ub));
  double mu = 0;
  PetscCall(lowestEigenvalue(&mu, phi));
  PetscCall(MatSetOption(K_, MAT_SYMMETRIC, PETSC_FALSE));  // K_ is the Newton matrix again
  PetscReal tt, tp, pn;
  PetscCall(VecDot(dUprev, dUprev, &tt));
  PetscCall(VecDot(dUprev, phi, &tp));
  if (tt > 0) PetscCall(VecAXPY(phi, -tp / tt, dUprev));  // orthogonal to the primary path
  PetscCall(VecNorm(phi, NORM_2, &pn));
  if (pn > 0 && std::isfinite(mu)) {
    // the eigenvector's sign is arbitrary (it may differ between rank counts): its largest entry positive
    PetscReal vmax, vmin;
    PetscCall(VecMax(phi, nullptr, &vmax));
    PetscCall(VecMin(phi, nullptr, &vmin));
    PetscCall(VecScale(phi, (-vmin > vmax ? -1.0 : 1.0) / pn));
    PetscCall(VecCopy(U, Ub));
    const auto Rsave = asm_.referenceRotations();
    PetscCall(loadDerivative(Ub, lambda, q_));
    PetscReal qn;
    PetscCall(VecNorm(q_, NORM_2, &qn));
    // the branch's amplitude at this load is unknown: perturbations tau, 2 tau, 4 tau, ... until Newton
    // stays off the primary path (from too small a one it returns there)
    for (int k = 0; k < 10 && !*ok; ++k) {
      const double t = std::abs(tau) * std::ldexp(1.0, k);
      PetscCall(VecWAXPY(U, t, phi, Ub));
      bool conv = false;
      PetscCall(solveFixedLoad(U, lambda, qn * std::max(1.0, std::abs(lambda)), &conv));
      PetscReal amp = 0;
      if (conv) {
        PetscCall(VecWAXPY(work_, -1.0, Ub, U));
        PetscCall(VecDot(work_, phi, &amp));
      }
      if (conv && std::abs(amp) > 0.1 * std::abs(tau)) {
        PetscCall(VecCopy(work_, dUprev));  // the next steps continue along the new branch
        *ok = true;
      } else {
        asm_.setReferenceRotations(Rsave);
      }
    }
    if (!*ok) PetscCall(VecCopy(Ub, U));
  }
  PetscCall(VecDestroy(&phi));
  PetscCall(VecDestroy(&Ub));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContinuationAnalysis::factor(Vec U, double lambda) {
  PetscFunctionBeginUser;
  LoadState ls;
  ls.loadFactor = ls.time = lambda;
  PetscCall(asm_.jacobian(U, ls, K_));
  PetscCall(KSPSetOperators(ksp_, K_, K_));
  PetscCall(KSPSetUp(ksp_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Negative eigenvalues of the tangent at a converged point: the inertia of a symmetric (LDL^T)
// MUMPS factorization. The tangent with rigid-mode multipliers is a saddle-point matrix whose
// inertia is that of the constrained stiffness plus one negative eigenvalue per multiplier.
PetscErrorCode ContinuationAnalysis::negativeEigenvalues(Vec U, double lambda, int* count, PathPoint* p) {
  PetscFunctionBeginUser;
  LoadState ls;
  ls.loadFactor = ls.time = lambda;
  const bool mixed = asm_.mixedStressNewton();
  asm_.setMixedStressNewton(false);  // the true tangent of the converged state
  PetscCall(asm_.jacobian(U, ls, K_));
  asm_.setMixedStressNewton(mixed);
  PetscCall(stabilityMatrix());
  Mat F;
  MatFactorInfo info;
  PetscCall(MatFactorInfoInitialize(&info));
  PetscCall(MatGetFactor(stab_, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &F));
  PetscCall(MatMumpsSetIcntl(F, 13, 1));  // root front factored sequentially: the global inertia is exact
  PetscCall(MatMumpsSetIcntl(F, 24, 1));  // null pivots detected (a critical point itself is singular)
  PetscCall(MatCholeskyFactorSymbolic(F, stab_, nullptr, &info));
  PetscCall(MatCholeskyFactorNumeric(F, stab_, &info));
  PetscInt neg = 0, zero = 0, pos = 0;
  PetscCall(MatGetInertia(F, &neg, &zero, &pos));
  PetscCall(MatDestroy(&F));
  if ((lowest_ || branchSwitch_) && p) PetscCall(lowestEigenvalue(&p->lowestEigenvalue, nullptr, &p->nearestNegative, &p->nearestPositive));
  PetscCall(MatSetOption(K_, MAT_SYMMETRIC, PETSC_FALSE));
  *count = static_cast<int>(neg - multipliers_);
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The matrix of the stability checks: the tangent K_ itself, or, when follower pressure loads make it
// unsymmetric (their load stiffness), its symmetric part (K + K^T)/2: the assembled pressure stiffness is
// symmetric where the pressure's boundary terms vanish (fixed edges, closed surfaces; Schweizerhof & Ramm
// 1984), and a symmetric LDL^T of K_ itself would read one triangle only. Marked symmetric for MUMPS' Cholesky and SLEPc.
PetscErrorCode ContinuationAnalysis::stabilityMatrix() {
  PetscFunctionBeginUser;
  stab_ = K_;
  if (asm_.hasPressure()) {
    PetscCall(MatDestroy(&Ks_));
    PetscCall(MatTranspose(K_, MAT_INITIAL_MATRIX, &Ks_));
    PetscCall(MatAXPY(Ks_, 1.0, K_, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatScale(Ks_, 0.5));
    stab_ = Ks_;
  }
  PetscCall(MatSetOption(stab_, MAT_SYMMETRIC, PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// An independent check of the inertia: the eigenvalues of K closest to 0 (shift-and-invert with MUMPS
// LU, K phi = mu phi), the lowest of them returned. Near a critical point the eigenvalue that crosses
// zero is the one closest to it, so its sign must agree with the negative-pivot count. The nearest
// below and above 0 are the ones a bifurcation is located with (classify).
PetscErrorCode ContinuationAnalysis::lowestEigenvalue(double* value, Vec phi, double* below, double* above) {
  PetscFunctionBeginUser;
  MPI_Comm comm = asm_.mesh().comm;
  EPS eps;
  ST st;
  KSP ksp;
  PC pc;
  PetscCall(EPSCreate(comm, &eps));
  PetscCall(EPSSetOperators(eps, stab_, nullptr));
  PetscCall(EPSSetProblemType(eps, multipliers_ > 0 ? EPS_NHEP : EPS_HEP));
  PetscCall(EPSSetWhichEigenpairs(eps, EPS_TARGET_MAGNITUDE));
  PetscCall(EPSSetTarget(eps, 0.0));
  PetscCall(EPSSetDimensions(eps, 4, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(EPSSetTolerances(eps, 1e-10, 200));
  PetscCall(EPSGetST(eps, &st));
  PetscCall(STSetType(st, STSINVERT));
  PetscCall(STGetKSP(st, &ksp));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCLU));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PetscCall(EPSSolve(eps));
  PetscInt nconv = 0;
  PetscCall(EPSGetConverged(eps, &nconv));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double low = nan, neg = nan, pos = nan;
  PetscInt at = -1;
  for (PetscInt i = 0; i < nconv; ++i) {
    PetscScalar re, im;
    PetscCall(EPSGetEigenvalue(eps, i, &re, &im));
    if (!(low <= re)) {
      low = re;
      at = i;
    }
    if (re < 0 && !(neg >= re)) neg = re;
    if (re >= 0 && !(pos <= re)) pos = re;
  }
  if (below) *below = neg;
  if (above) *above = pos;
  if (phi) {
    if (at >= 0) PetscCall(EPSGetEigenvector(eps, at, phi, nullptr));
    else PetscCall(VecSet(phi, 0.0));
  }
  PetscCall(EPSDestroy(&eps));
  *value = low;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContinuationAnalysis::controlDisplacement(Vec U, double, double* value) {
  PetscFunctionBeginUser;
  *value = 0.0;
  if (haveControl_) PetscCall(VecDot(U, e_, value));  // translations: the unknowns are x - X0
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContinuationAnalysis::pathSlopes(Vec U, double lambda, Vec dUlast, double dlLast, PathPoint* p) {
  PetscFunctionBeginUser;
  const double psi2 = opt_.method == "arclength" && opt_.constraint == "spherical" ? opt_.psi * opt_.psi : 0.0;
  PetscCall(loadDerivative(U, lambda, q_));
  PetscCall(factor(U, lambda));
  PetscCall(KSPSolve(ksp_, q_, duq_));  // tangent (du_q, 1) d lambda
  PetscReal a, qq, c, ec = 0;
  PetscCall(VecDot(duq_, duq_, &a));
  PetscCall(VecDot(q_, q_, &qq));
  PetscCall(VecDot(duq_, dUlast, &c));
  if (haveControl_) PetscCall(VecDot(duq_, e_, &ec));
  const double sign = (c + psi2 * qq * dlLast) >= 0 ? 1.0 : -1.0;
  if (opt_.method == "displacement") {  // s = u_control
    p->slopeLoad = ec != 0.0 ? 1.0 / ec : 0.0;
    p->slopeControl = 1.0;
  } else {
    const double n = std::sqrt(a + psi2 * qq);
    p->slopeLoad = sign / n;
    p->slopeControl = sign * ec / n;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// One path step from (U, lambda) with arc length (or displacement increment) ds. On success U and
// lambda hold the new point; on failure they are unchanged.
PetscErrorCode ContinuationAnalysis::correct(Vec U, double* lambda, Vec U0, double lambda0, double ds, double qnorm,
                                             double jnorm, KSPConvergedReason* kr, bool* ok, int* its) {
  PetscFunctionBeginUser;
  const bool displacement = opt_.method == "displacement" || landing_ == StopLanding::Displacement;
  const bool loadControl = landing_ == StopLanding::LoadFactor;  // lambda stays at the predictor's
  const double psi2 = opt_.constraint == "spherical" ? opt_.psi * opt_.psi : 0.0;
  for (int k = 0; k < maxIts_ && *kr >= 0 && std::isfinite(*lambda); ++k) {
    LoadState ls;
    ls.loadFactor = ls.time = *lambda;
    PetscCall(asm_.residual(U, ls, R_));
    PetscReal rnorm;
    PetscCall(VecNorm(R_, NORM_2, &rnorm));
    if (!std::isfinite(rnorm)) break;
    // the corrector's tolerance is relative to the load vector |dR/dlambda| max(1, |lambda|)
    if (newtonTest_.judge(iterate(k, rnorm, rtol_ * qnorm * std::max(1.0, std::abs(*lambda)), jnorm)) > 0) {
      *ok = true;
      lastResidual_ = rnorm;
      break;
    }
    ++*its;
    PetscCall(loadDerivative(U, *lambda, q_));
    PetscCall(factor(U, *lambda));
    PetscCall(VecScale(R_, -1.0));
    PetscCall(KSPSolve(ksp_, R_, duR_));
    PetscCall(KSPGetConvergedReason(ksp_, kr));
    if (*kr < 0) break;
    PetscCall(KSPSolve(ksp_, q_, duq_));
    PetscCall(VecWAXPY(dU_, -1.0, U0, U));  // increment so far
    double dll = 0.0;
    if (loadControl) {
    } else if (displacement) {
      PetscReal er, eq, eu;
      PetscCall(VecDot(duR_, e_, &er));
      PetscCall(VecDot(duq_, e_, &eq));
      PetscCall(VecDot(dU_, e_, &eu));
      if (eq == 0.0) break;
      dll = (ds - eu - er) / eq;
    } else {
      // |dU + du_R + dll du_q|^2 + psi^2 |q|^2 (dl + dll)^2 = ds^2
      PetscCall(VecAXPY(dU_, 1.0, duR_));  // dU + du_R
      PetscReal aa, bb, cc;
      PetscCall(VecDot(duq_, duq_, &aa));
      PetscCall(VecDot(duq_, dU_, &bb));
      PetscCall(VecDot(dU_, dU_, &cc));
      const double dlt = *lambda - lambda0, w = psi2 * qnorm * qnorm;
      const double A = aa + w, B = 2.0 * (bb + w * dlt), C = cc + w * dlt * dlt - ds * ds;
      const double disc = B * B - 4.0 * A * C;
      if (!(disc >= 0.0) || A <= 0.0) break;  // no real root: the step is cut
      const double sq = std::sqrt(disc);
      const double r1 = (-B + sq) / (2.0 * A), r2 = (-B - sq) / (2.0 * A);
      // the root whose increment makes the smaller angle with the increment so far (Crisfield 1981)
      PetscReal d0;
      PetscCall(VecWAXPY(work_, -1.0, U0, U));
      PetscCall(VecDot(work_, dU_, &d0));
      PetscReal dq;
      PetscCall(VecDot(work_, duq_, &dq));
      const double c1 = d0 + r1 * dq + w * dlt * (dlt + r1), c2 = d0 + r2 * dq + w * dlt * (dlt + r2);
      dll = c1 >= c2 ? r1 : r2;
    }
    PetscCall(VecAXPY(U, 1.0, duR_));
    PetscCall(VecAXPY(U, dll, duq_));
    *lambda += dll;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContinuationAnalysis::step(Vec U, double* lambda, double ds, Vec dUprev, double dlPrev, bool first,
                                          bool* ok, int* its) {
  PetscFunctionBeginUser;
  MPI_Comm comm = asm_.mesh().comm;
  const bool displacement = opt_.method == "displacement" || landing_ == StopLanding::Displacement;
  const bool loadControl = landing_ == StopLanding::LoadFactor;  // ds: the load factor's increment
  const double psi2 = opt_.constraint == "spherical" ? opt_.psi * opt_.psi : 0.0;
  Vec U0;
  PetscCall(VecDuplicate(U, &U0));
  PetscCall(VecCopy(U, U0));
  const double lambda0 = *lambda;
  // predictor along the tangent K du_q = q
  PetscCall(loadDerivative(U, lambda0, q_));
  PetscReal qnorm;
  PetscCall(VecNorm(q_, NORM_2, &qnorm));
  lastQnorm_ = qnorm;
  PetscCall(factor(U, lambda0));
  PetscCall(KSPSolve(ksp_, q_, duq_));
  KSPConvergedReason kr;
  PetscCall(KSPGetConvergedReason(ksp_, &kr));
  PetscReal jnorm;
  PetscCall(MatNorm(K_, NORM_INFINITY, &jnorm));
  double dl = 0.0;
  *ok = false;
  *its = 0;
  if (kr >= 0) {
    PetscReal a;
    PetscCall(VecDot(duq_, duq_, &a));
    if (loadControl) {
      dl = ds;
    } else if (displacement) {
      PetscReal ec;
      PetscCall(VecDot(duq_, e_, &ec));
      dl = ec != 0.0 ? ds / ec : 0.0;
    } else {
      dl = ds / std::sqrt(a + psi2 * qnorm * qnorm);
      // direction: continue the previous step (Feng et al.: the sign of du_q . dU_prev), loads up at first
      if (!first) {
        PetscReal c;
        PetscCall(VecDot(duq_, dUprev, &c));
        if (c + psi2 * qnorm * qnorm * dlPrev < 0) dl = -dl;
      }
    }
    PetscCall(VecAXPY(U, dl, duq_));
    *lambda = loadControl ? landingLambda_ : lambda0 + dl;
  }
  // a planned step: the coarser level's step; else the coarser level's path where it meets the constraint;
  // else (and when its corrector fails) the tangent
  bool guessed = false;
  Vec Upred = nullptr;
  const double lambdaPred = *lambda;
  if (kr >= 0 && !displacement && !loadControl && handover_ && !coarsePath().empty()) {
    PetscCall(VecDuplicate(U, &Upred));
    PetscCall(VecCopy(U, Upred));
    double dsPlan = 0;
    if (planned_) PetscCall(plannedStep(planStep_, U0, lambda0, &dsPlan, U, lambda));
    else PetscCall(coarsePathGuess(U0, lambda0, ds, psi2 * qnorm * qnorm, U, lambda, &guessed));
    guessed = guessed || planned_;
    if (!guessed) PetscCall(VecCopy(Upred, U));  // no coarser point ahead: the tangent (U was its scratch)
    if (guessed && handover_->fromStart) {
      PetscCall(nearerPredictor(U, lambda, Upred, lambdaPred, &guessed));
      if (planned_ && !guessed) planned_ = planActive_ = false, guessCursor_ = planStep_ - 1;  // then the own steps
    }
  }
  PetscCall(correct(U, lambda, U0, lambda0, ds, qnorm, jnorm, &kr, ok, its));
  if (guessed && *ok) ++handover_->guessesUsed;
  if (guessed && !*ok) {
    PetscCall(VecCopy(Upred, U));
    *lambda = lambdaPred;
    kr = KSP_CONVERGED_ITS;
    PetscCall(correct(U, lambda, U0, lambda0, ds, qnorm, jnorm, &kr, ok, its));
  }
  PetscCall(VecDestroy(&Upred));
  if (!*ok) {
    PetscCall(VecCopy(U0, U));
    *lambda = lambda0;
  }
  PetscCall(VecDestroy(&U0));
  (void)comm;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContinuationAnalysis::run(Vec U, const PointCallback& onPoint, bool* converged) {
  PetscFunctionBeginUser;
  MPI_Comm comm = asm_.mesh().comm;
  double lambda = 0.0;
  Vec dUprev = dUprev_, Uprev;
  PetscCall(VecDuplicate(U, &Uprev));
  double ds = opt_.ds, dlPrev = 0.0;  // ds: the step of the last point
  int its = 0;                        // its corrector iterations
  *converged = true;
  const bool resumed = resumed_;
  if (resumed) {
    lambda = resumeLambda_;
    ds = resumeDs_;
    dlPrev = resumeDlPrev_;
    its = resumeIts_;
    LoadState ls;
    ls.loadFactor = ls.time = lambda;
    PetscCall(asm_.setMixedReference(U, ls));
  } else {
    LoadState start;
    PetscCall(asm_.setMixedReference(U, start));
  }
  if (!resumed) {
    bool ok = true;
    PetscCall(equilibrateInitial(U, &ok));
    if (!ok) {
      failure_ = "the start state under the initial loads (load factor 0) did not converge after " + std::to_string(maxCuts_) +
                 " halvings of its increments; try -continuation_initial_steps with more increments";
      *converged = false;
      PetscCall(VecDestroy(&Uprev));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  }
  if (handover_ && !resumed) PetscCall(recordStart(U, lambda));  // the path's start, for the next level
  int prevNeg = resumed ? resumePrevNeg_ : -1;
  if (inertia_ && !resumed) PetscCall(negativeEigenvalues(U, 0.0, &prevNeg, nullptr));
  const std::string sizeName = opt_.method == "displacement" ? "displacement increment" : "arc length";
  // one step per path point, halved (at most -max_cuts times) on failure; adaptive arc length: aim
  // at desiredIts corrector iterations, within [ds/2, 2 ds] from point to point and |ds| <= ds_max.
  // With the model's ds_max (angleControl_) the turn of the path per step counts as iterations too:
  // a step that turned the path by theta counts as desiredIts (theta / kTargetAngle)^2 iterations, so
  // that the next step is about kTargetAngle / theta times as long; one that turned it by more than
  // kMaxAngle is repeated from its start that much shorter (at most 3 times per point). The count
  // is what the checkpoint keeps (ckIts_), so a restarted path takes the same steps.
  IterationTarget aim(desiredIts_, 0.5, 2.0, dsMax_);
  StepRules rules;
  rules.maxCuts = maxCuts_;
  std::vector<Mat3> Rsave;
  double turn = 0.0, lambdaStart = lambda;
  int correctorIts = 0, repeats = 0;
  rules.strategy = [&](double h, double proposal, const StepAttempt& a, double* next, bool* reject) -> int {
    if (planned_ && ++planStep_ < coarsePath().size()) {  // the plan's next step (its turn was the coarser one's)
      *reject = false;
      PetscCall(plannedStep(planStep_, U, lambda, &planSize_));
      *next = planSize_;
      return PETSC_SUCCESS;
    }
    if (planned_) planActive_ = false, guessCursor_ = planStep_ - 1;  // the plan ended: the own step control
    if (angleControl_ && turn > kMaxAngle && repeats < 3) {
      ++repeats, ++repeated_;
      *reject = true;
      *next = h * std::max(kTargetAngle / turn, 0.25);
      PetscCall(VecCopy(Uprev, U));  // back to the step's start
      lambda = lambdaStart;
      asm_.setReferenceRotations(Rsave);
      return PETSC_SUCCESS;
    }
    return aim(h, proposal, a, next, reject);
  };
  // -target_error levels: the coarser level's steps as the plan (no branch switch: its point would not be a step)
  if (!resumed && handover_ && plan_ && !branchSwitch_ && opt_.method != "displacement" && coarsePath().size() >= 2) {
    planActive_ = true, planStep_ = 1;
    PetscCall(plannedStep(planStep_, U, lambda, &planSize_));
    ds = planSize_;
  }
  StepController control(rules, {"path step", "load factor", sizeName});
  control.resume(ds);
  SteppedProcedure path;
  path.solve = [&](double, double, double h, StepAttempt* a) -> PetscErrorCode {
    Rsave = asm_.referenceRotations();
    PetscCall(VecCopy(U, Uprev));
    lambdaStart = lambda;
    planned_ = planActive_ && h == planSize_;
    PetscCall(step(U, &lambda, h, dUprev, dlPrev, control.step() == 1, &a->converged, &a->iterations));
    if (planned_ && !a->converged) planActive_ = false, guessCursor_ = planStep_ - 1;  // cut by the own control
    if (planned_ && a->converged) ++handover_->plannedSteps;
    landedDs_ = 0;
    if (a->converged && handover_ && plan_ && ((haveControl_ && opt_.stop_displacement) || opt_.stop_load_factor))
      PetscCall(landOnStop(U, &lambda, Uprev, lambdaStart, dUprev, dlPrev, &a->iterations));
    a->reason = "corrector did not converge";
    a->at = lambda;
    correctorIts = a->iterations;
    turn = 0.0;
    if (!a->converged) asm_.setReferenceRotations(Rsave);
    else if (angleControl_ && !(switchedAt_ > 0 && !points_.empty() && points_.back().step == switchedAt_)) {
      PetscCall(turnAngle(U, Uprev, lambda - lambdaStart, dUprev, dlPrev, &turn));
      const double equivalent = std::ceil(desiredIts_ * (turn / kTargetAngle) * (turn / kTargetAngle));
      a->iterations = std::max(a->iterations, static_cast<int>(std::min(equivalent, 1000.0)));
    }
    return PETSC_SUCCESS;
  };
  path.accept = [&](double, double, double h, const StepAttempt& a) -> PetscErrorCode {
    PetscCall(VecWAXPY(dUprev, -1.0, Uprev, U));
    dlPrev = lambda - (points_.empty() ? 0.0 : points_.back().loadFactor);
    LoadState ls;
    ls.loadFactor = ls.time = lambda;
    PetscCall(asm_.setMixedReference(U, ls));
    PetscCall(asm_.absorbRotations(U));
    ds = landedDs_ > 0 ? landedDs_ : h;
    its = a.iterations;
    repeats = 0;
    return PETSC_SUCCESS;
  };
  path.print = [comm](const std::string& m) { PetscPrintf(comm, "%s", m.c_str()); };
  // after path point n (p): a branch switch at a bifurcation just located (a point of its own), then
  // the stop criteria
  auto afterPoint = [&](int& n, const PathPoint& p, StepStop* stop) -> PetscErrorCode {
    if (branchSwitch_ && !switched_ && !critical_.empty() && critical_.back().kind == CriticalPoint::Bifurcation &&
        critical_.back().afterStep == static_cast<int>(points_.size()) - 1 && n < opt_.max_steps) {
      switched_ = true;
      bool sw = false;
      PetscCall(switchBranch(U, lambda, ds, dUprev, &sw));
      if (sw) {
        PathPoint b;
        b.step = ++n;
        LoadState lb;
        lb.loadFactor = lb.time = lambda;
        PetscCall(asm_.setMixedReference(U, lb));
        PetscCall(asm_.absorbRotations(U));
        b.loadFactor = lambda;
        PetscReal an;
        PetscCall(VecNorm(dUprev, NORM_2, &an));
        b.arcLength = an;
        dlPrev = 0.0;
        PetscCall(controlDisplacement(U, lambda, &b.controlValue));
        if (inertia_) PetscCall(pathSlopes(U, lambda, dUprev, dlPrev, &b));
        if (inertia_) PetscCall(negativeEigenvalues(U, lambda, &b.negativeEigenvalues, &b));
        points_.push_back(b);
        if (handover_) PetscCall(recordPoint(U, lambda));
        prevNeg = b.negativeEigenvalues;
        switchedAt_ = b.step;
        PetscCall(PetscPrintf(comm, "  branch switched at path point %d (load factor %.6g)\n", b.step, lambda));
        ckDs_ = ds;
        ckDlPrev_ = dlPrev;
        ckIts_ = its;
        if (onPoint) PetscCall(onPoint(b, U));
      } else {
        PetscCall(PetscPrintf(comm, "  branch switch at path point %d failed: Newton returned to the primary path\n", n));
      }
    }
    if (landedDs_ > 0 || (opt_.stop_load_factor && lambda >= *opt_.stop_load_factor) ||
        (opt_.stop_displacement && std::abs(p.controlValue) >= std::abs(*opt_.stop_displacement)))
      *stop = StepStop::StopCondition;
    return PETSC_SUCCESS;
  };
  StepSequence points;
  points.first = 1;
  points.last = opt_.max_steps;
  points.reached = [&](int& n, StepStop* stop) -> PetscErrorCode {
    PathPoint p;
    p.step = n;
    p.cuts = control.cuts();
    p.loadFactor = lambda;
    p.arcLength = ds;
    p.iterations = correctorIts;
    p.residualNorm = lastResidual_;
    PetscCall(controlDisplacement(U, lambda, &p.controlValue));
    if (inertia_) PetscCall(pathSlopes(U, lambda, dUprev, dlPrev, &p));
    if (inertia_) PetscCall(negativeEigenvalues(U, lambda, &p.negativeEigenvalues, &p));
    points_.push_back(p);
    if (handover_) PetscCall(recordPoint(U, lambda));
    if (inertia_ && prevNeg >= 0 && p.negativeEigenvalues != prevNeg) classify();
    prevNeg = p.negativeEigenvalues;
    ckDs_ = ds;
    ckDlPrev_ = dlPrev;
    ckIts_ = its;
    if (onPoint) PetscCall(onPoint(p, U));
    if (stop_ && *stop_) *stop = StepStop::Interrupted;
    else PetscCall(afterPoint(n, p, stop));
    return PETSC_SUCCESS;
  };
  StepStop stop = StepStop::None;
  if (resumed && !points_.empty()) {
    // a resumed path continues after its last point: the end of that point's iteration (branch switch,
    // step adaptation, stop criteria) first
    int n = points_.back().step;
    PetscCall(afterPoint(n, PathPoint(points_.back()), &stop));
    control.resume(aim.grown(ds, its));
    points.first = n + 1;
  }
  double arc = 0.0;
  if (stop == StepStop::None) PetscCall(control.run(path, points, &arc, &stop));
  if (stop == StepStop::CutLimit) {
    std::ostringstream msg;
    msg << "path step " << control.step() << " did not converge after " << maxCuts_ << " halvings of the " << sizeName
        << " (last converged load factor " << lambda << "). Try a smaller ds, -continuation_max_it, or check supports for a mechanism.";
    failure_ = msg.str();
    *converged = false;
  }
  PetscCall(VecDestroy(&Uprev));
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::string ContinuationAnalysis::summary() const {
  std::ostringstream s;
  s << "  path: " << points_.size() << " points, load factor " << (points_.empty() ? 0.0 : points_.back().loadFactor);
  int its = 0, cuts = 0;
  for (const PathPoint& p : points_) {
    its += p.iterations;
    cuts += p.cuts;
  }
  s << ", " << its << " corrector iterations, " << cuts << " cut steps";
  if (repeated_ > 0) s << ", " << repeated_ << " steps repeated shorter (the path turned too far)";
  s << "\n";
  for (const CriticalPoint& c : critical_) {
    s << "  " << (c.kind == CriticalPoint::Limit ? "limit point" : "bifurcation point") << " between path points "
      << c.afterStep << " and " << c.afterStep + 1 << ": load factor " << c.loadFactor;
    if (haveControl_) s << ", control displacement " << c.controlValue;
    if (c.kind == CriticalPoint::Bifurcation) s << (c.interpolated ? " (zero of the eigenvalue changing sign)" : " (midpoint)");
    s << "\n";
  }
  if (switchedAt_ > 0) s << "  branch switched: path point " << switchedAt_ << " is on the bifurcated branch\n";
  return s.str();
}

}  // namespace sinew
