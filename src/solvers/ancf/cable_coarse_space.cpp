#include "solvers/ancf/cable_coarse_space.hpp"

#include <petsc/private/pcimpl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include "parallel/collective_error.hpp"
#include "solvers/newton_test.hpp"
#include "solvers/solver_defaults.hpp"

namespace sinew {

namespace {

bool isAncf(const LocalElement& el) { return std::strcmp(el.kernel->name(), "ancf_cable2d") == 0; }

/// Scene-element layout as gathered from the ranks: split count, FE element length, end nodes.
struct SceneElementInfo {
  double s = 0, numSub = 0, lfe = 0, en0 = -1, en1 = -1;  // doubles: one MPI datatype
};

}  // namespace

int CableCoarseSpace::defaultRatio(const DistributedMesh& mesh, int minSplit) {
  long counts[2] = {0, 0};  // ANCF FE elements (owned by this rank's element list), largest split
  for (const LocalElement& el : mesh.elements)
    if (isAncf(el)) {
      ++counts[0];
      counts[1] = std::max<long>(counts[1], el.numSub);
    }
  long total = 0, split = 0;
  MPI_Allreduce(&counts[0], &total, 1, MPI_LONG, MPI_SUM, mesh.comm);
  MPI_Allreduce(&counts[1], &split, 1, MPI_LONG, MPI_MAX, mesh.comm);
  if (split < minSplit) return 0;
  // measured at 1,048,576 A1 elements (1 rank): r = 1024 took 39 GMRES iterations and 62 s,
  // r = 512 10 and 40 s, r = 2048 7 and 35 s; r = 2 sqrt(n) was as good as sqrt(n) from 16384 up
  return std::max(8, 2 * static_cast<int>(std::ceil(std::sqrt(static_cast<double>(total)))));
}

CableCoarseSpace::CableCoarseSpace(Assembler& assembler, int ratio) : asm_(assembler) {
  const DistributedMesh& m = asm_.mesh();
  MPI_Comm comm = m.comm;
  // 1. every rank's view of the split ANCF scene elements -> the same global layout everywhere
  std::map<int, SceneElementInfo> mine;
  for (const LocalElement& el : m.elements) {
    if (!isAncf(el)) continue;
    SceneElementInfo& info = mine[el.sceneElement];
    info.s = el.sceneElement;
    info.numSub = el.numSub;
    info.lfe = el.kernel->referenceLength();
    if (el.subIndex == 0) info.en0 = m.nodes[el.node[0]].sceneNode;
    if (el.subIndex == el.numSub - 1) info.en1 = m.nodes[el.node[1]].sceneNode;
  }
  std::vector<double> send;
  for (const auto& [s, info] : mine) send.insert(send.end(), {info.s, info.numSub, info.lfe, info.en0, info.en1});
  int n = static_cast<int>(send.size());
  std::vector<int> counts(m.size), displs(m.size, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < m.size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> all(static_cast<size_t>(displs.back() + counts.back()));
  MPI_Allgatherv(send.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, comm);
  std::map<int, SceneElementInfo> scene;
  for (size_t i = 0; i + 4 < all.size(); i += 5) {
    SceneElementInfo& info = scene[static_cast<int>(all[i])];
    info.s = all[i];
    info.numSub = all[i + 1];
    info.lfe = all[i + 2];
    info.en0 = std::max(info.en0, all[i + 3]);
    info.en1 = std::max(info.en1, all[i + 4]);
  }
  // 2. coarse nodes: the end nodes of those scene elements, then the interior break points
  std::map<int, int> endNode;  // scene node -> coarse node
  for (const auto& [s, info] : scene)
    for (double e : {info.en0, info.en1}) endNode.emplace(static_cast<int>(e), 0);
  int next = 0;
  for (auto& [sn, k] : endNode) k = next++;
  struct Layout {
    int numSub, mc, firstBreak;
    double lc;
  };
  std::map<int, Layout> layout;
  std::vector<std::array<int, 2>> elems;  // coarse elements (coarse node pairs)
  for (const auto& [s, info] : scene) {
    const int ns = static_cast<int>(info.numSub);
    const int mc = std::max(1, static_cast<int>(std::lround(static_cast<double>(ns) / ratio)));
    layout[s] = {ns, mc, next, info.lfe * ns / mc};
    const int a0 = endNode[static_cast<int>(info.en0)], b0 = endNode[static_cast<int>(info.en1)];
    for (int c = 0; c < mc; ++c) elems.push_back({c == 0 ? a0 : next + c - 1, c + 1 == mc ? b0 : next + c});
    next += mc - 1;
  }
  nodeCount_ = static_cast<size_t>(next);
  // 3. coarse graph (coarse element neighbours) and the CSR pattern of Ac
  std::vector<std::vector<int>> adjacency(nodeCount_);  // coarse node -> neighbours (incl. itself)
  for (size_t k = 0; k < nodeCount_; ++k) adjacency[k].push_back(static_cast<int>(k));
  for (const auto& e : elems) {
    adjacency[e[0]].push_back(e[1]);
    adjacency[e[1]].push_back(e[0]);
  }
  for (auto& a : adjacency) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  // a fine element straddling a break point couples the coarse nodes of two coarse elements:
  // rows of a coarse node also reach the neighbours of its neighbours
  std::vector<std::vector<int>> reach(nodeCount_);
  for (size_t k = 0; k < nodeCount_; ++k) {
    for (int j : adjacency[k]) reach[k].insert(reach[k].end(), adjacency[j].begin(), adjacency[j].end());
    std::sort(reach[k].begin(), reach[k].end());
    reach[k].erase(std::unique(reach[k].begin(), reach[k].end()), reach[k].end());
  }
  acRowStart_.assign(4 * nodeCount_ + 1, 0);
  for (size_t k = 0; k < nodeCount_; ++k)
    for (int d = 0; d < 4; ++d) {
      const size_t r = 4 * k + d;
      acRowStart_[r + 1] = acRowStart_[r] + 4 * static_cast<PetscInt>(reach[k].size());
      for (int j : reach[k])
        for (int dc = 0; dc < 4; ++dc) acCols_.push_back(4 * j + dc);
    }
  acValues_.assign(acCols_.size(), 0.0);
  // 4. constrained coarse unknowns: those of end nodes whose fine DOF is supported or prescribed
  std::vector<int> fixedInt(4 * nodeCount_, 0);
  for (const LocalNode& node : m.nodes) {
    if (node.kind != NodeKind::Ancf2D || node.sceneNode < 0) continue;
    auto it = endNode.find(node.sceneNode);
    if (it == endNode.end()) continue;
    for (int k = 0; k < 4; ++k)
      if (node.dof[k] < 0) fixedInt[4 * static_cast<size_t>(it->second) + k] = 1;
  }
  MPI_Allreduce(MPI_IN_PLACE, fixedInt.data(), static_cast<int>(fixedInt.size()), MPI_INT, MPI_MAX, comm);
  fixed_.assign(fixedInt.begin(), fixedInt.end());
  // 5. where every local fine node lies, and the rows of P for the owned ANCF unknowns
  nodeMap_.assign(m.nodes.size(), {});
  for (const LocalElement& el : m.elements) {
    if (!isAncf(el)) continue;
    const Layout& L = layout[el.sceneElement];
    const SceneElementInfo& info = scene[el.sceneElement];
    for (int side = 0; side < 2; ++side) {
      NodeMap& nm = nodeMap_[el.node[side]];
      if (nm.a >= 0) continue;
      const long p = el.subIndex + side;  // position along the scene element, in fine elements
      long c = p * L.mc / L.numSub;
      const long rem = p * L.mc - c * L.numSub;
      nm.xi = static_cast<double>(rem) / L.numSub;
      if (c == L.mc) {
        c = L.mc - 1;
        nm.xi = 1.0;
      }
      nm.a = c == 0 ? endNode[static_cast<int>(info.en0)] : L.firstBreak + static_cast<int>(c) - 1;
      nm.b = c + 1 == L.mc ? endNode[static_cast<int>(info.en1)] : L.firstBreak + static_cast<int>(c);
      nm.lc = L.lc;
    }
  }
  for (int i = 0; i < m.numOwnedNodes; ++i) {
    if (nodeMap_[i].a < 0) continue;
    for (int k = 0; k < 4; ++k) {
      if (m.nodes[i].dof[k] < 0) continue;
      Row row;
      row.fine = m.nodes[i].dof[k];
      weights(i, k, row.coarse, row.w);
      rows_.push_back(row);
    }
  }
  // 6. work vectors and the coarse matrix (4 unknowns per coarse node; constrained: identity rows)
  const PetscInt nc = 4 * static_cast<PetscInt>(nodeCount_);
  SinewCallThrow(comm, VecCreateSeq(PETSC_COMM_SELF, nc, &rc_));
  SinewCallThrow(comm, VecDuplicate(rc_, &yc_));
  SinewCallThrow(comm, asm_.createVector(&t1_));
  SinewCallThrow(comm, VecDuplicate(t1_, &t2_));
  std::vector<PetscInt> nnz(static_cast<size_t>(nc));
  for (PetscInt r = 0; r < nc; ++r) nnz[r] = acRowStart_[r + 1] - acRowStart_[r];
  SinewCallThrow(comm, MatCreateSeqAIJ(PETSC_COMM_SELF, nc, nc, 0, nnz.data(), &Ac_));
  SinewCallThrow(comm, KSPCreate(PETSC_COMM_SELF, &coarseKsp_));
  SinewCallThrow(comm, KSPSetOptionsPrefix(coarseKsp_, "coarse_"));
  SinewCallThrow(comm, KSPSetType(coarseKsp_, KSPPREONLY));
  PC cpc;
  SinewCallThrow(comm, KSPGetPC(coarseKsp_, &cpc));
  SinewCallThrow(comm, PCSetType(cpc, PCLU));
  SinewCallThrow(comm, PCFactorSetMatOrderingType(cpc, MATORDERINGND));
  SinewCallThrow(comm, PCFactorSetShiftType(cpc, MAT_SHIFT_NONZERO));
  SinewCallThrow(comm, KSPSetFromOptions(coarseKsp_));
}

CableCoarseSpace::~CableCoarseSpace() {
  SNESDestroy(&snes_);
  for (Vec* v : {&U0_, &Uw_, &Fw_, &uc_, &fc_}) VecDestroy(v);
  KSPDestroy(&coarseKsp_);
  KSPDestroy(&fineKsp_);
  MatDestroy(&Ac_);
  for (Vec* v : {&rc_, &yc_, &t1_, &t2_}) VecDestroy(v);
}

namespace {

// PC type PCCABLECOARSE: pc->data is the CableCoarseSpace that installed it (owned by the statics)
PetscErrorCode cableCoarseDestroy(PC pc) {
  PetscFunctionBeginUser;
  pc->data = nullptr;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode cableCoarseView(PC, PetscViewer viewer) {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "  Sinew cable coarse space + LU (two-level, multiplicative); fine LU: -fine_ksp_view\n"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode createCableCoarse(PC pc) {
  PetscFunctionBeginUser;
  pc->data = nullptr;
  pc->ops->setup = CableCoarseSpace::setUp;
  pc->ops->apply = CableCoarseSpace::apply;
  pc->ops->destroy = cableCoarseDestroy;
  pc->ops->view = cableCoarseView;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

PetscErrorCode registerCableCoarsePC() {
  PetscFunctionBeginUser;
  PetscCall(PCRegister(PCCABLECOARSE, createCableCoarse));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CableCoarseSpace::install(PC pc) {
  PetscFunctionBeginUser;
  PetscCall(registerCableCoarsePC());
  PetscCall(PCSetType(pc, PCCABLECOARSE));
  pc->data = this;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CableCoarseSpace::restrictTo(Vec fine, Vec coarse) {
  PetscFunctionBeginUser;
  const PetscScalar* f;
  PetscScalar* c;
  PetscCall(VecSet(coarse, 0.0));
  PetscCall(VecGetArrayRead(fine, &f));
  PetscCall(VecGetArray(coarse, &c));
  for (const Row& r : rows_)
    for (int j = 0; j < 4; ++j) c[r.coarse[j]] += r.w[j] * f[r.fine];
  PetscInt nc;
  PetscCall(VecGetLocalSize(coarse, &nc));
  MPI_Allreduce(MPI_IN_PLACE, c, static_cast<int>(nc), MPI_DOUBLE, MPI_SUM, asm_.mesh().comm);  // fixed: w = 0
  PetscCall(VecRestoreArray(coarse, &c));
  PetscCall(VecRestoreArrayRead(fine, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CableCoarseSpace::prolongAdd(Vec coarse, Vec fine) {
  PetscFunctionBeginUser;
  const PetscScalar* c;
  PetscScalar* f;
  PetscCall(VecGetArrayRead(coarse, &c));
  PetscCall(VecGetArray(fine, &f));
  for (const Row& r : rows_)
    f[r.fine] += r.w[0] * c[r.coarse[0]] + r.w[1] * c[r.coarse[1]] + r.w[2] * c[r.coarse[2]] + r.w[3] * c[r.coarse[3]];
  PetscCall(VecRestoreArray(fine, &f));
  PetscCall(VecRestoreArrayRead(coarse, &c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CableCoarseSpace::coarseCorrection(Vec r, Vec y) {
  PetscFunctionBeginUser;
  PetscCall(restrictTo(r, rc_));
  PetscCall(KSPSolve(coarseKsp_, rc_, yc_));
  PetscCall(prolongAdd(yc_, y));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void CableCoarseSpace::weights(int i, int k, std::array<int, 4>& coarse, std::array<double, 4>& w) const {
  const NodeMap& nm = nodeMap_[static_cast<size_t>(i)];
  const double xi = nm.xi, x2 = xi * xi, x3 = x2 * xi, lc = nm.lc;
  const int comp = k % 2;
  coarse = {4 * nm.a + comp, 4 * nm.a + 2 + comp, 4 * nm.b + comp, 4 * nm.b + 2 + comp};
  if (k < 2) w = {1 - 3 * x2 + 2 * x3, lc * (xi - 2 * x2 + x3), 3 * x2 - 2 * x3, lc * (-x2 + x3)};
  else w = {(-6 * xi + 6 * x2) / lc, 1 - 4 * xi + 3 * x2, (6 * xi - 6 * x2) / lc, -2 * xi + 3 * x2};
  for (int j = 0; j < 4; ++j)
    if (fixed_[coarse[j]]) w[j] = 0.0;
}

// Ac = sum_e P_e^T J_e P_e over the local ANCF elements (kept blocks, in element order), each
// J_e applied to a coarse function minus its translation at the element's first node; summed over
// the ranks in the fixed CSR pattern. Slope-torque tangents are not included (a preconditioner).
PetscErrorCode CableCoarseSpace::assembleCoarse() {
  PetscFunctionBeginUser;
  const DistributedMesh& m = asm_.mesh();
  std::fill(acValues_.begin(), acValues_.end(), 0.0);
  auto add = [&](int r, int c, double v) {
    const auto* first = acCols_.data() + acRowStart_[r];
    const auto* last = acCols_.data() + acRowStart_[r + 1];
    const auto* it = std::lower_bound(first, last, static_cast<PetscInt>(c));
    acValues_[static_cast<size_t>(it - acCols_.data())] += v;
  };
  size_t offset = 0;
  for (const LocalElement& el : m.elements) {
    const int n = el.kernel->numDofs() + el.kernel->numConstraints();
    const double* K = asm_.tangentBlock(offset);
    offset += static_cast<size_t>(n) * n;
    if (!isAncf(el)) continue;
    // P_e: 8 fine coordinates x up to 12 coarse unknowns (3 coarse nodes when the element straddles
    // a break point); constrained fine coordinates are rows of zeros
    std::array<int, 12> cols{};
    int nc = 0;
    std::array<double, 8 * 12> Pe{};
    for (int side = 0; side < 2; ++side)
      for (int k = 0; k < 4; ++k) {
        if (m.nodes[el.node[side]].dof[k] < 0) continue;
        std::array<int, 4> c;
        std::array<double, 4> w;
        weights(el.node[side], k, c, w);
        for (int j = 0; j < 4; ++j) {
          if (w[j] == 0.0) continue;
          int col = 0;
          while (col < nc && cols[col] != c[j]) ++col;
          if (col == nc) cols[nc++] = c[j];
          Pe[(4 * side + k) * 12 + col] = w[j];
        }
      }
    // JP = J_e (P_e - translation of node 0) column by column
    std::array<double, 8 * 12> JP{};
    for (int col = 0; col < nc; ++col) {
      double d[8];
      for (int r = 0; r < 8; ++r) d[r] = Pe[r * 12 + col];
      const double t0 = d[0], t1 = d[1];
      d[0] -= t0, d[1] -= t1, d[4] -= t0, d[5] -= t1;
      for (int r = 0; r < 8; ++r) {
        double s = 0;
        for (int c = 0; c < 8; ++c) s += K[r * 8 + c] * d[c];
        JP[r * 12 + col] = s;
      }
    }
    for (int a = 0; a < nc; ++a)
      for (int b = 0; b < nc; ++b) {
        double v = 0;
        for (int r = 0; r < 8; ++r) v += Pe[r * 12 + a] * JP[r * 12 + b];
        if (v != 0.0) add(cols[a], cols[b], v);
      }
  }
  MPI_Allreduce(MPI_IN_PLACE, acValues_.data(), static_cast<int>(acValues_.size()), MPI_DOUBLE, MPI_SUM, m.comm);
  PetscCall(MatZeroEntries(Ac_));
  const PetscInt nrows = 4 * static_cast<PetscInt>(nodeCount_);
  for (PetscInt r = 0; r < nrows; ++r) {
    if (fixed_[r]) {
      PetscCall(MatSetValue(Ac_, r, r, 1.0, INSERT_VALUES));
      continue;
    }
    const PetscInt n = acRowStart_[r + 1] - acRowStart_[r];
    PetscCall(MatSetValues(Ac_, 1, &r, n, acCols_.data() + acRowStart_[r], acValues_.data() + acRowStart_[r], INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(Ac_, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(Ac_, MAT_FINAL_ASSEMBLY));
  PetscCall(KSPSetOperators(coarseKsp_, Ac_, Ac_));
  PetscCall(KSPSetUp(coarseKsp_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CableCoarseSpace::setUp(PC pc) {
  PetscFunctionBeginUser;
  auto* self = static_cast<CableCoarseSpace*>(pc->data);
  if (!self) SETERRQ(PetscObjectComm(reinterpret_cast<PetscObject>(pc)), PETSC_ERR_ARG_WRONGSTATE,
                     "PC cablecoarse: no cable coarse space installed (it is set up by the ANCF statics)");
  PetscCall(PetscLogEventBegin(SinewEvents::get().coarseSpace, 0, 0, 0, 0));
  Mat A, P;
  PetscCall(PCGetOperators(pc, &A, &P));
  if (!self->fineKsp_) {
    PetscCall(KSPCreate(self->asm_.mesh().comm, &self->fineKsp_));
    PetscCall(KSPSetOptionsPrefix(self->fineKsp_, "fine_"));
    PetscCall(useDirectSolver(self->fineKsp_, self->asm_.mesh()));
    PetscCall(KSPSetFromOptions(self->fineKsp_));
  }
  PetscCall(KSPSetOperators(self->fineKsp_, P, P));
  PetscCall(KSPSetUp(self->fineKsp_));
  PetscCall(self->assembleCoarse());
  ++self->setups_;
  PetscCall(PetscLogEventEnd(SinewEvents::get().coarseSpace, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// y = y2 + P Ac^-1 P^T (x - J y2),  y2 = y1 + LU^-1 (x - J y1),  y1 = P Ac^-1 P^T x
PetscErrorCode CableCoarseSpace::apply(PC pc, Vec x, Vec y) {
  PetscFunctionBeginUser;
  auto* self = static_cast<CableCoarseSpace*>(pc->data);
  if (!self) SETERRQ(PetscObjectComm(reinterpret_cast<PetscObject>(pc)), PETSC_ERR_ARG_WRONGSTATE,
                     "PC cablecoarse: no cable coarse space installed (it is set up by the ANCF statics)");
  PetscCall(VecSet(y, 0.0));
  PetscCall(self->coarseCorrection(x, y));
  PetscCall(self->asm_.applyTangent(y, self->t1_));
  PetscCall(VecAYPX(self->t1_, -1.0, x));
  PetscCall(KSPSolve(self->fineKsp_, self->t1_, self->t2_));
  KSPConvergedReason why;
  PetscCall(KSPGetConvergedReason(self->fineKsp_, &why));
  if (why < 0) PetscCall(PCSetFailedReason(pc, PC_SUBPC_ERROR));
  PetscCall(VecAXPY(y, 1.0, self->t2_));
  PetscCall(self->asm_.applyTangent(y, self->t1_));
  PetscCall(VecAYPX(self->t1_, -1.0, x));
  PetscCall(self->coarseCorrection(self->t1_, y));
  ++self->applications_;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// ---- coarse predictor
PetscErrorCode CableCoarseSpace::coarseFunction(SNES, Vec u, Vec r, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<CableCoarseSpace*>(ctx);
  PetscCall(VecCopy(self->U0_, self->Uw_));
  PetscCall(self->prolongAdd(u, self->Uw_));
  PetscCall(self->asm_.residual(self->Uw_, self->ls_, self->Fw_));
  PetscCall(self->restrictTo(self->Fw_, r));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CableCoarseSpace::coarseJacobian(SNES, Vec u, Mat, Mat, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<CableCoarseSpace*>(ctx);
  PetscCall(VecCopy(self->U0_, self->Uw_));
  PetscCall(self->prolongAdd(u, self->Uw_));
  PetscCall(self->asm_.jacobian(self->Uw_, self->ls_, nullptr));  // element blocks only
  PetscCall(self->assembleCoarse());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// SNES's default test, or converged on the update (the residual P^T F has a round-off floor that
// grows with the fine cable's n: measured 1.5e-3 of a start residual of 135 at 16384 elements, 1.7
// of 68 at 262144; it is a self-equilibrated moment pattern that moves the solution by nothing
// measurable): the Newton update below 1e-8 of |u|, or below 1e-5 and no longer shrinking tenfold
// (the Newton test's update rule, solvers/newton_test.hpp)
PetscErrorCode CableCoarseSpace::coarseConverged(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm,
                                                 PetscReal fnorm, SNESConvergedReason* reason, void* ctx) {
  PetscFunctionBeginUser;
  NewtonIterate x(it, xnorm, snorm, fnorm);
  PetscCall(static_cast<CableCoarseSpace*>(ctx)->newtonTest_.judge(snes, x, reason));
  PetscFunctionReturn(PETSC_SUCCESS);
}

NewtonRules CableCoarseSpace::newtonRules() {
  NewtonRules r;
  r.snes = NewtonRules::Snes::KeepButUpdate;  // an update below -coarse_snes_stol is decided by the update rule
  r.snesUpdateForceRtol = 0;
  r.update = NewtonRules::Update::Relative;
  r.updateTight = 1e-8;
  r.updateLoose = 1e-5;
  r.updateFloorFactor = 0;  // at any residual
  return r;
}

PetscErrorCode CableCoarseSpace::predict(Vec U, const LoadState& ls) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().coarseSpace, 0, 0, 0, 0));
  ls_ = ls;
  if (!snes_) {
    PetscCall(VecDuplicate(U, &U0_));
    PetscCall(VecDuplicate(U, &Uw_));
    PetscCall(VecDuplicate(U, &Fw_));
    PetscCall(VecDuplicate(rc_, &uc_));
    PetscCall(VecDuplicate(rc_, &fc_));
    PetscCall(SNESCreate(PETSC_COMM_SELF, &snes_));
    PetscCall(SNESSetOptionsPrefix(snes_, "coarse_snes_"));
    PetscCall(SNESSetType(snes_, SNESNEWTONLS));
    SNESLineSearch lsearch;
    PetscCall(SNESGetLineSearch(snes_, &lsearch));
    PetscCall(SNESLineSearchSetType(lsearch, SNESLINESEARCHBASIC));
    PetscCall(SNESSetFunction(snes_, fc_, coarseFunction, this));
    PetscCall(SNESSetJacobian(snes_, Ac_, Ac_, coarseJacobian, this));
    // a predictor: 1e-6 of the start residual is plenty (the coarse residual has its own round-off
    // floor near 1e-5 of a fine cable's load); the fine Newton finishes the job
    PetscCall(SNESSetTolerances(snes_, 1e-300, 1e-6, 1e-14, 30, 10000));
    PetscCall(SNESSetConvergenceTest(snes_, coarseConverged, this, nullptr));
    PetscCall(SNESSetDivergenceTolerance(snes_, -1.0));
    KSP ksp;
    PetscCall(SNESGetKSP(snes_, &ksp));
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PC pc;
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCSetType(pc, PCLU));
    PetscCall(PCFactorSetMatOrderingType(pc, MATORDERINGND));
    PetscCall(PCFactorSetShiftType(pc, MAT_SHIFT_NONZERO));
    PetscCall(SNESSetFromOptions(snes_));
  }
  PetscCall(VecCopy(U, U0_));
  PetscCall(VecSet(uc_, 0.0));
  PetscCall(SNESSolve(snes_, nullptr, uc_));
  SNESConvergedReason why;
  PetscInt n;
  PetscCall(SNESGetConvergedReason(snes_, &why));
  PetscCall(SNESGetIterationNumber(snes_, &n));
  predictorIts_ += n;
  PetscReal un;
  PetscCall(VecNorm(uc_, NORM_INFINITY, &un));
  if (why > 0 && std::isfinite(un)) PetscCall(prolongAdd(uc_, U));  // on failure U stays as it was
  PetscCall(PetscLogEventEnd(SinewEvents::get().coarseSpace, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
