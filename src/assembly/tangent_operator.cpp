// Element-wise application of the tangent (see Assembler::applyTangent).
#include <array>

#include "assembly/assembler.hpp"

namespace sinew {

bool Assembler::elementwiseTangentAvailable() const {
  int ok = pressureElems_.empty() && cableElems_.empty();
  MPI_Allreduce(MPI_IN_PLACE, &ok, 1, MPI_INT, MPI_LAND, mesh_.comm);
  return ok != 0;
}

PetscErrorCode Assembler::applyTangent(Vec x, Vec y) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().tangentOperator, 0, 0, 0, 0));
  if (!xOp_) {
    PetscCall(createVector(&xOp_));
    PetscCall(VecDuplicate(xOp_, &yOp_));
  }
  PetscCall(loadLocal(x, xOp_));
  Vec xl, yl;
  const PetscScalar* xa;
  PetscScalar* ya;
  PetscCall(VecGhostGetLocalForm(xOp_, &xl));
  PetscCall(VecGhostGetLocalForm(yOp_, &yl));
  PetscCall(VecSet(yl, 0.0));
  PetscCall(VecGetArrayRead(xl, &xa));
  PetscCall(VecGetArray(yl, &ya));
  std::array<int, kMaxElementRows> idx;
  std::array<double, kMaxElementRows> d;
  size_t offset = 0;
  for (const LocalElement& el : mesh_.elements) {
    const auto kinds = el.kernel->nodeKinds();
    int n = 0;
    std::array<int, 4> nodeStart{};
    for (size_t i = 0; i < kinds.size(); ++i) {
      const LocalNode& node = mesh_.nodes[el.node[i]];
      nodeStart[i] = n;
      for (int k = 0; k < dofSize(kinds[i]); ++k, ++n) idx[n] = node.dof[k];
    }
    for (int j = 0; j < el.kernel->numConstraints(); ++j, ++n) idx[n] = el.firstMultiplier + j;
    for (int k = 0; k < n; ++k) d[k] = idx[k] >= 0 ? xa[idx[k]] : 0.0;
    // subtract the translation of the first node from every node's translation DOFs
    const int nt = kinds[0] == NodeKind::Ancf2D ? 2 : 3;
    std::array<double, 3> t{};
    for (int c = 0; c < nt; ++c) t[c] = d[c];
    for (size_t i = 0; i < kinds.size(); ++i) {
      const int ni = kinds[i] == NodeKind::Ancf2D ? 2 : 3;
      for (int c = 0; c < std::min(nt, ni); ++c) d[nodeStart[i] + c] -= t[c];
    }
    const double* K = blocks_.data() + offset;
    for (int r = 0; r < n; ++r) {
      if (idx[r] < 0) continue;
      double s = 0.0;
      for (int c = 0; c < n; ++c) s += K[r * n + c] * d[c];
      ya[idx[r]] += s;
    }
    offset += static_cast<size_t>(n) * n;
  }
  for (const auto& [i, K] : torqueBlocks_) {
    const LocalNode& node = mesh_.nodes[i];
    const int r0 = node.dof[2], r1 = node.dof[3];
    const double s0 = r0 >= 0 ? xa[r0] : 0.0, s1 = r1 >= 0 ? xa[r1] : 0.0;
    if (r0 >= 0) ya[r0] += K[0] * s0 + K[1] * s1;
    if (r1 >= 0) ya[r1] += K[2] * s0 + K[3] * s1;
  }
  PetscCall(VecRestoreArray(yl, &ya));
  PetscCall(VecRestoreArrayRead(xl, &xa));
  PetscCall(VecGhostRestoreLocalForm(yOp_, &yl));
  PetscCall(VecGhostRestoreLocalForm(xOp_, &xl));
  PetscCall(VecGhostUpdateBegin(yOp_, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecGhostUpdateEnd(yOp_, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecCopy(yOp_, y));
  PetscCall(PetscLogEventEnd(SinewEvents::get().tangentOperator, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
