// Compliance matrices of nodes (SPACAR Light `calccompl`): at every converged step the tangent
// J = dF/dU (rigid modes as multipliers, supports eliminated) is factored once with MUMPS (a small
// one-process model: a dense LU, every unit load in one solve); only
// the 6x6 diagonal blocks of J^-1 at the requested nodes are computed, never the inverse itself:
//   selinv (default): MUMPS selected entries of the inverse (ICNTL(30), MatMumpsGetInverse), the
//                     pattern of all wanted blocks in one sparse matrix on the MUMPS host;
//   sparse:           unit loads as sparse right-hand sides (MatMatTransposeSolve, ICNTL(20)=1);
//   dense:            unit loads as dense right-hand-side blocks (MatMatSolve).
//   CMglob[node] (6x6): rows = (translation, spin) response of the node, columns = unit (force,
//                       moment) on the node, global axes; constrained rows/columns are 0.
//   CMloc = Q^T CMglob Q, Q = blockdiag(R, R), R = current rotation of the node (node frame).
// Nodes without rotations (cables, membranes) have only the 3x3 translation block.
#pragma once
#include <petscksp.h>

#include <string>
#include <vector>

#include "settings/settings.hpp"
#include "step/step_analysis.hpp"

namespace sinew {

class ComplianceAnalysis : public StepAnalysis {
 public:
  using Method = ComplianceMethod;

  /// nodes: 0-based scene nodes whose compliance is computed; empty = every scene node.
  /// Options (prefix compl_): -compl_ksp_*/-compl_pc_* (factorization); settings: -compliance_method
  /// selinv|sparse|dense, -compliance_batch (right-hand-side columns per solve of the sparse and
  /// dense methods), -compl_mat_mumps_icntl_27 (columns per block of the selected inverse).
  /// denseMaxUnknowns (-dense_max_unknowns): a one-process model up to this size is factored by a
  /// dense LU (LAPACK, PC type denselu) and solved for all unit loads at once, whatever the method.
  ComplianceAnalysis(Assembler& assembler, const std::vector<int>& nodes, const ComplianceSettings& settings,
                     int denseMaxUnknowns);
  ~ComplianceAnalysis() override;
  const char* name() const override { return "compliance"; }
  PetscErrorCode atStep(Vec U, const LoadState& ls, ResultFile& file, bool* ok) override;
  std::string summary() const override;
  std::string failure() const override { return failure_; }

  /// Number of factorizations and MUMPS solve calls so far (tests, benchmarks).
  long factorizations() const { return factorizations_; }
  long batches() const { return batches_; }
  double factorSeconds() const { return factorTime_; }
  double solveSeconds() const { return solveTime_; }

 private:
  /// The free DOFs of one requested owned node: local node index and its DOF slots k (0..5).
  struct Group {
    int node;
    std::vector<int> k;
  };
  PetscErrorCode selectedInverse(Mat F, std::vector<double>& glob);
  PetscErrorCode rhsBlocks(Mat F, bool sparse, std::vector<double>& glob);

  Assembler& asm_;
  Mat J_ = nullptr;
  Mat rhs_ = nullptr, sol_ = nullptr;  // the dense right-hand side and solution blocks, kept between steps
  KSP ksp_ = nullptr;
  std::vector<Group> groups_;     ///< requested owned nodes with at least one free DOF
  bool dense_ = false;            ///< dense LU (PC type denselu) instead of MUMPS
  Method method_ = Method::SelectedInverse;
  PetscInt batch_ = 96;
  int blockColumns_ = 2048;  ///< MUMPS ICNTL(27) of the selected inverse (-compl_mat_mumps_icntl_27)
  long totalColumns_ = 0, factorizations_ = 0, batches_ = 0;
  double factorTime_ = 0, solveTime_ = 0;
  std::string failure_;
};

}  // namespace sinew
