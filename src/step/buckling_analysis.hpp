// Linearized buckling at every converged step (calcbuck): load multipliers mu of the current load,
// K_m phi = -mu K_g phi, with K_m the material tangent (constraint blocks of the rigid modes
// included) and K_g the stress-dependent part (multiplier terms included), from
// Assembler::splitTangent. SLEPc GNHEP, shift-and-invert about 0 with a MUMPS LU; the nearest
// eigenvalues are computed and the smallest positive real ones kept (more are computed when the
// nearest ones are negative). Options prefix "buck_": -buck_eps_*, -buck_st_*. Models up to
// -eigen_dense_max_unknowns solve the same shift-and-invert problem dense (LAPACK, every pair at
// once; step/dense_eigen.hpp); the pairs then go through the same selection and output.
#pragma once
#include <slepceps.h>

#include <string>
#include <vector>

#include "assembly/assembler.hpp"
#include "step/backward_error.hpp"
#include "settings/settings.hpp"
#include "step/dense_eigen.hpp"
#include "step/dense_gather.hpp"
#include "step/step_analysis.hpp"
#include "step/vec_pool.hpp"

namespace sinew {

class BucklingAnalysis : public StepAnalysis {
 public:
  /// settings: -eigen_operator, -buck_eps_nev given.
  BucklingAnalysis(Assembler& assembler, int nbuck, const EigenSettings& settings);
  ~BucklingAnalysis() override;
  BucklingAnalysis(const BucklingAnalysis&) = delete;
  BucklingAnalysis& operator=(const BucklingAnalysis&) = delete;

  const char* name() const override { return "buckling"; }
  /// Writes /buck [ns, nbuck] (ascending; +inf where the step has no positive multiplier) and
  /// mesh/mode_buck_<i>.
  PetscErrorCode atStep(Vec U, const LoadState& ls, ResultFile& file, bool* ok) override;
  std::string summary() const override;
  std::string failure() const override { return failure_; }
  const std::vector<double>& multipliers() const { return mu_; }

 private:
  PetscErrorCode solve(int nev, int* nconv);
  PetscErrorCode solveDense(DenseEigenpairs& pairs, const WantedPairs& wanted);
  KeptDense denseA_, denseB_;  // K_m (or its element-wise operator) and -K_g of the dense path, kept between steps
  static PetscErrorCode materialMult(Mat A, Vec x, Vec y);
  PetscErrorCode refine(const UnitFreeNorms& scaled, Vec x, PetscScalar* mu, double* backward);
  bool dense_ = false;        // -eigen_dense_max_unknowns: LAPACK on rank 0 instead of SLEPc
  long symmetricSolves_ = 0, qzSolves_ = 0;  // dense solves of symmetric (dsygvd) / nonsymmetric pencils
  bool elementwise_ = false;  // -eigen_operator: K_m x = (element-wise K) x - K_g x
  Mat Kop_ = nullptr;
  VecPool pool_;          // the steps' work vectors (kept between steps)
  UnitFreeNorms scaled_;  // scales of the backward errors (its matrices kept between steps)
  std::vector<double> estimate_, backward_;
  double tol_ = 1e-8;

  Assembler& asm_;
  int nbuck_;
  Mat Km_ = nullptr, Kg_ = nullptr;
  EPS eps_ = nullptr;
  bool userNev_ = false;
  std::vector<double> mu_;
  int step_ = 0;
  std::string failure_;
};

}  // namespace sinew
