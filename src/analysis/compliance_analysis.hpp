// Compliance matrices of nodes (SPACAR Light `calccompl`): at every converged step the tangent
// J = dF/dU (rigid modes as multipliers, supports eliminated) is factored once with MUMPS and
// solved for unit loads on the free DOFs of the requested nodes, in blocks of columns
// (MatMatSolve on a dense right-hand-side block), never forming an inverse.
//   CMglob[node] (6x6): rows = (translation, spin) response of the node, columns = unit (force,
//                       moment) on the node, global axes; constrained rows/columns are 0.
//   CMloc = Q^T CMglob Q, Q = blockdiag(R, R), R = current rotation of the node (node frame).
// Nodes without rotations (cables, membranes) have only the 3x3 translation block.
#pragma once
#include <petscksp.h>

#include <string>
#include <vector>

#include "analysis/step_analysis.hpp"

namespace sinew {

class ComplianceAnalysis : public StepAnalysis {
 public:
  /// nodes: 0-based scene nodes whose compliance is computed; empty = every scene node.
  /// Options (prefix compl_): -compl_ksp_*/-compl_pc_* (factorization), -compliance_batch
  /// (right-hand-side columns per MatMatSolve, default 96).
  ComplianceAnalysis(Assembler& assembler, const std::vector<int>& nodes);
  ~ComplianceAnalysis() override;
  const char* name() const override { return "compliance"; }
  PetscErrorCode atStep(Vec U, const LoadState& ls, ResultFile& file, bool* ok) override;
  std::string summary() const override;
  std::string failure() const override { return failure_; }

  /// Number of factorizations and MatMatSolve batches so far (tests, benchmarks).
  long factorizations() const { return factorizations_; }
  long batches() const { return batches_; }
  double factorSeconds() const { return factorTime_; }
  double solveSeconds() const { return solveTime_; }

 private:
  Assembler& asm_;
  Mat J_ = nullptr;
  KSP ksp_ = nullptr;
  std::vector<int> nodes_;        ///< owned local nodes (scene nodes) whose compliance is computed
  std::vector<char> wanted_;      ///< per owned local node
  PetscInt batch_ = 96;
  long totalColumns_ = 0, factorizations_ = 0, batches_ = 0;
  double factorTime_ = 0, solveTime_ = 0;
  std::string failure_;
};

}  // namespace sinew
