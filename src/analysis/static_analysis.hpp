// Load-stepped nonlinear statics: SNES (Newton, line search, MUMPS by default) on the
// assembler's residual; a failed increment is retried with halved increments.
#pragma once
#include <petscsnes.h>

#include <functional>
#include <string>
#include <vector>

#include "assembly/assembler.hpp"

namespace sinew {

struct StepReport {
  int step = 0;            ///< 1-based requested load step
  double loadFactor = 0;
  int newtonIterations = 0;
  int increments = 0;      ///< SNES solves used (1 = no cut)
  double residualNorm = 0;
};

class StaticAnalysis {
 public:
  /// options prefix "" -> -snes_*, -ksp_*, -pc_* act on this solver.
  StaticAnalysis(Assembler& assembler, int loadsteps);
  ~StaticAnalysis();
  /// Solves the steps k/loadsteps, k = 1..loadsteps, from U (in: start state, out: last
  /// converged state). onStep runs after each converged step. Sets converged and, when it fails,
  /// failureMessage (step, residual, what to try).
  using StepCallback = std::function<PetscErrorCode(const StepReport&, Vec U)>;
  PetscErrorCode run(Vec U, const StepCallback& onStep, bool* converged);
  const std::vector<StepReport>& reports() const { return reports_; }
  const std::string& failureMessage() const { return failure_; }
  SNES snes() const { return snes_; }

 private:
  static PetscErrorCode formFunction(SNES, Vec U, Vec F, void* ctx);
  static PetscErrorCode formJacobian(SNES, Vec U, Mat J, Mat P, void* ctx);
  static PetscErrorCode convergenceTest(SNES, PetscInt it, PetscReal xnorm, PetscReal snorm, PetscReal fnorm,
                                        SNESConvergedReason* reason, void* ctx);
  PetscErrorCode solveIncrement(Vec U, double lambda, bool* ok, int* its, double* fnorm, SNESConvergedReason* why);

  Assembler& asm_;
  int loadsteps_;
  SNES snes_ = nullptr;
  Mat J_ = nullptr;
  Vec F_ = nullptr;
  LoadState ls_;
  double forceRtol_ = 1e-11;
  int maxCuts_ = 10;
  bool predictor_ = true;  ///< secant predictor from the last converged increment
  std::vector<StepReport> reports_;
  std::string failure_;
};

}  // namespace sinew
