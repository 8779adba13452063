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

PetscErrorCode Assembler::prepareCorotatedCOO(Mat J) {
  PetscFunctionBeginUser;
  // a marker composed with the matrix: it dies with the matrix (a later matrix may reuse the address)
  PetscObject marker = nullptr;
  PetscCall(PetscObjectQuery(reinterpret_cast<PetscObject>(J), "SinewCorotatedCOO", &marker));
  if (marker) PetscFunctionReturn(PETSC_SUCCESS);
  std::vector<PetscInt> ci, cj;
  auto global = [&](int local) { return local >= 0 ? static_cast<PetscInt>(mesh_.localToGlobalUnknown(local)) : -1; };
  std::array<int, kMaxElementRows> idx;
  std::array<double, 48> q;
  for (const LocalElement& el : mesh_.elements) {
    gatherElement(el, q.data(), nullptr, idx.data(), nullptr);
    for (int r = 0; r < 8; ++r)
      for (int c = 0; c < 8; ++c) {
        ci.push_back(global(idx[r]));
        cj.push_back(global(idx[c]));
      }
  }
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    for (int k = 0; k < 2; ++k) {  // nodal mass
      ci.push_back(global(n.dof[k]));
      cj.push_back(global(n.dof[k]));
    }
    for (int r = 2; r < 4; ++r)  // slope torque
      for (int c = 2; c < 4; ++c) {
        ci.push_back(global(n.dof[r]));
        cj.push_back(global(n.dof[c]));
      }
  }
  corotatedValues_.assign(ci.size(), 0.0);
  PetscCall(MatSetPreallocationCOO(J, static_cast<PetscCount>(ci.size()), ci.data(), cj.data()));
  PetscContainer tag;
  PetscCall(PetscContainerCreate(mesh_.comm, &tag));
  PetscCall(PetscObjectCompose(reinterpret_cast<PetscObject>(J), "SinewCorotatedCOO", reinterpret_cast<PetscObject>(tag)));
  PetscCall(PetscContainerDestroy(&tag));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::corotatedJacobian(Vec U, const LoadState& ls, Mat J) {
  PetscFunctionBeginUser;
  if (!corotatedValid_) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ORDER, "corotatedJacobian: no kept ANCF blocks");
  PetscCall(PetscLogEventBegin(SinewEvents::get().corotatedJacobian, 0, 0, 0, 0));
  PetscCall(prepareCorotatedCOO(J));
  const double* u = nullptr;
  PetscCall(beginLocal(U, ls, &u));
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  double T[64];
  PetscScalar* K = corotatedValues_.data();
  for (size_t e = 0; e < mesh_.elements.size(); ++e, K += 64) {
    gatherElement(mesh_.elements[e], q.data(), u, idx.data(), nullptr);
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
  }
  for (int i = 0; i < mesh_.numOwnedNodes; ++i, K += 6) {  // node terms, as dynamicJacobian
    const LocalNode& n = mesh_.nodes[i];
    K[0] = K[1] = n.mass > 0 ? corotatedShiftA_ * n.mass : 0.0;
    if (!slopeTorqueBlock(i, ls, K + 2)) K[2] = K[3] = K[4] = K[5] = 0.0;
  }
  PetscCall(endLocal(&u));
  PetscCall(MatSetValuesCOO(J, corotatedValues_.data(), INSERT_VALUES));
  PetscCall(PetscLogEventEnd(SinewEvents::get().corotatedJacobian, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
