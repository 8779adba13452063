#include "dynamics/energy_momentum_scheme.hpp"
#include "assembly/assembler.hpp"
#include "parallel/collective_error.hpp"

namespace sinew {

EnergyMomentumScheme::EnergyMomentumScheme(double decay, Vec like, Vec multipliers, Assembler* rotations)
    : StepScheme(like, multipliers, rotations), decay_(decay) {
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(like));
  for (Vec* v : {&qc_, &vm_}) SinewCallThrow(comm, VecDuplicate(like, v));
}

EnergyMomentumScheme::~EnergyMomentumScheme() {
  for (Vec* v : {&qc_, &vm_}) VecDestroy(v);
}

PetscErrorCode EnergyMomentumScheme::beginStep(double h) {
  PetscFunctionBeginUser;
  h_ = h;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode EnergyMomentumScheme::predict(Vec q) const {
  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(q, h_, vn_, qn_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode EnergyMomentumScheme::rates(Vec q) {
  PetscFunctionBeginUser;
  // qd_{n+1} = 2 (q_c - q_n) / h - exp(theta) qd_n: q_c the iterate with the Cayley vectors theta_c in
  // place of the rotation increments theta (q_n = 0 there), exp(theta) turning only the spins
  if (rotations_) PetscCall(rotations_->cayleyIncrements(q, qc_));
  else PetscCall(VecCopy(q, qc_));
  PetscCall(midpointRates(q, qc_));
  PetscCall(VecAXPBYPCZ(vm_, 0.5, 0.5, 0.0, vn_, v1_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

EvaluationPoint EnergyMomentumScheme::evaluation(Vec q) const {
  const double h = h_;
  EvaluationPoint e;
  e.q = q;
  e.qd = vm_;
  e.qdd = a1_;
  e.timeShift = -(0.5 * h);
  e.shiftV = 1.0 / h;
  e.shiftA = 2.0 / (h * h);
  e.jacobianScale = 1.0;
  e.stepForces = true;
  return e;
}

}  // namespace sinew
