// Rank-local LU with an exact Woodbury correction of the coupling between ranks (useCutCorrectedLU).
#include "solvers/cut_corrected_lu.hpp"

#include <petsc/private/pcimpl.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "solvers/solver_defaults.hpp"

namespace sinew {

long couplingUnknowns(const DistributedMesh& mesh) {
  long m = static_cast<long>(mesh.ghostUnknowns.size());
  MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_LONG, MPI_SUM, mesh.comm);
  return m;
}

namespace {

/// LU with partial pivoting of the m x m column-major matrix a (in place); false if singular.
bool denseLU(std::vector<double>& a, std::vector<int>& piv, size_t m) {
  for (size_t k = 0; k < m; ++k) {
    size_t p = k;
    for (size_t i = k + 1; i < m; ++i)
      if (std::abs(a[k * m + i]) > std::abs(a[k * m + p])) p = i;
    piv[k] = static_cast<int>(p);
    if (a[k * m + p] == 0.0) return false;
    if (p != k)
      for (size_t j = 0; j < m; ++j) std::swap(a[j * m + k], a[j * m + p]);
    for (size_t i = k + 1; i < m; ++i) a[k * m + i] /= a[k * m + k];
    for (size_t j = k + 1; j < m; ++j)
      for (size_t i = k + 1; i < m; ++i) a[j * m + i] -= a[k * m + i] * a[j * m + k];
  }
  return true;
}

/// Solves with the factors of denseLU, b overwritten by the solution.
void denseSolve(const std::vector<double>& a, const std::vector<int>& piv, size_t m, std::vector<double>& b) {
  for (size_t k = 0; k < m; ++k) std::swap(b[k], b[static_cast<size_t>(piv[k])]);
  for (size_t j = 0; j < m; ++j)
    for (size_t i = j + 1; i < m; ++i) b[i] -= a[j * m + i] * b[j];
  for (size_t j = m; j-- > 0;) {
    b[j] /= a[j * m + j];
    for (size_t i = 0; i < j; ++i) b[i] -= a[j * m + i] * b[j];
  }
}

struct CutLU {
  PetscInt maxCoupling = 4096;      ///< -pc_cutlu_max_coupling: the dense capacitance matrix's bound
  KSP local = nullptr;              ///< LU of this rank's diagonal block D_r
  Vec b = nullptr, y = nullptr;     ///< sequential views of the local parts
  std::vector<PetscInt> coupling;   ///< global ids of the coupling unknowns, ascending (all ranks alike)
  std::vector<PetscInt> ownedRow;   ///< local row of each coupling unknown on its owner, else -1
  std::vector<PetscInt> columns;    ///< coupling columns of this rank's rows (indices into coupling)
  std::vector<double> Z;            ///< D_r^-1 W for those columns (local rows x columns.size())
  std::vector<double> C;            ///< LU factors of I + S^T D^-1 W (m x m, column-major)
  std::vector<int> pivots;
  std::vector<double> c;            ///< work: S^T D^-1 b and the correction coefficients
};

/// y = D_r^-1 b with this rank's factors (b, y: arrays of its local rows).
PetscErrorCode localSolve(CutLU* cut, const double* b, double* y) {
  PetscFunctionBeginUser;
  PetscCall(VecPlaceArray(cut->b, b));
  PetscCall(VecPlaceArray(cut->y, y));
  PetscCall(KSPSolve(cut->local, cut->b, cut->y));
  PetscCall(VecResetArray(cut->b));
  PetscCall(VecResetArray(cut->y));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// PCReset: the factors and the coupling pattern go (a new matrix may couple other unknowns).
PetscErrorCode cutReset(PC pc) {
  PetscFunctionBeginUser;
  auto* cut = static_cast<CutLU*>(pc->data);
  PetscCall(KSPDestroy(&cut->local));
  PetscCall(VecDestroy(&cut->b));
  PetscCall(VecDestroy(&cut->y));
  const PetscInt maxCoupling = cut->maxCoupling;
  *cut = CutLU{};
  cut->maxCoupling = maxCoupling;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode cutDestroy(PC pc) {
  PetscFunctionBeginUser;
  PetscCall(cutReset(pc));
  delete static_cast<CutLU*>(pc->data);
  pc->data = nullptr;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode cutSetFromOptions(PC pc, PetscOptionItems* PetscOptionsObject) {
  PetscFunctionBeginUser;
  auto* cut = static_cast<CutLU*>(pc->data);
  PetscOptionsHeadBegin(PetscOptionsObject, "Cut-corrected LU options");
  PetscCall(PetscOptionsInt("-pc_cutlu_max_coupling", "most unknowns coupling the ranks (the capacitance matrix is dense)",
                            "PCCUTLU", cut->maxCoupling, &cut->maxCoupling, nullptr));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode cutSetUp(PC pc) {
  PetscFunctionBeginUser;
  auto* cut = static_cast<CutLU*>(pc->data);
  Mat A, Ad, Ao;
  const PetscInt* colmap = nullptr;
  PetscCall(PCGetOperators(pc, nullptr, &A));
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(A));
  PetscBool mpi = PETSC_FALSE;
  PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(A), MATMPIAIJ, &mpi));
  Ad = A;
  Ao = nullptr;
  if (mpi) PetscCall(MatMPIAIJGetSeqAIJ(A, &Ad, &Ao, &colmap));
  PetscInt n = 0, no = 0, rstart = 0, rend = 0;
  PetscCall(MatGetLocalSize(Ad, &n, nullptr));
  if (Ao) PetscCall(MatGetLocalSize(Ao, nullptr, &no));
  PetscCall(MatGetOwnershipRange(A, &rstart, &rend));
  if (!cut->local) {
    // the coupling unknowns of all ranks, and where each one is owned
    int size = 1;
    PetscCallMPI(MPI_Comm_size(comm, &size));
    std::vector<int> counts(size), displs(size);
    int mine = static_cast<int>(no);
    PetscCallMPI(MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
    int total = 0;
    for (int r = 0; r < size; ++r) {
      displs[r] = total;
      total += counts[r];
    }
    std::vector<PetscInt> all(total);
    PetscCallMPI(MPI_Allgatherv(colmap, mine, MPIU_INT, all.data(), counts.data(), displs.data(), MPIU_INT, comm));
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    if (static_cast<PetscInt>(all.size()) > cut->maxCoupling)
      SETERRQ(comm, PETSC_ERR_SUP,
              "cut-corrected LU (-dynamics_chain_lu cut): %d unknowns couple the ranks, at most %d (-pc_cutlu_max_coupling; its "
              "capacitance matrix is dense); use -dynamics_chain_lu redundant or auto",
              static_cast<int>(all.size()), static_cast<int>(cut->maxCoupling));
    cut->coupling = all;
    cut->ownedRow.assign(all.size(), -1);
    for (size_t k = 0; k < all.size(); ++k)
      if (all[k] >= rstart && all[k] < rend) cut->ownedRow[k] = all[k] - rstart;
    cut->columns.resize(no);
    for (PetscInt j = 0; j < no; ++j)
      cut->columns[j] = std::lower_bound(all.begin(), all.end(), colmap[j]) - all.begin();
    PetscCall(KSPCreate(PETSC_COMM_SELF, &cut->local));
    const char* prefix = nullptr;  // the local LU's options: -<this PC's prefix>cut_<option>
    PetscCall(PCGetOptionsPrefix(pc, &prefix));
    PetscCall(KSPSetOptionsPrefix(cut->local, prefix));
    PetscCall(KSPAppendOptionsPrefix(cut->local, "cut_"));
    PetscCall(KSPSetType(cut->local, KSPPREONLY));
    PC lpc;
    PetscCall(KSPGetPC(cut->local, &lpc));
    PetscCall(PCSetType(lpc, PCLU));
    PetscCall(usePetscLU(cut->local, MATORDERINGRCM));
    PetscCall(KSPSetFromOptions(cut->local));
    PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, nullptr, &cut->b));
    PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, nullptr, &cut->y));
  }
  // refactor D_r (its values changed with A's)
  PetscCall(PetscObjectStateIncrease(reinterpret_cast<PetscObject>(Ad)));
  PetscCall(KSPSetOperators(cut->local, Ad, Ad));
  PetscCall(KSPSetUp(cut->local));
  // Z = D_r^-1 W_r, one local solve per coupling column of this rank
  const size_t m = cut->coupling.size();
  cut->Z.assign(static_cast<size_t>(n) * no, 0.0);
  std::vector<double> w(static_cast<size_t>(n) * no, 0.0);
  if (no > 0) {  // the columns of Ao (few rows have entries: MatGetRowIJ instead of a MatGetRow per row)
    const PetscInt *ia = nullptr, *ja = nullptr;
    PetscInt nr = 0;
    PetscBool done = PETSC_FALSE;
    const PetscScalar* va = nullptr;
    PetscCall(MatGetRowIJ(Ao, 0, PETSC_FALSE, PETSC_FALSE, &nr, &ia, &ja, &done));
    if (!done) SETERRQ(comm, PETSC_ERR_SUP, "cut-corrected LU: no row structure of the coupling block");
    PetscCall(MatSeqAIJGetArrayRead(Ao, &va));
    for (PetscInt i = 0; i < nr; ++i)
      for (PetscInt k = ia[i]; k < ia[i + 1]; ++k) w[static_cast<size_t>(ja[k]) * n + i] = va[k];
    PetscCall(MatSeqAIJRestoreArrayRead(Ao, &va));
    PetscCall(MatRestoreRowIJ(Ao, 0, PETSC_FALSE, PETSC_FALSE, &nr, &ia, &ja, &done));
  }
  for (PetscInt j = 0; j < no; ++j)
    PetscCall(localSolve(cut, w.data() + static_cast<size_t>(j) * n, cut->Z.data() + static_cast<size_t>(j) * n));
  // capacitance I + S^T D^-1 W: the rows of the owned coupling unknowns here, summed over the ranks
  cut->C.assign(m * m, 0.0);
  for (PetscInt j = 0; j < no; ++j) {
    const size_t col = static_cast<size_t>(cut->columns[j]);
    for (size_t k = 0; k < m; ++k)
      if (cut->ownedRow[k] >= 0) cut->C[col * m + k] += cut->Z[static_cast<size_t>(j) * n + cut->ownedRow[k]];
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, cut->C.data(), static_cast<int>(m * m), MPI_DOUBLE, MPI_SUM, comm));
  for (size_t k = 0; k < m; ++k) cut->C[k * m + k] += 1.0;
  cut->pivots.resize(m);
  cut->c.resize(m);
  if (!denseLU(cut->C, cut->pivots, m)) SETERRQ(comm, PETSC_ERR_MAT_LU_ZRPVT, "cut-corrected LU: singular coupling matrix");
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode cutApply(PC pc, Vec x, Vec y) {
  PetscFunctionBeginUser;
  auto* cut = static_cast<CutLU*>(pc->data);
  const PetscScalar* xa;
  PetscScalar* ya;
  PetscCall(VecGetArrayRead(x, &xa));
  PetscCall(VecGetArray(y, &ya));
  PetscCall(localSolve(cut, xa, ya));
  const size_t m = cut->coupling.size();
  if (m > 0) {
    PetscInt n = 0;
    PetscCall(VecGetLocalSize(x, &n));
    for (size_t k = 0; k < m; ++k) cut->c[k] = cut->ownedRow[k] >= 0 ? ya[cut->ownedRow[k]] : 0.0;
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, cut->c.data(), static_cast<int>(m), MPI_DOUBLE, MPI_SUM,
                               PetscObjectComm(reinterpret_cast<PetscObject>(pc))));
    denseSolve(cut->C, cut->pivots, m, cut->c);
    for (size_t j = 0; j < cut->columns.size(); ++j) {
      const double cj = cut->c[static_cast<size_t>(cut->columns[j])];
      const double* z = cut->Z.data() + j * static_cast<size_t>(n);
      for (PetscInt i = 0; i < n; ++i) ya[i] -= cj * z[i];
    }
  }
  PetscCall(VecRestoreArray(y, &ya));
  PetscCall(VecRestoreArrayRead(x, &xa));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode cutView(PC pc, PetscViewer viewer) {
  PetscFunctionBeginUser;
  auto* cut = static_cast<CutLU*>(pc->data);
  PetscCall(PetscViewerASCIIPrintf(viewer, "  cut-corrected LU: %d coupling unknowns; rank 0's local LU:\n",
                                   static_cast<int>(cut->coupling.size())));
  PetscViewer sub;
  PetscCall(PetscViewerGetSubViewer(viewer, PETSC_COMM_SELF, &sub));
  int rank = 0;
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm(reinterpret_cast<PetscObject>(pc)), &rank));
  if (rank == 0 && cut->local) {
    PetscCall(PetscViewerASCIIPushTab(sub));
    PetscCall(KSPView(cut->local, sub));
    PetscCall(PetscViewerASCIIPopTab(sub));
  }
  PetscCall(PetscViewerRestoreSubViewer(viewer, PETSC_COMM_SELF, &sub));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// PCCreate for PCCUTLU (PCRegister: -pc_type cutlu).
PetscErrorCode createCutLU(PC pc) {
  PetscFunctionBeginUser;
  pc->data = new CutLU;
  pc->ops->setup = cutSetUp;
  pc->ops->apply = cutApply;
  pc->ops->reset = cutReset;
  pc->ops->destroy = cutDestroy;
  pc->ops->view = cutView;
  pc->ops->setfromoptions = cutSetFromOptions;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

PetscErrorCode registerCutCorrectedLU() {
  PetscFunctionBeginUser;
  PetscCall(PCRegister(PCCUTLU, createCutLU));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode useCutCorrectedLU(KSP ksp) {
  PetscFunctionBeginUser;
  PetscCall(registerCutCorrectedLU());
  PC pc;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCCUTLU));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
