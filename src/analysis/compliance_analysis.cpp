#include "analysis/compliance_analysis.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <set>

namespace sinew {

ComplianceAnalysis::ComplianceAnalysis(Assembler& assembler, const std::vector<int>& nodes) : asm_(assembler) {
  DistributedMesh& m = asm_.mesh();
  const std::set<int> requested(nodes.begin(), nodes.end());
  wanted_.assign(m.numOwnedNodes, 0);
  long cols = 0;
  for (int i = 0; i < m.numOwnedNodes; ++i) {
    const LocalNode& n = m.nodes[i];
    if (n.sceneNode < 0 || n.kind == NodeKind::Ancf2D) continue;
    if (!requested.empty() && !requested.count(n.sceneNode)) continue;
    wanted_[i] = 1;
    nodes_.push_back(i);
    for (int k = 0; k < n.ndof; ++k) cols += n.dof[k] >= 0;
  }
  MPI_Allreduce(&cols, &totalColumns_, 1, MPI_LONG, MPI_SUM, m.comm);
  PetscBool set = PETSC_FALSE;
  PetscCallAbort(m.comm, PetscOptionsGetInt(nullptr, nullptr, "-compliance_batch", &batch_, &set));
  batch_ = std::max<PetscInt>(batch_, 1);
  PetscCallAbort(m.comm, asm_.createMatrix(&J_));
  PetscCallAbort(m.comm, KSPCreate(m.comm, &ksp_));
  PetscCallAbort(m.comm, KSPSetOptionsPrefix(ksp_, "compl_"));
  PetscCallAbort(m.comm, KSPSetType(ksp_, KSPPREONLY));
  PC pc;
  PetscCallAbort(m.comm, KSPGetPC(ksp_, &pc));
  PetscCallAbort(m.comm, PCSetType(pc, PCLU));
  PetscCallAbort(m.comm, PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PetscCallAbort(m.comm, KSPSetFromOptions(ksp_));
}

ComplianceAnalysis::~ComplianceAnalysis() {
  KSPDestroy(&ksp_);
  MatDestroy(&J_);
}

PetscErrorCode ComplianceAnalysis::atStep(Vec U, const LoadState& ls, ResultFile& file, bool* ok) {
  PetscFunctionBeginUser;
  DistributedMesh& m = asm_.mesh();
  PetscCall(PetscLogEventBegin(SinewEvents::get().compliance, 0, 0, 0, 0));
  *ok = true;
  // 1. Tangent at the converged state (rotation increments absorbed: spin columns) and one LU.
  const double t0 = MPI_Wtime();
  PetscCall(asm_.jacobian(U, ls, J_));
  PetscCall(KSPSetOperators(ksp_, J_, J_));
  PetscCall(KSPSetUp(ksp_));
  PC pc;
  PetscCall(KSPGetPC(ksp_, &pc));
  PCFailedReason why = PC_NOERROR;
  PetscCall(PCGetFailedReason(pc, &why));
  int bad = why != PC_NOERROR;
  MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPI_INT, MPI_LOR, m.comm);
  ++factorizations_;
  factorTime_ += MPI_Wtime() - t0;
  const int nOwned = static_cast<int>(nodes_.size());
  std::vector<double> glob(36 * static_cast<size_t>(m.numOwnedNodes), 0.0);
  if (bad) {
    *ok = false;
    failure_ = "compliance: the tangent is singular at the converged state (a mechanism or redundant constraints); "
               "check supports, rigid modes and releases (opt.rls)";
  } else if (totalColumns_ > 0) {
    const double t1 = MPI_Wtime();
    Mat F;
    PetscCall(PCFactorGetMatrix(pc, &F));
    // My columns: the free DOFs of my requested nodes, numbered after those of lower ranks.
    std::vector<PetscInt> colRow;  // owned row (local index) of each of my columns
    std::vector<std::array<int, 2>> colNodeDof;
    for (int idx = 0; idx < nOwned; ++idx) {
      const LocalNode& n = m.nodes[nodes_[idx]];
      for (int k = 0; k < n.ndof; ++k)
        if (n.dof[k] >= 0) {
          colRow.push_back(n.dof[k]);
          colNodeDof.push_back({nodes_[idx], k});
        }
    }
    long mine = static_cast<long>(colRow.size()), first = 0;
    MPI_Exscan(&mine, &first, 1, MPI_LONG, MPI_SUM, m.comm);
    if (m.rank == 0) first = 0;
    const PetscInt nloc = m.numOwnedUnknowns, N = static_cast<PetscInt>(m.numGlobalUnknowns);
    const PetscInt nb = static_cast<PetscInt>(std::min<long>(batch_, totalColumns_));
    Mat B, X;
    PetscCall(MatCreateDense(m.comm, nloc, PETSC_DECIDE, N, nb, nullptr, &B));
    PetscCall(MatCreateDense(m.comm, nloc, PETSC_DECIDE, N, nb, nullptr, &X));
    PetscInt rStart;
    PetscCall(MatGetOwnershipRange(B, &rStart, nullptr));
    for (long c0 = 0; c0 < totalColumns_; c0 += nb) {
      const long c1 = std::min<long>(c0 + nb, totalColumns_);
      PetscCall(MatZeroEntries(B));
      const long lo = std::max(c0, first), hi = std::min(c1, first + mine);
      for (long c = lo; c < hi; ++c)
        PetscCall(MatSetValue(B, rStart + colRow[c - first], static_cast<PetscInt>(c - c0), 1.0, INSERT_VALUES));
      PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
      PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
      PetscCall(MatMatSolve(F, B, X));
      ++batches_;
      if (lo < hi) {
        const PetscScalar* x;
        PetscInt lda;
        PetscCall(MatDenseGetLDA(X, &lda));
        PetscCall(MatDenseGetArrayRead(X, &x));
        for (long c = lo; c < hi; ++c) {
          const auto [node, kc] = colNodeDof[c - first];
          const LocalNode& n = m.nodes[node];
          const double* col = x + static_cast<size_t>(c - c0) * lda;
          double* C = &glob[36 * static_cast<size_t>(node)];
          for (int kr = 0; kr < n.ndof; ++kr)
            if (n.dof[kr] >= 0) C[6 * kr + kc] = col[n.dof[kr]];
        }
        PetscCall(MatDenseRestoreArrayRead(X, &x));
      }
    }
    PetscCall(MatDestroy(&B));
    PetscCall(MatDestroy(&X));
    solveTime_ += MPI_Wtime() - t1;
  }
  // 2. Rows in StepResults' order (owned scene nodes); CMloc = Q^T CMglob Q.
  std::vector<double> outGlob, outLoc;
  for (int i = 0; i < m.numOwnedNodes; ++i) {
    const LocalNode& n = m.nodes[i];
    if (n.sceneNode < 0) continue;
    const double* C = &glob[36 * static_cast<size_t>(i)];
    std::array<double, 36> L{};
    if (n.kind == NodeKind::Frame6) {
      const double* s = asm_.nodeState(i);
      const double* R = s + 3;  // row-major, columns = node axes in global components
      // L = Q^T C Q, block by block: L_ab = R^T C_ab R
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
              double v = 0.0;
              for (int p = 0; p < 3; ++p)
                for (int q = 0; q < 3; ++q) v += R[3 * p + r] * C[6 * (3 * a + p) + 3 * b + q] * R[3 * q + c];
              L[6 * (3 * a + r) + 3 * b + c] = v;
            }
    } else {
      std::copy(C, C + 36, L.begin());
    }
    outGlob.insert(outGlob.end(), C, C + 36);
    outLoc.insert(outLoc.end(), L.begin(), L.end());
  }
  file.writeNodeField("node/CMglob", outGlob, {6, 6});
  file.writeNodeField("node/CMloc", outLoc, {6, 6});
  PetscCall(PetscLogEventEnd(SinewEvents::get().compliance, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::string ComplianceAnalysis::summary() const {
  char line[256];
  std::snprintf(line, sizeof line,
                "\n compliance: %ld unit loads per step, %ld factorization%s, %ld block solves; factor %.3f s, "
                "solves %.3f s\n",
                totalColumns_, factorizations_, factorizations_ == 1 ? "" : "s", batches_, factorTime_, solveTime_);
  return line;
}

}  // namespace sinew
