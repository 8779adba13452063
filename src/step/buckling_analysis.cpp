#include "solvers/solver_defaults.hpp"
#include "step/buckling_analysis.hpp"
#include "step/backward_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "parallel/collective_error.hpp"
#include "step/dense_gather.hpp"
#include "step/modal_analysis.hpp"

namespace sinew {

BucklingAnalysis::BucklingAnalysis(Assembler& assembler, int nbuck, const EigenSettings& settings)
    : asm_(assembler), nbuck_(nbuck) {
  MPI_Comm comm = asm_.mesh().comm;
  SinewCallThrow(comm, asm_.createMatrix(&Km_));
  SinewCallThrow(comm, asm_.createMatrix(&Kg_));
  SinewCallThrow(comm, EPSCreate(comm, &eps_));
  SinewCallThrow(comm, EPSSetOptionsPrefix(eps_, "buck_"));
  SinewCallThrow(comm, EPSSetProblemType(eps_, EPS_GNHEP));
  SinewCallThrow(comm, EPSSetDimensions(eps_, 2 * nbuck + 2, PETSC_DEFAULT, PETSC_DEFAULT));
  SinewCallThrow(comm, EPSSetWhichEigenpairs(eps_, EPS_TARGET_MAGNITUDE));
  SinewCallThrow(comm, EPSSetTarget(eps_, 0.0));
  ST st;
  KSP ksp;
  SinewCallThrow(comm, EPSGetST(eps_, &st));
  SinewCallThrow(comm, STSetType(st, STSINVERT));
  SinewCallThrow(comm, STSetMatStructure(st, SUBSET_NONZERO_PATTERN));
  SinewCallThrow(comm, STGetKSP(st, &ksp));
  SinewCallThrow(comm, useDirectSolver(ksp, asm_.mesh()));
  SinewCallThrow(comm, eigenOperator(asm_, settings.eigenOperator, &elementwise_));
  if (elementwise_) {  // as the frequency analysis (modal_analysis.cpp)
    const PetscInt nloc = asm_.mesh().numOwnedUnknowns, N = static_cast<PetscInt>(asm_.mesh().numGlobalUnknowns);
    SinewCallThrow(comm, MatCreateShell(comm, nloc, nloc, N, N, this, &Kop_));
    SinewCallThrow(comm, MatShellSetOperation(Kop_, MATOP_MULT, reinterpret_cast<void (*)(void)>(materialMult)));
    SinewCallThrow(comm, STSetMatMode(st, ST_MATMODE_SHELL));
    SinewCallThrow(comm, useAccurateInnerSolver(ksp));
  }
  SinewCallThrow(comm, EPSSetFromOptions(eps_));
  userNev_ = settings.userBucklingNev;
  dense_ = asm_.mesh().numGlobalUnknowns <= settings.denseMaxUnknowns;
}

BucklingAnalysis::~BucklingAnalysis() {
  EPSDestroy(&eps_);
  MatDestroy(&Km_);
  MatDestroy(&Kg_);
  MatDestroy(&Kop_);
  destroyUnitFreeNorms(&scaled_);
}

// K_m x = K x + (-K_g) x: the element-wise (rigid-motion-free) product with the whole tangent minus
// the assembled geometric part (Kg_ holds -K_g while the eigenproblem is solved)
PetscErrorCode BucklingAnalysis::materialMult(Mat A, Vec x, Vec y) {
  PetscFunctionBeginUser;
  void* ctx;
  PetscCall(MatShellGetContext(A, &ctx));
  auto* self = static_cast<BucklingAnalysis*>(ctx);
  PetscCall(self->asm_.applyTangent(x, y, true));
  PetscCall(MatMultAdd(self->Kg_, x, y, y));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode BucklingAnalysis::solve(int nev, int* nconv) {
  PetscFunctionBeginUser;
  if (!userNev_) PetscCall(EPSSetDimensions(eps_, nev, PETSC_DEFAULT, PETSC_DEFAULT));
  if (elementwise_) {
    ST st;
    PetscCall(EPSGetST(eps_, &st));
    PetscCall(STSetPreconditionerMat(st, Km_));
    PetscCall(EPSSetOperators(eps_, Kop_, Kg_));
  } else {
    PetscCall(EPSSetOperators(eps_, Km_, Kg_));
  }
  PetscCall(PetscLogEventBegin(SinewEvents::get().eigen, 0, 0, 0, 0));
  PetscCall(EPSSolve(eps_));
  PetscCall(PetscLogEventEnd(SinewEvents::get().eigen, 0, 0, 0, 0));
  PetscInt n;
  PetscCall(EPSGetConverged(eps_, &n));
  *nconv = static_cast<int>(n);
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Every pair of the pencil SLEPc solves (K_m or its element-wise operator, and -K_g), dense on rank 0
// about the target, nearest first, with the vectors of the first wanted(re, im); to every rank.
PetscErrorCode BucklingAnalysis::solveDense(DenseEigenpairs& pairs, const WantedPairs& wanted) {
  PetscFunctionBeginUser;
  const DistributedMesh& mesh = asm_.mesh();
  if (elementwise_) {
    PetscCall(operatorToDense(Kop_, denseA_.full));
    denseA_.rowStart.clear();  // no AIJ pattern behind it
  } else {
    PetscCall(gatherDense(Km_, denseA_));
  }
  PetscCall(gatherDense(Kg_, denseB_));
  const std::vector<double>&A = denseA_.full, &B = denseB_.full;
  PetscScalar target;
  PetscCall(EPSGetTarget(eps_, &target));
  const int n = static_cast<int>(mesh.numGlobalUnknowns);
  PetscCall(PetscLogEventBegin(SinewEvents::get().eigen, 0, 0, 0, 0));
  // symmetric pencil with K_m positive definite on the constraints' null space: the symmetric-definite
  // reduction (dsygvd); otherwise (or not definite) QZ
  int symmetric = 0;
  if (mesh.rank == 0) {
    symmetric = symmetricDefinitePencil(A, B, n, target, wanted, pairs);
    if (!symmetric) pairs = generalPencil(A, B, n, target, wanted);
  }
  PetscCall(broadcastPairs(mesh.comm, pairs));
  MPI_Bcast(&symmetric, 1, MPI_INT, 0, mesh.comm);
  ++(symmetric ? symmetricSolves_ : qzSolves_);
  PetscCall(PetscLogEventEnd(SinewEvents::get().eigen, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Rayleigh quotient mu = x^T K_m x / x^T (-K_g) x with the operator used (element-wise: accurate for
// the smooth modes of fine meshes; error quadratic in the mode's), and the backward error of
// K_m x - mu (-K_g) x, rotations scaled by the model size (scaledBackwardError; `scaled`: the scales of
// the step's pencil, the same for all its pairs). Kg_ holds -K_g.
PetscErrorCode BucklingAnalysis::refine(const UnitFreeNorms& scaled, Vec x, PetscScalar* mu, double* backward) {
  PetscFunctionBeginUser;
  if (!std::isfinite(*mu)) PetscFunctionReturn(PETSC_SUCCESS);
  Vec a, b;
  PetscCall(pool_.get(Km_, &a));
  PetscCall(pool_.get(Km_, &b));
  if (elementwise_) PetscCall(MatMult(Kop_, x, a));
  else PetscCall(MatMult(Km_, x, a));
  PetscCall(MatMult(Kg_, x, b));
  PetscScalar xa, xb;
  PetscCall(VecDot(x, a, &xa));
  PetscCall(VecDot(x, b, &xb));
  if (elementwise_ && xb != 0.0) *mu = xa / xb;
  PetscCall(VecAXPY(a, -*mu, b));
  PetscCall(scaledBackwardError(scaled, x, a, *mu, backward));
  pool_.put(&a);
  pool_.put(&b);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode BucklingAnalysis::atStep(Vec U, const LoadState& ls, ResultFile& file, bool* ok) {
  PetscFunctionBeginUser;
  ++step_;
  const DistributedMesh& mesh = asm_.mesh();
  const double inf = std::numeric_limits<double>::infinity();
  PetscCall(asm_.splitTangent(U, ls, Km_, Kg_));
  if (elementwise_) {  // the element blocks of K = K_m + K_g, for materialMult
    const Assembler::KeptBlocksScope keep(asm_);
    PetscCall(asm_.jacobian(U, ls, nullptr));
  }
  PetscReal nm, ng;
  PetscCall(MatNorm(Km_, NORM_FROBENIUS, &nm));
  PetscCall(MatNorm(Kg_, NORM_FROBENIUS, &ng));
  mu_.assign(nbuck_, inf);
  estimate_.assign(nbuck_, std::numeric_limits<double>::quiet_NaN());
  backward_.assign(nbuck_, std::numeric_limits<double>::quiet_NaN());
  std::vector<Vec> shapes;
  if (ng > 1e-13 * nm) {  // a stress-free state has no buckling load: every multiplier +inf
    PetscCall(MatScale(Kg_, -1.0));  // K_m phi = mu (-K_g) phi
    // scales of the backward errors: the pencil's, once for all its pairs
    PetscCall(unitFreeNorms(mesh, Km_, Kg_, &scaled_));
    PetscInt N;
    PetscCall(MatGetSize(Km_, &N, nullptr));
    struct Pair {
      double mu;
      Vec x;
      double estimate, backward;
    };
    std::vector<Pair> positive;
    int nev = 2 * nbuck_ + 2, nconv = 0;
    EPSConvergedReason reason = EPS_CONVERGED_ITERATING;
    DenseEigenpairs dense;
    // mu ||K_g|| > 1e4 ||K_m||: a null direction of K_g (infinite multiplier) computed at round-off level;
    // a real buckling load has mu ||K_g|| / ||K_m|| of the order of (thickness / length)^2
    auto kept = [&](PetscScalar kr, PetscScalar ki) {
      const bool finite = std::isfinite(kr) && kr * ng < 1e4 * nm;
      return finite && kr > 0 && std::abs(ki) <= 1e-6 * std::abs(kr);
    };
    // the dense solve's vectors: the assembled operator needs those of the nbuck_ smallest positive
    // multipliers, nearest to the target 0 first (the element-wise one refines every pair; -buck_eps_nev: all)
    auto wanted = [&](const std::vector<double>& re, const std::vector<double>& im) {
      if (elementwise_ || userNev_) return static_cast<int>(re.size());
      int found = 0;
      for (size_t i = 0; i < re.size(); ++i)
        if (kept(re[i], im[i]) && ++found == nbuck_) return static_cast<int>(i) + 1;
      return static_cast<int>(re.size());
    };
    for (int attempt = 0; attempt < 3; ++attempt) {
      for (auto& p : positive) pool_.put(&p.x);
      positive.clear();
      if (dense_) {  // every pair at once; -buck_eps_nev: SLEPc's count of the nearest
        PetscCall(solveDense(dense, wanted));
        PetscInt userNev, ncv, mpd;
        PetscCall(EPSGetDimensions(eps_, &userNev, &ncv, &mpd));
        nconv = userNev_ ? std::min<int>(dense.count(), static_cast<int>(userNev)) : dense.count();
        reason = dense.singular ? EPS_DIVERGED_BREAKDOWN : EPS_CONVERGED_TOL;
      } else {
        PetscCall(solve(std::min<int>(nev, static_cast<int>(N)), &nconv));
        PetscCall(EPSGetConvergedReason(eps_, &reason));
      }
      for (int i = 0; i < nconv; ++i) {
        // the assembled operator's multiplier is the solver's: a dense pair that is not kept needs no vector
        if (dense_ && !elementwise_ && (i >= dense.wanted() || !kept(dense.re[i], dense.im[i]))) continue;
        PetscScalar kr, ki;
        Vec x;
        PetscReal est = 0;
        PetscCall(pool_.get(Km_, &x));
        if (dense_) {
          kr = dense.re[i];
          ki = dense.im[i];
          est = dense.estimate[i];
          PetscCall(pairVector(dense, i, x));
        } else {
          PetscCall(EPSGetEigenpair(eps_, i, &kr, &ki, x, nullptr));
          PetscCall(EPSGetErrorEstimate(eps_, i, &est));
        }
        double back = 0;
        // the element-wise operator's Rayleigh quotient is the multiplier, before the selection
        if (elementwise_) PetscCall(refine(scaled_, x, &kr, &back));
        if (kept(kr, ki)) positive.push_back({kr, x, est, back});
        else pool_.put(&x);
      }
      // enough positive multipliers, or the nearest ones are all negative and the spectrum is exhausted
      if (static_cast<int>(positive.size()) >= nbuck_ || userNev_ || nev >= N || dense_) break;
      nev *= 4;
    }
    std::sort(positive.begin(), positive.end(), [](const Pair& a, const Pair& b) { return a.mu < b.mu; });
    // the assembled operator: the backward errors of the pairs written (refine leaves their multiplier)
    if (!elementwise_)
      for (int j = 0; j < nbuck_ && j < static_cast<int>(positive.size()); ++j)
        PetscCall(refine(scaled_, positive[j].x, &positive[j].mu, &positive[j].backward));
    PetscReal tol;
    PetscInt maxit;
    PetscCall(EPSGetTolerances(eps_, &tol, &maxit));
    tol_ = tol > 0 ? tol : SLEPC_DEFAULT_TOL;  // set by EPSSetUp, which the dense path skips
    double worst = 0;
    for (int j = 0; j < nbuck_ && j < static_cast<int>(positive.size()); ++j) {
      mu_[j] = positive[j].mu;
      estimate_[j] = positive[j].estimate;
      backward_[j] = positive[j].backward;
      worst = std::max({worst, positive[j].estimate, positive[j].backward});
      shapes.push_back(positive[j].x);
      positive[j].x = nullptr;
    }
    for (auto& p : positive) pool_.put(&p.x);
    if (worst > tol_)
      PetscCall(PetscPrintf(mesh.comm,
                            "  warning: buckling at step %d: error estimate or backward error %.2e of an eigenpair exceeds "
                            "-buck_eps_tol %.1e (/buck_error_estimate, /buck_backward_error)\n",
                            step_, worst, tol_));
    PetscCall(PetscInfo(nullptr, "buckling step %d: %d converged (%s), %zu positive multipliers kept\n", step_, nconv,
                        dense_ ? "dense LAPACK" : EPSConvergedReasons[reason], shapes.size()));
    if (reason < 0 && shapes.empty()) {
      *ok = false;
      std::ostringstream msg;
      if (dense_)
        msg << "buckling at step " << step_ << ": the dense eigensolver failed (K_m singular at the target); "
            << "try -eigen_dense_max_unknowns 0 (SLEPc) or -buck_eps_target";
      else
        msg << "buckling at step " << step_ << ": SLEPc did not converge (" << EPSConvergedReasons[reason]
            << "); try -buck_eps_max_it, -buck_eps_ncv or -buck_eps_tol";
      failure_ = msg.str();
    }
  }
  file.writeStepRow("buck", mu_, true);
  file.writeStepRow("buck_error_estimate", estimate_, true);
  file.writeStepRow("buck_backward_error", backward_, true);
  std::vector<double> rows, rot;
  std::vector<double>* withRot = mesh.anyRotations ? &rot : nullptr;
  for (int j = 0; j < nbuck_; ++j) {
    if (j < static_cast<int>(shapes.size())) {
      PetscCall(modeShapeRows(mesh, shapes[j], rows, withRot));
    } else {
      rows.assign(3 * static_cast<size_t>(mesh.numOwnedNodes), 0.0);
      rot = rows;
    }
    file.writeMeshField("mesh/mode_buck_" + std::to_string(j + 1), rows, {3});
    if (withRot) file.writeMeshField("mesh/mode_buck_" + std::to_string(j + 1) + "_rot", rot, {3});
  }
  for (Vec& x : shapes) pool_.put(&x);
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::string BucklingAnalysis::summary() const {
  if (mu_.empty()) return {};
  std::ostringstream s;
  char buf[64];
  s << "\n buckling load multipliers (last step):";
  bool anyInf = false;
  for (double m : mu_) {
    std::snprintf(buf, sizeof buf, " %.6g", m);
    s << buf;
    anyInf |= std::isinf(m);
  }
  s << "\n";
  if (anyInf) s << "   inf: no (further) positive multiplier: no compressive stress state that the current load can buckle\n";
  if (dense_)
    s << "   eigensolver: dense LAPACK for " << asm_.mesh().numGlobalUnknowns
      << " unknowns (up to -eigen_dense_max_unknowns; 0: SLEPc): " << symmetricSolves_
      << " symmetric pencils (dsygvd), " << qzSolves_ << " nonsymmetric\n";
  return s.str();
}

}  // namespace sinew
