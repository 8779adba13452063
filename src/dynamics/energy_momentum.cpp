#include "dynamics/energy_momentum.hpp"

#include <set>

#include "parallel/collective_error.hpp"

namespace sinew {

EnergyMomentum::EnergyMomentum(Assembler& assembler) : asm_(assembler) {
  MPI_Comm comm = asm_.mesh().comm;
  SinewCallThrow(comm, asm_.createMatrix(&M_));
  SinewCallThrow(comm, asm_.createVector(&f_));
  SinewCallThrow(comm, VecDuplicate(f_, &pi_));
}

EnergyMomentum::~EnergyMomentum() {
  MatDestroy(&M_);
  VecDestroy(&f_);
  VecDestroy(&pi_);
}

PetscErrorCode EnergyMomentum::evaluate(Vec U, Vec V, const LoadState& ls, EnergyMomentumRow* row, bool* ok,
                                        std::string* missing) {
  PetscFunctionBeginUser;
  const DistributedMesh& mesh = asm_.mesh();
  PetscCall(asm_.kineticEnergy(U, V, ls, &row->kinetic));
  // strain energy: the kernels' own (their internal force is its gradient)
  const double* u = nullptr;
  PetscCall(asm_.beginLocal(U, ls, &u));
  std::array<double, 48> q{};
  std::array<int, 48> idx{};
  double s = 0.0;
  std::set<std::string> kinds;
  for (const LocalElement& el : mesh.elements) {
    asm_.gather(el, q.data(), idx.data());
    double e = 0.0;
    if (el.kernel->strainEnergy(q.data(), &e)) s += e;
    else kinds.insert(el.kernel->name());
  }
  // momentum pi = M V and the node positions (states of U)
  PetscCall(asm_.mass(U, ls, M_));
  PetscCall(MatMult(M_, V, pi_));
  const PetscScalar* pi = nullptr;
  PetscCall(VecGetArrayRead(pi_, &pi));
  double m[7] = {s, 0, 0, 0, 0, 0, 0};  // strain, p, H
  for (int i = 0; i < mesh.numOwnedNodes; ++i) {
    const LocalNode& n = mesh.nodes[i];
    if (n.kind == NodeKind::Ancf2D) {
      // x, y and the slope coordinates: the translation part is the first two; a rotation turns
      // positions and slopes alike (the cable's int rhoA r x v dx = sum over both pairs of q x pi)
      const double* x = asm_.nodeState(i);
      double pc[4];
      for (int k = 0; k < 4; ++k) pc[k] = n.dof[k] >= 0 ? pi[n.dof[k]] : 0.0;
      m[1] += pc[0];
      m[2] += pc[1];
      m[6] += x[0] * pc[1] - x[1] * pc[0] + x[2] * pc[3] - x[3] * pc[2];
      continue;
    }
    const double* x = asm_.nodeState(i);
    Vec3 pt{}, pr{};
    for (int k = 0; k < 3; ++k) pt[k] = n.dof[k] >= 0 ? pi[n.dof[k]] : 0.0;
    if (n.kind == NodeKind::Frame6)
      for (int k = 0; k < 3; ++k) pr[k] = n.dof[3 + k] >= 0 ? pi[n.dof[3 + k]] : 0.0;
    const Vec3 H = cross(Vec3{x[0], x[1], x[2]}, pt) + pr;
    for (int k = 0; k < 3; ++k) {
      m[1 + k] += pt[k];
      m[4 + k] += H[k];
    }
  }
  PetscCall(VecRestoreArrayRead(pi_, &pi));
  PetscCall(asm_.endLocal(&u));
  MPI_Allreduce(MPI_IN_PLACE, m, 7, MPI_DOUBLE, MPI_SUM, mesh.comm);
  row->strain = m[0];
  row->linear = {m[1], m[2], m[3]};
  row->angular = {m[4], m[5], m[6]};
  // element kinds without strain energy, agreed on every rank
  std::string local;
  for (const auto& k : kinds) local += (local.empty() ? "" : ", ") + k;
  // the longest local list stands for all (the kinds are few): agreeOnFailure picks the lowest key
  const long key = local.empty() ? -1 : (1L << 30) - static_cast<long>(local.size());
  const RunFailure agreed = agreeOnFailure(mesh.comm, RunFailure{local.empty() ? 0 : 1, local}, key);
  *ok = !agreed;
  if (agreed) *missing = agreed.message;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode EnergyMomentum::externalPower(Vec U, Vec V, const LoadState& ls, double* power) {
  PetscFunctionBeginUser;
  const DistributedMesh& mesh = asm_.mesh();
  // f_int: the elements' internal forces alone (owned and ghost rows, summed onto the owners)
  const double* u = nullptr;
  PetscCall(asm_.beginLocal(U, ls, &u));
  Vec fl;
  PetscScalar* f = nullptr;
  PetscCall(VecGhostGetLocalForm(f_, &fl));
  PetscCall(VecSet(fl, 0.0));  // owned and ghost entries
  PetscCall(VecGetArray(fl, &f));
  std::array<double, 48> q{};
  std::array<int, 48> idx{};
  KernelOutput out;
  const KernelNeeds needs;
  for (const LocalElement& el : mesh.elements) {
    asm_.gather(el, q.data(), idx.data());
    KernelInput in{q.data(), nullptr, el.firstMultiplier >= 0 ? u + el.firstMultiplier : nullptr, ls.time};
    el.kernel->evaluate(in, needs, out);
    for (int k = 0; k < el.kernel->numDofs(); ++k)
      if (idx[k] >= 0) f[idx[k]] += out.f[k];
  }
  PetscCall(VecRestoreArray(fl, &f));
  PetscCall(VecGhostRestoreLocalForm(f_, &fl));
  PetscCall(asm_.endLocal(&u));
  PetscCall(VecGhostUpdateBegin(f_, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecGhostUpdateEnd(f_, ADD_VALUES, SCATTER_REVERSE));
  // f_ext = f_int - (f_int - f_ext): the residual of the same state
  PetscCall(asm_.residual(U, ls, pi_));
  PetscCall(VecAXPY(f_, -1.0, pi_));
  PetscCall(VecDot(f_, V, power));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
