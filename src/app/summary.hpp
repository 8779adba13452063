// The human summary on stdout (rank 0).
#pragma once
#include <petscsys.h>

#include <string>
#include <vector>

#include "analysis/static_analysis.hpp"
#include "step/step_results.hpp"

namespace sinew {

/// Wall time per phase (output and step analyses excluded from the solver phases) and the
/// Newton iterations each solver phase took (-1: the phase did not run).
struct Timings {
  double setup = 0, check = 0, formfinding = 0, statics = 0, continuation = 0, dynamics = 0, analyses = 0, output = 0;
  double checkpoint = 0;  ///< part of output: writing /checkpoint (src/restart/checkpoint.*)
  long formfindingIts = -1, staticsIts = -1, continuationIts = -1, dynamicsIts = -1;
};

struct SummaryHeader {
  std::string title, scene;
  int nranks = 1;
  long unknowns = 0;
  std::string plan;
  bool inputOnly = false;  ///< opt.showinputonly: no analyses line
};

struct SummaryBody {
  std::vector<StepReport> reports;
  std::vector<NodeSummaryRow> nodes;
  /// A model of cables and membranes only: what a designer reads (cable forces, membrane resultants,
  /// slack / wrinkled counts, reactions, the node that moves most) instead of the node table.
  bool tensileOnly = false;
  bool rotations = true;       ///< the model has rotation unknowns (else no rotation columns)
  TensileSummary tensile;      ///< cables / membranes of the model (counts 0: none)
  NodeSummaryRow mostMoving;   ///< node 0: none moves
  bool verbose = false;        ///< -verbose: also the developer counters
  std::string developerLines;  ///< counters printed with -verbose (element kinds' force-law evaluations)
  bool stress = false;
  double stressMax = 0;
  int stressElement = -1;
  std::string analysisLines;
  AssemblyCounters counters;
  Timings times;
  std::string h5, xdmf, failure;
  bool converged = true;
  bool planar = false;
  long commits = 0, syncedCommits = 0;  ///< result file commits, and those forced to the disk  ///< a 2D model (ANCF cables in the x-y plane): ux, uy, rz and Fx, Fy, Mz only
};

PetscErrorCode printHeader(MPI_Comm comm, const SummaryHeader& h);
PetscErrorCode printSummary(MPI_Comm comm, const SummaryBody& b);

}  // namespace sinew
