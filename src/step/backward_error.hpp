// The backward error of an eigenpair in the same terms whatever the units of the model.
#pragma once
#include <petscmat.h>

#include "mesh/distributed_mesh.hpp"
#include "sinew/petsc_compat.hpp"

namespace sinew {

/// The pencil (A, B) with its unknowns scaled per kind: translations as they are, rotations and ANCF
/// slopes times the model size L (the diagonal of the nodes' bounding box), so that every scaled
/// unknown is a length and every scaled row a force; rigid-mode multiplier rows are left out. A scene
/// in mm, N, MPa then gives the pencil of its m, N, Pa twin times one factor (K in N/mm and N mm/rad
/// scale differently, K S^-1 ... does not), and the backward error below the same value.
struct UnitFreeNorms {
  Vec w = nullptr;            ///< 1 / S: 1 on translation rows, 1/L on rotation and slope rows, 0 on multiplier rows
  double normA = 0.0, normB = 0.0;  ///< ||S^-1 A S^-1||_inf, ||S^-1 B S^-1||_inf
  Mat scaledA = nullptr, scaledB = nullptr;  ///< S^-1 A S^-1, S^-1 B S^-1: kept for the next step's pencil
};

/// Collective; n may hold the norms of an earlier step's pencil (the same unknowns), whose vector and
/// matrices are reused (a matrix again when its number of nonzeros is unchanged). Destroy with
/// destroyUnitFreeNorms.
PetscErrorCode unitFreeNorms(const DistributedMesh& mesh, Mat A, Mat B, UnitFreeNorms* n);
PetscErrorCode destroyUnitFreeNorms(UnitFreeNorms* n);

/// Backward error of the eigenpair (lambda, x) of A x = lambda B x from its residual r = A x - lambda B x,
/// in the scaled unknowns: ||S^-1 r|| / ((||S^-1 A S^-1|| + |lambda| ||S^-1 B S^-1||) ||S x||). The
/// same for a scene in m, N, Pa and in mm, N, MPa, where ||r|| / ((||A|| + |lambda| ||B||) ||x||)
/// mixed N/m with N m/rad and grew 300-fold from the SI crosshinge to its mm twin (issue 24 item 13).
PetscErrorCode scaledBackwardError(const UnitFreeNorms& n, Vec x, Vec r, PetscReal lambda, PetscReal* eta);

}  // namespace sinew
