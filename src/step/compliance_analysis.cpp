#include "step/compliance_analysis.hpp"
#include "parallel/collective_error.hpp"
#include "solvers/solver_defaults.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <numeric>
#include <set>
#include <string>

namespace sinew {

namespace {
const char* methodName(ComplianceAnalysis::Method m) {
  switch (m) {
    case ComplianceAnalysis::Method::SelectedInverse: return "selected inverse entries";
    case ComplianceAnalysis::Method::SparseRhs: return "sparse right-hand sides";
    case ComplianceAnalysis::Method::DenseRhs: return "dense right-hand sides";
  }
  return "";
}
}  // namespace

ComplianceAnalysis::ComplianceAnalysis(Assembler& assembler, const std::vector<int>& nodes, const ComplianceSettings& settings,
                                       int denseMaxUnknowns)
    : asm_(assembler), dense_(useDenseTangentLU(assembler.mesh(), denseMaxUnknowns)) {
  DistributedMesh& m = asm_.mesh();
  const std::set<int> requested(nodes.begin(), nodes.end());
  long cols = 0;
  for (int i = 0; i < m.numOwnedNodes; ++i) {
    const LocalNode& n = m.nodes[i];
    if (n.sceneNode < 0 || n.kind == NodeKind::Ancf2D) continue;
    if (!requested.empty() && !requested.count(n.sceneNode)) continue;
    Group g{i, {}};
    for (int k = 0; k < n.ndof; ++k)
      if (n.dof[k] >= 0) g.k.push_back(k);
    cols += static_cast<long>(g.k.size());
    if (!g.k.empty()) groups_.push_back(std::move(g));
  }
  MPI_Allreduce(&cols, &totalColumns_, 1, MPI_LONG, MPI_SUM, m.comm);
  batch_ = std::max<PetscInt>(settings.batch, 1);
  method_ = settings.method;
  blockColumns_ = settings.mumpsBlockColumns;
  SinewCallThrow(m.comm, asm_.createMatrix(&J_));
  SinewCallThrow(m.comm, KSPCreate(m.comm, &ksp_));
  SinewCallThrow(m.comm, KSPSetOptionsPrefix(ksp_, "compl_"));
  if (dense_) {  // a small one-process model: LAPACK LU, every unit load in one getrs (KSPMatSolve)
    SinewCallThrow(m.comm, useDenseLU(ksp_));
  } else {
    SinewCallThrow(m.comm, KSPSetType(ksp_, KSPPREONLY));
    PC pc;
    SinewCallThrow(m.comm, KSPGetPC(ksp_, &pc));
    SinewCallThrow(m.comm, PCSetType(pc, PCLU));
    SinewCallThrow(m.comm, PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  }
  SinewCallThrow(m.comm, KSPSetFromOptions(ksp_));
  if (dense_) {  // -compl_pc_type given: the user's solver, through its factor as below
    PC pc;
    PCType type;
    SinewCallThrow(m.comm, KSPGetPC(ksp_, &pc));
    SinewCallThrow(m.comm, PCGetType(pc, &type));
    dense_ = std::string(type) == PCDENSELU;
  }
}

ComplianceAnalysis::~ComplianceAnalysis() {
  KSPDestroy(&ksp_);
  MatDestroy(&J_);
  MatDestroy(&rhs_);
  MatDestroy(&sol_);
}

// Selected entries of J^-1 (MUMPS ICNTL(30)): the wanted entries are the 6x6 blocks
// (J^-1)_{ab}, a, b in the free DOFs of one requested node. MUMPS takes their pattern as a sparse
// matrix on the host (rank 0) and returns the values in it; only the blocks travel (gathered to
// rank 0 and back to the owners), every column solve is pruned to the entries asked for.
PetscErrorCode ComplianceAnalysis::selectedInverse(Mat F, std::vector<double>& glob) {
  PetscFunctionBeginUser;
  DistributedMesh& m = asm_.mesh();
  PetscInt rStart;
  PetscCall(MatGetOwnershipRange(J_, &rStart, nullptr));
  const PetscInt N = static_cast<PetscInt>(m.numGlobalUnknowns);
  // my groups as [ng, g_1 .. g_ng] (global unknowns), and the number of block values I get back
  std::vector<PetscInt> send;
  int nvals = 0;
  for (const Group& g : groups_) {
    const LocalNode& n = m.nodes[g.node];
    send.push_back(static_cast<PetscInt>(g.k.size()));
    for (int k : g.k) send.push_back(rStart + n.dof[k]);
    nvals += static_cast<int>(g.k.size() * g.k.size());
  }
  const bool host = m.rank == 0;
  int nsend = static_cast<int>(send.size());
  std::vector<int> counts(host ? m.size : 0), displs(host ? m.size : 0), vcounts(host ? m.size : 0),
      vdispls(host ? m.size : 0);
  MPI_Gather(&nsend, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, m.comm);
  MPI_Gather(&nvals, 1, MPI_INT, vcounts.data(), 1, MPI_INT, 0, m.comm);
  std::vector<PetscInt> all;
  if (host) {
    std::exclusive_scan(counts.begin(), counts.end(), displs.begin(), 0);
    std::exclusive_scan(vcounts.begin(), vcounts.end(), vdispls.begin(), 0);
    all.resize(static_cast<size_t>(displs.back()) + counts.back());
  }
  MPI_Gatherv(send.data(), nsend, MPIU_INT, all.data(), counts.data(), displs.data(), MPIU_INT, 0, m.comm);

  // Bt = pattern^T on the host: row b (a column of J^-1) holds the rows a of the node of b.
  Mat Bt, spRHS;
  PetscCall(MatCreate(m.comm, &Bt));
  PetscCall(MatSetSizes(Bt, host ? N : 0, host ? N : 0, N, N));
  PetscCall(MatSetType(Bt, MATAIJ));
  {
    std::vector<PetscInt> nnz(host ? N : 0, 0);
    for (size_t p = 0; p < all.size(); p += 1 + all[p])
      for (PetscInt j = 1; j <= all[p]; ++j) nnz[all[p + j]] = all[p];
    PetscCall(MatSeqAIJSetPreallocation(Bt, 0, nnz.data()));
    PetscCall(MatMPIAIJSetPreallocation(Bt, 0, nnz.data(), 0, nullptr));
  }
  const PetscScalar ones[36] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
                                1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  for (size_t p = 0; p < all.size(); p += 1 + all[p])
    PetscCall(MatSetValues(Bt, all[p], &all[p + 1], all[p], &all[p + 1], ones, INSERT_VALUES));
  PetscCall(MatAssemblyBegin(Bt, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(Bt, MAT_FINAL_ASSEMBLY));
  PetscCall(MatCreateTranspose(Bt, &spRHS));
  // ICNTL(27): columns per block of the solve phase. MUMPS's automatic choice (about 32) costs a
  // round of messages per block on every tree node; 2048 was the fastest measured (docs/performance.md).
  // (-compl_mat_mumps_icntl_27: the user's value, which MUMPS has also read from the options)
  PetscCall(MatMumpsSetIcntl(F, 27, blockColumns_));
  PetscCall(MatMumpsGetInverse(F, spRHS));
  PetscCall(MatMumpsSetIcntl(F, 30, 0));
  ++batches_;
  // blocks back to their owners: per group, v[kc * ng + kr] = Bt(b_kc, a_kr) = (J^-1)(a_kr, b_kc)
  std::vector<double> vals(host ? static_cast<size_t>(vdispls.back()) + vcounts.back() : 0), mine(nvals);
  for (size_t p = 0, q = 0; p < all.size(); p += 1 + all[p]) {
    const PetscInt ng = all[p];
    PetscCall(MatGetValues(Bt, ng, &all[p + 1], ng, &all[p + 1], &vals[q]));
    q += static_cast<size_t>(ng * ng);
  }
  MPI_Scatterv(vals.data(), vcounts.data(), vdispls.data(), MPI_DOUBLE, mine.data(), nvals, MPI_DOUBLE, 0, m.comm);
  PetscCall(MatDestroy(&spRHS));
  PetscCall(MatDestroy(&Bt));
  size_t q = 0;
  for (const Group& g : groups_) {
    const size_t ng = g.k.size();
    double* C = &glob[36 * static_cast<size_t>(g.node)];
    for (size_t c = 0; c < ng; ++c)
      for (size_t r = 0; r < ng; ++r) C[6 * g.k[r] + g.k[c]] = mine[q + c * ng + r];
    q += ng * ng;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Unit loads in blocks of batch_ columns; column c of block j solves J x = e_(free DOF c), and the
// owner of the node reads its rows of x. sparse: the block is a sparse matrix on the host
// (MatMatTransposeSolve, MUMPS prunes the forward substitution); dense: a distributed dense block;
// F null (the dense LU): a dense block solved by the KSP (KSPMatSolve, one getrs for the block).
PetscErrorCode ComplianceAnalysis::rhsBlocks(Mat F, bool sparse, std::vector<double>& glob) {
  PetscFunctionBeginUser;
  DistributedMesh& m = asm_.mesh();
  // My columns: the free DOFs of my requested nodes, numbered after those of lower ranks.
  std::vector<PetscInt> colRow;  // owned row (local index) of each of my columns
  std::vector<std::array<int, 2>> colNodeDof;
  for (const Group& g : groups_)
    for (int k : g.k) {
      colRow.push_back(m.nodes[g.node].dof[k]);
      colNodeDof.push_back({g.node, k});
    }
  long mine = static_cast<long>(colRow.size()), first = 0;
  MPI_Exscan(&mine, &first, 1, MPI_LONG, MPI_SUM, m.comm);
  if (m.rank == 0) first = 0;
  const PetscInt nloc = m.numOwnedUnknowns, N = static_cast<PetscInt>(m.numGlobalUnknowns);
  const PetscInt nb = static_cast<PetscInt>(std::min<long>(batch_, totalColumns_));
  PetscInt rStart;
  PetscCall(MatGetOwnershipRange(J_, &rStart, nullptr));
  // sparse: the host needs the global row of every column
  std::vector<PetscInt> allRows;
  if (sparse) {
    std::vector<PetscInt> g(colRow.size());
    for (size_t c = 0; c < colRow.size(); ++c) g[c] = rStart + colRow[c];
    int n = static_cast<int>(g.size());
    std::vector<int> counts(m.rank == 0 ? m.size : 0), displs(counts.size());
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, m.comm);
    if (m.rank == 0) {
      std::exclusive_scan(counts.begin(), counts.end(), displs.begin(), 0);
      allRows.resize(static_cast<size_t>(totalColumns_));
    }
    MPI_Gatherv(g.data(), n, MPIU_INT, allRows.data(), counts.data(), displs.data(), MPIU_INT, 0, m.comm);
  }
  if (!sparse && !rhs_) {  // assembled once; each block is then written into its array
    PetscCall(MatCreateDense(m.comm, nloc, PETSC_DECIDE, N, nb, nullptr, &rhs_));
    PetscCall(MatAssemblyBegin(rhs_, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(rhs_, MAT_FINAL_ASSEMBLY));
  }
  if (!sol_) PetscCall(MatCreateDense(m.comm, nloc, PETSC_DECIDE, N, nb, nullptr, &sol_));
  Mat B = rhs_, X = sol_;
  for (long c0 = 0; c0 < totalColumns_; c0 += nb) {
    const long c1 = std::min<long>(c0 + nb, totalColumns_);
    const long lo = std::max(c0, first), hi = std::min(c1, first + mine);
    if (sparse) {
      Mat Bt;  // nb x N on the host, row c = e_(row of column c0 + c)^T
      PetscCall(MatCreateAIJ(m.comm, m.rank == 0 ? nb : 0, m.rank == 0 ? N : 0, nb, N, 1, nullptr, 0, nullptr, &Bt));
      if (m.rank == 0)
        for (long c = c0; c < c1; ++c) {
          const PetscInt row = static_cast<PetscInt>(c - c0);
          PetscCall(MatSetValue(Bt, row, allRows[c], 1.0, INSERT_VALUES));
        }
      PetscCall(MatAssemblyBegin(Bt, MAT_FINAL_ASSEMBLY));
      PetscCall(MatAssemblyEnd(Bt, MAT_FINAL_ASSEMBLY));
      PetscCall(MatMatTransposeSolve(F, Bt, X));
      PetscCall(MatDestroy(&Bt));
    } else {
      {  // B = the unit loads of my columns, written into my rows of the dense block
        PetscScalar* b;
        PetscInt ldb;
        PetscCall(MatDenseGetLDA(B, &ldb));
        PetscCall(MatDenseGetArrayWrite(B, &b));
        for (PetscInt c = 0; c < nb; ++c) std::fill_n(b + static_cast<size_t>(c) * ldb, nloc, 0.0);
        for (long c = lo; c < hi; ++c) b[static_cast<size_t>(c - c0) * ldb + colRow[c - first]] = 1.0;
        PetscCall(MatDenseRestoreArrayWrite(B, &b));
      }
      if (F) PetscCall(MatMatSolve(F, B, X));
      else PetscCall(KSPMatSolve(ksp_, B, X));
    }
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
  PetscFunctionReturn(PETSC_SUCCESS);
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
  std::vector<double> glob(36 * static_cast<size_t>(m.numOwnedNodes), 0.0);
  if (bad) {
    *ok = false;
    failure_ = "compliance: the tangent is singular at the converged state (a mechanism or redundant constraints); "
               "check supports, rigid modes and releases (opt.rls)";
  } else if (totalColumns_ > 0) {
    const double t1 = MPI_Wtime();
    if (dense_) {
      PetscCall(rhsBlocks(nullptr, false, glob));
    } else {
      Mat F;
      PetscCall(PCFactorGetMatrix(pc, &F));
      if (method_ == Method::SelectedInverse) PetscCall(selectedInverse(F, glob));
      else PetscCall(rhsBlocks(F, method_ == Method::SparseRhs, glob));
    }
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
                "solves %.3f s (%s)\n",
                totalColumns_, factorizations_, factorizations_ == 1 ? "" : "s", batches_, factorTime_, solveTime_,
                dense_ ? "dense LU, up to -dense_max_unknowns" : methodName(method_));
  return line;
}

}  // namespace sinew
