#include "app/summary.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace sinew {

namespace {

constexpr std::size_t kReactionTableRows = 12;  // a longer list of supports is summed up, not listed

// Cables and membranes: extreme forces / stress resultants with their element (1-based), slack and
// wrinkled counts.
void tensileLines(std::ostringstream& s, const TensileSummary& t) {
  char line[320];
  if (t.cables > 0) {
    std::snprintf(line, sizeof line,
                  "\n cables (last step): axial force max %.4e N (element %d), min %.4e N (element %d); %ld of %ld slack\n",
                  t.forceMax, t.forceMaxElement + 1, t.forceMin, t.forceMinElement + 1, t.slack, t.cables);
    s << line;
  }
  if (t.membranes > 0) {
    std::snprintf(line, sizeof line,
                  "%s membranes (last step): principal stress resultant n1 max %.4e N/m (element %d), n2 min %.4e N/m "
                  "(element %d); %ld of %ld wrinkled (n2 <= 0)\n",
                  t.cables > 0 ? "" : "\n", t.n1Max, t.n1MaxElement + 1, t.n2Min, t.n2MinElement + 1, t.wrinkled, t.membranes);
    s << line;
  }
}

// A model without rotations: the node that moves most and the reactions (listed up to
// kReactionTableRows supports, else their sum and the largest).
/// The last step's node table (`motion`: indices into NodeSummaryRow::v, 0..5 = ux uy uz rx ry rz) and
/// reaction table (`reaction`: 6..11 = Fx Fy Fz Mx My Mz; nodes whose reactions there are all 0 left out).
void nodeTables(std::ostringstream& s, const std::vector<NodeSummaryRow>& nodes, const std::vector<int>& motion,
                const std::vector<int>& reaction) {
  static const char* kHeads[12] = {"      ux [m]", "      uy [m]", "      uz [m]", "   rx [rad]", "   ry [rad]", "   rz [rad]",
                                   "      Fx [N]", "      Fy [N]", "      Fz [N]", "    Mx [N m]", "    My [N m]", "    Mz [N m]"};
  char cell[48];
  s << "\n loaded and supported nodes, and the node that moves most (last step)\n node";
  for (int k : motion) s << kHeads[k];
  s << "\n";
  for (const auto& n : nodes) {
    std::snprintf(cell, sizeof cell, " %4d", n.node);
    s << cell;
    for (int k : motion) {  // displacements in m, rotations in rad
      if (k < 3) std::snprintf(cell, sizeof cell, " %11.4e", n.v[k]);
      else std::snprintf(cell, sizeof cell, " %10.4g", n.v[k]);
      s << cell;
    }
    s << "\n";
  }
  s << "\n reactions (last step)\n node";
  for (int k : reaction) s << kHeads[k];
  s << "\n";
  for (const auto& n : nodes) {
    bool any = false;
    for (int k : reaction) any = any || n.v[k] != 0.0;
    if (!any) continue;
    std::snprintf(cell, sizeof cell, " %4d", n.node);
    s << cell;
    for (int k : reaction) {
      std::snprintf(cell, sizeof cell, " %11.4e", n.v[k]);
      s << cell;
    }
    s << "\n";
  }
}

void pointNodeLines(std::ostringstream& s, const SummaryBody& b) {
  char line[256];
  if (b.mostMoving.node > 0) {
    const auto& v = b.mostMoving.v;
    std::snprintf(line, sizeof line, " node that moves most (last step): node %d, |u| = %.4e m (ux %.4e, uy %.4e, uz %.4e)\n",
                  b.mostMoving.node, std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), v[0], v[1], v[2]);
    s << line;
  }
  std::vector<const NodeSummaryRow*> supports;
  for (const auto& n : b.nodes)
    if (n.v[6] != 0.0 || n.v[7] != 0.0 || n.v[8] != 0.0) supports.push_back(&n);
  if (supports.empty()) return;
  if (supports.size() <= kReactionTableRows) {
    s << "\n reactions (last step)\n"
         " node      Fx [N]      Fy [N]      Fz [N]\n";
    for (const NodeSummaryRow* n : supports) {
      std::snprintf(line, sizeof line, " %4d %11.4e %11.4e %11.4e\n", n->node, n->v[6], n->v[7], n->v[8]);
      s << line;
    }
    return;
  }
  double sum[3] = {0, 0, 0}, largest = -1;
  const NodeSummaryRow* top = nullptr;
  for (const NodeSummaryRow* n : supports) {
    for (int k = 0; k < 3; ++k) sum[k] += n->v[6 + k];
    const double f = std::sqrt(n->v[6] * n->v[6] + n->v[7] * n->v[7] + n->v[8] * n->v[8]);
    if (f > largest) largest = f, top = n;
  }
  std::snprintf(line, sizeof line,
                " reactions (last step): %zu supported nodes, sum (%.4e, %.4e, %.4e) N; largest |F| = %.4e N at node %d "
                "(%.4e, %.4e, %.4e) (every reaction: /node/Freac)\n",
                supports.size(), sum[0], sum[1], sum[2], largest, top->node, top->v[6], top->v[7], top->v[8]);
  s << line;
}

}  // namespace

PetscErrorCode printHeader(MPI_Comm comm, const SummaryHeader& h) {
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "Sinew %s\n", h.title.empty() ? "" : ("- " + h.title).c_str()));
  PetscCall(PetscPrintf(comm, "  scene %s, %d rank%s, %ld unknowns\n", h.scene.c_str(), h.nranks, h.nranks > 1 ? "s" : "",
                        h.unknowns));
  if (!h.inputOnly) PetscCall(PetscPrintf(comm, "  analyses: %s\n", h.plan.c_str()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode printSummary(MPI_Comm comm, const SummaryBody& b) {
  PetscFunctionBeginUser;
  std::ostringstream s;
  char line[256];
  if (!b.reports.empty()) {
    s << "\n step  load factor  Newton its  increments  |residual| [N, N m]\n";
    bool onUpdate = false;
    for (const auto& r : b.reports) {
      std::snprintf(line, sizeof line, " %4d  %11.4g  %10d  %10d  %.3e%s\n", r.step, r.loadFactor, r.newtonIterations,
                    r.increments, r.residualNorm, r.convergedOnUpdate ? " *" : "");
      s << line;
      onUpdate = onUpdate || r.convergedOnUpdate;
    }
    if (onUpdate) {
      const auto& last = b.reports.back();
      std::snprintf(line, sizeof line,
                    " * converged on the Newton update (last |dU|/|U| = %.1e): the residual is at the round-off\n"
                    "   noise of the stored coordinates, see docs/ancf_cable2d.md\n",
                    last.relativeUpdate);
      s << line;
    }
  }
  if (b.tensileOnly) {
    tensileLines(s, b.tensile);
    pointNodeLines(s, b);
  } else if (!b.nodes.empty() && b.planar) {
    nodeTables(s, b.nodes, {0, 1, 5}, {6, 7, 11});
  } else if (!b.nodes.empty() && !b.rotations) {  // point nodes only (cables, membranes with beams absent): no rotation columns
    nodeTables(s, b.nodes, {0, 1, 2}, {6, 7, 8});
  } else if (!b.nodes.empty()) {
    nodeTables(s, b.nodes, {0, 1, 2, 3, 4, 5}, {6, 7, 8, 9, 10, 11});
  }
  if (!b.tensileOnly) tensileLines(s, b.tensile);  // cables / membranes beside beams
  if (b.stress) {
    std::snprintf(line, sizeof line, "\n max Von Mises stress %.4e Pa (element %d)\n", b.stressMax, b.stressElement + 1);
    s << line;
  }
  s << b.analysisLines;
  // one entry per phase that ran: its wall time and, for solver phases, its Newton iterations
  std::snprintf(line, sizeof line, "\n wall time: setup %.3f s, constraint check %.3f s", b.times.setup, b.times.check);
  s << line;
  const struct {
    const char* name;
    double seconds;
    long its;
  } phases[] = {{"form finding", b.times.formfinding, b.times.formfindingIts},
                {"statics", b.times.statics, b.times.staticsIts},
                {"path following", b.times.continuation, b.times.continuationIts},
                {"dynamics", b.times.dynamics, b.times.dynamicsIts}};
  for (const auto& p : phases) {
    if (p.its < 0) continue;
    std::snprintf(line, sizeof line, ", %s %.3f s (%ld Newton iterations)", p.name, p.seconds, p.its);
    s << line;
  }
  std::snprintf(line, sizeof line, ", step analyses %.3f s, output %.3f s (checkpoints %.3f s)\n", b.times.analyses,
                b.times.output, b.times.checkpoint);
  s << line;
  if (b.verbose) {  // developer counters
    std::snprintf(line, sizeof line, " assemblies: %ld residuals, %ld tangents, %ld mass, %ld split tangents, %ld stress\n",
                  b.counters.residuals, b.counters.jacobians, b.counters.masses, b.counters.splitTangents,
                  b.counters.stressRecoveries);
    s << line;
    if (b.counters.pressureLoads > 0) s << " pressure: " << b.counters.pressureLoads << " follower element loads (rank 0)\n";
    s << b.developerLines;
  }
  if (b.h5.empty()) s << " results: in memory (no file)";  // the library entry point (sinew/simulation.hpp)
  else s << " results: " << b.h5 << " (ParaView: " << b.xdmf << ")";
  if (b.verbose) s << "; " << b.commits << " commits, " << b.syncedCommits << " forced to the disk (-output_fsync_interval)";
  s << "\n";
  if (!b.converged) s << "\nerror: " << b.failure << "\n";
  PetscCall(PetscPrintf(comm, "%s", s.str().c_str()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
