#include "step/dense_gather.hpp"

#include <algorithm>
#include <numeric>

#include "assembly/aij_pattern.hpp"

namespace sinew {

PetscErrorCode gatherDense(Mat A, std::vector<double>& full) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(A));
  PetscMPIInt rank, size;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscInt n, r0, r1;
  PetscCall(MatGetSize(A, &n, nullptr));
  PetscCall(MatGetOwnershipRange(A, &r0, &r1));
  if (size == 1) {  // the rows straight into the column-major array
    full.assign(static_cast<size_t>(n) * n, 0.0);
    for (PetscInt i = 0; i < n; ++i) {
      PetscInt nc;
      const PetscInt* cols;
      const PetscScalar* vals;
      PetscCall(MatGetRow(A, i, &nc, &cols, &vals));
      for (PetscInt k = 0; k < nc; ++k) full[static_cast<size_t>(cols[k]) * n + i] = vals[k];
      PetscCall(MatRestoreRow(A, i, &nc, &cols, &vals));
    }
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  // my rows, row-major
  std::vector<double> rows(static_cast<size_t>(r1 - r0) * n, 0.0);
  for (PetscInt i = r0; i < r1; ++i) {
    PetscInt nc;
    const PetscInt* cols;
    const PetscScalar* vals;
    PetscCall(MatGetRow(A, i, &nc, &cols, &vals));
    for (PetscInt k = 0; k < nc; ++k) rows[static_cast<size_t>(i - r0) * n + cols[k]] = vals[k];
    PetscCall(MatRestoreRow(A, i, &nc, &cols, &vals));
  }
  int mine = static_cast<int>(rows.size());
  std::vector<int> counts(rank == 0 ? size : 0), displs(counts.size());
  PetscCallMPI(MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm));
  std::vector<double> rowMajor;
  if (rank == 0) {
    std::exclusive_scan(counts.begin(), counts.end(), displs.begin(), 0);
    rowMajor.resize(static_cast<size_t>(n) * n);
  }
  PetscCallMPI(MPI_Gatherv(rows.data(), mine, MPI_DOUBLE, rowMajor.data(), counts.data(), displs.data(), MPI_DOUBLE, 0, comm));
  full.assign(rank == 0 ? static_cast<size_t>(n) * n : 0, 0.0);
  if (rank == 0)
    for (PetscInt i = 0; i < n; ++i)
      for (PetscInt j = 0; j < n; ++j) full[static_cast<size_t>(j) * n + i] = rowMajor[static_cast<size_t>(i) * n + j];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode gatherDense(Mat A, KeptDense& kept) {
  PetscFunctionBeginUser;
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm(reinterpret_cast<PetscObject>(A)), &size));
  PetscBool seq = PETSC_FALSE;
  PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(A), MATSEQAIJ, &seq));
  PetscInt n;
  const PetscInt *ia, *ja;
  PetscBool done = PETSC_FALSE;
  if (size == 1 && seq) PetscCall(MatGetRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  if (!done) {
    PetscCall(gatherDense(A, kept.full));
    kept.rowStart.clear();
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  const size_t nn = static_cast<size_t>(n) * n;
  if (kept.full.size() != nn || !samePattern(n, ia, ja, kept.rowStart, kept.cols)) {
    kept.full.assign(nn, 0.0);
    kept.rowStart.assign(ia, ia + n + 1);
    kept.cols.assign(ja, ja + ia[n]);
  }
  const PetscScalar* a;
  PetscCall(MatSeqAIJGetArrayRead(A, &a));
  for (PetscInt i = 0; i < n; ++i)
    for (PetscInt k = ia[i]; k < ia[i + 1]; ++k) kept.full[static_cast<size_t>(ja[k]) * n + i] = a[k];
  PetscCall(MatSeqAIJRestoreArrayRead(A, &a));
  PetscCall(MatRestoreRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode operatorToDense(Mat A, std::vector<double>& full) {
  PetscFunctionBeginUser;
  Mat D;
  PetscCall(MatComputeOperator(A, MATDENSE, &D));
  PetscCall(gatherDense(D, full));
  PetscCall(MatDestroy(&D));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode destroyProductGather(ProductGather* g) {
  PetscFunctionBeginUser;
  PetscCall(VecScatterDestroy(&g->toZero));
  PetscCall(VecDestroy(&g->y0));
  PetscCall(VecDestroy(&g->x));
  PetscCall(VecDestroy(&g->y));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode operatorProducts(Mat A, const DenseEigenpairs& p, std::vector<double>& AX, ProductGather* g) {
  PetscFunctionBeginUser;
  if (!g->x) {
    PetscCall(MatCreateVecs(A, &g->x, &g->y));
    PetscCall(VecScatterCreateToZero(g->y, &g->toZero, &g->y0));
  }
  PetscInt n0;
  PetscCall(VecGetSize(g->y0, &n0));  // n on rank 0, 0 elsewhere
  AX.assign(static_cast<size_t>(n0) * p.wanted(), 0.0);
  for (int j = 0; j < p.wanted(); ++j) {
    PetscCall(pairVector(p, j, g->x));
    PetscCall(MatMult(A, g->x, g->y));
    PetscCall(VecScatterBegin(g->toZero, g->y, g->y0, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(g->toZero, g->y, g->y0, INSERT_VALUES, SCATTER_FORWARD));
    const PetscScalar* a;
    PetscCall(VecGetArrayRead(g->y0, &a));
    std::copy_n(a, n0, &AX[static_cast<size_t>(j) * n0]);
    PetscCall(VecRestoreArrayRead(g->y0, &a));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode broadcastPairs(MPI_Comm comm, DenseEigenpairs& p) {
  PetscFunctionBeginUser;
  int head[2] = {p.n, p.singular ? 1 : 0};
  int counts[2] = {p.count(), p.wanted()};
  PetscCallMPI(MPI_Bcast(head, 2, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(counts, 2, MPI_INT, 0, comm));
  p.n = head[0];
  p.singular = head[1] != 0;
  p.re.resize(counts[0]);
  p.im.resize(counts[0]);
  p.estimate.resize(counts[1]);
  p.vectors.resize(static_cast<size_t>(p.n) * counts[1]);
  PetscCallMPI(MPI_Bcast(p.re.data(), counts[0], MPI_DOUBLE, 0, comm));
  PetscCallMPI(MPI_Bcast(p.im.data(), counts[0], MPI_DOUBLE, 0, comm));
  PetscCallMPI(MPI_Bcast(p.estimate.data(), counts[1], MPI_DOUBLE, 0, comm));
  PetscCallMPI(MPI_Bcast(p.vectors.data(), static_cast<int>(p.vectors.size()), MPI_DOUBLE, 0, comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode pairVector(const DenseEigenpairs& p, int j, Vec x) {
  PetscFunctionBeginUser;
  PetscInt r0, r1;
  PetscCall(VecGetOwnershipRange(x, &r0, &r1));
  PetscScalar* a;
  PetscCall(VecGetArray(x, &a));
  const double* col = &p.vectors[static_cast<size_t>(j) * p.n];
  for (PetscInt i = r0; i < r1; ++i) a[i - r0] = col[i];
  PetscCall(VecRestoreArray(x, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
