// Linear viscous damping of the time integration (opt.dynamics, docs/dynamics.md "Damping"):
//   f_d = C qd,  C = alpha M0 + beta K0 + M0 Phi diag(2 zeta_i omega_i) Phi^T M0
// With -stiffness_damping corotated (the default) the beta part of the kernels that damp their own
// strain rates (beams: sigma_d = beta S epsd, epsd = grad eps . qd; 3D cables: N_d = beta EA/L ld;
// membranes: S_d = beta C Ed; ANCF cables without user force laws: N_d = beta EA eps_t, M_d = beta EI K_t;
// ElementKernel::setStrainRateDamping)
// is theirs, in their forces and tangents wherever the assembler passes velocities: it never damps rigid
// motion. K0 then holds the other kinds only; -stiffness_damping initial keeps beta K0 for every kind.
// M0, K0: consistent mass and tangent stiffness (material + geometric) of the state the time loop
// starts from (Rayleigh damping with the initial tangent: a constant C, exact for small motions
// about the start state); Phi, omega: the mass-normalized modes and circular frequencies of that
// state from Sinew's own frequency analysis (ModalAnalysis, SLEPc). The modal part is applied as
// M0 (Phi (d .* (Phi^T (M0 qd)))), never as a dense matrix; it is left out of the Newton matrix
// (Newton then contracts by about 2 zeta omega h gamma per iteration: the residual and so the
// solution are exact, the iteration count grows a little). Multiplier rows and columns (index-3
// constraints) are masked out: constraints carry no damping.
#pragma once
#include <petscmat.h>

#include <vector>

#include "assembly/assembler.hpp"
#include "settings/settings.hpp"
#include "sinew/model.hpp"
#include "sinew/result_file.hpp"

namespace sinew {

class Damping {
 public:
  /// eigen: the settings of the frequency analysis behind modal damping.
  /// mode: -stiffness_damping (corotated: beams, 3D cables, ANCF cables and membranes damp their strain rates themselves).
  Damping(Assembler& assembler, const DynamicsOptions& opts, const EigenSettings& eigen, StiffnessDamping mode);
  ~Damping();
  Damping(const Damping&) = delete;
  Damping& operator=(const Damping&) = delete;

  /// Some damping is asked for (Rayleigh or modal).
  bool active() const { return rayleigh_ || modal_; }
  /// Builds C from the start state U (rotations absorbed). keep: 1 on coordinates, 0 on
  /// multipliers (or null). file is only passed to the frequency analysis (it writes nothing).
  PetscErrorCode setup(Vec U, const LoadState& ls, Vec keep, ResultFile& file);
  /// F += C V.
  PetscErrorCode addForce(Vec V, Vec F);
  /// J += shiftV (alpha M0 + beta K0) (the modal part stays out of the Newton matrix).
  PetscErrorCode addJacobian(double shiftV, Mat J);
  /// Some kernels damp their strain rates (corotated beta; no matrix to build for them).
  bool strainRateDamping() const { return strainRate_; }
  /// Damped modes: circular frequency and ratio (for the summary).
  const std::vector<double>& modalOmega() const { return omega_; }
  const std::vector<double>& modalZeta() const { return zeta_; }

 private:
  Assembler& asm_;
  DynamicsOptions opts_;
  EigenSettings eigen_;  ///< of the frequency analysis of modal damping
  bool rayleigh_ = false, modal_ = false;
  bool strainRate_ = false;  ///< some kernels damp their strain rates (corotated beta)
  Mat C0_ = nullptr;  ///< alpha M0 + beta K0
  Mat M0_ = nullptr;  ///< for the modal part
  std::vector<Vec> phi_;
  std::vector<double> omega_, zeta_;
  Vec w_ = nullptr, y_ = nullptr;
};

}  // namespace sinew
