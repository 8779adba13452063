// Assembler core (assembler.hpp): the PetscLogEvents, construction (work vectors, lumped inertia,
// the COO decision, the local-to-global map), the node states from the unknowns (positions,
// rotations R = exp(theta) R_ref and prescribed motions), gathering element states and DOF indices,
// the mixed-stress linearization, the rotation columns K T(theta), element evaluation with the
// agreement on non-finite force laws, element stresses and absorbing the incremental rotations.
// The residual is in assembler_residual.cpp, the Jacobian, split tangent and mass matrices in
// assembler_tangents.cpp, matrix preallocation and COO patterns in assembler_matrices.cpp.
#include "assembly/assembler.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "parallel/collective_error.hpp"
#include "sinew/rotation.hpp"

namespace sinew {

const SinewEvents& SinewEvents::get() {
  static SinewEvents ev = [] {
    SinewEvents e{};
    PetscClassId cls;
    PetscClassIdRegister("Sinew", &cls);
    PetscLogEventRegister("SinewSetup", cls, &e.setup);
    PetscLogEventRegister("SinewResidual", cls, &e.residual);
    PetscLogEventRegister("SinewJacobian", cls, &e.jacobian);
    PetscLogEventRegister("SinewMassAsm", cls, &e.mass);
    PetscLogEventRegister("SinewSplitTan", cls, &e.splitTangent);
    PetscLogEventRegister("SinewStress", cls, &e.stress);
    PetscLogEventRegister("SinewEigen", cls, &e.eigen);
    PetscLogEventRegister("SinewCompliance", cls, &e.compliance);
    PetscLogEventRegister("SinewOutput", cls, &e.output);
    PetscLogEventRegister("SinewDynamics", cls, &e.dynamics);
    PetscLogEventRegister("SinewFormFind", cls, &e.formfinding);
    PetscLogEventRegister("SinewConstrCheck", cls, &e.constraintCheck);
    PetscLogEventRegister("SinewJacElements", cls, &e.jacobianElements);
    PetscLogEventRegister("SinewTangentOp", cls, &e.tangentOperator);
    PetscLogEventRegister("SinewCOOSetup", cls, &e.cooSetup);
    PetscLogEventRegister("SinewCoarseSpace", cls, &e.coarseSpace);
    PetscLogEventRegister("SinewCorotJac", cls, &e.corotatedJacobian);
    return e;
  }();
  return ev;
}

Assembler::Assembler(DistributedMesh& mesh, const std::optional<Vec3>& gravity, bool cooAssembly)
    : mesh_(mesh), gravity_(gravity) {
  const int nl = static_cast<int>(mesh_.nodes.size());
  state_.assign(12 * static_cast<size_t>(nl), 0.0);
  disp_.assign(3 * static_cast<size_t>(nl), 0.0);
  Rref_.assign(nl, identity3());
  T_.assign(nl, identity3());
  hasTheta_.assign(nl, 0);
  SinewCallThrow(mesh_.comm, addLumpedInertia());
  int inertia = 0;
  for (const LocalElement& e : mesh_.elements) inertia |= e.kernel->hasInertia();
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    inertia |= n.mass > 0;
    for (double v : n.mominertia) inertia |= v != 0.0;
  }
  MPI_Allreduce(MPI_IN_PLACE, &inertia, 1, MPI_INT, MPI_LOR, mesh_.comm);
  for (const LocalNode& n : mesh_.nodes)
    for (double x : n.X0) coordMax_ = std::max(coordMax_, std::abs(x));
  MPI_Allreduce(MPI_IN_PLACE, &coordMax_, 1, MPI_DOUBLE, MPI_MAX, mesh_.comm);
  hasInertia_ = inertia != 0;
  initLoads();
  SinewCallThrow(mesh_.comm, createVector(&uWork_));
  SinewCallThrow(mesh_.comm, VecDuplicate(uWork_, &fWork_));
  SinewCallThrow(mesh_.comm, createFullVector(&fullWork_));
  // the same decision on every rank (the COO calls are collective): no rank has cables, pressure
  // elements or ANCF nodes (their node and load tangents are added outside the element blocks)
  int cooOk = cooAssembly && !mesh_.anyAncf && pressureElems_.empty() && cableElems_.empty();
  MPI_Allreduce(MPI_IN_PLACE, &cooOk, 1, MPI_INT, MPI_LAND, mesh_.comm);
  cooAssembly_ = cooOk != 0;
  std::vector<PetscInt> l2g(mesh_.numLocalUnknowns());
  for (int i = 0; i < mesh_.numLocalUnknowns(); ++i) l2g[i] = static_cast<PetscInt>(mesh_.localToGlobalUnknown(i));
  SinewCallThrow(mesh_.comm, ISLocalToGlobalMappingCreate(mesh_.comm, 1, static_cast<PetscInt>(l2g.size()), l2g.data(),
                                                          PETSC_COPY_VALUES, &l2g_));
}

Assembler::~Assembler() {
  VecDestroy(&uWork_);
  VecDestroy(&fWork_);
  VecDestroy(&fullWork_);
  VecDestroy(&xOp_);
  VecDestroy(&yOp_);
  ISLocalToGlobalMappingDestroy(&l2g_);
  MatDestroy(&structure_);
}

PetscErrorCode Assembler::createVector(Vec* v) const {
  PetscFunctionBeginUser;
  std::vector<PetscInt> ghosts(mesh_.ghostUnknowns.begin(), mesh_.ghostUnknowns.end());
  PetscCall(VecCreateGhost(mesh_.comm, mesh_.numOwnedUnknowns, static_cast<PetscInt>(mesh_.numGlobalUnknowns),
                           static_cast<PetscInt>(ghosts.size()), ghosts.data(), v));
  PetscCall(VecSetFromOptions(*v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::createFullVector(Vec* v) const {
  PetscFunctionBeginUser;
  std::vector<PetscInt> ghosts(mesh_.ghostFull.begin(), mesh_.ghostFull.end());
  PetscCall(VecCreateGhost(mesh_.comm, mesh_.numOwnedFull, static_cast<PetscInt>(mesh_.numGlobalFull),
                           static_cast<PetscInt>(ghosts.size()), ghosts.data(), v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Kernels with lumped inertia (-beam_mass lumped) add their nodal masses and rotary inertias to the
// nodes' mass and mominertia, summed over the ranks onto owned and ghost nodes (two all-node-DOF
// vectors carry the 7 values per node), once per mesh.
PetscErrorCode Assembler::addLumpedInertia() {
  PetscFunctionBeginUser;
  int any = 0;
  double mJ[7 * 4];
  for (const LocalElement& el : mesh_.elements) any |= el.kernel->lumpedInertia(mJ);
  MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_LOR, mesh_.comm);
  if (!any || mesh_.lumpedInertiaAdded) PetscFunctionReturn(PETSC_SUCCESS);
  Vec a, b, al, bl;
  PetscCall(createFullVector(&a));
  PetscCall(VecDuplicate(a, &b));
  PetscScalar *fa, *fb;
  PetscCall(VecGhostGetLocalForm(a, &al));
  PetscCall(VecGhostGetLocalForm(b, &bl));
  PetscCall(VecSet(al, 0.0));
  PetscCall(VecSet(bl, 0.0));
  PetscCall(VecGetArray(al, &fa));
  PetscCall(VecGetArray(bl, &fb));
  for (const LocalElement& el : mesh_.elements) {
    if (!el.kernel->lumpedInertia(mJ)) continue;
    for (int i = 0; i < el.numNodes; ++i) {
      const LocalNode& n = mesh_.nodes[el.node[i]];
      if (n.kind != NodeKind::Frame6) continue;
      for (int k = 0; k < 6; ++k) fa[n.fullDof[k]] += mJ[7 * i + k];
      fb[n.fullDof[0]] += mJ[7 * i + 6];
    }
  }
  PetscCall(VecRestoreArray(al, &fa));
  PetscCall(VecRestoreArray(bl, &fb));
  PetscCall(VecGhostRestoreLocalForm(a, &al));
  PetscCall(VecGhostRestoreLocalForm(b, &bl));
  const PetscScalar *ra, *rb;
  for (Vec v : {a, b}) {
    PetscCall(ghostUpdate(v, ADD_VALUES, SCATTER_REVERSE));
    PetscCall(ghostUpdate(v, INSERT_VALUES, SCATTER_FORWARD));
  }
  PetscCall(VecGhostGetLocalForm(a, &al));
  PetscCall(VecGhostGetLocalForm(b, &bl));
  PetscCall(VecGetArrayRead(al, &ra));
  PetscCall(VecGetArrayRead(bl, &rb));
  for (LocalNode& n : mesh_.nodes) {
    if (n.kind != NodeKind::Frame6) continue;
    n.mass += ra[n.fullDof[0]];
    for (int k = 0; k < 5; ++k) n.mominertia[k] += ra[n.fullDof[1 + k]];
    n.mominertia[5] += rb[n.fullDof[0]];
  }
  PetscCall(VecRestoreArrayRead(bl, &rb));
  PetscCall(VecRestoreArrayRead(al, &ra));
  PetscCall(VecGhostRestoreLocalForm(b, &bl));
  PetscCall(VecGhostRestoreLocalForm(a, &al));
  PetscCall(VecDestroy(&a));
  PetscCall(VecDestroy(&b));
  mesh_.lumpedInertiaAdded = true;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::loadLocal(Vec U, Vec local) {
  PetscFunctionBeginUser;
  PetscCall(VecCopy(U, local));
  PetscCall(ghostUpdate(local, INSERT_VALUES, SCATTER_FORWARD));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void Assembler::computeStates(const double* u, const LoadState& ls) {
  const double lam = ls.loadFactor, lam0 = ls.initialFactor;
  presRatesActive_ = false;
  const bool shiftedMotion = !std::isnan(ls.motionTime);
  for (size_t i = 0; i < mesh_.nodes.size(); ++i) {
    const LocalNode& n = mesh_.nodes[i];
    double* s = &state_[12 * i];
    // a prescribed function of time (dynamics): value, velocity and acceleration from its exact derivatives
    const NodeTimeFunctions* tf = ls.timeFunctions ? n.timeFn.get() : nullptr;
    double* rate = nullptr;
    if (tf) {
      if (presRate_.size() != 12 * mesh_.nodes.size()) presRate_.assign(12 * mesh_.nodes.size(), 0.0);
      rate = &presRate_[12 * i];
      std::fill(rate, rate + 12, 0.0);
      presRatesActive_ = true;
    }
    auto value = [&](int k) {
      switch (n.status[k]) {
        case DofStatus::Free: return u[n.dof[k]];
        case DofStatus::Prescribed:
          if (tf && tf->prescribed[k]) {
            const Expression::TimeJet j = tf->prescribed[k]->timeJet(ls.time);
            rate[k] = lam * j.df;
            rate[6 + k] = lam * j.ddf;
            const double f = shiftedMotion ? tf->prescribed[k]->timeJet(ls.motionTime).f : j.f;
            return lam * f + lam0 * n.prescribedInitial[k];
          }
          return lam * n.prescribed[k] + lam0 * n.prescribedInitial[k];
        default: return 0.0;
      }
    };
    hasTheta_[i] = 0;
    if (n.kind == NodeKind::Ancf2D) {
      s[0] = n.X0[0] + value(0);
      s[1] = n.X0[1] + value(1);
      s[2] = n.slope0[0] + value(2);
      s[3] = n.slope0[1] + value(3);
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      disp_[3 * i + k] = value(k);
      s[k] = n.X0[k] + disp_[3 * i + k];
    }
    if (n.kind != NodeKind::Frame6) continue;
    Mat3 R;
    if (n.rotationPrescribed && tf && tf->rotAngle) {
      // rot = angle(t) e about a fixed axis e: R = exp(angle e) R0, spatial angular velocity angle' e
      const Expression::TimeJet j = tf->rotAngle->timeJet(ls.time);
      const double angle = shiftedMotion ? tf->rotAngle->timeJet(ls.motionTime).f : j.f;
      R = expSO3(lam * angle * tf->rotAxis) * expSO3(lam0 * n.rotInitial);
      for (int k = 0; k < 3; ++k) {
        rate[3 + k] = lam * j.df * tf->rotAxis[k];
        rate[9 + k] = lam * j.ddf * tf->rotAxis[k];
      }
    } else if (n.rotationPrescribed) {
      R = expSO3(lam * n.rot) * expSO3(lam0 * n.rotInitial);  // rot_initial first, then the ramped rot
    } else {
      const Vec3 theta{u[n.dof[3]], u[n.dof[4]], u[n.dof[5]]};
      if (theta[0] != 0.0 || theta[1] != 0.0 || theta[2] != 0.0) {
        R = expSO3(theta) * Rref_[i];
        T_[i] = dexpSO3(theta);
        hasTheta_[i] = 1;
      } else {
        R = Rref_[i];
      }
    }
    for (int k = 0; k < 9; ++k) s[3 + k] = R[k];
  }
}

void Assembler::gatherElement(const LocalElement& el, double* q, const double* /*u*/, int* idx, int* fullIdx) const {
  const auto kinds = el.kernel->nodeKinds();
  int qs = 0, d = 0;
  for (size_t i = 0; i < kinds.size(); ++i) {
    const LocalNode& n = mesh_.nodes[el.node[i]];
    const double* s = &state_[12 * static_cast<size_t>(el.node[i])];
    for (int k = 0; k < stateSize(kinds[i]); ++k) q[qs++] = s[k];
    if (kinds[i] != NodeKind::Ancf2D && i < 4)
      for (int k = 0; k < 3; ++k) elemDisp_[3 * i + k] = disp_[3 * static_cast<size_t>(el.node[i]) + k];
    for (int k = 0; k < dofSize(kinds[i]); ++k, ++d) {
      idx[d] = n.dof[k];
      if (fullIdx) fullIdx[d] = n.fullDof[k];
    }
  }
  for (int j = 0; j < el.kernel->numConstraints(); ++j) idx[d + j] = el.firstMultiplier + j;
}

void Assembler::gatherStates(const LocalElement& el, const double* states, double* q) const {
  const auto kinds = el.kernel->nodeKinds();
  int qs = 0;
  for (size_t i = 0; i < kinds.size(); ++i) {
    const double* s = states + 12 * static_cast<size_t>(el.node[i]);
    for (int k = 0; k < stateSize(kinds[i]); ++k) q[qs++] = s[k];
  }
}

bool Assembler::hasMixedStressKernels() const {
  int any = 0;
  for (const LocalElement& el : mesh_.elements) any |= el.kernel->numMixedStresses() > 0;
  MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_LOR, mesh_.comm);
  return any != 0;
}

PetscErrorCode Assembler::setMixedReference(Vec U, const LoadState& ls) {
  PetscFunctionBeginUser;
  if (mixedNewton_) {
    PetscCall(updateStates(U, ls));
    keepMixedReference();
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

void Assembler::linearizeMixedStresses(const LocalElement& el, const double* q, std::array<double, 6>& sigma,
                                       KernelInput& in) const {
  if (!mixedNewton_ || el.kernel->numMixedStresses() == 0) return;
  std::array<double, 48> q0;
  if (mixedRefValid_) gatherStates(el, mixedRef_.data(), q0.data());
  el.kernel->linearizedStresses(mixedRefValid_ ? q0.data() : nullptr, q, sigma.data());
  in.sigmaMixed = sigma.data();
}

void Assembler::rotationColumns(const LocalElement& el, int n, double* K) const {
  const auto kinds = el.kernel->nodeKinds();
  int c0 = 0;
  for (size_t i = 0; i < kinds.size(); ++i) {
    if (kinds[i] == NodeKind::Frame6 && hasTheta_[el.node[i]]) {
      const Mat3& T = T_[el.node[i]];
      for (int r = 0; r < n; ++r) {
        double* row = K + static_cast<size_t>(r) * n + c0 + 3;
        const double a = row[0], b = row[1], c = row[2];
        for (int j = 0; j < 3; ++j) row[j] = a * T[j] + b * T[3 + j] + c * T[6 + j];
      }
    }
    c0 += dofSize(kinds[i]);
  }
}

void Assembler::evaluateElement(const LocalElement& el, const KernelInput& in, const KernelNeeds& needs) {
  try {
    if (stepForces_.h > 0 && el.kernel->hasStepForce()) {  // energy-momentum: the step's force from the kept start
      std::array<double, 48> q0;
      std::array<double, 12> disp0{};
      gatherStates(el, startState_.data(), q0.data());
      const auto kinds = el.kernel->nodeKinds();
      for (size_t i = 0; i < kinds.size() && i < 4; ++i)
        if (kinds[i] != NodeKind::Ancf2D)
          for (int k = 0; k < 3; ++k) disp0[3 * i + k] = startDisp_[3 * static_cast<size_t>(el.node[i]) + k];
      StepForceInput s;
      s.q0 = q0.data();
      s.q1 = in.q;
      s.disp0 = disp0.data();
      s.disp1 = in.disp;
      s.lambda = in.lambda;
      s.h = stepForces_.h;
      s.decay = stepForces_.decay;
      el.kernel->stepForce(s, needs.tangent, out_);
      return;
    }
    el.kernel->evaluate(in, needs, out_);
  } catch (const ElementValueError& ex) {
    if (elementValueError_.empty()) {
      elementValueError_ = "error: " + ex.law() + (el.set >= 0 ? " of " + epropsName(el.set) : std::string()) +
                           " returned " + ex.returned() + ", which is not finite, at element " + std::to_string(el.sceneElement + 1);
      if (el.numSub > 1)
        elementValueError_ += " (part " + std::to_string(el.subIndex + 1) + " of " + std::to_string(el.numSub) + ")";
      elementValueError_ += ", " + ex.where();
      elementValueErrorAt_ = el.feIndex;
    }
    // zeros of the right sizes: the assembly completes on this rank, agreeElementValues ends it
    const size_t n = static_cast<size_t>(el.kernel->numDofs() + el.kernel->numConstraints());
    const size_t nd = static_cast<size_t>(el.kernel->numDofs());
    out_.f.assign(n, 0.0);
    if (needs.tangent) out_.K.assign(n * n, 0.0);
    if (needs.splitGeometric) out_.Kg.assign(n * n, 0.0);
    if (needs.damping) out_.D.assign(nd * nd, 0.0);
  }
}

PetscErrorCode Assembler::agreeElementValues() {
  PetscFunctionBeginUser;
  if (elementValueErrorKnown_) {  // a residual assembly reduced it already
    elementValueErrorKnown_ = false;
    if (!anyElementValueError_) PetscFunctionReturn(PETSC_SUCCESS);
  }
  RunFailure local;
  if (!elementValueError_.empty()) local = {3, elementValueError_};
  elementValueError_.clear();
  const long at = elementValueErrorAt_;
  elementValueErrorAt_ = -1;
  if (RunFailure f = agreeOnFailure(mesh_.comm, local, at)) {
    if (!nonFiniteLawsFatal_) {
      if (nonFiniteLaw_.empty()) nonFiniteLaw_ = f.message;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    f.message += "; the analysis cannot continue (every user function must give finite values over the states the "
                 "solver visits)";
    return raiseCollective(mesh_.comm, f);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::updateStates(Vec U, const LoadState& ls) {
  PetscFunctionBeginUser;
  const double* u = nullptr;
  PetscCall(beginLocal(U, ls, &u));
  PetscCall(endLocal(&u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::beginLocal(Vec U, const LoadState& ls, const double** u) {
  PetscFunctionBeginUser;
  PetscCall(loadLocal(U, uWork_));
  Vec ul;
  PetscCall(VecGhostGetLocalForm(uWork_, &ul));
  PetscCall(VecGetArrayRead(ul, u));
  PetscCall(VecGhostRestoreLocalForm(uWork_, &ul));  // the array stays valid until endLocal
  computeStates(*u, ls);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::endLocal(const double** u) {
  PetscFunctionBeginUser;
  Vec ul;
  PetscCall(VecGhostGetLocalForm(uWork_, &ul));
  PetscCall(VecRestoreArrayRead(ul, u));
  PetscCall(VecGhostRestoreLocalForm(uWork_, &ul));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::elementStress(Vec U, const LoadState& ls, std::vector<double>& stress) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().stress, 0, 0, 0, 0));
  ++counters_.stressRecoveries;
  const double* u = nullptr;
  PetscCall(beginLocal(U, ls, &u));
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  stress.resize(mesh_.elements.size());
  for (size_t e = 0; e < mesh_.elements.size(); ++e) {
    const LocalElement& el = mesh_.elements[e];
    gatherElement(el, q.data(), u, idx.data(), nullptr);
    stress[e] = el.kernel->vonMisesMax(q.data(), el.firstMultiplier >= 0 ? u + el.firstMultiplier : nullptr);
  }
  PetscCall(endLocal(&u));
  PetscCall(PetscLogEventEnd(SinewEvents::get().stress, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::absorbRotations(Vec U) {
  PetscFunctionBeginUser;
  if (!mesh_.anyRotations) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(loadLocal(U, uWork_));
  Vec ul;
  const PetscScalar* u;
  PetscCall(VecGhostGetLocalForm(uWork_, &ul));
  PetscCall(VecGetArrayRead(ul, &u));
  for (size_t i = 0; i < mesh_.nodes.size(); ++i) {
    const LocalNode& n = mesh_.nodes[i];
    if (n.kind != NodeKind::Frame6 || n.rotationPrescribed) continue;
    const Vec3 theta{u[n.dof[3]], u[n.dof[4]], u[n.dof[5]]};
    Rref_[i] = expSO3(theta) * Rref_[i];
  }
  PetscCall(VecRestoreArrayRead(ul, &u));
  PetscCall(VecGhostRestoreLocalForm(uWork_, &ul));
  PetscScalar* uo;
  PetscCall(VecGetArray(U, &uo));
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    if (n.kind != NodeKind::Frame6 || n.rotationPrescribed) continue;
    for (int k = 3; k < 6; ++k) uo[n.dof[k]] = 0.0;
  }
  PetscCall(VecRestoreArray(U, &uo));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
