// Assembler residuals: the internal forces of the elements (with their inertia M_e qdd_e when
// reactions of a dynamic step are asked for), nodal loads and torques on ANCF slopes, gravity and
// per-set body accelerations, follower pressure; assembled into the residual of the free unknowns
// (Assembler::residual) or into all node DOFs for reactions (Assembler::fullResidual), with the
// force norms that set the round-off floor of the balance.
#include <array>
#include <cmath>

#include "assembly/assembler.hpp"

namespace sinew {

bool Assembler::bodyAcceleration(const LocalElement& el, const LoadState& ls, Vec3* a) const {
  const std::vector<SetLoads>& loads = mesh_.setLoads;
  const std::optional<Vec3>* own = el.set >= 0 && static_cast<size_t>(el.set) < loads.size() && loads[el.set].acceleration
                                       ? &loads[el.set].acceleration
                                       : nullptr;
  if ((!gravity_ && !own) || !el.kernel->hasInertia()) return false;
  const double scale = ls.gravityRamped ? ls.loadFactor : 1.0;
  Vec3 b = gravity_ ? *gravity_ : Vec3{};
  if (own) b = b + **own;
  *a = scale * b;
  return true;
}

PetscErrorCode Assembler::assembleForces(const double* u, const LoadState& ls, Target target, double* out) {
  PetscFunctionBeginUser;
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx, fidx;
  std::array<double, kMaxElementRows> qdot;
  std::vector<double> fb;
  const double gscale = ls.gravityRamped ? ls.loadFactor : 1.0;
  const Vec3 g = gravity_ ? gscale * *gravity_ : Vec3{};
  double fint2 = 0, fext2 = 0;
  KernelNeeds needs;
  std::vector<double> MeBuf;
  for (const LocalElement& el : mesh_.elements) {
    gatherElement(el, q.data(), u, idx.data(), fidx.data());
    if (aLocal_ && el.kernel->hasInertia()) addElementInertia(el, q.data(), idx.data(), fidx.data(), aLocal_, target, out, MeBuf);
    KernelInput in{q.data(), gatherVelocity(el, idx.data(), qdot.data()),
                   el.firstMultiplier >= 0 ? u + el.firstMultiplier : nullptr, ls.time};
    in.disp = elemDisp_.data();
    evaluateElement(el, in, needs);
    const int nd = el.kernel->numDofs(), nc = el.kernel->numConstraints();
    const int* map = target == Target::Residual ? idx.data() : fidx.data();
    for (int k = 0; k < nd; ++k) {
      fint2 += out_.f[k] * out_.f[k];  // element force scale: the round-off floor of the balance
      if (map[k] >= 0) out[map[k]] += out_.f[k];
    }
    if (target == Target::Residual)
      for (int j = 0; j < nc; ++j) out[idx[nd + j]] += out_.f[nd + j];
    if (Vec3 a; bodyAcceleration(el, ls, &a)) {
      el.kernel->bodyForce(q.data(), a, fb);
      for (int k = 0; k < nd; ++k)
        if (map[k] >= 0) out[map[k]] -= fb[k];
    }
  }
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    std::array<double, 6> fe{};
    for (int k = 0; k < 6; ++k) fe[k] = ls.initialFactor * n.loadInitial[k] + ls.loadFactor * n.load[k];
    if (ls.timeFunctions && n.timeFn)  // loads as functions of time (dynamics); statics: their t = 0 values above
      for (int k = 0; k < 6; ++k)
        if (n.timeFn->load[k]) fe[k] = ls.initialFactor * n.loadInitial[k] + ls.loadFactor * n.timeFn->load[k]->timeJet(ls.time).f;
    if (n.kind == NodeKind::Ancf2D) {
      // a torque acts on the slope: generalized force tau (-s_y, s_x) / |s|^2
      const double* s = &state_[12 * static_cast<size_t>(i)];
      const double tau = fe[4], s2 = s[2] * s[2] + s[3] * s[3];
      fe = {fe[0] + n.mass * g[0], fe[1] + n.mass * g[1], -tau * s[3] / s2, tau * s[2] / s2, 0, 0};
    } else {
      for (int k = 0; k < 3; ++k) fe[k] += n.mass * g[k];
    }
    const int* map = target == Target::Residual ? n.dof.data() : n.fullDof.data();
    for (int k = 0; k < n.ndof; ++k) {
      fext2 += fe[k] * fe[k];
      if (map[k] >= 0) out[map[k]] -= fe[k];
    }
  }
  if (anyPressure_) fext2 += addPressureForces(ls, target, out);
  // third entry: ranks with a non-finite force law in this assembly (agreeElementValues needs no
  // reduction of its own after a residual)
  double norms[3] = {fint2, fext2, elementValueError_.empty() ? 0.0 : 1.0};
  MPI_Allreduce(MPI_IN_PLACE, norms, 3, MPI_DOUBLE, MPI_SUM, mesh_.comm);
  fextNorm_ = std::sqrt(norms[1]);
  fintNorm_ = std::sqrt(norms[0]);
  elementValueErrorKnown_ = true;
  anyElementValueError_ = norms[2] > 0.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::forceVector(Vec U, const LoadState& ls, Vec work, Vec out,
                                      const std::function<PetscErrorCode(const double* u, double* f)>& add) {
  PetscFunctionBeginUser;
  const double* u = nullptr;
  PetscCall(beginLocal(U, ls, &u));
  Vec fl;
  PetscScalar* f;
  PetscCall(VecGhostGetLocalForm(work, &fl));
  PetscCall(VecSet(fl, 0.0));
  PetscCall(VecGetArray(fl, &f));
  const PetscErrorCode ierr = add(u, f);
  PetscCall(VecRestoreArray(fl, &f));
  PetscCall(VecGhostRestoreLocalForm(work, &fl));
  PetscCall(endLocal(&u));
  PetscCall(ierr);
  PetscCall(ghostUpdate(work, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecCopy(work, out));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::residual(Vec U, const LoadState& ls, Vec F) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().residual, 0, 0, 0, 0));
  ++counters_.residuals;
  PetscCall(forceVector(U, ls, fWork_, F,
                        [&](const double* u, double* f) { return assembleForces(u, ls, Target::Residual, f); }));
  PetscCall(PetscLogEventEnd(SinewEvents::get().residual, 0, 0, 0, 0));
  PetscCall(agreeElementValues());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::fullResidual(Vec U, const LoadState& ls, Vec Ffull) {
  PetscFunctionBeginUser;
  if (reactionA_) {  // dynamics: reactions include the inertia M qdd (ghost values needed below)
    PetscCall(ghostUpdate(reactionV_, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(ghostUpdate(reactionA_, INSERT_VALUES, SCATTER_FORWARD));
  }
  PetscCall(forceVector(U, ls, fullWork_, Ffull, [&](const double* u, double* f) {
    PetscFunctionBeginUser;
    if (!reactionA_) PetscFunctionReturn(assembleForces(u, ls, Target::Full, f));
    Vec vl, al;
    const PetscScalar *v, *a;
    PetscCall(VecGhostGetLocalForm(reactionV_, &vl));
    PetscCall(VecGhostGetLocalForm(reactionA_, &al));
    PetscCall(VecGetArrayRead(vl, &v));
    PetscCall(VecGetArrayRead(al, &a));
    aLocal_ = a;  // the elements' M_e qdd_e in the force loop
    inertiaV_ = v;
    const PetscErrorCode e = assembleForces(u, ls, Target::Full, f);
    aLocal_ = inertiaV_ = nullptr;
    addNodeInertia(v, a, Target::Full, f);
    PetscCall(VecRestoreArrayRead(al, &a));
    PetscCall(VecRestoreArrayRead(vl, &v));
    PetscCall(VecGhostRestoreLocalForm(reactionA_, &al));
    PetscCall(VecGhostRestoreLocalForm(reactionV_, &vl));
    PetscCall(e);
    PetscFunctionReturn(PETSC_SUCCESS);
  }));
  PetscCall(agreeElementValues());
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
