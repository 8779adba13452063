// Energy and momentum of a dynamic state (opt.dynamics with -dynamics_energy; docs/dynamics.md
// "Energy and momentum"):
//   kinetic  T = 1/2 V^T M(U) V (element masses, nodal masses, nodal mominertia J_s)
//   strain   S = sum of the kernels' strain energies (ElementKernel::strainEnergy)
//   external work W(t) = int_0^t f_ext . qd dt (power of the applied loads incl. gravity and
//            pressure, trapezoidal rule over the time steps; f_ext = sum of the elements' internal
//            forces minus the residual, so follower loads and body forces are included)
//   momentum pi = M(U) V (generalized): linear p = sum_i pi_t,i, angular about the origin
//            H = sum_i x_i x pi_t,i + pi_r,i (a rigid velocity (v, w) has power p.v + H.w with
//            pi, so this is the momentum of the kinetic energy's mass matrix); an ANCF node adds
//            s x pi_s of its slope coordinates (a rotation turns them with the positions).
// Supported nodes (eliminated DOFs) carry no velocity and no momentum entry.
#pragma once
#include <petscmat.h>

#include <array>
#include <string>

#include "assembly/assembler.hpp"

namespace sinew {

struct EnergyMomentumRow {
  double kinetic = 0, strain = 0;
  std::array<double, 3> linear{}, angular{};
};

class EnergyMomentum {
 public:
  explicit EnergyMomentum(Assembler& assembler);
  ~EnergyMomentum();
  EnergyMomentum(const EnergyMomentum&) = delete;
  EnergyMomentum& operator=(const EnergyMomentum&) = delete;

  /// Kinetic and strain energy, linear and angular momentum of (U, V). *ok false when some
  /// element kind gives no strain energy (then `missing` names the kinds). Collective.
  PetscErrorCode evaluate(Vec U, Vec V, const LoadState& ls, EnergyMomentumRow* row, bool* ok, std::string* missing);
  /// Power of the external loads f_ext(U, t) . V. Collective.
  PetscErrorCode externalPower(Vec U, Vec V, const LoadState& ls, double* power);

 private:
  Assembler& asm_;
  Mat M_ = nullptr;
  Vec f_ = nullptr, pi_ = nullptr;
};

}  // namespace sinew
