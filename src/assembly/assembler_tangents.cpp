// Assembler matrices from element blocks: the Jacobian (by MatSetValuesLocal or COO, optionally
// keeping the element blocks for the element-wise tangent operator), the tangent of slope torques
// on ANCF nodes, the split tangent K = Km + Kg (material and geometric parts, for buckling) and the
// mass matrix (element masses, nodal point masses and rotary inertias).
#include <algorithm>
#include <array>

#include "assembly/aij_pattern.hpp"
#include "assembly/assembler.hpp"

namespace sinew {

PetscErrorCode Assembler::jacobian(Vec U, const LoadState& ls, Mat J) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().jacobian, 0, 0, 0, 0));
  ++counters_.jacobians;
  const double* u = nullptr;
  PetscCall(beginLocal(U, ls, &u));
  const bool coo = J && cooApplies();
  bool cooSums = false;
  if (coo) PetscCall(prepareCOO(J, &cooSums));
  else if (J) PetscCall(MatZeroEntries(J));
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  KernelNeeds needs;
  needs.tangent = true;
  PetscCall(PetscLogEventBegin(SinewEvents::get().jacobianElements, 0, 0, 0, 0));
  size_t offset = 0, kept = 0;
  if (keepBlocks_) torqueBlocks_.clear();
  if (keepBlocks_ && keepRigid_) {
    rigidInfo_.clear();
    rigidData_.clear();
  }
  std::array<double, 6> sigmaMixed;
  for (const LocalElement& el : mesh_.elements) {
    gatherElement(el, q.data(), u, idx.data(), nullptr);
    KernelInput in{q.data(), nullptr, el.firstMultiplier >= 0 ? u + el.firstMultiplier : nullptr, ls.time};
    in.disp = elemDisp_.data();
    linearizeMixedStresses(el, q.data(), sigmaMixed, in);
    evaluateElement(el, in, needs);
    const int n = el.kernel->numDofs() + el.kernel->numConstraints();
    rotationColumns(el, n, out_.K.data());
    if (keepBlocks_) {
      if (blocks_.size() < kept + static_cast<size_t>(n) * n) blocks_.resize(kept + static_cast<size_t>(n) * n);
      std::copy(out_.K.begin(), out_.K.begin() + n * n, blocks_.begin() + static_cast<long>(kept));
      kept += static_cast<size_t>(n) * n;
      if (keepRigid_) keepRigid(el, q.data(), out_.f.data(), out_.K.data(), n);
    }
    if (coo) {
      std::copy(out_.K.begin(), out_.K.begin() + n * n, cooValues_.begin() + static_cast<long>(offset));
      offset += static_cast<size_t>(n) * n;
    } else if (J) {
      PetscCall(MatSetValuesLocal(J, n, idx.data(), n, idx.data(), out_.K.data(), ADD_VALUES));
    }
  }
  PetscCall(PetscLogEventEnd(SinewEvents::get().jacobianElements, 0, 0, 0, 0));
  if (mixedNewton_) keepMixedReference();  // the next Newton iterate linearizes its stresses about this state
  if (cooSums) {  // one process: the same sums, from the assembler's kept COO pattern
    PetscCall(setValuesFromCooSums(J));
  } else if (coo) {  // the matrix is assembled by MatSetValuesCOO (repeated entries are summed)
    PetscCall(MatSetValuesCOO(J, cooValues_.data(), INSERT_VALUES));
  } else {
    PetscCall(addSlopeTorqueTangent(ls, J));
    if (J) PetscCall(addLoadTangents(ls, J));
  }
  PetscCall(endLocal(&u));
  if (J && !coo) {
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscCall(PetscLogEventEnd(SinewEvents::get().jacobian, 0, 0, 0, 0));
  PetscCall(agreeElementValues());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// tangent of a slope torque on ANCF node i (node state current): d/ds of -tau (-s_y, s_x)/|s|^2;
// false (K untouched) without a torque
bool Assembler::slopeTorqueBlock(int i, const LoadState& ls, double* K) const {
  const LocalNode& n = mesh_.nodes[i];
  if (n.kind != NodeKind::Ancf2D) return false;
  const double tau = ls.initialFactor * n.loadInitial[4] + ls.loadFactor * n.load[4];
  if (tau == 0.0) return false;
  const double* s = &state_[12 * static_cast<size_t>(i)];
  const double sx = s[2], sy = s[3], s2 = sx * sx + sy * sy, s4 = s2 * s2;
  // r = -tau * (-sy, sx) / s2
  K[0] = -tau * (2 * sx * sy / s4);
  K[1] = -tau * (-1 / s2 + 2 * sy * sy / s4);
  K[2] = -tau * (1 / s2 - 2 * sx * sx / s4);
  K[3] = -tau * (-2 * sx * sy / s4);
  return true;
}

// tangent of slope torques on ANCF nodes (slopeTorqueBlock); J = nullptr: only kept as blocks for applyTangent
PetscErrorCode Assembler::addSlopeTorqueTangent(const LoadState& ls, Mat J) {
  PetscFunctionBeginUser;
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    double K[4];
    if (!slopeTorqueBlock(i, ls, K)) continue;
    const PetscInt rows[2] = {n.dof[2], n.dof[3]};
    if (J) PetscCall(MatSetValuesLocal(J, 2, rows, 2, rows, K, ADD_VALUES));
    if (keepBlocks_) torqueBlocks_.push_back({i, {K[0], K[1], K[2], K[3]}});
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The positions in the value array of the one-rank AIJ matrix A of every entry of every element block
// (row-major per block, -1 where the row or column is no unknown) into splitPositions_; kept while A's
// pattern is the one they were found in (every matrix of createMatrix). False: A is no such matrix.
PetscErrorCode Assembler::elementBlockPositions(Mat A, bool* ok) {
  PetscFunctionBeginUser;
  *ok = false;
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(mesh_.comm, &size));
  PetscBool seq = PETSC_FALSE;
  PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(A), MATSEQAIJ, &seq));
  if (size != 1 || !seq) PetscFunctionReturn(PETSC_SUCCESS);
  PetscInt nrows;
  const PetscInt *ia, *ja;
  PetscBool done;
  PetscCall(MatGetRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &nrows, &ia, &ja, &done));
  if (!done) PetscFunctionReturn(PETSC_SUCCESS);
  if (samePattern(nrows, ia, ja, splitRowStart_, splitCols_)) {
    PetscCall(MatRestoreRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &nrows, &ia, &ja, &done));
    *ok = true;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  const std::vector<PetscInt> rowStart(ia, ia + nrows + 1), cols(ja, ja + ia[nrows]);
  PetscCall(MatRestoreRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &nrows, &ia, &ja, &done));
  // the (row, column) of every block entry as the COO assembly lists them (row-major per block)
  std::vector<PetscInt> ci, cj;
  cooIndices(&ci, &cj);
  std::vector<PetscInt> pos(ci.size(), -1);
  for (size_t e = 0; e < ci.size(); ++e) {
    if (ci[e] < 0 || cj[e] < 0) continue;
    const auto first = cols.begin() + rowStart[ci[e]], last = cols.begin() + rowStart[ci[e] + 1];
    const auto it = std::lower_bound(first, last, cj[e]);
    if (it == last || *it != cj[e]) PetscFunctionReturn(PETSC_SUCCESS);  // not in the pattern
    pos[e] = static_cast<PetscInt>(it - cols.begin());
  }
  splitPositions_ = std::move(pos);
  splitRowStart_ = rowStart;
  splitCols_ = cols;
  *ok = true;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::splitTangent(Vec U, const LoadState& ls, Mat Km, Mat Kg) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().splitTangent, 0, 0, 0, 0));
  ++counters_.splitTangents;
  const double* u = nullptr;
  PetscCall(beginLocal(U, ls, &u));
  // one rank: the blocks added straight into the value arrays (the additions of MatSetValuesLocal's
  // ADD_VALUES, in the same element order, without its index searches), else by MatSetValuesLocal
  bool direct = false, directG = false;
  PetscCall(elementBlockPositions(Km, &direct));
  if (direct) PetscCall(elementBlockPositions(Kg, &directG));
  direct = direct && directG;
  PetscScalar *km = nullptr, *kg = nullptr;
  if (direct) {
    PetscCall(MatSeqAIJGetArray(Km, &km));
    PetscCall(MatSeqAIJGetArray(Kg, &kg));
    std::fill(km, km + splitCols_.size(), 0.0);
    std::fill(kg, kg + splitCols_.size(), 0.0);
  } else {
    PetscCall(MatZeroEntries(Km));
    PetscCall(MatZeroEntries(Kg));
  }
  size_t offset = 0;
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  KernelNeeds needs;
  needs.tangent = true;
  needs.splitGeometric = true;
  for (const LocalElement& el : mesh_.elements) {
    gatherElement(el, q.data(), u, idx.data(), nullptr);
    KernelInput in{q.data(), nullptr, el.firstMultiplier >= 0 ? u + el.firstMultiplier : nullptr, ls.time};
    in.disp = elemDisp_.data();
    evaluateElement(el, in, needs);
    const int n = el.kernel->numDofs() + el.kernel->numConstraints();
    rotationColumns(el, n, out_.K.data());
    rotationColumns(el, n, out_.Kg.data());
    if (direct) {
      const PetscInt* pos = &splitPositions_[offset];
      for (int e = 0; e < n * n; ++e)
        if (pos[e] >= 0) {
          km[pos[e]] += out_.K[e];
          kg[pos[e]] += out_.Kg[e];
        }
      offset += static_cast<size_t>(n) * n;
    } else {
      PetscCall(MatSetValuesLocal(Km, n, idx.data(), n, idx.data(), out_.K.data(), ADD_VALUES));
      PetscCall(MatSetValuesLocal(Kg, n, idx.data(), n, idx.data(), out_.Kg.data(), ADD_VALUES));
    }
  }
  PetscCall(endLocal(&u));
  if (direct) {
    PetscCall(MatSeqAIJRestoreArray(Km, &km));
    PetscCall(MatSeqAIJRestoreArray(Kg, &kg));
  }
  for (Mat A : {Km, Kg}) {
    PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  }
  PetscCall(PetscLogEventEnd(SinewEvents::get().splitTangent, 0, 0, 0, 0));
  PetscCall(agreeElementValues());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::mass(Vec U, const LoadState& ls, Mat M) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().mass, 0, 0, 0, 0));
  ++counters_.masses;
  PetscCall(updateStates(U, ls));
  PetscCall(MatZeroEntries(M));
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  std::vector<double> Me;
  for (const LocalElement& el : mesh_.elements) {
    if (!el.kernel->hasInertia()) continue;
    gatherElement(el, q.data(), nullptr, idx.data(), nullptr);
    el.kernel->mass(q.data(), Me);
    const int n = el.kernel->numDofs();
    PetscCall(MatSetValuesLocal(M, n, idx.data(), n, idx.data(), Me.data(), ADD_VALUES));
  }
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    if (n.mass > 0) {
      const int nt = n.kind == NodeKind::Ancf2D ? 2 : 3;
      for (int k = 0; k < nt; ++k) {
        const PetscInt r = n.dof[k];
        PetscCall(MatSetValuesLocal(M, 1, &r, 1, &r, &n.mass, ADD_VALUES));
      }
    }
    if (n.kind == NodeKind::Frame6) {
      const Mat3 J = spatialInertia(i);
      const PetscInt rows[3] = {n.dof[3], n.dof[4], n.dof[5]};
      PetscCall(MatSetValuesLocal(M, 3, rows, 3, rows, J.data(), ADD_VALUES));
    }
  }
  PetscCall(MatAssemblyBegin(M, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(M, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscLogEventEnd(SinewEvents::get().mass, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
