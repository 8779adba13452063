#include "dynamics/midpoint_scheme.hpp"
#include "assembly/assembler.hpp"
#include "parallel/collective_error.hpp"

namespace sinew {

MidpointScheme::MidpointScheme(Vec like, Vec multipliers, Assembler* rotations) : StepScheme(like, multipliers, rotations) {
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(like));
  for (Vec* v : {&qm_, &vm_}) SinewCallThrow(comm, VecDuplicate(like, v));
  if (keep_) {  // the constraint rows: notKeep = 1 - keep, scale 1 + notKeep
    SinewCallThrow(comm, VecDuplicate(like, &notKeep_));
    SinewCallThrow(comm, VecDuplicate(like, &constraintScale_));
    SinewCallThrow(comm, VecSet(notKeep_, 1.0));
    SinewCallThrow(comm, VecAXPY(notKeep_, -1.0, keep_));
    SinewCallThrow(comm, VecWAXPY(constraintScale_, 1.0, notKeep_, keep_));
    SinewCallThrow(comm, VecAXPY(constraintScale_, 1.0, notKeep_));
  }
}

MidpointScheme::~MidpointScheme() {
  for (Vec* v : {&qm_, &vm_, &notKeep_, &constraintScale_}) VecDestroy(v);
}

PetscErrorCode MidpointScheme::beginStep(double h) {
  PetscFunctionBeginUser;
  h_ = h;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MidpointScheme::predict(Vec q) const {
  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(q, h_, vn_, qn_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MidpointScheme::rates(Vec q) {
  PetscFunctionBeginUser;
  // qd_{n+1} = 2 (q_{n+1} - q_n) / h - qd_n; spins (spatial form): w_{n+1} = 2 theta / h - exp(theta) w_n
  // (q_n = 0 on the rotation unknowns: theta is their value in q_{n+1})
  // (qd_{n+1} - qd_n) / h: the inertia of the translations (and output accelerations)
  PetscCall(midpointRates(q, q));
  // mid configuration and velocity: q_n + (q_{n+1} - q_n) / 2 (rotations exp(theta / 2) R_n)
  PetscCall(VecAXPBYPCZ(qm_, 0.5, 0.5, 0.0, qn_, q));
  PetscCall(VecAXPBYPCZ(vm_, 0.5, 0.5, 0.0, vn_, v1_));
  if (notKeep_) {  // the multipliers are those of the mid-step forces themselves (no average)
    PetscCall(VecPointwiseMult(qm_, keep_, qm_));
    PetscCall(VecPointwiseMult(work_, notKeep_, q));
    PetscCall(VecAXPY(qm_, 1.0, work_));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

EvaluationPoint MidpointScheme::evaluation(Vec) const {
  const double h = h_;
  EvaluationPoint e;
  e.q = qm_;
  e.qd = vm_;
  e.qdd = a1_;
  e.timeShift = -(0.5 * h);
  e.shiftV = 2.0 / h;
  e.shiftA = 4.0 / (h * h);
  e.jacobianScale = 0.5;
  e.midStep = true;
  return e;
}

}  // namespace sinew
