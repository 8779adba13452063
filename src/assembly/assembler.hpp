// Maps element kernels into distributed PETSc objects. The unknowns are free node DOFs
// (translations; incremental rotation vectors theta with R = exp(theta) R_ref; ANCF coordinate
// increments) and the multipliers of rigid deformation modes. Residual rows of rotations are
// spin (moment) balances, so the exact Jacobian is K_spin * T(theta) column-wise.
#pragma once
#include <petscmat.h>
#include "sinew/petsc_compat.hpp"
#include <petscvec.h>

#include <optional>
#include <vector>

#include "mesh/distributed_mesh.hpp"

namespace sinew {

struct LoadState {
  double loadFactor = 0.0;     ///< ramps `force`, `moment`, `displ_*`, `rot`, gravity
  double time = 0.0;           ///< passed to kernels (user functions)
  bool gravityRamped = true;   ///< gravity scaled by the load factor (statics)
};

/// Counters that prove which phases ran (also visible as PetscLogEvents in -log_view).
struct AssemblyCounters {
  long residuals = 0, jacobians = 0, masses = 0, splitTangents = 0, stressRecoveries = 0;
};

class Assembler {
 public:
  Assembler(DistributedMesh& mesh, const std::optional<Vec3>& gravity);
  ~Assembler();
  Assembler(const Assembler&) = delete;
  Assembler& operator=(const Assembler&) = delete;

  DistributedMesh& mesh() { return mesh_; }
  /// Ghosted vector of unknowns (the layout of every solution/residual vector).
  PetscErrorCode createVector(Vec* v) const;
  /// Ghosted vector over every node DOF (constrained included).
  PetscErrorCode createFullVector(Vec* v) const;
  /// AIJ matrix over the unknowns with exact preallocation from the element graph.
  PetscErrorCode createMatrix(Mat* A) const;

  /// F = f_int(U) - f_ext at the unknowns (constraint rows: constraint values).
  PetscErrorCode residual(Vec U, const LoadState& ls, Vec F);
  /// J = dF/dU.
  PetscErrorCode jacobian(Vec U, const LoadState& ls, Mat J);
  /// Material and geometric parts of the tangent (spin columns, used at converged states).
  PetscErrorCode splitTangent(Vec U, const LoadState& ls, Mat Km, Mat Kg);
  /// Consistent mass of elements and nodes over the unknowns (zero rows for multipliers).
  PetscErrorCode mass(Vec U, const LoadState& ls, Mat M);
  /// f_int - f_ext over every node DOF of owned nodes (reactions at constrained DOFs).
  PetscErrorCode fullResidual(Vec U, const LoadState& ls, Vec Ffull);
  /// Largest Von Mises stress per local element (order of mesh().elements).
  PetscErrorCode elementStress(Vec U, const LoadState& ls, std::vector<double>& stress);

  /// Node state (x, R or ANCF coordinates) of local node i, valid after any evaluation.
  const double* nodeState(int i) const { return &state_[12 * static_cast<size_t>(i)]; }
  /// Evaluates node states from U (ghosts updated inside) without assembling.
  PetscErrorCode updateStates(Vec U, const LoadState& ls);
  /// Moves rotation increments into the reference rotations: R_ref = exp(theta) R_ref, theta = 0.
  PetscErrorCode absorbRotations(Vec U);
  /// Restores/saves the reference rotations (for retrying a failed load increment).
  std::vector<Mat3> referenceRotations() const { return Rref_; }
  void setReferenceRotations(const std::vector<Mat3>& r) { Rref_ = r; }

  // ---- building blocks for analyses that run their own element loops (dynamics, form finding)
  /// Ghost-updated local form of U (owned entries, then ghosts) with the node states evaluated;
  /// pair with endLocal(). Indices from gather() address this array.
  PetscErrorCode beginLocal(Vec U, const LoadState& ls, const double** u);
  PetscErrorCode endLocal(const double** u);
  /// Element state q (kernel layout) and local unknown indices (-1 = constrained; multipliers
  /// after the node DOFs) after beginLocal() or any evaluation.
  void gather(const LocalElement& el, double* q, int* idx) const { gatherElement(el, q, nullptr, idx, nullptr); }
  /// Multiplies the spin columns of a dense n x n element tangent by T(theta) (exact Jacobian columns).
  void applyRotationColumns(const LocalElement& el, int n, double* K) const { rotationColumns(el, n, K); }
  ISLocalToGlobalMapping localToGlobal() const { return l2g_; }
  AssemblyCounters& mutableCounters() { return counters_; }

  const AssemblyCounters& counters() const { return counters_; }
  bool hasInertia() const { return hasInertia_; }
  bool hasGravity() const { return gravity_.has_value(); }
  /// Characteristic force of the current external loads (for relative convergence tests).
  double externalForceNorm() const { return fextNorm_; }
  double internalForceNorm() const { return fintNorm_; }

 private:
  enum class Target { Residual, Full };
  PetscErrorCode loadLocal(Vec U, Vec local);
  void computeStates(const double* u, const LoadState& ls);
  void gatherElement(const LocalElement& el, double* q, const double* u, int* idx, int* fullIdx) const;
  void rotationColumns(const LocalElement& el, int n, double* K) const;
  PetscErrorCode assembleForces(const double* u, const LoadState& ls, Target target, double* out);

  DistributedMesh& mesh_;
  std::optional<Vec3> gravity_;
  bool hasInertia_ = false;
  Vec uWork_ = nullptr, fWork_ = nullptr, fullWork_ = nullptr;
  ISLocalToGlobalMapping l2g_ = nullptr;
  std::vector<double> state_;  // 12 per local node
  std::vector<Mat3> Rref_, T_;
  std::vector<char> hasTheta_;
  KernelOutput out_;
  AssemblyCounters counters_;
  double fextNorm_ = 0, fintNorm_ = 0;
};

/// PetscLogEvents of Sinew's phases (registered once).
struct SinewEvents {
  PetscLogEvent setup, residual, jacobian, mass, splitTangent, stress, eigen, compliance, output, dynamics, formfinding;
  static const SinewEvents& get();
};

}  // namespace sinew
