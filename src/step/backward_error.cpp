#include "step/backward_error.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace sinew {

PetscErrorCode unitFreeNorms(const DistributedMesh& mesh, Mat A, Mat B, UnitFreeNorms* n) {
  PetscFunctionBeginUser;
  // model size L: the diagonal of the nodes' bounding box (1 for a model without extent)
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const LocalNode& node : mesh.nodes)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], node.X0[k]);
      hi[k] = std::max(hi[k], node.X0[k]);
    }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, lo, 3, MPI_DOUBLE, MPI_MIN, mesh.comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, hi, 3, MPI_DOUBLE, MPI_MAX, mesh.comm));
  double L2 = 0.0;
  for (int k = 0; k < 3; ++k)
    if (hi[k] >= lo[k]) L2 += (hi[k] - lo[k]) * (hi[k] - lo[k]);
  const double L = L2 > 0.0 ? std::sqrt(L2) : 1.0;
  if (!n->w) PetscCall(MatCreateVecs(A, &n->w, nullptr));
  PetscCall(VecSet(n->w, 0.0));
  PetscScalar* w;
  PetscCall(VecGetArray(n->w, &w));
  for (int i = 0; i < mesh.numOwnedNodes; ++i) {
    const LocalNode& node = mesh.nodes[static_cast<size_t>(i)];
    const int translations = node.kind == NodeKind::Ancf2D ? 2 : 3;
    for (int k = 0; k < node.ndof; ++k)
      if (node.dof[static_cast<size_t>(k)] >= 0) w[node.dof[static_cast<size_t>(k)]] = k < translations ? 1.0 : 1.0 / L;
  }
  PetscCall(VecRestoreArray(n->w, &w));
  for (auto [M, S, norm] : {std::tuple<Mat, Mat*, double*>{A, &n->scaledA, &n->normA},
                            std::tuple<Mat, Mat*, double*>{B, &n->scaledB, &n->normB}}) {
    MatInfo mi, si;
    PetscCall(MatGetInfo(M, MAT_GLOBAL_SUM, &mi));
    if (*S) PetscCall(MatGetInfo(*S, MAT_GLOBAL_SUM, &si));
    if (*S && si.nz_used == mi.nz_used) {
      PetscCall(MatCopy(M, *S, SAME_NONZERO_PATTERN));
    } else {
      PetscCall(MatDestroy(S));
      PetscCall(MatDuplicate(M, MAT_COPY_VALUES, S));
    }
    PetscCall(MatDiagonalScale(*S, n->w, n->w));
    PetscReal v;
    PetscCall(MatNorm(*S, NORM_INFINITY, &v));
    *norm = v;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode destroyUnitFreeNorms(UnitFreeNorms* n) {
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&n->w));
  PetscCall(MatDestroy(&n->scaledA));
  PetscCall(MatDestroy(&n->scaledB));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode scaledBackwardError(const UnitFreeNorms& n, Vec x, Vec r, PetscReal lambda, PetscReal* eta) {
  PetscFunctionBeginUser;
  const PetscScalar *w, *xv, *rv;
  PetscInt len;
  PetscCall(VecGetLocalSize(x, &len));
  PetscCall(VecGetArrayRead(n.w, &w));
  PetscCall(VecGetArrayRead(x, &xv));
  PetscCall(VecGetArrayRead(r, &rv));
  double sums[2] = {0.0, 0.0};  // ||S^-1 r||^2, ||S x||^2 over the node rows
  for (PetscInt i = 0; i < len; ++i) {
    if (!(w[i] > 0.0)) continue;
    sums[0] += rv[i] * rv[i] * w[i] * w[i];
    sums[1] += xv[i] * xv[i] / (w[i] * w[i]);
  }
  PetscCall(VecRestoreArrayRead(r, &rv));
  PetscCall(VecRestoreArrayRead(x, &xv));
  PetscCall(VecRestoreArrayRead(n.w, &w));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, PetscObjectComm(reinterpret_cast<PetscObject>(x))));
  const double scale = (n.normA + std::abs(lambda) * n.normB) * std::sqrt(sums[1]);
  *eta = scale > 0.0 ? std::sqrt(sums[0]) / scale : 0.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
