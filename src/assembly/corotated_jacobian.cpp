// Corotated Newton matrix of ANCF cables (see Assembler::corotatedJacobian).
//
// A Jacobian kept across Newton iterations and time steps goes stale on a fine cable as its elements
// turn: an element's bending stiffness EI/l^3 exceeds its axial stiffness EA/l by EI/(EA l^2) (9e5 for
// A1 at 65536 elements), and a rotation by d theta moves the bending stiffness into the element's
// former axial direction, and a kept matrix stops contracting Newton (estimate d theta ~ EA l^2/EI,
// 1e-6 rad there; measured, A1g: kept matrices stalled from a turn of 2.3e-4 rad; docs/performance.md,
// "Why 65536 elements cost more per element, and what was done"). The
// element blocks themselves are objective, B(Q q) = Q B(q) Q^T, so the kept blocks rotated by each
// element's own rotation are the current Newton matrix up to the elements' deformation since they
// were kept. Rotating per node instead breaks the blocks' translation invariance (neighbouring
// nodes turn by different angles) and is worse than not rotating at all on coarser cables as a
// matrix; as a preconditioner of the element-wise product it serves fine cables (turnToIterate,
// rotateNodes; src/solvers/ancf/node_rotated_pc.hpp).
#include <algorithm>
#include <cmath>

#include "assembly/assembler.hpp"

namespace sinew {

namespace {

/// d = (x, y) / |(x, y)|
void unitDirection(double x, double y, double* d) {
  const double r = 1.0 / std::hypot(x, y);
  d[0] = x * r;
  d[1] = y * r;
}

/// Direction (unit vector) of an ANCF cable element's mean slope s1 + s2, from its nodes' states
/// (x, y, sx, sy, ...).
void meanSlopeDirection(const double* n1, const double* n2, double* d) { unitDirection(n1[2] + n2[2], n1[3] + n2[3], d); }

/// cos and sin of the turn from unit vector d0 to unit vector d: d0 . d and d0 x d
void turnBetween(const double* d0, const double* d, double* c, double* s) {
  *c = d0[0] * d[0] + d0[1] * d[1];
  *s = d0[0] * d[1] - d0[1] * d[0];
}

bool corotatable(const LocalElement& el) {
  const auto kinds = el.kernel->nodeKinds();
  return kinds.size() == 2 && kinds[0] == NodeKind::Ancf2D && kinds[1] == NodeKind::Ancf2D &&
         el.kernel->numDofs() == 8 && el.kernel->numConstraints() == 0;
}

}  // namespace

void Assembler::keepCorotatedBlocks(bool on) {
  keepCorotated_ = on;
  corotatedValid_ = false;
  corotatedCOO_ = on && std::all_of(mesh_.elements.begin(), mesh_.elements.end(), corotatable) &&
                  std::all_of(mesh_.nodes.begin(), mesh_.nodes.end(), [](const LocalNode& n) { return n.kind == NodeKind::Ancf2D; });
}

void Assembler::keepCorotated(size_t e, const LocalElement& el, const double* q, const double* K) {
  if (!corotatable(el)) {
    corotatedValid_ = false;
    return;
  }
  std::copy(K, K + 64, corotatedBlocks_.begin() + static_cast<long>(64 * e));
  meanSlopeDirection(q, q + 4, &corotatedDir_[2 * e]);
}

void Assembler::turnSinceKept(size_t e, double* c, double* s) const {
  const LocalElement& el = mesh_.elements[e];
  double d[2];
  meanSlopeDirection(&state_[12 * static_cast<size_t>(el.node[0])], &state_[12 * static_cast<size_t>(el.node[1])], d);
  turnBetween(&corotatedDir_[2 * e], d, c, s);
}

void Assembler::keepCorotatedNodeTerms(const LoadState& ls, double shiftA) {
  corotatedNodeTerms_.resize(6 * static_cast<size_t>(mesh_.numOwnedNodes));
  double* K = corotatedNodeTerms_.data();
  for (int i = 0; i < mesh_.numOwnedNodes; ++i, K += 6) {
    const LocalNode& n = mesh_.nodes[i];
    K[0] = K[1] = n.mass > 0 ? shiftA * n.mass : 0.0;
    if (!slopeTorqueBlock(i, ls, K + 2)) K[2] = K[3] = K[4] = K[5] = 0.0;
  }
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

PetscErrorCode Assembler::setCorotatedValues(Mat J, bool rotate) {
  PetscFunctionBeginUser;
  PetscCall(prepareCorotatedCOO(J));
  PetscScalar* K = corotatedValues_.data();
  if (!rotate) {
    K = std::copy(corotatedBlocks_.begin(), corotatedBlocks_.end(), K);
  } else {
    double T[64];
    for (size_t e = 0; e < mesh_.elements.size(); ++e, K += 64) {
      const double c = corotationCS_[2 * e], s = corotationCS_[2 * e + 1];
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
  }
  std::copy(corotatedNodeTerms_.begin(), corotatedNodeTerms_.end(), K);
  PetscCall(MatSetValuesCOO(J, corotatedValues_.data(), INSERT_VALUES));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::corotatedJacobian(Vec U, const LoadState& ls, Mat J) {
  PetscFunctionBeginUser;
  if (!corotatedValid_) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ORDER, "corotatedJacobian: no kept ANCF blocks");
  PetscCall(PetscLogEventBegin(SinewEvents::get().corotatedJacobian, 0, 0, 0, 0));
  const double* u = nullptr;
  PetscCall(beginLocal(U, ls, &u));
  for (size_t e = 0; e < mesh_.elements.size(); ++e) turnSinceKept(e, &corotationCS_[2 * e], &corotationCS_[2 * e + 1]);
  keepCorotatedNodeTerms(ls, corotatedShiftA_);  // node terms, as dynamicJacobian
  keepNodeDirections();
  PetscCall(endLocal(&u));
  PetscCall(setCorotatedValues(J, true));
  PetscCall(PetscLogEventEnd(SinewEvents::get().corotatedJacobian, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::corotationTurn(Vec U, const LoadState& ls, double* turn) {
  PetscFunctionBeginUser;
  if (!corotatedValid_) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ORDER, "corotationTurn: no kept ANCF blocks");
  const double* u = nullptr;
  PetscCall(beginLocal(U, ls, &u));
  double t = 0.0;
  for (size_t e = 0; e < mesh_.elements.size(); ++e) {
    double c, s;
    turnSinceKept(e, &c, &s);
    const double ca = corotationCS_[2 * e], sa = corotationCS_[2 * e + 1];  // the turn the matrix applies
    t = std::max(t, std::abs(std::atan2(s * ca - c * sa, c * ca + s * sa)));
  }
  PetscCall(endLocal(&u));
  PetscCallMPI(MPI_Allreduce(&t, turn, 1, MPI_DOUBLE, MPI_MAX, mesh_.comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void Assembler::keepNodeDirections() {
  const size_t n = static_cast<size_t>(mesh_.numOwnedNodes);
  nodeDir0_.resize(2 * n);
  nodeCS_.assign(2 * n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    unitDirection(state_[12 * i + 2], state_[12 * i + 3], &nodeDir0_[2 * i]);
    nodeCS_[2 * i] = 1.0;
  }
}

PetscErrorCode Assembler::turnToIterate(Vec U, const LoadState& ls) {
  PetscFunctionBeginUser;
  if (!corotatedValid_) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ORDER, "turnToIterate: no kept ANCF blocks");
  const double* u = nullptr;
  PetscCall(beginLocal(U, ls, &u));
  for (size_t e = 0; e < mesh_.elements.size(); ++e) turnSinceKept(e, &corotationCS_[2 * e], &corotationCS_[2 * e + 1]);
  for (size_t i = 0; i < static_cast<size_t>(mesh_.numOwnedNodes); ++i) {
    double d[2];
    unitDirection(state_[12 * i + 2], state_[12 * i + 3], d);
    turnBetween(&nodeDir0_[2 * i], d, &nodeCS_[2 * i], &nodeCS_[2 * i + 1]);
  }
  PetscCall(endLocal(&u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void Assembler::rotateNodes(const double* x, double* y, bool back) const {
  const double sign = back ? -1.0 : 1.0;
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    const LocalNode& n = mesh_.nodes[i];
    const double c = nodeCS_[2 * i], s = sign * nodeCS_[2 * i + 1];
    for (int a = 0; a < 4; a += 2) {
      const int i0 = n.dof[a], i1 = n.dof[a + 1];
      if (i0 < 0 || i1 < 0) {
        if (i0 >= 0) y[i0] = x[i0];
        if (i1 >= 0) y[i1] = x[i1];
        continue;
      }
      const double x0 = x[i0], x1 = x[i1];
      y[i0] = c * x0 - s * x1;
      y[i1] = s * x0 + c * x1;
    }
  }
}

PetscErrorCode Assembler::applyCorotated(Vec x, Vec y) {
  PetscFunctionBeginUser;
  if (!corotatedValid_) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ORDER, "applyCorotated: no kept ANCF blocks");
  PetscCall(elementProduct(x, y, [&](const double* xa, double* ya) {
    const double* B = corotatedBlocks_.data();
    const double* cs = corotationCS_.data();
    std::vector<double> MeBuf;
    std::array<double, 48> q{};
    for (const LocalElement& el : mesh_.elements) {
      int idx[8];
      for (int a = 0; a < 2; ++a)
        for (int k = 0; k < 4; ++k) idx[4 * a + k] = mesh_.nodes[el.node[a]].dof[k];
      double d[8];
      for (int k = 0; k < 8; ++k) d[k] = idx[k] >= 0 ? xa[idx[k]] : 0.0;
      const double t[2] = {d[0], d[1]};  // the first node's translation, applied exactly below
      d[0] = 0.0;
      d[1] = 0.0;
      d[4] -= t[0];
      d[5] -= t[1];
      // into the frame the block was kept in: Q^T d (every 2-vector turned back by the element's turn)
      const double c = cs[0], sn = cs[1];
      for (int a = 0; a < 8; a += 2) {
        const double x0 = d[a], x1 = d[a + 1];
        d[a] = c * x0 + sn * x1;
        d[a + 1] = -sn * x0 + c * x1;
      }
      double z[8];
      for (int r = 0; r < 8; ++r) {
        double s = 0.0;
        for (int k = 0; k < 8; ++k) s += B[8 * r + k] * d[k];
        z[r] = s;
      }
      for (int a = 0; a < 8; a += 2) {  // back: Q z
        const double x0 = z[a], x1 = z[a + 1];
        z[a] = c * x0 - sn * x1;
        z[a + 1] = sn * x0 + c * x1;
      }
      // the translation's response: shiftA M_e (t, 0, t, 0) (M_e = m (x) I_2 is invariant under Q)
      const double* Me = el.kernel->hasInertia() ? elementMass(el, q.data(), MeBuf) : nullptr;
      for (int r = 0; r < 8; ++r) {
        if (Me) z[r] += corotatedShiftA_ * ((Me[8 * r + 0] + Me[8 * r + 4]) * t[0] + (Me[8 * r + 1] + Me[8 * r + 5]) * t[1]);
        if (idx[r] >= 0) ya[idx[r]] += z[r];
      }
      B += 64;
      cs += 2;
    }
    const double* K = corotatedNodeTerms_.data();
    for (int i = 0; i < mesh_.numOwnedNodes; ++i, K += 6) {
      const LocalNode& n = mesh_.nodes[i];
      for (int k = 0; k < 2; ++k)
        if (n.dof[k] >= 0) ya[n.dof[k]] += K[k] * xa[n.dof[k]];
      addSlopeBlock(n, K + 2, xa, ya);
    }
  }));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
