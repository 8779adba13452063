// PC type denselu: LAPACK LU with partial pivoting of a one-process matrix (dense_lu.hpp).
#include "solvers/dense_lu.hpp"

#include <petsc/private/pcimpl.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

#include "sinew/petsc_compat.hpp"

extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda, const int* ipiv,
             double* b, const int* ldb, int* info);
}

namespace sinew {

namespace {

std::atomic<long> gFactorizations{0};
PetscLogEvent gFactorEvent = 0;  // SinewDenseLU: one per factorization (-log_view shows the path ran)

struct DenseLU {
  int n = 0;
  std::vector<double> d;       // symmetric equilibration: the factors are those of D A D
  std::vector<PetscInt> row;   // D A D by rows (CSR, columns ascending), for the refinement residual:
  std::vector<PetscInt> col;   //   row i holds col[row[i] .. row[i+1]) with values val[...]
  std::vector<double> val;
  std::vector<double> lu;      // column-major n x n factors
  std::vector<int> piv;
  std::vector<double> rhs;     // a solve's scaled right-hand sides, then their residuals
  bool failed = false;
};

/// The rows of A into d's CSR arrays (values unscaled); columns ascending within a row.
PetscErrorCode copyRows(Mat A, DenseLU* d) {
  PetscFunctionBeginUser;
  const int n = d->n;
  PetscBool seq = PETSC_FALSE;
  PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(A), MATSEQAIJ, &seq));
  if (seq) {  // the CSR arrays as they are (AIJ keeps every row sorted by column)
    PetscInt m;
    const PetscInt *ia, *ja;
    PetscBool done;
    PetscCall(MatGetRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
    const bool whole = done && m == n;
    if (whole) {
      const PetscScalar* a;
      PetscCall(MatSeqAIJGetArrayRead(A, &a));
      d->row.assign(ia, ia + n + 1);
      d->col.assign(ja, ja + ia[n]);
      d->val.assign(a, a + ia[n]);
      PetscCall(MatSeqAIJRestoreArrayRead(A, &a));
    }
    PetscCall(MatRestoreRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
    if (whole) PetscFunctionReturn(PETSC_SUCCESS);
  }
  d->row.assign(static_cast<size_t>(n) + 1, 0);
  d->col.clear();
  d->val.clear();
  for (PetscInt i = 0; i < n; ++i) {
    PetscInt nc;
    const PetscInt* cols;
    const PetscScalar* vals;
    PetscCall(MatGetRow(A, i, &nc, &cols, &vals));
    d->col.insert(d->col.end(), cols, cols + nc);
    d->val.insert(d->val.end(), vals, vals + nc);
    PetscCall(MatRestoreRow(A, i, &nc, &cols, &vals));
    d->row[i + 1] = static_cast<PetscInt>(d->col.size());
  }
  for (PetscInt i = 0; i < n; ++i)
    for (PetscInt k = d->row[i] + 1; k < d->row[i + 1]; ++k)
      PetscCheck(d->col[k - 1] < d->col[k], PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
                 "-pc_type denselu: row %" PetscInt_FMT " of the matrix is not sorted by column", i);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// A = P L U of the preconditioning matrix, its rows copied into the column-major array.
PetscErrorCode denseSetUp(PC pc) {
  PetscFunctionBeginUser;
  auto* d = static_cast<DenseLU*>(pc->data);
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm(reinterpret_cast<PetscObject>(pc)), &size));
  PetscCheck(size == 1, PetscObjectComm(reinterpret_cast<PetscObject>(pc)), PETSC_ERR_SUP,
             "-pc_type denselu: one process only (the dense LU of a small one-process model)");
  PetscCall(PetscLogEventBegin(gFactorEvent, pc, 0, 0, 0));
  PetscInt m, ncol;
  PetscCall(MatGetSize(pc->pmat, &m, &ncol));
  PetscCheck(m == ncol, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "-pc_type denselu: the matrix is not square");
  const int n = static_cast<int>(m);
  d->n = n;
  PetscCall(copyRows(pc->pmat, d));
  // D A D with d_i = 1/sqrt(max_j |A_ij|): rows of translations, rotations and multipliers differ by
  // orders of magnitude in their units; partial pivoting then compares like with like
  d->d.assign(n, 0.0);
  for (int i = 0; i < n; ++i)
    for (PetscInt k = d->row[i]; k < d->row[i + 1]; ++k) d->d[i] = std::max(d->d[i], std::abs(d->val[k]));
  for (double& v : d->d) v = v > 0 ? 1.0 / std::sqrt(v) : 1.0;
  // the scaled rows, and the same values into the zeroed column-major array for getrf
  d->lu.assign(static_cast<size_t>(n) * n, 0.0);
  for (int i = 0; i < n; ++i)
    for (PetscInt k = d->row[i]; k < d->row[i + 1]; ++k) {
      const PetscInt j = d->col[k];
      d->val[k] *= d->d[i] * d->d[j];
      d->lu[static_cast<size_t>(j) * n + i] = d->val[k];
    }
  d->piv.resize(n);
  int info = 0;
  if (n > 0) dgetrf_(&n, &n, d->lu.data(), &n, d->piv.data(), &info);
  d->failed = info != 0;
  if (d->failed) {
    PetscCall(PetscInfo(pc, "dense LU: zero pivot in column %d of %d\n", info, n));
    PetscCall(PCSetFailedReason(pc, PC_FACTOR_NUMERIC_ZEROPIVOT));
  } else {
    PetscCall(PCSetFailedReason(pc, PC_NOERROR));
  }
  ++gFactorizations;
  PetscCall(PetscLogEventEnd(gFactorEvent, pc, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// Solves with the factors: x = A^-1 b for the columns of b (nrhs of them, leading dimension ld).
PetscErrorCode denseSolve(PC pc, int nrhs, PetscScalar* b, int ld) {
  PetscFunctionBeginUser;
  auto* d = static_cast<DenseLU*>(pc->data);
  if (d->failed) {  // as a failed LU factor's solve: the KSP reports KSP_DIVERGED_PC_FAILED
    for (int c = 0; c < nrhs; ++c)
      for (int i = 0; i < d->n; ++i) b[static_cast<size_t>(c) * ld + i] = PETSC_INFINITY;
    PetscCall(PCSetFailedReason(pc, PC_FACTOR_NUMERIC_ZEROPIVOT));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  // x = D (D A D)^-1 D b, with one step of iterative refinement: x += (D A D)^-1 (D b - D A D x)
  const int n = d->n;
  for (int c = 0; c < nrhs; ++c)
    for (int i = 0; i < n; ++i) b[static_cast<size_t>(c) * ld + i] *= d->d[i];
  d->rhs.resize(static_cast<size_t>(n) * nrhs);
  for (int c = 0; c < nrhs; ++c) std::copy_n(b + static_cast<size_t>(c) * ld, n, &d->rhs[static_cast<size_t>(c) * n]);
  int info = 0;
  if (n > 0 && nrhs > 0) dgetrs_("N", &d->n, &nrhs, d->lu.data(), &d->n, d->piv.data(), b, &ld, &info);
  PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "LAPACK dgetrs: info %d", info);
  // r_i = (D b)_i - sum_j (D A D)_ij x_j over the stored entries, j ascending
  const PetscInt* row = d->row.data();
  const PetscInt* col = d->col.data();
  const double* val = d->val.data();
  for (int c = 0; c < nrhs; ++c) {
    double* r = &d->rhs[static_cast<size_t>(c) * n];
    const double* x = b + static_cast<size_t>(c) * ld;
    for (int i = 0; i < n; ++i) {
      double s = r[i];
      for (PetscInt k = row[i]; k < row[i + 1]; ++k) s -= val[k] * x[col[k]];
      r[i] = s;
    }
  }
  if (n > 0 && nrhs > 0) dgetrs_("N", &d->n, &nrhs, d->lu.data(), &d->n, d->piv.data(), d->rhs.data(), &d->n, &info);
  for (int c = 0; c < nrhs; ++c)
    for (int i = 0; i < n; ++i) b[static_cast<size_t>(c) * ld + i] += d->rhs[static_cast<size_t>(c) * n + i];
  for (int c = 0; c < nrhs; ++c)
    for (int i = 0; i < d->n; ++i) b[static_cast<size_t>(c) * ld + i] *= d->d[i];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode denseApply(PC pc, Vec x, Vec y) {
  PetscFunctionBeginUser;
  PetscCall(VecCopy(x, y));
  PetscScalar* a;
  PetscCall(VecGetArray(y, &a));
  PetscCall(denseSolve(pc, 1, a, std::max(static_cast<DenseLU*>(pc->data)->n, 1)));
  PetscCall(VecRestoreArray(y, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// Several right-hand sides at once (KSPMatSolve: the compliance's unit loads), one getrs.
PetscErrorCode denseMatApply(PC pc, Mat B, Mat X) {
  PetscFunctionBeginUser;
  PetscCall(MatCopy(B, X, SAME_NONZERO_PATTERN));
  PetscInt nrhs, lda;
  PetscCall(MatGetSize(X, nullptr, &nrhs));
  PetscCall(MatDenseGetLDA(X, &lda));
  PetscScalar* a;
  PetscCall(MatDenseGetArray(X, &a));
  PetscCall(denseSolve(pc, static_cast<int>(nrhs), a, static_cast<int>(lda)));
  PetscCall(MatDenseRestoreArray(X, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode denseReset(PC pc) {
  PetscFunctionBeginUser;
  auto* d = static_cast<DenseLU*>(pc->data);
  *d = DenseLU{};
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode denseDestroy(PC pc) {
  PetscFunctionBeginUser;
  delete static_cast<DenseLU*>(pc->data);
  pc->data = nullptr;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode denseView(PC pc, PetscViewer viewer) {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "  dense LU (LAPACK getrf/getrs) of %d unknowns\n",
                                   static_cast<DenseLU*>(pc->data)->n));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// PCCreate for PCDENSELU (PCRegister: -pc_type denselu).
PetscErrorCode createDenseLU(PC pc) {
  PetscFunctionBeginUser;
  pc->data = new DenseLU;
  pc->ops->setup = denseSetUp;
  pc->ops->apply = denseApply;
  pc->ops->applytranspose = nullptr;
  pc->ops->matapply = denseMatApply;
  pc->ops->reset = denseReset;
  pc->ops->destroy = denseDestroy;
  pc->ops->view = denseView;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

PetscErrorCode registerDenseLU() {
  PetscFunctionBeginUser;
  PetscCall(PCRegister(PCDENSELU, createDenseLU));
  if (!gFactorEvent) PetscCall(PetscLogEventRegister("SinewDenseLU", PC_CLASSID, &gFactorEvent));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode useDenseLU(KSP ksp) {
  PetscFunctionBeginUser;
  PetscCall(registerDenseLU());
  PC pc;
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCDENSELU));
  PetscFunctionReturn(PETSC_SUCCESS);
}

long denseLUFactorizations() { return gFactorizations.load(); }

}  // namespace sinew
