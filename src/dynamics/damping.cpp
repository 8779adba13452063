#include "dynamics/damping.hpp"

#include <cmath>

#include "parallel/collective_error.hpp"
#include "step/modal_analysis.hpp"

namespace sinew {

Damping::Damping(Assembler& assembler, const DynamicsOptions& opts, const EigenSettings& eigen, StiffnessDamping mode)
    : asm_(assembler), opts_(opts), eigen_(eigen) {
  const double beta = opts_.stiffness_proportional_damping;
  // beta on the strain rates of the kernels that take it (beams), or (initial) beta K0 for every kind
  int local = 0, others = 0;
  for (const LocalElement& e : asm_.mesh().elements) {
    const bool own = e.kernel->setStrainRateDamping(mode == StiffnessDamping::Corotated ? beta : 0.0) && e.kernel->strainRateDamped();
    local |= own;
    others |= !own;
  }
  int any[2] = {local, others};
  MPI_Allreduce(MPI_IN_PLACE, any, 2, MPI_INT, MPI_LOR, asm_.mesh().comm);
  strainRate_ = any[0];
  const bool stiffnessK0 = beta > 0 && any[1];  // some kinds keep beta K0
  rayleigh_ = opts_.mass_proportional_damping > 0 || stiffnessK0;
  for (double z : opts_.modal_damping) modal_ = modal_ || z > 0;
}

Damping::~Damping() {
  MatDestroy(&C0_);
  MatDestroy(&M0_);
  for (Vec& v : phi_) VecDestroy(&v);
  VecDestroy(&w_);
  VecDestroy(&y_);
}

PetscErrorCode Damping::setup(Vec U, const LoadState& ls, Vec keep, ResultFile& file) {
  PetscFunctionBeginUser;
  if (!active()) PetscFunctionReturn(PETSC_SUCCESS);
  const double alpha = opts_.mass_proportional_damping, beta = opts_.stiffness_proportional_damping;
  Mat M;
  PetscCall(asm_.createMatrix(&M));
  PetscCall(asm_.mass(U, ls, M));
  if (rayleigh_) {
    // C0 = alpha M0 + beta K0, K0 = the dynamic tangent at rest (shiftV = shiftA = 0)
    Vec V;
    PetscCall(VecDuplicate(U, &V));
    PetscCall(VecSet(V, 0.0));
    PetscCall(asm_.createMatrix(&C0_));
    asm_.setSkipStrainRateDamped(true);  // K0 of the kinds that do not damp their strain rates
    const PetscErrorCode ierr = asm_.dynamicJacobian(U, V, nullptr, ls, 0.0, 0.0, C0_);
    asm_.setSkipStrainRateDamped(false);
    PetscCall(ierr);
    PetscCall(VecDestroy(&V));
    PetscCall(MatScale(C0_, beta));
    PetscCall(MatAXPY(C0_, alpha, M, SAME_NONZERO_PATTERN));
    if (keep) PetscCall(MatDiagonalScale(C0_, keep, keep));  // no damping on multiplier rows/columns
  }
  if (modal_) {
    // modes of the start state: the first n of Sinew's frequency analysis, mass-normalized
    const int n = static_cast<int>(opts_.modal_damping.size() == 1 ? opts_.modal_damping_modes : opts_.modal_damping.size());
    ModalAnalysis modal(asm_, n, false, eigen_);
    bool ok = true;
    PetscCall(modal.atStep(U, ls, file, &ok));
    if (!ok)
      SETERRQ(asm_.mesh().comm, PETSC_ERR_NOT_CONVERGED, "opt.dynamics.modal_damping: the frequency analysis of the start state failed: %s",
              modal.failure().c_str());
    const auto& hz = modal.frequencies();
    for (size_t i = 0; i < hz.size() && i < modal.modes().size(); ++i) {
      const double z = opts_.modal_damping.size() == 1 ? opts_.modal_damping[0] : opts_.modal_damping[i];
      if (!(hz[i] > 0) || z <= 0) continue;  // rigid-body (or unstable) modes and zeta = 0: no damping
      Vec p;
      PetscCall(VecDuplicate(modal.modes()[i], &p));
      PetscCall(VecCopy(modal.modes()[i], p));
      phi_.push_back(p);
      omega_.push_back(2.0 * M_PI * hz[i]);
      zeta_.push_back(z);
    }
    M0_ = M;
    M = nullptr;
    PetscCall(VecDuplicate(U, &w_));
    PetscCall(VecDuplicate(U, &y_));
  }
  PetscCall(MatDestroy(&M));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Damping::addForce(Vec V, Vec F) {
  PetscFunctionBeginUser;
  if (C0_) PetscCall(MatMultAdd(C0_, V, F, F));
  if (!phi_.empty()) {
    // M0 Phi diag(2 zeta_i omega_i) Phi^T M0 V: n dot products and one mass product each way
    PetscCall(MatMult(M0_, V, w_));
    std::vector<PetscScalar> c(phi_.size());
    PetscCall(VecMDot(w_, static_cast<PetscInt>(phi_.size()), phi_.data(), c.data()));
    for (size_t i = 0; i < c.size(); ++i) c[i] *= 2.0 * zeta_[i] * omega_[i];
    PetscCall(VecSet(w_, 0.0));
    PetscCall(VecMAXPY(w_, static_cast<PetscInt>(phi_.size()), c.data(), phi_.data()));
    PetscCall(MatMult(M0_, w_, y_));
    PetscCall(VecAXPY(F, 1.0, y_));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Damping::addJacobian(double shiftV, Mat J) {
  PetscFunctionBeginUser;
  if (C0_ && shiftV != 0.0) PetscCall(MatAXPY(J, shiftV, C0_, SAME_NONZERO_PATTERN));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
