#include "analysis/stiffness_spread.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace sinew {
namespace {

/// Largest and smallest positive diagonal entry of K over the element's translational DOFs (the first 3
/// of a Point3 or Frame6 node, x and y of an ANCF node): stiffnesses in force per length whatever the
/// kind (a beam's EA/L and 12 EI/L^3).
std::pair<double, double> translationalStiffness(const ElementKernel& kernel, const std::vector<double>& K) {
  const int n = kernel.numDofs() + kernel.numConstraints();
  double hi = 0.0, lo = 0.0;
  int first = 0;
  for (NodeKind kind : kernel.nodeKinds()) {
    const int translations = kind == NodeKind::Ancf2D ? 2 : 3;
    for (int k = 0; k < translations; ++k) {
      const double d = std::abs(K[static_cast<size_t>((first + k) * n + first + k)]);
      if (!(d > 0.0) || !std::isfinite(d)) continue;
      hi = std::max(hi, d);
      lo = lo > 0.0 ? std::min(lo, d) : d;
    }
    first += dofSize(kind);
  }
  return {hi, lo};
}

}  // namespace

PetscErrorCode stiffnessSpread(Assembler& assembler, Vec U, const LoadState& ls, StiffnessSpread* spread) {
  PetscFunctionBeginUser;
  *spread = StiffnessSpread{};
  const DistributedMesh& m = assembler.mesh();
  struct {
    double value;
    int element;
  } hi{0.0, -1}, lo{-INFINITY, -1};  // lo: the smallest positive stiffness, as -value for MAXLOC
  const double* u = nullptr;
  PetscCall(assembler.beginLocal(U, ls, &u));
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  KernelNeeds needs;
  needs.tangent = true;
  KernelOutput out;
  for (const LocalElement& el : m.elements) {
    assembler.gather(el, q.data(), idx.data());
    const KernelInput in{q.data(), nullptr, el.firstMultiplier >= 0 ? u + el.firstMultiplier : nullptr, ls.time};
    el.kernel->evaluate(in, needs, out);
    const auto [largest, smallest] = translationalStiffness(*el.kernel, out.K);
    if (largest > hi.value) hi = {largest, el.sceneElement};
    if (smallest > 0.0 && -smallest > lo.value) lo = {-smallest, el.sceneElement};
  }
  PetscCall(assembler.endLocal(&u));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPI_DOUBLE_INT, MPI_MAXLOC, m.comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPI_DOUBLE_INT, MPI_MAXLOC, m.comm));
  if (hi.element >= 0 && lo.element >= 0) *spread = StiffnessSpread{hi.value, -lo.value, hi.element, lo.element};
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
