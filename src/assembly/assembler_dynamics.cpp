// Assembler members for time integration: residual and Jacobian of the equations of motion
//   F(U, V, A, t) = M A + f_int(U, V, t) - f_ext(t),   J = K + shiftV D + shiftA M,
// with the kernels' consistent (constant for ANCF) mass, their damping matrices D = df/dqdot
// (only kernels with hasDamping()) and nodal point masses on the translations.
#include <array>

#include "assembly/assembler.hpp"
#include "elements/rotary_momentum.hpp"
#include "sinew/rotation.hpp"

namespace sinew {

namespace {

/// Ghost-updated local form of a ghosted vector (read access); pair with restoreLocalRead.
PetscErrorCode getLocalRead(Vec X, Vec* xl, const PetscScalar** x) {
  PetscFunctionBeginUser;
  PetscCall(ghostUpdate(X, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGhostGetLocalForm(X, xl));
  PetscCall(VecGetArrayRead(*xl, x));
  PetscFunctionReturn(PETSC_SUCCESS);
}
PetscErrorCode restoreLocalRead(Vec X, Vec* xl, const PetscScalar** x) {
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArrayRead(*xl, x));
  PetscCall(VecGhostRestoreLocalForm(X, xl));
  PetscFunctionReturn(PETSC_SUCCESS);
}
}  // namespace

// Spatial inertia tensor J_s = R J0 R^T of a Frame6 node's mominertia at its current rotation.
Mat3 Assembler::spatialInertia(int i) const {
  const LocalNode& n = mesh_.nodes[i];
  const auto& I = n.mominertia;
  const Mat3 J0{I[0], I[1], I[2], I[1], I[3], I[4], I[2], I[4], I[5]};
  const double* s = &state_[12 * static_cast<size_t>(i)];
  const Mat3 R{s[3], s[4], s[5], s[6], s[7], s[8], s[9], s[10], s[11]};
  return R * J0 * transpose(R);
}

bool Assembler::hasRotaryInertia(int i) const {
  const LocalNode& n = mesh_.nodes[i];
  if (n.kind != NodeKind::Frame6 || n.rotationPrescribed) return false;
  for (double v : n.mominertia)
    if (v != 0.0) return true;
  return false;
}

bool Assembler::prescribedRates(const LocalElement& el, double* v, double* a) const {
  if (!presRatesActive_) return false;
  const auto kinds = el.kernel->nodeKinds();
  bool any = false;
  for (size_t i = 0; i < kinds.size(); ++i) any = any || mesh_.nodes[el.node[i]].timeFn;
  if (!any) return false;
  int d = 0;
  for (size_t i = 0; i < kinds.size(); ++i) {
    const LocalNode& n = mesh_.nodes[el.node[i]];
    const double* r = n.timeFn ? &presRate_[12 * static_cast<size_t>(el.node[i])] : nullptr;
    for (int k = 0; k < dofSize(kinds[i]); ++k, ++d) {
      v[d] = r ? r[k] : 0.0;
      a[d] = r ? r[6 + k] : 0.0;
    }
  }
  return true;
}

const double* Assembler::elementMass(const LocalElement& el, const double* q, std::vector<double>& buf) const {
  if (const double* M = el.kernel->constantMass()) return M;  // no copy per element and assembly
  el.kernel->mass(q, buf);
  return buf.data();
}

const double* Assembler::gatherVelocity(const LocalElement& el, const int* idx, double* qdot) const {
  if (!vLocal_) return nullptr;
  const int nd = el.kernel->numDofs();
  std::array<double, kMaxElementRows> pv, pa;
  const bool moving = prescribedRates(el, pv.data(), pa.data());
  for (int k = 0; k < nd; ++k) qdot[k] = idx[k] >= 0 ? vLocal_[idx[k]] : (moving ? pv[k] : 0.0);
  return qdot;
}

void Assembler::elementRates(const LocalElement& el, const int* idx, const double* v, const double* a, double* ve,
                             double* ae) const {
  std::array<double, kMaxElementRows> pv, pa;
  const bool moving = prescribedRates(el, pv.data(), pa.data());
  const int n = el.kernel->numDofs();
  for (int c = 0; c < n; ++c) {
    ve[c] = idx[c] >= 0 ? (v ? v[idx[c]] : 0.0) : (moving ? pv[c] : 0.0);
    ae[c] = idx[c] >= 0 ? (a ? a[idx[c]] : 0.0) : (moving ? pa[c] : 0.0);
  }
}

void Assembler::addElementInertia(const LocalElement& el, const double* q, const int* idx, const int* fidx, const double* a,
                                  Target target, double* out, std::vector<double>& MeBuf) const {
  const int n = el.kernel->numDofs();
  const int* map = target == Target::Residual ? idx : fidx;
  if (completeInertia_ && el.kernel->hasInertiaForce()) {  // the complete inertia force of M(q) (its kinetic energy)
    std::array<double, kMaxElementRows> ve, ae;
    elementRates(el, idx, inertiaV_, a, ve.data(), ae.data());
    el.kernel->inertiaForce(q, ve.data(), ae.data(), false, inertiaOut_);
    for (int r = 0; r < n; ++r)
      if (map[r] >= 0) out[map[r]] += inertiaOut_.f[r];
    return;
  }
  std::array<double, kMaxElementRows> pv, pa;
  const bool moving = prescribedRates(el, pv.data(), pa.data());
  const double* Me = elementMass(el, q, MeBuf);
  // the element's accelerations (prescribed ones from their time functions), then M_e qdd_e
  std::array<double, kMaxElementRows> ae;
  for (int c = 0; c < n; ++c) ae[c] = idx[c] >= 0 ? a[idx[c]] : (moving ? pa[c] : 0.0);
  for (int r = 0; r < n; ++r) {
    if (map[r] < 0) continue;
    const double* Mr = Me + static_cast<size_t>(r) * n;
    double s = 0.0;
    for (int c = 0; c < n; ++c) s += Mr[c] * ae[c];
    out[map[r]] += s;
  }
}

void Assembler::addNodeInertia(const double* v, const double* a, Target target, double* out) {
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    const double* pr = presRatesActive_ && n.timeFn ? &presRate_[12 * static_cast<size_t>(i)] : nullptr;
    const int* map = target == Target::Residual ? n.dof.data() : n.fullDof.data();
    if (n.mass > 0) {
      const int nt = n.kind == NodeKind::Ancf2D ? 2 : 3;
      for (int k = 0; k < nt; ++k) {
        if (map[k] < 0) continue;
        const double acc = n.dof[k] >= 0 ? a[n.dof[k]] : (pr ? pr[6 + k] : 0.0);
        out[map[k]] += n.mass * acc;
      }
    }
    // nodal rotary inertia (spatial angular velocity w and acceleration wd, Lie-group form):
    // moment J_s wd + w x (J_s w), J_s = R J0 R^T; a prescribed rotation only in the reactions
    const bool free = hasRotaryInertia(i);
    const bool presc = !free && target == Target::Full && pr && n.kind == NodeKind::Frame6 &&
                       n.mominertia != std::array<double, 6>{};
    if (!free && !presc) continue;
    if (free && momentum_.h > 0) {  // midpoint rule: the change of the spin momentum (J_s w)_{n+1} - (J_s w)_n over h
      const Vec3 m = midpointMomentum(i).r;
      for (int k = 0; k < 3; ++k) out[map[3 + k]] += m[k];
      continue;
    }
    const Mat3 J = spatialInertia(i);
    Vec3 w, wd;
    for (int k = 0; k < 3; ++k) {
      w[k] = free ? v[n.dof[3 + k]] : pr[3 + k];
      wd[k] = free ? a[n.dof[3 + k]] : pr[9 + k];
    }
    const Vec3 m = J * wd + cross(w, J * w);
    for (int k = 0; k < 3; ++k) out[map[3 + k]] += m[k];
  }
}

RotaryMomentumStep Assembler::midpointMomentum(int i) const {
  const LocalNode& n = mesh_.nodes[i];
  const auto& I = n.mominertia;
  const Mat3 J0{I[0], I[1], I[2], I[1], I[3], I[4], I[2], I[4], I[5]};
  const Vec3 theta{momentum_.u1[n.dof[3]], momentum_.u1[n.dof[4]], momentum_.u1[n.dof[5]]};
  const Vec3 w0{momentum_.w0[n.dof[3]], momentum_.w0[n.dof[4]], momentum_.w0[n.dof[5]]};
  return momentum_.cayley ? rotaryCayleyStep(J0, Rref_[i], theta, w0, momentum_.h)
                          : rotaryMomentumStep(J0, Rref_[i], theta, w0, momentum_.h);
}

PetscErrorCode Assembler::rotateSpins(Vec U, Vec W) const {
  PetscFunctionBeginUser;
  if (!mesh_.anyRotations) PetscFunctionReturn(PETSC_SUCCESS);
  const PetscScalar* u;
  PetscScalar* w;
  PetscCall(VecGetArrayRead(U, &u));
  PetscCall(VecGetArray(W, &w));
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    if (n.kind != NodeKind::Frame6 || n.rotationPrescribed) continue;
    const Vec3 wr = expSO3(Vec3{u[n.dof[3]], u[n.dof[4]], u[n.dof[5]]}) * Vec3{w[n.dof[3]], w[n.dof[4]], w[n.dof[5]]};
    for (int k = 0; k < 3; ++k) w[n.dof[3 + k]] = wr[k];
  }
  PetscCall(VecRestoreArray(W, &w));
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::cayleyIncrements(Vec U, Vec W) const {
  PetscFunctionBeginUser;
  PetscCall(VecCopy(U, W));
  if (!mesh_.anyRotations) PetscFunctionReturn(PETSC_SUCCESS);
  PetscScalar* w;
  PetscCall(VecGetArray(W, &w));
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    if (n.kind != NodeKind::Frame6 || n.rotationPrescribed) continue;
    const Vec3 c = cayleyVector(Vec3{w[n.dof[3]], w[n.dof[4]], w[n.dof[5]]});
    for (int k = 0; k < 3; ++k) w[n.dof[3 + k]] = c[k];
  }
  PetscCall(VecRestoreArray(W, &w));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::setStepStart(Vec Un, const LoadState& ls) {
  PetscFunctionBeginUser;
  PetscCall(updateStates(Un, ls));
  startState_ = state_;
  startDisp_ = disp_;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::rigidMotionPredictor(Vec V, double h, Vec U) const {
  PetscFunctionBeginUser;
  const PetscScalar* v;
  PetscScalar* u;
  PetscCall(VecGetArrayRead(V, &v));
  PetscCall(VecGetArray(U, &u));
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    if (n.kind != NodeKind::Frame6) continue;
    Vec3 w{}, vt{};
    for (int k = 0; k < 3; ++k) {
      w[k] = n.dof[3 + k] >= 0 ? v[n.dof[3 + k]] : 0.0;
      vt[k] = n.dof[k] >= 0 ? v[n.dof[k]] : 0.0;
    }
    const Vec3 phi = h * w, dx = h * (dexpSO3(phi) * vt);  // x(t) = c + exp(t w)(x_n - c) + t v_par
    for (int k = 0; k < 3; ++k) {
      if (n.dof[k] >= 0) u[n.dof[k]] += dx[k];
      if (n.dof[3 + k] >= 0) u[n.dof[3 + k]] += phi[k];
    }
  }
  PetscCall(VecRestoreArray(U, &u));
  PetscCall(VecRestoreArrayRead(V, &v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::dynamicResidual(Vec U, Vec V, Vec A, const LoadState& ls, Vec F) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().residual, 0, 0, 0, 0));
  ++counters_.residuals;
  Vec vl, al;
  const PetscScalar *v, *a;
  PetscCall(getLocalRead(V, &vl, &v));
  PetscCall(getLocalRead(A, &al, &a));
  const PetscErrorCode ierr = forceVector(U, ls, fWork_, F, [&](const double* u, double* f) {
    PetscFunctionBeginUser;
    vLocal_ = inertiaV_ = v;
    aLocal_ = a;  // the elements' M_e qdd_e in the force loop (their data read once)
    const PetscErrorCode e = assembleForces(u, ls, Target::Residual, f);
    vLocal_ = aLocal_ = inertiaV_ = nullptr;
    PetscCall(e);
    // inertia M A of nodal point masses and rotary inertia
    addNodeInertia(v, a, Target::Residual, f);
    PetscFunctionReturn(PETSC_SUCCESS);
  });
  PetscCall(restoreLocalRead(A, &al, &a));
  PetscCall(restoreLocalRead(V, &vl, &v));
  PetscCall(ierr);
  PetscCall(PetscLogEventEnd(SinewEvents::get().residual, 0, 0, 0, 0));
  PetscCall(agreeElementValues());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::dynamicJacobian(Vec U, Vec V, Vec A, const LoadState& ls, double shiftV, double shiftA, Mat J) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().jacobian, 0, 0, 0, 0));
  ++counters_.jacobians;
  const double* u = nullptr;
  PetscCall(beginLocal(U, ls, &u));
  Vec vl;
  const PetscScalar* v;
  PetscCall(getLocalRead(V, &vl, &v));
  Vec al = nullptr;
  const PetscScalar* a = nullptr;
  if (A && completeInertia_) PetscCall(getLocalRead(A, &al, &a));
  // ANCF cables only: every block is kept (CorotatedNewtonMatrix) and the matrix set from the kept blocks
  // in one COO call (A1g, 2 ranks: 56 ms against 108 ms with MatSetValuesLocal per block at 65536
  // elements, 3.6 ms against 6.6 ms at 4096; the COO pattern is set up once per matrix)
  const bool coo = sink_ && sink_->setsMatrix();
  if (!coo) PetscCall(MatZeroEntries(J));
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  std::array<double, kMaxElementRows> qdot;
  std::vector<double> MeBuf;
  std::array<double, 6> sigmaMixed;
  if (sink_) sink_->start(shiftA);
  vLocal_ = v;
  for (const LocalElement& el : mesh_.elements) {
    if (skipStrainRateDamped_ && el.kernel->strainRateDamped()) continue;
    gatherElement(el, q.data(), u, idx.data(), nullptr);
    KernelNeeds needs;
    needs.tangent = true;
    needs.damping = shiftV != 0.0 && el.kernel->hasDamping() && !(stepForces_.h > 0);  // step forces: inside them
    counters_.dampingMatrices += needs.damping;
    KernelInput in{q.data(), gatherVelocity(el, idx.data(), qdot.data()),
                   el.firstMultiplier >= 0 ? u + el.firstMultiplier : nullptr, ls.time};
    in.disp = elemDisp_.data();
    linearizeMixedStresses(el, q.data(), sigmaMixed, in);
    evaluateElement(el, in, needs);
    const int nd = el.kernel->numDofs(), n = nd + el.kernel->numConstraints();
    const bool complete = completeInertia_ && shiftA != 0.0 && el.kernel->hasInertiaForce();
    if (complete) {  // the complete inertia: d f / d q (rotation columns as the stiffness) and shiftV d f / d v
      std::array<double, kMaxElementRows> ve, ae;
      elementRates(el, idx.data(), v, a, ve.data(), ae.data());
      el.kernel->inertiaForce(q.data(), ve.data(), ae.data(), true, inertiaOut_);
      for (int r = 0; r < nd; ++r)
        for (int c = 0; c < nd; ++c) {
          const size_t rc = static_cast<size_t>(r) * nd + c;
          out_.K[static_cast<size_t>(r) * n + c] += inertiaOut_.Kq[rc];
        }
    }
    rotationColumns(el, n, out_.K.data());
    if (complete)
      for (int r = 0; r < nd; ++r)
        for (int c = 0; c < nd; ++c)
          out_.K[static_cast<size_t>(r) * n + c] += shiftV * inertiaOut_.Dv[static_cast<size_t>(r) * nd + c];
    if (needs.damping)
      for (int r = 0; r < nd; ++r)
        for (int c = 0; c < nd; ++c) out_.K[static_cast<size_t>(r) * n + c] += shiftV * out_.D[static_cast<size_t>(r) * nd + c];
    if (shiftA != 0.0 && el.kernel->hasInertia()) {
      const double* Me = elementMass(el, q.data(), MeBuf);
      for (int r = 0; r < nd; ++r)
        for (int c = 0; c < nd; ++c) out_.K[static_cast<size_t>(r) * n + c] += shiftA * Me[static_cast<size_t>(r) * nd + c];
    }
    if (sink_) sink_->element(static_cast<size_t>(&el - mesh_.elements.data()), el, q.data(), out_.K.data());
    if (!coo) PetscCall(MatSetValuesLocal(J, n, idx.data(), n, idx.data(), out_.K.data(), ADD_VALUES));
  }
  vLocal_ = nullptr;
  if (mixedNewton_) keepMixedReference();  // the next Newton iterate linearizes its stresses about this state
  // node terms (nodal masses, rotary inertia, slope torques); with coo they come with the kept blocks
  for (int i = 0; i < mesh_.numOwnedNodes && !coo; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    if (n.mass <= 0 || shiftA == 0.0) continue;
    const int nt = n.kind == NodeKind::Ancf2D ? 2 : 3;
    const double m = shiftA * n.mass;
    for (int k = 0; k < nt; ++k) {
      const PetscInt r = n.dof[k];
      PetscCall(MatSetValuesLocal(J, 1, &r, 1, &r, &m, ADD_VALUES));
    }
  }
  // rotary inertia: d/dtheta of J_s wd + w x (J_s w) with dwd/dtheta = shiftA, dw/dtheta = shiftV
  // (the change of J_s with the rotation is left out: an approximate tangent)
  for (int i = 0; i < mesh_.numOwnedNodes && !coo; ++i) {
    if (!hasRotaryInertia(i)) continue;
    const LocalNode& n = mesh_.nodes[i];
    const Mat3 Js = spatialInertia(i);
    const Vec3 w{v[n.dof[3]], v[n.dof[4]], v[n.dof[5]]}, Jw = Js * w;
    const Mat3 G = skew(w) * Js - skew(Jw);  // d(w x J w)/dw
    std::array<double, 9> B;
    for (int k = 0; k < 9; ++k) B[k] = shiftA * Js[k] + shiftV * G[k];
    if (momentum_.h > 0) {  // midpoint rule: the exact derivative of its momentum change (times 2: the caller halves J)
      const Mat3 dr = midpointMomentum(i).dr;
      const double factor = momentum_.cayley ? 1.0 : 2.0;  // energy-momentum: J is not halved
      for (int k = 0; k < 9; ++k) B[k] = factor * dr[k];
    }
    const PetscInt rows[3] = {n.dof[3], n.dof[4], n.dof[5]};
    PetscCall(MatSetValuesLocal(J, 3, rows, 3, rows, B.data(), ADD_VALUES));
  }
  if (!coo) PetscCall(addSlopeTorqueTangent(ls, J));
  if (sink_) sink_->nodeTerms(ls);
  PetscCall(endLocal(&u));
  PetscCall(restoreLocalRead(V, &vl, &v));
  if (al) PetscCall(restoreLocalRead(A, &al, &a));
  if (coo) {
    PetscCall(sink_->setMatrix(J));
  } else {
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscCall(PetscLogEventEnd(SinewEvents::get().jacobian, 0, 0, 0, 0));
  PetscCall(agreeElementValues());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::kineticEnergy(Vec U, Vec V, const LoadState& ls, double* T) {
  PetscFunctionBeginUser;
  PetscCall(updateStates(U, ls));
  Vec vl;
  const PetscScalar* v;
  PetscCall(getLocalRead(V, &vl, &v));
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  std::vector<double> Me;
  double t = 0.0;
  // elements: each element once (owned by one rank)
  for (const LocalElement& el : mesh_.elements) {
    if (!el.kernel->hasInertia()) continue;
    gatherElement(el, q.data(), nullptr, idx.data(), nullptr);
    el.kernel->mass(q.data(), Me);
    const int n = el.kernel->numDofs();
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        if (idx[r] >= 0 && idx[c] >= 0) t += 0.5 * v[idx[r]] * Me[static_cast<size_t>(r) * n + c] * v[idx[c]];
  }
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    const int nt = n.kind == NodeKind::Ancf2D ? 2 : 3;
    for (int k = 0; k < nt && n.mass > 0; ++k)
      if (n.dof[k] >= 0) t += 0.5 * n.mass * v[n.dof[k]] * v[n.dof[k]];
    if (hasRotaryInertia(i)) {
      const Vec3 w{v[n.dof[3]], v[n.dof[4]], v[n.dof[5]]};
      t += 0.5 * dot(w, spatialInertia(i) * w);
    }
  }
  PetscCall(restoreLocalRead(V, &vl, &v));
  MPI_Allreduce(MPI_IN_PLACE, &t, 1, MPI_DOUBLE, MPI_SUM, mesh_.comm);
  *T = t;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
