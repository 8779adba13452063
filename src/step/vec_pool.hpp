// Vectors of one layout handed out and taken back within an analysis' steps, so that a step's
// work vectors (eigenvector candidates, residuals) are created once per run, not once per use.
#pragma once
#include <petscmat.h>

#include <vector>

#include "sinew/petsc_compat.hpp"

namespace sinew {

class VecPool {
 public:
  VecPool() = default;
  VecPool(const VecPool&) = delete;
  VecPool& operator=(const VecPool&) = delete;
  ~VecPool();
  /// A vector with the column layout of A (its values are whatever the last user left: overwrite them).
  PetscErrorCode get(Mat A, Vec* v);
  /// Takes v back (null is ignored); v is set to null.
  void put(Vec* v);

 private:
  std::vector<Vec> free_;
};

}  // namespace sinew
