#include "step/vec_pool.hpp"

namespace sinew {

VecPool::~VecPool() {
  for (Vec& v : free_) VecDestroy(&v);
}

PetscErrorCode VecPool::get(Mat A, Vec* v) {
  PetscFunctionBeginUser;
  if (free_.empty()) {
    PetscCall(MatCreateVecs(A, v, nullptr));
  } else {
    *v = free_.back();
    free_.pop_back();
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

void VecPool::put(Vec* v) {
  if (*v) free_.push_back(*v);
  *v = nullptr;
}

}  // namespace sinew
