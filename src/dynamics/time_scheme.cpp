#include "dynamics/time_scheme.hpp"
#include "assembly/assembler.hpp"
#include "parallel/collective_error.hpp"

namespace sinew {

StepScheme::StepScheme(Vec like, Vec multipliers, Assembler* rotations) : keep_(multipliers), rotations_(rotations) {
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(like));
  for (Vec* v : {&qn_, &vn_, &an_, &qddn_, &v1_, &a1_, &qdd1_, &work_}) SinewCallThrow(comm, VecDuplicate(like, v));
}

StepScheme::~StepScheme() {
  for (Vec* v : {&qn_, &vn_, &an_, &qddn_, &v1_, &a1_, &qdd1_, &work_}) VecDestroy(v);
}

PetscErrorCode StepScheme::restore(const SchemeState& s) {
  PetscFunctionBeginUser;
  PetscCall(VecCopy(s.q, qn_));
  PetscCall(VecCopy(s.qd, vn_));
  PetscCall(VecCopy(s.a, an_));
  PetscCall(VecCopy(s.qdd, qddn_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode StepScheme::copyState(const SchemeState& to) const {
  PetscFunctionBeginUser;
  PetscCall(VecCopy(qn_, to.q));
  PetscCall(VecCopy(vn_, to.qd));
  PetscCall(VecCopy(an_, to.a));
  PetscCall(VecCopy(qddn_, to.qdd));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode StepScheme::midpointRates(Vec q, Vec qEnd) {
  PetscFunctionBeginUser;
  PetscCall(VecCopy(vn_, work_));
  if (rotations_) PetscCall(rotations_->rotateSpins(q, work_));
  PetscCall(VecWAXPY(v1_, -1.0, qn_, qEnd));
  PetscCall(VecAXPBY(v1_, -1.0, 2.0 / h_, work_));
  PetscCall(VecWAXPY(a1_, -1.0, vn_, v1_));
  PetscCall(VecScale(a1_, 1.0 / h_));
  PetscCall(VecCopy(a1_, qdd1_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode StepScheme::commit(Vec q) {
  PetscFunctionBeginUser;
  PetscCall(VecCopy(q, qn_));
  PetscCall(VecCopy(v1_, vn_));
  PetscCall(VecCopy(a1_, an_));
  PetscCall(VecCopy(qdd1_, qddn_));
  if (keep_)  // multipliers are algebraic (index 3): no velocity or acceleration; predictor lambda_n
    for (Vec v : {vn_, an_, qddn_}) PetscCall(VecPointwiseMult(v, keep_, v));
  // Lie-group form for Frame6 nodes: R_{n+1} = exp(theta) R_n, then theta_{n+1} = 0, so the next
  // step's rotation unknowns are again the spatial increment h Delta q from R_{n+1}. V and A
  // hold spatial angular velocities and accelerations (vectors in the fixed frame): no transport.
  if (rotations_) PetscCall(rotations_->absorbRotations(qn_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
