// DynamicAnalysis on a level of a -target_error study whose levels refine the elements (opt.accuracy_refine
// space or both; analysis/time_handover.hpp, docs/accuracy.md "Reuse between levels"): the record of the
// converged time steps by FE node, and the Newton start of a time step from the coarser level's record.
// The levels have different nodes and partitions, so the record holds the state (positions, rotations,
// ANCF coordinates) and rates (velocities, spatial angular velocities) of every FE node, gathered on
// every rank by node number. The start at t: on the coarse nodes the coarse state at its own times, the
// cubic Hermite in time between two of them (positions and ANCF coordinates from their values and rates,
// Frame6 rotations on SO(3) from their end rotations and spins, math/time_hermite.hpp), mapped onto this
// level's nodes (StaticsHandover::coarseNodeMap: inherited nodes keep their values, new midside nodes the
// element's interpolation). Newton starts from this level's own q_n plus the coarser level's motion over
// the step, mapped: positions and ANCF coordinates g(t1) - g(t1 - h), rotations theta = log(R(t1) R(t1 - h)^T)
// (R = exp(theta) R_n); the multipliers stay at q_n. The motion and not the mapped state itself: the
// coarser shape differs from this level's by the coarser discretization error, which on a finer beam is a
// residual in its stiff directions (a cantilever of 1 to 8 elements, both refined: 416 iterations on the
// finest level from the mapped state, 320 from q_n plus the motion, 412 from the predictor), and after a
// form finding each level starts from its own found shape. Runs with modified Newton (a kept Jacobian,
// from 200 unknowns) start from the predictor (useCoarseNodes). The converged state does not depend on
// Newton's start beyond Newton's tolerance; the start only saves iterations.
#include <algorithm>
#include <cmath>

#include "dynamics/dynamic_analysis.hpp"
#include "math/time_hermite.hpp"
#include "sinew/rotation.hpp"

namespace sinew {

namespace {

Vec3 vec3(const double* x) { return {x[0], x[1], x[2]}; }

/// The node states of the record at t on its own (coarse) nodes: exact at a recorded time, the cubic
/// Hermite in time between two; empty when t is outside the record.
std::vector<double> coarseNodesAt(const TimeHandover& c, double t) {
  const std::vector<TimeHandover::NodeStep>& steps = c.nodeSteps;
  const double tol = 1e-9 * (steps[1].t - steps[0].t);  // the summed steps' round-off
  const auto after = std::lower_bound(steps.begin(), steps.end(), t - tol,
                                      [](const TimeHandover::NodeStep& s, double time) { return s.t < time; });
  if (after == steps.end()) return {};
  const TimeHandover::NodeStep& b = *after;
  if (std::abs(b.t - t) <= tol) return b.states;
  if (after == steps.begin()) return {};
  const TimeHandover::NodeStep& a = *(after - 1);
  const double H = b.t - a.t, s = (t - a.t) / H;
  const HermiteWeights w = hermiteWeights(s);
  std::vector<double> x(b.states.size(), 0.0);
  for (std::size_t n = 0; n < c.nodeKinds.size(); ++n) {
    const NodeKind kind = static_cast<NodeKind>(c.nodeKinds[n]);
    const std::size_t o = 12 * n, r = 6 * n;
    const std::size_t values = kind == NodeKind::Ancf2D ? 4 : 3;  // positions (and slopes) with their rates
    for (std::size_t k = 0; k < values; ++k)
      x[o + k] = w.h00 * a.states[o + k] + w.h10 * H * a.rates[r + k] + w.h01 * b.states[o + k] + w.h11 * H * b.rates[r + k];
    if (kind != NodeKind::Frame6) continue;
    Mat3 Ra, Rb;
    std::copy(&a.states[o + 3], &a.states[o + 12], Ra.begin());
    std::copy(&b.states[o + 3], &b.states[o + 12], Rb.begin());
    const Mat3 R = hermiteRotation(Ra, vec3(&a.rates[r + 3]), Rb, vec3(&b.rates[r + 3]), H, s);
    std::copy(R.begin(), R.end(), &x[o + 3]);
  }
  return x;
}

}  // namespace

PetscErrorCode DynamicAnalysis::recordNodeStep(double t, Vec q, Vec qd) {
  PetscFunctionBeginUser;
  TimeHandover& rec = *handover_->history;
  const DistributedMesh& mesh = asm_.mesh();
  const std::size_t nn = static_cast<std::size_t>(mesh.numFeNodes);
  if (rec.nodeKinds.empty()) {  // every FE node is owned by one rank
    rec.nodeKinds.assign(nn, 0);
    for (int i = 0; i < mesh.numOwnedNodes; ++i)
      rec.nodeKinds[static_cast<std::size_t>(mesh.nodes[static_cast<std::size_t>(i)].gid)] =
          static_cast<int>(mesh.nodes[static_cast<std::size_t>(i)].kind);
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, rec.nodeKinds.data(), static_cast<int>(nn), MPI_INT, MPI_SUM, mesh.comm));
  }
  TimeHandover::NodeStep s;
  s.t = t;
  LoadState ls = ls_;
  ls.time = t;
  PetscCall(asm_.updateStates(q, ls));  // the node states of q (prescribed motions at t)
  LevelState st;
  PetscCall(gatherLevelState(asm_, t, &st));
  s.states = std::move(st.nodes);
  s.rates.assign(6 * nn, 0.0);  // constrained DOFs: 0
  const PetscScalar* v;
  PetscCall(VecGetArrayRead(qd, &v));
  for (int i = 0; i < mesh.numOwnedNodes; ++i) {
    const LocalNode& n = mesh.nodes[static_cast<std::size_t>(i)];
    for (int k = 0; k < dofSize(n.kind); ++k)
      if (n.status[static_cast<std::size_t>(k)] == DofStatus::Free && n.dof[static_cast<std::size_t>(k)] >= 0)
        s.rates[6 * static_cast<std::size_t>(n.gid) + static_cast<std::size_t>(k)] = v[n.dof[static_cast<std::size_t>(k)]];
  }
  PetscCall(VecRestoreArrayRead(qd, &v));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, s.rates.data(), static_cast<int>(s.rates.size()), MPI_DOUBLE, MPI_SUM, mesh.comm));
  rec.nodeSteps.push_back(std::move(s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::useCoarseNodes(const TimeHandover& c) {
  PetscFunctionBeginUser;
  // the record and the map are the same on every rank: every rank decides alike
  if (!handover_->coarseNodeMap || c.nodeSteps.size() < 2) PetscFunctionReturn(PETSC_SUCCESS);
  // a kept (modified-Newton) Jacobian judges itself by the residual's fall from the predictor's start;
  // from the closer coarse start it refactored at most iterations (ANCF, 128 elements: 3254 iterations
  // on 592 Jacobians against 1629 on 182): the start of these runs stays the predictor
  if (modifiedNewton_) PetscFunctionReturn(PETSC_SUCCESS);
  if (handover_->coarseNodeMap(c.nodeSteps.front().states).size() != 12 * static_cast<std::size_t>(asm_.mesh().numFeNodes))
    PetscFunctionReturn(PETSC_SUCCESS);
  coarse_ = &c;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::startFromCoarseNodes(double t1, Vec U, bool* found) {
  PetscFunctionBeginUser;
  const std::vector<double> c0 = coarseNodesAt(*coarse_, t1 - h_), c1 = coarseNodesAt(*coarse_, t1);
  *found = !c0.empty() && !c1.empty();
  if (!*found) PetscFunctionReturn(PETSC_SUCCESS);
  // the coarser level's motion over the step on this level's nodes, added to this level's q_n
  const std::vector<double> g0 = handover_->coarseNodeMap(c0), g1 = handover_->coarseNodeMap(c1);
  PetscCall(VecCopy(stepScheme_->state().q, U));  // rotations absorbed: R_n = R_ref, theta = 0
  const DistributedMesh& mesh = asm_.mesh();
  PetscScalar* u;
  PetscCall(VecGetArray(U, &u));
  for (int i = 0; i < mesh.numOwnedNodes; ++i) {
    const LocalNode& n = mesh.nodes[static_cast<std::size_t>(i)];
    const std::size_t o = 12 * static_cast<std::size_t>(n.gid);
    auto add = [&](std::size_t k, double value) {
      if (n.status[k] == DofStatus::Free && n.dof[k] >= 0) u[n.dof[k]] += value;
    };
    const std::size_t values = n.kind == NodeKind::Ancf2D ? 4 : 3;
    for (std::size_t k = 0; k < values; ++k) add(k, g1[o + k] - g0[o + k]);
    if (n.kind != NodeKind::Frame6 || n.rotationPrescribed) continue;
    Mat3 R0, R1;
    std::copy(&g0[o + 3], &g0[o + 12], R0.begin());
    std::copy(&g1[o + 3], &g1[o + 12], R1.begin());
    const Vec3 theta = logSO3(R1 * transpose(R0));  // R = exp(theta) R_n: the coarser level's turn over the step
    for (std::size_t k = 0; k < 3; ++k) add(3 + k, theta[k]);
  }
  PetscCall(VecRestoreArray(U, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
