// Distributed PETSc matrices to one rank for the dense eigensolvers (step/dense_eigen.hpp), and
// their eigenpairs back to every rank.
#pragma once
#include <petscmat.h>

#include <vector>

#include "sinew/petsc_compat.hpp"

#include "step/dense_eigen.hpp"

namespace sinew {

/// The global n x n matrix A (AIJ or dense: any type with MatGetRow) as a column-major array on
/// rank 0 (empty on the other ranks). Collective.
PetscErrorCode gatherDense(Mat A, std::vector<double>& full);

/// A matrix of the dense path kept from one step to the next, and the one-rank AIJ pattern it was filled from.
struct KeptDense {
  std::vector<double> full;
  std::vector<PetscInt> rowStart, cols;
};
/// gatherDense into kept.full. On one rank an AIJ matrix of the kept pattern writes only its pattern's
/// entries (the others keep the zeros of the fill that set the pattern: no n x n zeros at every step);
/// otherwise gatherDense itself. The same values either way. Collective.
PetscErrorCode gatherDense(Mat A, KeptDense& kept);

/// The dense matrix of an operator known by its products (a shell: the element-wise tangent),
/// columns A e_j, on rank 0 as gatherDense. Collective.
PetscErrorCode operatorToDense(Mat A, std::vector<double>& full);

/// The vectors and the scatter to rank 0 of operatorProducts, kept from one call to the next (the
/// same operator's layout); created by the first call. Destroy with destroyProductGather.
struct ProductGather {
  Vec x = nullptr, y = nullptr, y0 = nullptr;
  VecScatter toZero = nullptr;
};
PetscErrorCode destroyProductGather(ProductGather* g);

/// The products A x_j of every vector of `pairs` (on every rank), column-major n x wanted() on rank 0. Collective.
PetscErrorCode operatorProducts(Mat A, const DenseEigenpairs& pairs, std::vector<double>& AX, ProductGather* g);

/// The eigenpairs computed on rank 0 to every rank (eigenvalues, estimates, vectors). Collective.
PetscErrorCode broadcastPairs(MPI_Comm comm, DenseEigenpairs& pairs);

/// This rank's owned part of column j of pairs.vectors into the distributed vector x. Not collective.
PetscErrorCode pairVector(const DenseEigenpairs& pairs, int j, Vec x);

}  // namespace sinew
