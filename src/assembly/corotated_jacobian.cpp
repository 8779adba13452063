// Corotated Newton matrix of ANCF cables (see Assembler::corotatedJacobian).
//
// A Jacobian kept across Newton iterations and time steps goes stale on a fine cable as its elements
// turn: an element's bending stiffness EI/l^3 exceeds its axial stiffness EA/l by EI/(EA l^2) (9e5 for
// A1 at 65536 elements), and a rotation by d theta moves the bending stiffness into the element's
// former axial direction; from d theta ~ EA l^2/EI (1e-6 rad there) the kept matrix no longer
// contracts Newton (docs/performance.md, "Why 65536 elements still cost more per element"). The
// element blocks themselves are objective, B(Q q) = Q B(q) Q^T, so the kept blocks rotated by each
// element's own rotation are the current Newton matrix up to the elements' deformation since they
// were kept. Rotating per node instead breaks the blocks' translation invariance (neighbouring
// nodes turn by different angles) and is worse than not rotating at all on coarser cables.
#include <cmath>

#include "assembly/assembler.hpp"

namespace sinew {

namespace {

/// Angle of an ANCF cable element's mean slope (s1 + s2) from its state (x1, y1, sx1, sy1, x2, ...).
double elementAngle(const double* q) { return std::atan2(q[3] + q[7], q[2] + q[6]); }

bool corotatable(const LocalElement& el) {
  const auto kinds = el.kernel->nodeKinds();
  return kinds.size() == 2 && kinds[0] == NodeKind::Ancf2D && kinds[1] == NodeKind::Ancf2D &&
         el.kernel->numDofs() == 8 && el.kernel->numConstraints() == 0;
}

}  // namespace

void Assembler::keepCorotated(size_t e, const LocalElement& el, const double* q, const double* K) {
  if (!corotatable(el)) {
    corotatedValid_ = false;
    return;
  }
  std::copy(K, K + 64, corotatedBlocks_.begin() + static_cast<long>(64 * e));
  corotatedAngle_[e] = elementAngle(q);
}

PetscErrorCode Assembler::corotatedJacobian(Vec U, const LoadState& ls, Mat J) {
  PetscFunctionBeginUser;
  if (!corotatedValid_) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ORDER, "corotatedJacobian: no kept ANCF blocks");
  PetscCall(PetscLogEventBegin(SinewEvents::get().corotatedJacobian, 0, 0, 0, 0));
  PetscCall(loadLocal(U, uWork_));
  Vec ul;
  const PetscScalar* u;
  PetscCall(VecGhostGetLocalForm(uWork_, &ul));
  PetscCall(VecGetArrayRead(ul, &u));
  computeStates(u, ls);
  PetscCall(MatZeroEntries(J));
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  double T[64], K[64];
  for (size_t e = 0; e < mesh_.elements.size(); ++e) {
    const LocalElement& el = mesh_.elements[e];
    gatherElement(el, q.data(), u, idx.data(), nullptr);
    const double d = elementAngle(q.data()) - corotatedAngle_[e];
    const double c = std::cos(d), s = std::sin(d);
    const double* B = corotatedBlocks_.data() + 64 * e;
    // T = Q B (each row pair (2a, 2a + 1) rotated), K = T Q^T (each column pair rotated)
    for (int a = 0; a < 8; a += 2)
      for (int b = 0; b < 8; ++b) {
        T[8 * a + b] = c * B[8 * a + b] - s * B[8 * (a + 1) + b];
        T[8 * (a + 1) + b] = s * B[8 * a + b] + c * B[8 * (a + 1) + b];
      }
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; b += 2) {
        K[8 * a + b] = c * T[8 * a + b] - s * T[8 * a + b + 1];
        K[8 * a + b + 1] = s * T[8 * a + b] + c * T[8 * a + b + 1];
      }
    PetscCall(MatSetValuesLocal(J, 8, idx.data(), 8, idx.data(), K, ADD_VALUES));
  }
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {  // nodal masses, as dynamicJacobian
    const LocalNode& n = mesh_.nodes[i];
    if (n.mass <= 0 || corotatedShiftA_ == 0.0) continue;
    const double m = corotatedShiftA_ * n.mass;
    for (int k = 0; k < 2; ++k) {
      const PetscInt r = n.dof[k];
      PetscCall(MatSetValuesLocal(J, 1, &r, 1, &r, &m, ADD_VALUES));
    }
  }
  PetscCall(addSlopeTorqueTangent(ls, J));
  PetscCall(VecRestoreArrayRead(ul, &u));
  PetscCall(VecGhostRestoreLocalForm(uWork_, &ul));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscLogEventEnd(SinewEvents::get().corotatedJacobian, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
