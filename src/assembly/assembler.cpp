#include "assembly/assembler.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "sinew/rotation.hpp"
#include "mesh/collective_error.hpp"

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

// Nonzeros per owned row, once per assembler: through the local elements, every local node couples
// with its neighbour nodes (all their free DOFs) and the multipliers of its elements; multiplier
// rows with their element's DOFs and multipliers. Counts of ghost rows are added to their owners,
// so rows on partition interfaces may be counted a little high (never low).
PetscErrorCode Assembler::preallocationCounts() const {
  PetscFunctionBeginUser;
  if (countsReady_) PetscFunctionReturn(PETSC_SUCCESS);
  const int nl = mesh_.numLocalUnknowns(), nown = mesh_.numOwnedUnknowns;
  std::vector<long> first(static_cast<size_t>(mesh_.size) + 1, 0);
  MPI_Allgather(&mesh_.firstOwnedUnknown, 1, MPI_LONG, first.data(), 1, MPI_LONG, mesh_.comm);
  first[static_cast<size_t>(mesh_.size)] = mesh_.numGlobalUnknowns;
  const size_t nn = mesh_.nodes.size();
  std::vector<std::vector<int>> nbr(nn), mult(nn);
  for (size_t a = 0; a < nn; ++a) nbr[a].push_back(static_cast<int>(a));
  for (const LocalElement& el : mesh_.elements) {
    const int nc = el.kernel->numConstraints();
    for (int i = 0; i < el.numNodes; ++i) {
      for (int j = 0; j < el.numNodes; ++j) nbr[el.node[i]].push_back(el.node[j]);
      for (int c = 0; c < nc; ++c) mult[el.node[i]].push_back(el.firstMultiplier + c);
    }
  }
  std::vector<double> dc(nl, 0.0), oc(nl, 0.0);
  auto count = [&](int row, const std::vector<int>& cols) {
    const long g = mesh_.localToGlobalUnknown(row);
    const size_t o = static_cast<size_t>(std::upper_bound(first.begin(), first.end(), g) - first.begin()) - 1;
    for (int c : cols) {
      const long gc = mesh_.localToGlobalUnknown(c);
      (gc >= first[o] && gc < first[o + 1] ? dc : oc)[row] += 1.0;
    }
  };
  std::vector<int> cols;
  for (size_t a = 0; a < nn; ++a) {
    auto& nb = nbr[a];
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
    cols.clear();
    for (int b : nb)
      for (int k = 0; k < mesh_.nodes[b].ndof; ++k)
        if (mesh_.nodes[b].dof[k] >= 0) cols.push_back(mesh_.nodes[b].dof[k]);
    std::sort(mult[a].begin(), mult[a].end());
    mult[a].erase(std::unique(mult[a].begin(), mult[a].end()), mult[a].end());
    cols.insert(cols.end(), mult[a].begin(), mult[a].end());
    const LocalNode& n = mesh_.nodes[a];
    for (int k = 0; k < n.ndof; ++k)
      if (n.dof[k] >= 0) count(n.dof[k], cols);
  }
  for (const LocalElement& el : mesh_.elements) {
    const int nc = el.kernel->numConstraints();
    if (nc == 0) continue;
    cols.clear();
    for (int i = 0; i < el.numNodes; ++i) {
      const LocalNode& n = mesh_.nodes[el.node[i]];
      for (int k = 0; k < n.ndof; ++k)
        if (n.dof[k] >= 0) cols.push_back(n.dof[k]);
    }
    for (int c = 0; c < nc; ++c) cols.push_back(el.firstMultiplier + c);
    for (int c = 0; c < nc; ++c) count(el.firstMultiplier + c, cols);
  }
  Vec D, O;
  PetscCall(createVector(&D));
  PetscCall(VecDuplicate(D, &O));
  for (auto [v, src] : {std::pair<Vec, std::vector<double>*>{D, &dc}, {O, &oc}}) {
    Vec loc;
    PetscScalar* x;
    PetscCall(VecGhostGetLocalForm(v, &loc));
    PetscCall(VecGetArray(loc, &x));
    std::copy(src->begin(), src->end(), x);
    PetscCall(VecRestoreArray(loc, &x));
    PetscCall(VecGhostRestoreLocalForm(v, &loc));
    PetscCall(ghostUpdate(v, ADD_VALUES, SCATTER_REVERSE));
  }
  const PetscScalar *d, *o;
  PetscCall(VecGetArrayRead(D, &d));
  PetscCall(VecGetArrayRead(O, &o));
  dnnz_.resize(nown);
  onnz_.resize(nown);
  const long offMax = mesh_.numGlobalUnknowns - nown;
  for (int i = 0; i < nown; ++i) {
    dnnz_[i] = static_cast<PetscInt>(std::min<double>(std::max(d[i], 1.0), nown));
    onnz_[i] = static_cast<PetscInt>(std::min<double>(o[i], static_cast<double>(offMax)));
  }
  PetscCall(VecRestoreArrayRead(D, &d));
  PetscCall(VecRestoreArrayRead(O, &o));
  PetscCall(VecDestroy(&D));
  PetscCall(VecDestroy(&O));
  countsReady_ = true;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The structure is every element block plus the diagonal of every unknown, inserted as zeros and
// assembled, so that later assemblies, shifts and diagonal updates never allocate.
PetscErrorCode Assembler::createMatrix(Mat* A) const {
  PetscFunctionBeginUser;
  const PetscInt nloc = mesh_.numOwnedUnknowns, N = static_cast<PetscInt>(mesh_.numGlobalUnknowns);
  PetscCall(preallocationCounts());
  PetscCall(MatCreate(mesh_.comm, A));
  PetscCall(MatSetSizes(*A, nloc, nloc, N, N));
  PetscCall(MatSetType(*A, MATAIJ));
  PetscCall(MatXAIJSetPreallocation(*A, 1, dnnz_.data(), onnz_.data(), nullptr, nullptr));
  PetscCall(MatSetLocalToGlobalMapping(*A, l2g_, l2g_));
  PetscCall(MatSetOption(*A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  std::array<PetscInt, kMaxElementRows> idx;
  std::array<PetscScalar, kMaxElementRows * kMaxElementRows> zeros{};
  for (const LocalElement& el : mesh_.elements) {
    int n = 0;
    const auto kinds = el.kernel->nodeKinds();
    for (size_t i = 0; i < kinds.size(); ++i)
      for (int k = 0; k < dofSize(kinds[i]); ++k) idx[n++] = mesh_.nodes[el.node[i]].dof[k];
    for (int j = 0; j < el.kernel->numConstraints(); ++j) idx[n++] = el.firstMultiplier + j;
    PetscCall(MatSetValuesLocal(*A, n, idx.data(), n, idx.data(), zeros.data(), INSERT_VALUES));
  }
  // node-level blocks (nodal inertia) lie inside element blocks; the diagonal of every unknown too
  for (PetscInt i = 0; i < nloc; ++i) PetscCall(MatSetValuesLocal(*A, 1, &i, 1, &i, zeros.data(), INSERT_VALUES));
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  // every assembly sends the same off-process entries: PETSc reuses the communication pattern
  PetscCall(MatSetOption(*A, MAT_SUBSET_OFF_PROC_ENTRIES, PETSC_TRUE));
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
            return lam * j.f + lam0 * n.prescribedInitial[k];
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
      R = expSO3(lam * j.f * tf->rotAxis) * expSO3(lam0 * n.rotInitial);
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

void Assembler::evaluateElement(const LocalElement& el, const KernelInput& in, const KernelNeeds& needs) {
  try {
    el.kernel->evaluate(in, needs, out_);
  } catch (const ElementValueError& ex) {
    if (elementValueError_.empty()) {
      elementValueError_ = "error: " + ex.law() + (el.set >= 0 ? " of eprops[" + std::to_string(el.set) + "]" : std::string()) +
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
  PetscCall(loadLocal(U, uWork_));
  Vec ul;
  const PetscScalar* u;
  PetscCall(VecGhostGetLocalForm(uWork_, &ul));
  PetscCall(VecGetArrayRead(ul, &u));
  computeStates(u, ls);
  PetscCall(VecRestoreArrayRead(ul, &u));
  PetscCall(VecGhostRestoreLocalForm(uWork_, &ul));
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

PetscErrorCode Assembler::forceVector(Vec U, const LoadState& ls, Vec work, Vec out,
                                      const std::function<PetscErrorCode(const double* u, double* f)>& add) {
  PetscFunctionBeginUser;
  PetscCall(loadLocal(U, uWork_));
  Vec ul, fl;
  const PetscScalar* u;
  PetscScalar* f;
  PetscCall(VecGhostGetLocalForm(uWork_, &ul));
  PetscCall(VecGhostGetLocalForm(work, &fl));
  PetscCall(VecGetArrayRead(ul, &u));
  PetscCall(VecSet(fl, 0.0));
  PetscCall(VecGetArray(fl, &f));
  computeStates(u, ls);
  const PetscErrorCode ierr = add(u, f);
  PetscCall(VecRestoreArray(fl, &f));
  PetscCall(VecRestoreArrayRead(ul, &u));
  PetscCall(VecGhostRestoreLocalForm(work, &fl));
  PetscCall(VecGhostRestoreLocalForm(uWork_, &ul));
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
    const PetscErrorCode e = assembleForces(u, ls, Target::Full, f);
    aLocal_ = nullptr;
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

PetscErrorCode Assembler::jacobian(Vec U, const LoadState& ls, Mat J) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().jacobian, 0, 0, 0, 0));
  ++counters_.jacobians;
  PetscCall(loadLocal(U, uWork_));
  Vec ul;
  const PetscScalar* u;
  PetscCall(VecGhostGetLocalForm(uWork_, &ul));
  PetscCall(VecGetArrayRead(ul, &u));
  computeStates(u, ls);
  const bool coo = J && cooApplies();
  if (coo) PetscCall(prepareCOO(J));
  else if (J) PetscCall(MatZeroEntries(J));
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  KernelNeeds needs;
  needs.tangent = true;
  PetscCall(PetscLogEventBegin(SinewEvents::get().jacobianElements, 0, 0, 0, 0));
  size_t offset = 0, kept = 0;
  if (keepBlocks_) torqueBlocks_.clear();
  if (keepBlocks_ && keepRigid_) {
    rigidInfo_.clear();
    rigidData_.clear();
  }
  std::array<double, 6> sigmaMixed;
  for (const LocalElement& el : mesh_.elements) {
    gatherElement(el, q.data(), u, idx.data(), nullptr);
    KernelInput in{q.data(), nullptr, el.firstMultiplier >= 0 ? u + el.firstMultiplier : nullptr, ls.time};
    in.disp = elemDisp_.data();
    linearizeMixedStresses(el, q.data(), sigmaMixed, in);
    evaluateElement(el, in, needs);
    const int n = el.kernel->numDofs() + el.kernel->numConstraints();
    rotationColumns(el, n, out_.K.data());
    if (keepBlocks_) {
      if (blocks_.size() < kept + static_cast<size_t>(n) * n) blocks_.resize(kept + static_cast<size_t>(n) * n);
      std::copy(out_.K.begin(), out_.K.begin() + n * n, blocks_.begin() + static_cast<long>(kept));
      kept += static_cast<size_t>(n) * n;
      if (keepRigid_) keepRigid(el, q.data(), out_.f.data(), out_.K.data(), n);
    }
    if (coo) {
      std::copy(out_.K.begin(), out_.K.begin() + n * n, cooValues_.begin() + static_cast<long>(offset));
      offset += static_cast<size_t>(n) * n;
    } else if (J) {
      PetscCall(MatSetValuesLocal(J, n, idx.data(), n, idx.data(), out_.K.data(), ADD_VALUES));
    }
  }
  PetscCall(PetscLogEventEnd(SinewEvents::get().jacobianElements, 0, 0, 0, 0));
  if (mixedNewton_) keepMixedReference();  // the next Newton iterate linearizes its stresses about this state
  if (coo) {  // the matrix is assembled by MatSetValuesCOO (repeated entries are summed)
    PetscCall(MatSetValuesCOO(J, cooValues_.data(), INSERT_VALUES));
  } else {
    PetscCall(addSlopeTorqueTangent(ls, J));
    if (J) PetscCall(addLoadTangents(ls, J));
  }
  PetscCall(VecRestoreArrayRead(ul, &u));
  PetscCall(VecGhostRestoreLocalForm(uWork_, &ul));
  if (J && !coo) {
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscCall(PetscLogEventEnd(SinewEvents::get().jacobian, 0, 0, 0, 0));
  PetscCall(agreeElementValues());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// COO assembly needs the tangent to be exactly the element blocks: no node-level or load tangents.
bool Assembler::cooApplies() const { return cooAssembly_; }

PetscErrorCode Assembler::prepareCOO(Mat J) {
  PetscFunctionBeginUser;
  // a marker composed with the matrix: it dies with the matrix (a later matrix may reuse the address)
  PetscObject marker = nullptr;
  PetscCall(PetscObjectQuery(reinterpret_cast<PetscObject>(J), "SinewCOO", &marker));
  if (marker) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(SinewEvents::get().cooSetup, 0, 0, 0, 0));
  std::vector<PetscInt> ci, cj;
  std::array<int, kMaxElementRows> idx;
  std::array<double, 48> q;
  for (const LocalElement& el : mesh_.elements) {
    gatherElement(el, q.data(), nullptr, idx.data(), nullptr);
    const int n = el.kernel->numDofs() + el.kernel->numConstraints();
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        ci.push_back(idx[r] >= 0 ? static_cast<PetscInt>(mesh_.localToGlobalUnknown(idx[r])) : -1);
        cj.push_back(idx[c] >= 0 ? static_cast<PetscInt>(mesh_.localToGlobalUnknown(idx[c])) : -1);
      }
  }
  cooValues_.assign(ci.size(), 0.0);
  PetscCall(MatSetPreallocationCOO(J, static_cast<PetscCount>(ci.size()), ci.data(), cj.data()));
  PetscContainer tag;
  PetscCall(PetscContainerCreate(mesh_.comm, &tag));
  PetscCall(PetscObjectCompose(reinterpret_cast<PetscObject>(J), "SinewCOO", reinterpret_cast<PetscObject>(tag)));
  PetscCall(PetscContainerDestroy(&tag));
  PetscCall(PetscLogEventEnd(SinewEvents::get().cooSetup, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// tangent of a slope torque on ANCF node i (node state current): d/ds of -tau (-s_y, s_x)/|s|^2;
// false (K untouched) without a torque
bool Assembler::slopeTorqueBlock(int i, const LoadState& ls, double* K) const {
  const LocalNode& n = mesh_.nodes[i];
  if (n.kind != NodeKind::Ancf2D) return false;
  const double tau = ls.initialFactor * n.loadInitial[4] + ls.loadFactor * n.load[4];
  if (tau == 0.0) return false;
  const double* s = &state_[12 * static_cast<size_t>(i)];
  const double sx = s[2], sy = s[3], s2 = sx * sx + sy * sy, s4 = s2 * s2;
  // r = -tau * (-sy, sx) / s2
  K[0] = -tau * (2 * sx * sy / s4);
  K[1] = -tau * (-1 / s2 + 2 * sy * sy / s4);
  K[2] = -tau * (1 / s2 - 2 * sx * sx / s4);
  K[3] = -tau * (-2 * sx * sy / s4);
  return true;
}

// tangent of slope torques on ANCF nodes (slopeTorqueBlock); J = nullptr: only kept as blocks for applyTangent
PetscErrorCode Assembler::addSlopeTorqueTangent(const LoadState& ls, Mat J) {
  PetscFunctionBeginUser;
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    double K[4];
    if (!slopeTorqueBlock(i, ls, K)) continue;
    const PetscInt rows[2] = {n.dof[2], n.dof[3]};
    if (J) PetscCall(MatSetValuesLocal(J, 2, rows, 2, rows, K, ADD_VALUES));
    if (keepBlocks_) torqueBlocks_.push_back({i, {K[0], K[1], K[2], K[3]}});
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::splitTangent(Vec U, const LoadState& ls, Mat Km, Mat Kg) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().splitTangent, 0, 0, 0, 0));
  ++counters_.splitTangents;
  PetscCall(loadLocal(U, uWork_));
  Vec ul;
  const PetscScalar* u;
  PetscCall(VecGhostGetLocalForm(uWork_, &ul));
  PetscCall(VecGetArrayRead(ul, &u));
  computeStates(u, ls);
  PetscCall(MatZeroEntries(Km));
  PetscCall(MatZeroEntries(Kg));
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  KernelNeeds needs;
  needs.tangent = true;
  needs.splitGeometric = true;
  for (const LocalElement& el : mesh_.elements) {
    gatherElement(el, q.data(), u, idx.data(), nullptr);
    KernelInput in{q.data(), nullptr, el.firstMultiplier >= 0 ? u + el.firstMultiplier : nullptr, ls.time};
    in.disp = elemDisp_.data();
    evaluateElement(el, in, needs);
    const int n = el.kernel->numDofs() + el.kernel->numConstraints();
    rotationColumns(el, n, out_.K.data());
    rotationColumns(el, n, out_.Kg.data());
    PetscCall(MatSetValuesLocal(Km, n, idx.data(), n, idx.data(), out_.K.data(), ADD_VALUES));
    PetscCall(MatSetValuesLocal(Kg, n, idx.data(), n, idx.data(), out_.Kg.data(), ADD_VALUES));
  }
  PetscCall(VecRestoreArrayRead(ul, &u));
  PetscCall(VecGhostRestoreLocalForm(uWork_, &ul));
  for (Mat A : {Km, Kg}) {
    PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  }
  PetscCall(PetscLogEventEnd(SinewEvents::get().splitTangent, 0, 0, 0, 0));
  PetscCall(agreeElementValues());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::mass(Vec U, const LoadState& ls, Mat M) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().mass, 0, 0, 0, 0));
  ++counters_.masses;
  PetscCall(updateStates(U, ls));
  PetscCall(MatZeroEntries(M));
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  std::vector<double> Me;
  for (const LocalElement& el : mesh_.elements) {
    if (!el.kernel->hasInertia()) continue;
    gatherElement(el, q.data(), nullptr, idx.data(), nullptr);
    el.kernel->mass(q.data(), Me);
    const int n = el.kernel->numDofs();
    PetscCall(MatSetValuesLocal(M, n, idx.data(), n, idx.data(), Me.data(), ADD_VALUES));
  }
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    if (n.mass > 0) {
      const int nt = n.kind == NodeKind::Ancf2D ? 2 : 3;
      for (int k = 0; k < nt; ++k) {
        const PetscInt r = n.dof[k];
        PetscCall(MatSetValuesLocal(M, 1, &r, 1, &r, &n.mass, ADD_VALUES));
      }
    }
    if (n.kind == NodeKind::Frame6) {
      const Mat3 J = spatialInertia(i);
      const PetscInt rows[3] = {n.dof[3], n.dof[4], n.dof[5]};
      PetscCall(MatSetValuesLocal(M, 3, rows, 3, rows, J.data(), ADD_VALUES));
    }
  }
  PetscCall(MatAssemblyBegin(M, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(M, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscLogEventEnd(SinewEvents::get().mass, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::elementStress(Vec U, const LoadState& ls, std::vector<double>& stress) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().stress, 0, 0, 0, 0));
  ++counters_.stressRecoveries;
  PetscCall(loadLocal(U, uWork_));
  Vec ul;
  const PetscScalar* u;
  PetscCall(VecGhostGetLocalForm(uWork_, &ul));
  PetscCall(VecGetArrayRead(ul, &u));
  computeStates(u, ls);
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  stress.resize(mesh_.elements.size());
  for (size_t e = 0; e < mesh_.elements.size(); ++e) {
    const LocalElement& el = mesh_.elements[e];
    gatherElement(el, q.data(), u, idx.data(), nullptr);
    stress[e] = el.kernel->vonMisesMax(q.data(), el.firstMultiplier >= 0 ? u + el.firstMultiplier : nullptr);
  }
  PetscCall(VecRestoreArrayRead(ul, &u));
  PetscCall(VecGhostRestoreLocalForm(uWork_, &ul));
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
