// PETSc's TSALPHA2 (-dynamics_scheme tsalpha2): generalized alpha in the variant of Chung & Hulbert
// (1993), equilibrium at t_{n+1-alpha_f}, on the unknowns as a vector space (no rotations). PETSc keeps
// the accelerations inside TS: the state exposes q and qd only, and it cannot be restarted.
#pragma once
#include <petscts.h>

#include <functional>

#include "dynamics/time_scheme.hpp"

namespace sinew {

class TSAlpha2Scheme : public TimeScheme {
 public:
  explicit TSAlpha2Scheme(MotionEquations& equations) : equations_(equations) {}
  ~TSAlpha2Scheme() override;
  TSAlpha2Scheme(const TSAlpha2Scheme&) = delete;
  TSAlpha2Scheme& operator=(const TSAlpha2Scheme&) = delete;

  bool restartable() const override { return false; }
  SchemeState state() const override { return {q_, qd_, nullptr, nullptr}; }
  /// The TS on residual vector F and matrix J: spectral radius rho, steps of dt to tend (the last one
  /// lands on tend), a failed Newton solve retried with smaller steps up to maxRejections times; the
  /// velocities state().qd (a vector like F, set by the caller before solve).
  PetscErrorCode create(Vec F, Mat J, double rho, double dt, double tend, int maxRejections);
  /// Its Newton solver (configured by the caller before solve).
  PetscErrorCode snes(SNES* snes) const;
  /// Called after every time step; *stop ends the run after it.
  using Monitor = std::function<PetscErrorCode(int step, double t, Vec q, Vec qd, bool* stop)>;
  /// Integrates from q (in: q_0; out: the last state) and qd_0 = state().qd, options from the database
  /// (TSSetFromOptions).
  PetscErrorCode solve(Vec q, Monitor monitor);
  /// After solve: Newton iterations, rejected steps, the reason and time TS stopped at.
  PetscErrorCode statistics(int* newtonIterations, int* rejected, TSConvergedReason* why, double* t) const;

 private:
  static PetscErrorCode i2Function(TS, PetscReal t, Vec U, Vec V, Vec A, Vec F, void* ctx);
  static PetscErrorCode i2Jacobian(TS, PetscReal t, Vec U, Vec V, Vec A, PetscReal shiftV, PetscReal shiftA, Mat J,
                                   Mat P, void* ctx);
  static PetscErrorCode monitor(TS ts, PetscInt step, PetscReal t, Vec U, void* ctx);
  MotionEquations& equations_;
  TS ts_ = nullptr;
  Vec q_ = nullptr;   ///< the positions TS integrates (the caller's vector given to solve)
  Vec qd_ = nullptr;  ///< the velocities (owned)
  Monitor monitor_;
};

}  // namespace sinew
