#include "parallel/collective_error.hpp"
#include "solvers/solver_defaults.hpp"
#include "step/dense_gather.hpp"
#include "step/modal_analysis.hpp"
#include "step/backward_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>

namespace sinew {

namespace {

// max |v| over all ranks
double globalMaxAbs(MPI_Comm comm, const std::vector<double>& v) {
  double amax = 0.0;
  for (double a : v) amax = std::max(amax, std::abs(a));
  MPI_Allreduce(MPI_IN_PLACE, &amax, 1, MPI_DOUBLE, MPI_MAX, comm);
  return amax;
}

// +1 or -1: the sign that makes the largest component of v (lowest FE node and direction among
// near-ties) positive; amax = globalMaxAbs(v) > 0.
double signOfLargest(const DistributedMesh& m, const std::vector<double>& v, double amax) {
  long key = std::numeric_limits<long>::max();
  double sign = 0.0;
  for (int i = 0; i < m.numOwnedNodes; ++i)
    for (int k = 0; k < 3; ++k) {
      const double a = v[3 * i + k];
      const long kk = 3 * m.nodes[i].gid + k;
      if (std::abs(a) >= (1.0 - 1e-8) * amax && kk < key) {
        key = kk;
        sign = a > 0 ? 1.0 : -1.0;
      }
    }
  long gkey = key;
  MPI_Allreduce(MPI_IN_PLACE, &gkey, 1, MPI_LONG, MPI_MIN, m.comm);
  double s = key == gkey ? sign : 0.0;
  MPI_Allreduce(MPI_IN_PLACE, &s, 1, MPI_DOUBLE, MPI_SUM, m.comm);
  return s < 0 ? -1.0 : 1.0;
}

}  // namespace

PetscErrorCode modeShapeRows(const DistributedMesh& m, Vec x, std::vector<double>& rows, std::vector<double>* rot) {
  PetscFunctionBeginUser;
  rows.assign(3 * static_cast<size_t>(m.numOwnedNodes), 0.0);
  if (rot) rot->assign(3 * static_cast<size_t>(m.numOwnedNodes), 0.0);
  const PetscScalar* a;
  PetscCall(VecGetArrayRead(x, &a));
  auto value = [&](const LocalNode& n, int k) {
    const int d = n.dof[k];
    return n.status[k] == DofStatus::Free && d >= 0 && d < m.numOwnedUnknowns ? a[d] : 0.0;
  };
  for (int i = 0; i < m.numOwnedNodes; ++i) {
    const LocalNode& n = m.nodes[i];
    const int nt = n.kind == NodeKind::Ancf2D ? 2 : 3;
    for (int k = 0; k < nt; ++k) rows[3 * i + k] = value(n, k);
    if (rot && n.kind == NodeKind::Frame6)
      for (int k = 0; k < 3; ++k) (*rot)[3 * i + k] = value(n, 3 + k);  // spatial spin: a rotation vector
  }
  PetscCall(VecRestoreArrayRead(x, &a));
  PetscReal xmax;
  PetscCall(VecNorm(x, NORM_INFINITY, &xmax));
  const double tmax = globalMaxAbs(m.comm, rows);
  const double rmax = rot ? globalMaxAbs(m.comm, *rot) : 0.0;
  double scale = 0.0;  // no translation and no rotation (round-off is not a shape): all 0
  if (tmax > 1e-10 * xmax) scale = signOfLargest(m, rows, tmax) / tmax;
  else if (rmax > 1e-10 * xmax) scale = signOfLargest(m, *rot, rmax) / rmax;  // torsion, pure rotation
  if (!(tmax > 1e-10 * xmax)) std::fill(rows.begin(), rows.end(), 0.0);
  for (double& v : rows) v *= scale;
  if (rot)
    for (double& v : *rot) v *= scale;
  PetscFunctionReturn(PETSC_SUCCESS);
}

double frequencyHz(double omega2, double zeroTol) {
  const double twoPi = 2.0 * std::numbers::pi;
  if (!std::isfinite(omega2)) return std::numeric_limits<double>::quiet_NaN();
  if (omega2 >= 0.0) return std::sqrt(omega2) / twoPi;
  if (omega2 > -zeroTol) return 0.0;
  return -std::sqrt(-omega2) / twoPi;
}

ModalAnalysis::ModalAnalysis(Assembler& assembler, int nfreq, bool writeResults, const EigenSettings& settings)
    : asm_(assembler), write_(writeResults), all_(nfreq == Options::kAllFrequencies),
      nev_(all_ ? static_cast<int>(assembler.mesh().numGlobalUnknowns) : nfreq) {
  MPI_Comm comm = asm_.mesh().comm;
  SinewCallThrow(comm, asm_.createMatrix(&K_));
  SinewCallThrow(comm, asm_.createMatrix(&M_));
  SinewCallThrow(comm, MatCreateVecs(K_, &dK_, &dM_));
  SinewCallThrow(comm, EPSCreate(comm, &eps_));
  SinewCallThrow(comm, EPSSetProblemType(eps_, EPS_GHEP));
  SinewCallThrow(comm, EPSSetDimensions(eps_, nev_, PETSC_DEFAULT, PETSC_DEFAULT));
  SinewCallThrow(comm, EPSSetWhichEigenpairs(eps_, EPS_TARGET_MAGNITUDE));
  SinewCallThrow(comm, EPSSetTarget(eps_, 0.0));
  SinewCallThrow(comm, EPSSetPurify(eps_, PETSC_TRUE));  // keeps the multipliers' infinite eigenvalues out
  ST st;
  KSP ksp;
  SinewCallThrow(comm, EPSGetST(eps_, &st));
  SinewCallThrow(comm, STSetType(st, STSINVERT));
  SinewCallThrow(comm, STSetMatStructure(st, SUBSET_NONZERO_PATTERN));  // pattern(M) within pattern(K)
  SinewCallThrow(comm, STGetKSP(st, &ksp));
  SinewCallThrow(comm, useDirectSolver(ksp, asm_.mesh()));
  SinewCallThrow(comm, eigenOperator(asm_, settings.eigenOperator, &elementwise_, true));
  if (elementwise_) {
    // K x by the element-wise, rigid-motion-free products (accurate for the soft modes of fine
    // meshes); (K - sigma M) y = b by GMRES preconditioned with the LU of the assembled K - sigma M
    const PetscInt nloc = asm_.mesh().numOwnedUnknowns, N = static_cast<PetscInt>(asm_.mesh().numGlobalUnknowns);
    SinewCallThrow(comm, MatCreateShell(comm, nloc, nloc, N, N, this, &Kop_));
    SinewCallThrow(comm, MatShellSetOperation(Kop_, MATOP_MULT, reinterpret_cast<void (*)(void)>(stiffnessMult)));
    SinewCallThrow(comm, MatSetOption(Kop_, MAT_SYMMETRIC, PETSC_TRUE));
    SinewCallThrow(comm, asm_.createMatrix(&P_));
    SinewCallThrow(comm, STSetMatMode(st, ST_MATMODE_SHELL));
    SinewCallThrow(comm, useAccurateInnerSolver(ksp));
  }
  SinewCallThrow(comm, EPSSetFromOptions(eps_));  // last: -eps_* and -st_* flags win
  PetscInt nev, ncv, mpd;
  SinewCallThrow(comm, EPSGetDimensions(eps_, &nev, &ncv, &mpd));
  nev_ = static_cast<int>(nev);
  // never more pairs than unknowns (nfreq 100000 allocated that many vectors: 48 s, a 373 MB file)
  const long N = asm_.mesh().numGlobalUnknowns;
  if (nev_ > N && !all_) {
    SinewCallThrow(comm, PetscPrintf(comm, "warning: %d natural frequencies asked for (nfreq), the model has %ld unknowns: "
                                           "computing at most %ld\n", nev_, N, N));
    nev_ = static_cast<int>(N);
    SinewCallThrow(comm, EPSSetDimensions(eps_, nev_, ncv > N ? PETSC_DEFAULT : ncv, PETSC_DEFAULT));
  }
  userTarget_ = settings.userTarget;
  shiftRel_ = settings.freqShiftRel;
  dense_ = N <= settings.denseMaxUnknowns;
  modes_.resize(nev_, nullptr);
  for (Vec& v : modes_) SinewCallThrow(comm, MatCreateVecs(K_, &v, nullptr));
}

ModalAnalysis::~ModalAnalysis() {
  EPSDestroy(&eps_);
  for (Vec& v : modes_) VecDestroy(&v);
  VecDestroy(&dK_);
  VecDestroy(&dM_);
  MatDestroy(&K_);
  MatDestroy(&Kt_);
  MatDestroy(&Kskew_);
  MatDestroy(&M_);
  MatDestroy(&Kop_);
  MatDestroy(&P_);
  destroyUnitFreeNorms(&scaled_);
  destroyProductGather(&gather_);
}

PetscErrorCode ModalAnalysis::stiffnessMult(Mat A, Vec x, Vec y) {
  PetscFunctionBeginUser;
  void* ctx;
  PetscCall(MatShellGetContext(A, &ctx));
  auto* self = static_cast<ModalAnalysis*>(ctx);
  PetscCall(self->asm_.applyTangent(x, y, true));
  if (self->Kskew_) PetscCall(MatMultAdd(self->Kskew_, x, y, y));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// K: tangent at the converged state (theta = 0), made symmetric: at equilibrium under conservative
// loads it is; what remains (follower-type moment terms) is reported as asymmetry_ (-info).
PetscErrorCode ModalAnalysis::assemble(Vec U, const LoadState& ls) {
  PetscFunctionBeginUser;
  if (elementwise_) {  // the element blocks and rigid-motion data of this tangent, for stiffnessMult
    const Assembler::KeptBlocksScope keep(asm_);
    PetscCall(asm_.jacobian(U, ls, K_));
  } else {
    PetscCall(asm_.jacobian(U, ls, K_));
  }
  // K^T - K in Kt_, a transpose of K kept from one step to the next (its values overwritten) while K's
  // structure is the one it was made for and K^T - K kept its structure
  PetscObjectState kState, tState, tAfter;
  PetscCall(MatGetNonzeroState(K_, &kState));
  PetscCall(MatDestroy(&Kskew_));  // a second reference to Kt_ (below)
  if (Kt_ && kState != transposedState_) PetscCall(MatDestroy(&Kt_));
  if (!Kt_) transposedState_ = kState;
  PetscCall(MatTranspose(K_, Kt_ ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &Kt_));
  PetscCall(MatGetNonzeroState(Kt_, &tState));
  PetscCall(MatAXPY(Kt_, -1.0, K_, UNKNOWN_NONZERO_PATTERN));  // K^T - K
  PetscCall(MatGetNonzeroState(Kt_, &tAfter));
  PetscReal nk, nd;
  PetscCall(MatNorm(K_, NORM_FROBENIUS, &nk));
  PetscCall(MatNorm(Kt_, NORM_FROBENIUS, &nd));
  const double asym = nk > 0 ? nd / nk : 0.0;
  asymmetry_ = std::max(asymmetry_, asym);
  if (nd > 0) PetscCall(MatAXPY(K_, 0.5, Kt_, UNKNOWN_NONZERO_PATTERN));
  // the element-wise operator is made symmetric the same way: its products plus (K^T - K)/2 x of
  // the assembled matrix (the skew part is of the order of the moments, no cancellation; without it
  // the loaded crosshinge's f2 differed by 2.1e-5 between the two operators at every mesh size)
  if (elementwise_ && nd > 0) {
    PetscCall(MatScale(Kt_, 0.5));
    PetscCall(PetscObjectReference(reinterpret_cast<PetscObject>(Kt_)));
    Kskew_ = Kt_;
  }
  if (tAfter != tState) PetscCall(MatDestroy(&Kt_));  // no longer the transpose's structure
  PetscCall(PetscInfo(nullptr, "step %d: ||K - K^T||_F / ||K||_F = %g (symmetric part used)\n", step_, asym));
  PetscCall(asm_.mass(U, ls, M_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Spectrum scale s = min over rows with mass and stiffness of K_ii / M_ii (the Rayleigh quotient of
// a unit vector: an estimate from above of the lowest eigenvalues). sigma = -shiftRel * s keeps
// K - sigma M regular when K is singular (free-free structures: rigid-body modes at omega = 0).
PetscErrorCode ModalAnalysis::shiftTarget(double* sigma, double* scale) {
  PetscFunctionBeginUser;
  PetscCall(MatGetDiagonal(K_, dK_));
  PetscCall(MatGetDiagonal(M_, dM_));
  const PetscScalar *k, *m;
  PetscInt n;
  PetscCall(VecGetLocalSize(dK_, &n));
  PetscCall(VecGetArrayRead(dK_, &k));
  PetscCall(VecGetArrayRead(dM_, &m));
  double s = std::numeric_limits<double>::max();
  for (PetscInt i = 0; i < n; ++i)
    if (m[i] > 0 && k[i] > 0) s = std::min(s, k[i] / m[i]);
  PetscCall(VecRestoreArrayRead(dK_, &k));
  PetscCall(VecRestoreArrayRead(dM_, &m));
  MPI_Allreduce(MPI_IN_PLACE, &s, 1, MPI_DOUBLE, MPI_MIN, asm_.mesh().comm);
  if (s == std::numeric_limits<double>::max()) s = 1.0;
  *scale = s;
  *sigma = -shiftRel_ * s;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Finite eigenvalues: at most (unknowns with mass) - (constraint multipliers), every multiplier
// removing one massive direction. Asking for more gives infinite eigenvalues, never frequencies:
// the finite ones are computed, with a warning saying how many exist (issue 10 item 8; before /freq
// gets its width at the first step).
PetscErrorCode ModalAnalysis::clampToFiniteModes() {
  PetscFunctionBeginUser;
  const DistributedMesh& m = asm_.mesh();
  const PetscScalar* d;
  PetscCall(VecGetArrayRead(dM_, &d));
  long counts[2] = {0, 0};  // rows with mass, node-DOF unknowns
  for (int i = 0; i < m.numOwnedUnknowns; ++i) counts[0] += d[i] > 0;
  PetscCall(VecRestoreArrayRead(dM_, &d));
  for (int i = 0; i < m.numOwnedNodes; ++i)
    for (int k = 0; k < m.nodes[i].ndof; ++k) counts[1] += m.nodes[i].dof[k] >= 0;
  MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPI_LONG, MPI_SUM, m.comm);
  const long multipliers = m.numGlobalUnknowns - counts[1];
  const long finite = counts[0] - multipliers;
  if (finite < 1 || nev_ <= finite) PetscFunctionReturn(PETSC_SUCCESS);
  if (!all_)  // nfreq: all asks for every finite one: no warning
    PetscCall(PetscPrintf(m.comm,
                        "warning: %d natural frequencies asked for, the model has %ld finite ones (%ld unknowns, %ld with "
                        "mass, %ld constraint multipliers): computing %ld\n",
                        nev_, finite, m.numGlobalUnknowns, counts[0], multipliers, finite));
  for (int j = static_cast<int>(finite); j < nev_; ++j) PetscCall(VecDestroy(&modes_[j]));
  nev_ = static_cast<int>(finite);
  modes_.resize(nev_);
  PetscInt nev, ncv, mpd;
  PetscCall(EPSGetDimensions(eps_, &nev, &ncv, &mpd));
  PetscCall(EPSSetDimensions(eps_, nev_, ncv > nev_ ? ncv : PETSC_DEFAULT, PETSC_DEFAULT));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The pencil SLEPc solves, gathered to rank 0 and solved dense about the target; the pairs (nearest
// first, as SLEPc orders them) go to every rank. With the element-wise operator, the dense solve of
// the assembled K gives a basis of the nearest modes and a Rayleigh-Ritz step with the element-wise
// products in that basis the pairs (a dense factorization perturbs soft modes by eps ||K||, as the
// assembled products do; the element-wise products do not).
PetscErrorCode ModalAnalysis::solveDense(double target, DenseEigenpairs& pairs) {
  PetscFunctionBeginUser;
  const DistributedMesh& mesh = asm_.mesh();
  const int n = static_cast<int>(mesh.numGlobalUnknowns);
  PetscCall(gatherDense(K_, denseK_));
  PetscCall(gatherDense(M_, denseM_));
  const std::vector<double>&K = denseK_.full, &M = denseM_.full;
  // the Ritz basis: twice the pairs looked at (a wider one adds stiff modes, whose reduced
  // eigenproblem's round-off, eps lambda_max, would reach the soft ones)
  if (mesh.rank == 0) pairs = symmetricPencil(K, M, n, target, elementwise_ ? 2 * (nev_ + 8) : nev_ + 8, !elementwise_);
  PetscCall(broadcastPairs(mesh.comm, pairs));
  if (elementwise_ && !pairs.singular) {
    std::vector<double> KX;
    PetscCall(operatorProducts(Kop_, pairs, KX, &gather_));
    PetscReal normK;
    PetscCall(MatNorm(K_, NORM_INFINITY, &normK));
    if (mesh.rank == 0) pairs = ritzPairs(pairs.vectors, KX, M, n, pairs.wanted(), target, normK, nev_ + 8);
    PetscCall(broadcastPairs(mesh.comm, pairs));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ModalAnalysis::atStep(Vec U, const LoadState& ls, ResultFile& file, bool* ok) {
  PetscFunctionBeginUser;
  ++step_;
  const DistributedMesh& mesh = asm_.mesh();
  PetscCall(assemble(U, ls));
  double sigma = 0, scale = 1;
  PetscCall(shiftTarget(&sigma, &scale));
  if (step_ == 1) PetscCall(clampToFiniteModes());
  if (!userTarget_) PetscCall(EPSSetTarget(eps_, sigma));
  if (elementwise_ && !dense_) {
    PetscScalar target;
    PetscCall(EPSGetTarget(eps_, &target));
    PetscCall(MatCopy(K_, P_, SAME_NONZERO_PATTERN));
    PetscCall(MatAXPY(P_, -target, M_, SUBSET_NONZERO_PATTERN));
    ST st;
    PetscCall(EPSGetST(eps_, &st));
    PetscCall(STSetPreconditionerMat(st, P_));
    PetscCall(EPSSetOperators(eps_, Kop_, M_));
  } else {
    PetscCall(EPSSetOperators(eps_, K_, M_));
  }

  PetscCall(PetscLogEventBegin(SinewEvents::get().eigen, 0, 0, 0, 0));
  DenseEigenpairs dense;
  PetscInt nconv;
  EPSConvergedReason reason = EPS_CONVERGED_TOL;
  if (dense_) {
    PetscScalar target;
    PetscCall(EPSGetTarget(eps_, &target));
    PetscCall(solveDense(target, dense));
    nconv = dense.count();
  } else {
    PetscCall(EPSSolve(eps_));
    PetscCall(EPSGetConverged(eps_, &nconv));
    PetscCall(EPSGetConvergedReason(eps_, &reason));
  }
  PetscCall(PetscLogEventEnd(SinewEvents::get().eigen, 0, 0, 0, 0));
  PetscReal tol;
  PetscInt maxit;
  PetscCall(EPSGetTolerances(eps_, &tol, &maxit));
  tol_ = tol > 0 ? tol : SLEPC_DEFAULT_TOL;  // set by EPSSetUp, which the dense path skips
  PetscCall(unitFreeNorms(mesh, K_, M_, &scaled_));
  Vec r;
  PetscCall(pool_.get(K_, &r));

  // eigenpairs: drop infinite ones (zero mass norm: constraint directions), M-normalize the rest
  PetscReal mmax;
  PetscCall(VecMax(dM_, nullptr, &mmax));
  struct Pair {
    double lambda;
    int index;
    double estimate, backward;
  };
  std::vector<Pair> pairs;
  Vec Mx;
  PetscCall(pool_.get(K_, &Mx));
  std::vector<Vec> found;
  const int take = std::min<int>(static_cast<int>(nconv), nev_ + 8);
  for (int i = 0; i < take && static_cast<int>(pairs.size()) < nev_; ++i) {
    PetscScalar kr, ki;
    Vec x;
    PetscCall(pool_.get(K_, &x));
    if (dense_) {
      kr = dense.re[i];
      PetscCall(pairVector(dense, i, x));
    } else {
      PetscCall(EPSGetEigenpair(eps_, i, &kr, &ki, x, nullptr));
    }
    PetscReal xn;
    PetscCall(VecNormalize(x, &xn));
    PetscCall(MatMult(M_, x, Mx));
    PetscScalar xMx;
    PetscCall(VecDot(x, Mx, &xMx));
    if (!std::isfinite(kr) || !(xMx > 1e-12 * mmax)) {
      ++spurious_;
      pool_.put(&x);
      continue;
    }
    PetscReal estimate = 0;
    if (dense_) estimate = dense.estimate[i];
    else PetscCall(EPSGetErrorEstimate(eps_, i, &estimate));
    PetscCall(VecScale(x, 1.0 / std::sqrt(xMx)));
    PetscCall(MatMult(M_, x, Mx));
    if (elementwise_) {  // Rayleigh quotient with the accurate operator (error quadratic in the mode's)
      PetscCall(asm_.applyTangent(x, r, true));
      PetscScalar xKx;
      PetscCall(VecDot(x, r, &xKx));
      kr = xKx;
    } else {
      PetscCall(MatMult(K_, x, r));
    }
    // backward error of K x - lambda M x with the operator used, rotations scaled by the model size
    PetscCall(VecAXPY(r, -kr, Mx));
    PetscReal backward;
    PetscCall(scaledBackwardError(scaled_, x, r, kr, &backward));
    pairs.push_back({kr, static_cast<int>(found.size()), estimate, backward});
    found.push_back(x);
  }
  pool_.put(&Mx);
  pool_.put(&r);
  std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.lambda < b.lambda; });

  const double zeroTol = 1e-6 * scale;
  hz_.assign(nev_, std::numeric_limits<double>::quiet_NaN());
  estimate_.assign(nev_, std::numeric_limits<double>::quiet_NaN());
  backward_.assign(nev_, std::numeric_limits<double>::quiet_NaN());
  double worst = 0;
  for (size_t j = 0; j < pairs.size(); ++j) {
    hz_[j] = frequencyHz(pairs[j].lambda, zeroTol);
    estimate_[j] = pairs[j].estimate;
    backward_[j] = pairs[j].backward;
    worst = std::max({worst, pairs[j].estimate, pairs[j].backward});
    PetscCall(VecCopy(found[pairs[j].index], modes_[j]));
  }
  for (Vec& x : found) pool_.put(&x);
  PetscCall(PetscInfo(nullptr, "step %d: target %g (scale %g), %d converged, reason %s\n", step_, userTarget_ ? 0.0 : sigma,
                      scale, static_cast<int>(nconv), dense_ ? "dense LAPACK" : EPSConvergedReasons[reason]));
  if (elementwise_) {
    const long rf = asm_.rigidFreeElements();
    PetscCall(PetscInfo(nullptr, "step %d: %ld elements (all ranks; %ld local) apply K rigid-motion free\n", step_, rf, static_cast<long>(mesh.elements.size())));
  }

  if (static_cast<int>(pairs.size()) < nev_) {
    *ok = false;
    std::ostringstream msg;
    msg << "natural frequencies at step " << step_ << ": ";
    if (dense_)
      msg << "the dense eigensolver found " << pairs.size() << " of " << nev_ << " eigenpairs"
          << (dense.singular ? " (K - sigma M is singular at the target)" : "")
          << "; try -eigen_dense_max_unknowns 0 (SLEPc), -eps_target, or fewer frequencies (-nfreq)";
    else
      msg << "SLEPc converged " << pairs.size() << " of " << nev_ << " eigenpairs (" << EPSConvergedReasons[reason]
          << "); try -eps_max_it, -eps_ncv, a looser -eps_tol, or fewer frequencies (-nfreq)";
    failure_ = msg.str();
  }
  if (worst > tol_) {
    ++warned_;
    PetscCall(PetscPrintf(mesh.comm,
                          "  warning: natural frequencies at step %d: error estimate or backward error %.2e of an "
                          "eigenpair exceeds -eps_tol %.1e (/freq_error_estimate, /freq_backward_error)\n",
                          step_, worst, tol_));
  }
  if (write_) {
    file.writeStepRow("freq", hz_, true);
    file.writeStepRow("freq_error_estimate", estimate_, true);
    file.writeStepRow("freq_backward_error", backward_, true);
    std::vector<double> rows, rot;
    std::vector<double>* withRot = mesh.anyRotations ? &rot : nullptr;
    for (int j = 0; j < nev_; ++j) {
      if (j < static_cast<int>(pairs.size())) {
        PetscCall(modeShapeRows(mesh, modes_[j], rows, withRot));
      } else {
        rows.assign(3 * static_cast<size_t>(mesh.numOwnedNodes), 0.0);
        rot = rows;
      }
      file.writeMeshField("mesh/mode_freq_" + std::to_string(j + 1), rows, {3});
      if (withRot) file.writeMeshField("mesh/mode_freq_" + std::to_string(j + 1) + "_rot", rot, {3});
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::string ModalAnalysis::summary() const {
  if (!write_ || hz_.empty()) return {};
  std::ostringstream s;
  char buf[64];
  s << "\n natural frequencies (Hz, last step):";
  int zeros = 0, negative = 0;
  for (double f : hz_) {
    std::snprintf(buf, sizeof buf, " %.6g", f);
    s << buf;
    zeros += f == 0.0;
    negative += f < 0.0;
  }
  s << "\n";
  if (zeros) s << "   " << zeros << " rigid-body mode(s) (omega^2 at round-off level, reported as 0)\n";
  if (negative) s << "   " << negative << " negative omega^2 reported as -sqrt(-omega^2)/(2 pi): the state is unstable\n";
  if (dense_)
    s << "   eigensolver: dense LAPACK for " << asm_.mesh().numGlobalUnknowns
      << " unknowns (up to -eigen_dense_max_unknowns; 0: SLEPc)\n";
  if (asymmetry_ > 1e-6) {
    std::snprintf(buf, sizeof buf, "%.2e", asymmetry_);
    s << "   tangent asymmetry ||K - K^T||/||K|| up to " << buf << " (non-conservative loads): symmetric part used\n";
  }
  return s.str();
}

}  // namespace sinew
