// DynamicAnalysis on a level of a -target_error study in time (analysis/time_handover.hpp,
// docs/accuracy.md "Reuse between levels"): the record of the converged time steps for the next level,
// which halves dt, and the Newton start of a time step from the coarser level's record (levels that refine the
// elements too: level_space_time_reuse.cpp). In time alone the levels
// have the same mesh, partition and unknowns, so each rank keeps and reads its own entries. At a time
// the coarser level reached (every other step of the finer) its state is the start; between two of its
// times t_a, t_b (H = t_b - t_a, s = (t - t_a) / H) the cubic Hermite in time of the entries from their
// values and rates, q(s) = h00 q_a + h10 H qd_a + h01 q_b + h11 H qd_b, and of each Frame6 node's
// rotation from its end rotations and spatial angular velocities (math/time_hermite.hpp); multipliers
// have no rates (their Hermite has flat ends). The converged state does not depend on Newton's start
// beyond Newton's tolerance; the start only saves iterations.
#include <algorithm>
#include <cmath>

#include "dynamics/dynamic_analysis.hpp"
#include "math/time_hermite.hpp"
#include "sinew/rotation.hpp"

namespace sinew {

namespace {

/// The owned Frame6 nodes whose rotation is an unknown, in node order (the record's rotations).
bool rotationUnknowns(const LocalNode& n) { return n.kind == NodeKind::Frame6 && !n.rotationPrescribed; }

std::size_t numRotationNodes(const DistributedMesh& mesh) {
  std::size_t r = 0;
  for (int i = 0; i < mesh.numOwnedNodes; ++i) r += rotationUnknowns(mesh.nodes[static_cast<std::size_t>(i)]);
  return r;
}

/// The coarser record at t (owned entries q, the rotation of every rotation node R): its state at its
/// own times, the cubic Hermite in time between two of them; false when t is outside the record.
bool coarseStateAt(const TimeHandover& c, const DistributedMesh& mesh, double t, std::vector<double>* q,
                   std::vector<Mat3>* R) {
  const std::vector<TimeHandover::Step>& steps = c.steps;
  const double tol = 1e-9 * (steps[1].t - steps[0].t);  // the summed steps' round-off
  // b: the first recorded time at or after t (up to tol)
  const auto after = std::lower_bound(steps.begin(), steps.end(), t - tol,
                                      [](const TimeHandover::Step& s, double time) { return s.t < time; });
  if (after == steps.end()) return false;
  const TimeHandover::Step& b = *after;
  const bool exact = std::abs(b.t - t) <= tol;
  if (!exact && after == steps.begin()) return false;
  const TimeHandover::Step& a = exact ? b : *(after - 1);
  const double H = b.t - a.t, s = exact ? 1.0 : (t - a.t) / H;
  const HermiteWeights w = hermiteWeights(s);
  q->resize(b.q.size());
  for (std::size_t j = 0; j < b.q.size(); ++j)
    (*q)[j] = exact ? b.q[j] : w.h00 * a.q[j] + w.h10 * H * a.v[j] + w.h01 * b.q[j] + w.h11 * H * b.v[j];
  R->clear();
  for (int i = 0; i < mesh.numOwnedNodes; ++i) {
    const LocalNode& n = mesh.nodes[static_cast<std::size_t>(i)];
    if (!rotationUnknowns(n)) continue;
    const std::size_t r = R->size();
    const Mat3 Rb = rotationOfQuaternion(&b.rotations[4 * r]);
    const auto spin = [&](const TimeHandover::Step& st) {
      return Vec3{st.v[static_cast<std::size_t>(n.dof[3])], st.v[static_cast<std::size_t>(n.dof[4])],
                  st.v[static_cast<std::size_t>(n.dof[5])]};
    };
    R->push_back(exact ? Rb : hermiteRotation(rotationOfQuaternion(&a.rotations[4 * r]), spin(a), Rb, spin(b), H, s));
  }
  return true;
}

}  // namespace

PetscErrorCode DynamicAnalysis::useCoarseLevel() {
  PetscFunctionBeginUser;
  coarse_ = nullptr;
  if (!handover_ || !handover_->coarseHistory) PetscFunctionReturn(PETSC_SUCCESS);
  const TimeHandover& c = *handover_->coarseHistory;
  if (c.byNode) {  // levels that refine the elements (level_space_time_reuse.cpp)
    PetscCall(useCoarseNodes(c));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscInt lo = 0, hi = 0;
  PetscCall(VecGetOwnershipRange(F_, &lo, &hi));
  const std::size_t owned = static_cast<std::size_t>(hi - lo), rotations = 4 * numRotationNodes(asm_.mesh());
  int same = c.firstOwnedUnknown == lo && c.steps.size() >= 2;
  for (const TimeHandover::Step& s : c.steps)
    same = same && s.q.size() == owned && s.v.size() == owned && s.rotations.size() == rotations;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &same, 1, MPI_INT, MPI_LAND, asm_.mesh().comm));
  if (same) coarse_ = &c;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::recordLevelStep(double t, Vec q, Vec qd) {
  PetscFunctionBeginUser;
  if (!handover_ || !handover_->history) PetscFunctionReturn(PETSC_SUCCESS);
  TimeHandover& rec = *handover_->history;
  if (rec.byNode) {  // levels that refine the elements (level_space_time_reuse.cpp)
    PetscCall(recordNodeStep(t, q, qd));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscInt lo = 0, n = 0;
  PetscCall(VecGetOwnershipRange(q, &lo, nullptr));
  PetscCall(VecGetLocalSize(q, &n));
  rec.firstOwnedUnknown = lo;
  TimeHandover::Step s;
  s.t = t;
  const PetscScalar *u, *v;
  PetscCall(VecGetArrayRead(q, &u));
  PetscCall(VecGetArrayRead(qd, &v));
  s.q.assign(u, u + n);
  s.v.assign(v, v + n);
  PetscCall(VecRestoreArrayRead(qd, &v));
  PetscCall(VecRestoreArrayRead(q, &u));
  const DistributedMesh& mesh = asm_.mesh();
  const std::vector<Mat3> R = asm_.referenceRotations();  // R = R_ref: the increments are absorbed
  s.rotations.reserve(4 * numRotationNodes(mesh));
  for (int i = 0; i < mesh.numOwnedNodes; ++i)
    if (rotationUnknowns(mesh.nodes[static_cast<std::size_t>(i)])) {
      const std::array<double, 4> quat = quaternionOf(R[static_cast<std::size_t>(i)]);
      s.rotations.insert(s.rotations.end(), quat.begin(), quat.end());
    }
  rec.steps.push_back(std::move(s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DynamicAnalysis::startFromCoarseLevel(double t1, Vec U, bool* found) {
  PetscFunctionBeginUser;
  if (coarse_->byNode) {
    PetscCall(startFromCoarseNodes(t1, U, found));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  const DistributedMesh& mesh = asm_.mesh();
  std::vector<double> q;
  std::vector<Mat3> R;
  *found = coarseStateAt(*coarse_, mesh, t1, &q, &R);
  if (!*found) PetscFunctionReturn(PETSC_SUCCESS);
  PetscScalar* u;
  PetscCall(VecGetArray(U, &u));
  std::copy(q.begin(), q.end(), u);
  const std::vector<Mat3> Rref = asm_.referenceRotations();  // R_n of this level: the unknowns are exp(theta) R_n
  std::size_t r = 0;
  for (int i = 0; i < mesh.numOwnedNodes; ++i) {
    const LocalNode& n = mesh.nodes[static_cast<std::size_t>(i)];
    if (!rotationUnknowns(n)) continue;
    const Vec3 theta = logSO3(R[r++] * transpose(Rref[static_cast<std::size_t>(i)]));
    for (int k = 0; k < 3; ++k) u[n.dof[3 + k]] = theta[static_cast<std::size_t>(k)];
  }
  PetscCall(VecRestoreArray(U, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
