// Natural frequencies at every converged step: K x = omega^2 M x with K the tangent (material +
// geometric, rotations absorbed so theta = 0) and M the consistent mass, solved with SLEPc
// (GHEP, shift-and-invert, MUMPS LU). Supports are eliminated; rigid deformation modes are
// multipliers with zero mass rows (infinite eigenvalues, which shift-and-invert maps to 0 and
// purification keeps out). Options prefix "": every -eps_* / -st_* flag acts on this solver.
// Models up to -eigen_dense_max_unknowns solve the same shift-and-invert problem dense (LAPACK,
// step/dense_eigen.hpp) instead; the pairs then go through the same selection and output.
#pragma once
#include <slepceps.h>

#include <string>
#include <vector>

#include "assembly/assembler.hpp"
#include "settings/settings.hpp"
#include "step/backward_error.hpp"
#include "step/dense_eigen.hpp"
#include "step/dense_gather.hpp"
#include "step/step_analysis.hpp"
#include "step/vec_pool.hpp"

namespace sinew {

/// Translation part of x (unknowns layout, owned entries) on this rank's owned FE nodes, 3 values
/// per node in the order of ResultLayout::ownedMeshNodes (constrained DOFs give 0), and with `rot`
/// the rotation part (rotation vectors of Frame6 nodes, 0 on other nodes), scaled by the same
/// factor. Scaled so that max |u| over all ranks is 1 and the largest component (lowest FE node,
/// then x < y < z, among ties) is positive. When x has no translation (max |u| <= 1e-10 max |x|:
/// torsion, rotation only) u is 0 and the rotations are scaled instead (max 1, largest positive);
/// all 0 when x has neither. Collective.
PetscErrorCode modeShapeRows(const DistributedMesh& mesh, Vec x, std::vector<double>& rows,
                             std::vector<double>* rot = nullptr);

/// Reported frequency (Hz) of an eigenvalue omega^2: 0 for round-off negatives above -zeroTol
/// (rigid-body modes), -sqrt(-omega^2)/(2 pi) for a clearly negative one (unstable state).
double frequencyHz(double omega2, double zeroTol);

class ModalAnalysis : public StepAnalysis {
 public:
  /// nfreq: number of frequencies (-eps_nev overrides). writeResults: /freq and mesh/mode_freq_<i>
  /// (false when only the state-space model needs the modes). settings: -eigen_operator,
  /// -freq_shift_rel, -eps_target given.
  ModalAnalysis(Assembler& assembler, int nfreq, bool writeResults, const EigenSettings& settings);
  ~ModalAnalysis() override;
  ModalAnalysis(const ModalAnalysis&) = delete;
  ModalAnalysis& operator=(const ModalAnalysis&) = delete;

  const char* name() const override { return "natural frequencies"; }
  PetscErrorCode atStep(Vec U, const LoadState& ls, ResultFile& file, bool* ok) override;
  std::string summary() const override;
  std::string failure() const override { return failure_; }

  /// Results of the last step: frequencies (Hz, ascending, NaN where not converged) and the
  /// mass-normalized modes (Phi^T M Phi = I) of the converged ones, in the same order.
  const std::vector<double>& frequencies() const { return hz_; }
  const std::vector<Vec>& modes() const { return modes_; }
  int numRequested() const { return nev_; }

 private:
  PetscErrorCode assemble(Vec U, const LoadState& ls);
  PetscErrorCode shiftTarget(double* sigma, double* scale);
  PetscErrorCode clampToFiniteModes();
  PetscErrorCode solveDense(double target, DenseEigenpairs& pairs);
  static PetscErrorCode stiffnessMult(Mat A, Vec x, Vec y);

  Assembler& asm_;
  bool write_;
  bool all_ = false;  ///< nfreq: all (every finite frequency)
  int nev_ = 6;
  bool userTarget_ = false;
  double shiftRel_ = 1e-8;
  Mat K_ = nullptr, Kt_ = nullptr, M_ = nullptr;
  Mat Kskew_ = nullptr;  ///< (K^T - K)/2 of the assembled tangent, added to the element-wise products (or null)
  PetscObjectState transposedState_ = 0;  ///< K's nonzero state Kt_ was made from (MatTranspose reuse)
  bool dense_ = false;         // -eigen_dense_max_unknowns: LAPACK on rank 0 instead of SLEPc
  bool elementwise_ = false;   // -eigen_operator: K applied element by element (rigid-motion free)
  Mat Kop_ = nullptr;          // shell: Assembler::applyTangent(x, y, true)
  Mat P_ = nullptr;            // assembled K - sigma M: the preconditioner (LU) of the inner GMRES
  std::vector<double> estimate_;  // SLEPc's error estimate per reported pair, last step
  VecPool pool_;                  // the steps' work vectors (kept between steps)
  KeptDense denseK_, denseM_;     // K and M of the dense path, kept between steps
  ProductGather gather_;          // the element-wise products of the dense path's Ritz step
  UnitFreeNorms scaled_;          // scales of the backward error (its matrices kept between steps)
  std::vector<double> backward_;  // backward error of K x - lambda M x, unit-free (scaledBackwardError)
  double tol_ = 1e-8;
  int warned_ = 0;
  Vec dK_ = nullptr, dM_ = nullptr;
  EPS eps_ = nullptr;
  std::vector<double> hz_;
  std::vector<Vec> modes_;
  int step_ = 0;
  int spurious_ = 0;       // eigenpairs dropped as infinite (zero mass norm), all steps
  double asymmetry_ = 0;   // largest ||K - K^T||_F / ||K||_F seen
  std::string failure_;
};

}  // namespace sinew
