// Per-step results of the node and element state: positions, rotations (quaternion, axis-angle,
// Euler ZYX), ANCF slopes, reactions, Von Mises stress; the visualization mesh (its reference
// geometry /mesh/p0 through the layout, positions and displacements per step) and its cell fields (stress, axial force,
// membrane stress resultants); written to the result file and kept for the stdout summary.
#pragma once
#include <petscsf.h>
#include <petscvec.h>

#include <array>
#include <vector>

#include "assembly/assembler.hpp"
#include "sinew/result_file.hpp"

namespace sinew {

struct StepResultOptions {
  bool stress = false;            ///< recover Von Mises stress (/stressmax)
  bool stressPerElement = false;  ///< also /element/stressmax
};

/// A node row for the summary: 1-based scene node and 12 values (u xyz, rotation vector xyz, F xyz, M xyz).
struct NodeSummaryRow {
  int node = 0;
  std::array<double, 12> v{};
};

/// Cables and membranes at the last written step, for the summary (collective: tensileSummary()).
/// Elements are 0-based scene elements (-1: none).
struct TensileSummary {
  long cables = 0, slack = 0;       ///< tension-only cable FE elements, those slack
  double forceMax = 0, forceMin = 0;  ///< cable axial force [N]
  int forceMaxElement = -1, forceMinElement = -1;
  long membranes = 0, wrinkled = 0;  ///< membrane FE elements, those with a principal resultant n2 <= 0
  double n1Max = 0, n2Min = 0;       ///< principal stress resultants [N/m]
  int n1MaxElement = -1, n2MinElement = -1;
};

class StepResults {
 public:
  StepResults(Assembler& assembler, const StepResultOptions& opts);
  ~StepResults();
  StepResults(const StepResults&) = delete;
  StepResults& operator=(const StepResults&) = delete;

  /// Adds this rank's rows, cells and reference positions (/mesh/p0) to the result layout (call
  /// before creating the ResultFile).
  void fillLayout(ResultLayout& layout) const;
  /// Writes node/element/mesh/cell fields of the state U for the current step (beginStep done). Collective.
  PetscErrorCode write(ResultFile& file, Vec U, const LoadState& ls);
  /// Rows of the loaded or supported scene nodes at the last written step, gathered on rank 0.
  std::vector<NodeSummaryRow> summaryRows() const;
  /// The free scene node (no support, no prescribed motion) with the largest displacement at the last
  /// written step, on rank 0 (node 0: none).
  NodeSummaryRow mostMovingNode() const;
  /// Cable forces and membrane resultants at the last written step (every rank).
  TensileSummary tensileSummary() const;
  double lastStressMax() const { return stressMax_; }
  int lastStressElement() const { return stressElement_; }

 private:
  Assembler& asm_;
  StepResultOptions opts_;
  Vec full_ = nullptr;
  PetscSF stressSF_ = nullptr;  // FE element leaves -> scene element roots, MPI_MAX
  PetscInt elemLo_ = 0, elemHi_ = 0;
  PetscErrorCode writeCellFields(ResultFile& file, Vec U, const LoadState& ls, const std::vector<double>& stress);
  void addCable(const double* q, const ElementKernel& kernel, double force, int element);
  void addMembrane(const std::vector<double>& n, int element);

  long cellCounts_[3] = {0, 0, 0};  ///< global lines, triangles, quads
  /// Reference positions of the owned nodes at construction (/mesh/p0; /mesh/u = x - X0 from them,
  /// also after a form finding whose FORCE restart moves the nodes' X0 to the found shape).
  std::vector<Vec3> reference_;
  std::vector<NodeSummaryRow> rows_;
  struct MaxMove {
    double u = -1.0;
    NodeSummaryRow row;
  } maxMove_;  ///< the unreported node with the largest displacement (for the summary)
  MaxMove anyMove_;  ///< the node with the largest displacement (for the summary of cable nets and membranes)
  TensileSummary tensile_;  ///< this rank's elements
  double stressMax_ = 0;
  int stressElement_ = -1;
};

}  // namespace sinew
