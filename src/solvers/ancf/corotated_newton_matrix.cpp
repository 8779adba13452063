// Corotated Newton matrix of ANCF cables (corotated_newton_matrix.hpp).
#include "solvers/ancf/corotated_newton_matrix.hpp"

#include <algorithm>
#include <array>
#include <cmath>

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

/// The 8 local unknown indices of an ANCF cable element (-1: constrained).
void elementUnknowns(const DistributedMesh& mesh, const LocalElement& el, int* idx) {
  for (int a = 0; a < 2; ++a)
    for (int k = 0; k < 4; ++k) idx[4 * a + k] = mesh.nodes[el.node[a]].dof[k];
}

}  // namespace

CorotatedNewtonMatrix::CorotatedNewtonMatrix(Assembler& assembler) : asm_(assembler) {
  const DistributedMesh& mesh = asm_.mesh();
  coo_ = std::all_of(mesh.elements.begin(), mesh.elements.end(), corotatable) &&
         std::all_of(mesh.nodes.begin(), mesh.nodes.end(), [](const LocalNode& n) { return n.kind == NodeKind::Ancf2D; });
  asm_.setNewtonBlockSink(this);
}

CorotatedNewtonMatrix::~CorotatedNewtonMatrix() { asm_.setNewtonBlockSink(nullptr); }

void CorotatedNewtonMatrix::start(double shiftA) {
  const size_t ne = asm_.mesh().elements.size();
  blocks_.resize(64 * ne);
  dir_.resize(2 * ne);
  shiftA_ = shiftA;
  valid_ = true;
}

void CorotatedNewtonMatrix::element(std::size_t e, const LocalElement& el, const double* q, const double* K) {
  if (!corotatable(el)) {
    valid_ = false;
    return;
  }
  std::copy(K, K + 64, blocks_.begin() + static_cast<long>(64 * e));
  meanSlopeDirection(q, q + 4, &dir_[2 * e]);
}

void CorotatedNewtonMatrix::nodeTerms(const LoadState& ls) {
  keepNodeTerms(ls, shiftA_);
  cs_.assign(2 * asm_.mesh().elements.size(), 0.0);
  for (size_t e = 0; e < asm_.mesh().elements.size(); ++e) cs_[2 * e] = 1.0;
  keepNodeDirections();
}

void CorotatedNewtonMatrix::turnSinceKept(size_t e, double* c, double* s) const {
  const LocalElement& el = asm_.mesh().elements[e];
  double d[2];
  meanSlopeDirection(asm_.nodeState(el.node[0]), asm_.nodeState(el.node[1]), d);
  turnBetween(&dir_[2 * e], d, c, s);
}

void CorotatedNewtonMatrix::keepNodeTerms(const LoadState& ls, double shiftA) {
  const DistributedMesh& mesh = asm_.mesh();
  nodeTerms_.resize(6 * static_cast<size_t>(mesh.numOwnedNodes));
  double* K = nodeTerms_.data();
  for (int i = 0; i < mesh.numOwnedNodes; ++i, K += 6) {
    const LocalNode& n = mesh.nodes[i];
    K[0] = K[1] = n.mass > 0 ? shiftA * n.mass : 0.0;
    if (!asm_.slopeTorqueBlock(i, ls, K + 2)) K[2] = K[3] = K[4] = K[5] = 0.0;
  }
}

void CorotatedNewtonMatrix::keepNodeDirections() {
  const size_t n = static_cast<size_t>(asm_.mesh().numOwnedNodes);
  nodeDir0_.resize(2 * n);
  nodeCS_.assign(2 * n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    const double* x = asm_.nodeState(static_cast<int>(i));
    unitDirection(x[2], x[3], &nodeDir0_[2 * i]);
    nodeCS_[2 * i] = 1.0;
  }
}

PetscErrorCode CorotatedNewtonMatrix::prepareCOO(Mat J) {
  PetscFunctionBeginUser;
  // a marker composed with the matrix: it dies with the matrix (a later matrix may reuse the address)
  PetscObject marker = nullptr;
  PetscCall(PetscObjectQuery(reinterpret_cast<PetscObject>(J), "SinewCorotatedCOO", &marker));
  if (marker) PetscFunctionReturn(PETSC_SUCCESS);
  const DistributedMesh& mesh = asm_.mesh();
  std::vector<PetscInt> ci, cj;
  auto global = [&](int local) { return local >= 0 ? static_cast<PetscInt>(mesh.localToGlobalUnknown(local)) : -1; };
  for (const LocalElement& el : mesh.elements) {
    int idx[8];
    elementUnknowns(mesh, el, idx);
    for (int r = 0; r < 8; ++r)
      for (int c = 0; c < 8; ++c) {
        ci.push_back(global(idx[r]));
        cj.push_back(global(idx[c]));
      }
  }
  for (int i = 0; i < mesh.numOwnedNodes; ++i) {
    const LocalNode& n = mesh.nodes[i];
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
  values_.assign(ci.size(), 0.0);
  PetscCall(MatSetPreallocationCOO(J, static_cast<PetscCount>(ci.size()), ci.data(), cj.data()));
  PetscContainer tag;
  PetscCall(PetscContainerCreate(mesh.comm, &tag));
  PetscCall(PetscObjectCompose(reinterpret_cast<PetscObject>(J), "SinewCorotatedCOO", reinterpret_cast<PetscObject>(tag)));
  PetscCall(PetscContainerDestroy(&tag));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CorotatedNewtonMatrix::setValues(Mat J, bool rotate) {
  PetscFunctionBeginUser;
  PetscCall(prepareCOO(J));
  PetscScalar* K = values_.data();
  if (!rotate) {
    K = std::copy(blocks_.begin(), blocks_.end(), K);
  } else {
    double T[64];
    for (size_t e = 0; e < asm_.mesh().elements.size(); ++e, K += 64) {
      const double c = cs_[2 * e], s = cs_[2 * e + 1];
      const double* B = blocks_.data() + 64 * e;
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
  std::copy(nodeTerms_.begin(), nodeTerms_.end(), K);
  PetscCall(MatSetValuesCOO(J, values_.data(), INSERT_VALUES));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CorotatedNewtonMatrix::assemble(Vec U, const LoadState& ls, Mat J) {
  PetscFunctionBeginUser;
  if (!valid_) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ORDER, "corotated Newton matrix: no kept ANCF blocks");
  PetscCall(PetscLogEventBegin(SinewEvents::get().corotatedJacobian, 0, 0, 0, 0));
  const double* u = nullptr;
  PetscCall(asm_.beginLocal(U, ls, &u));
  for (size_t e = 0; e < asm_.mesh().elements.size(); ++e) turnSinceKept(e, &cs_[2 * e], &cs_[2 * e + 1]);
  keepNodeTerms(ls, shiftA_);  // node terms, as dynamicJacobian
  keepNodeDirections();
  PetscCall(asm_.endLocal(&u));
  PetscCall(setValues(J, true));
  PetscCall(PetscLogEventEnd(SinewEvents::get().corotatedJacobian, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CorotatedNewtonMatrix::turn(Vec U, const LoadState& ls, double* turn) {
  PetscFunctionBeginUser;
  if (!valid_) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ORDER, "corotated Newton matrix turn: no kept ANCF blocks");
  const double* u = nullptr;
  PetscCall(asm_.beginLocal(U, ls, &u));
  double t = 0.0;
  for (size_t e = 0; e < asm_.mesh().elements.size(); ++e) {
    double c, s;
    turnSinceKept(e, &c, &s);
    const double ca = cs_[2 * e], sa = cs_[2 * e + 1];  // the turn the matrix applies
    t = std::max(t, std::abs(std::atan2(s * ca - c * sa, c * ca + s * sa)));
  }
  PetscCall(asm_.endLocal(&u));
  PetscCallMPI(MPI_Allreduce(&t, turn, 1, MPI_DOUBLE, MPI_MAX, asm_.mesh().comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CorotatedNewtonMatrix::turnToIterate(Vec U, const LoadState& ls) {
  PetscFunctionBeginUser;
  if (!valid_) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ORDER, "corotated Newton matrix turnToIterate: no kept ANCF blocks");
  const double* u = nullptr;
  PetscCall(asm_.beginLocal(U, ls, &u));
  for (size_t e = 0; e < asm_.mesh().elements.size(); ++e) turnSinceKept(e, &cs_[2 * e], &cs_[2 * e + 1]);
  for (size_t i = 0; i < static_cast<size_t>(asm_.mesh().numOwnedNodes); ++i) {
    const double* x = asm_.nodeState(static_cast<int>(i));
    double d[2];
    unitDirection(x[2], x[3], d);
    turnBetween(&nodeDir0_[2 * i], d, &nodeCS_[2 * i], &nodeCS_[2 * i + 1]);
  }
  PetscCall(asm_.endLocal(&u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void CorotatedNewtonMatrix::rotateNodes(const double* x, double* y, bool back) const {
  const DistributedMesh& mesh = asm_.mesh();
  const double sign = back ? -1.0 : 1.0;
  for (int i = 0; i < mesh.numOwnedNodes; ++i) {
    const LocalNode& n = mesh.nodes[i];
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

PetscErrorCode CorotatedNewtonMatrix::apply(Vec x, Vec y) {
  PetscFunctionBeginUser;
  if (!valid_) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ORDER, "corotated Newton matrix apply: no kept ANCF blocks");
  const DistributedMesh& mesh = asm_.mesh();
  PetscCall(asm_.elementProduct(x, y, [&](const double* xa, double* ya) {
    const double* B = blocks_.data();
    const double* cs = cs_.data();
    std::vector<double> MeBuf;
    std::array<double, 48> q{};
    for (const LocalElement& el : mesh.elements) {
      int idx[8];
      elementUnknowns(mesh, el, idx);
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
      const double* Me = el.kernel->hasInertia() ? asm_.elementMass(el, q.data(), MeBuf) : nullptr;
      for (int r = 0; r < 8; ++r) {
        if (Me) z[r] += shiftA_ * ((Me[8 * r + 0] + Me[8 * r + 4]) * t[0] + (Me[8 * r + 1] + Me[8 * r + 5]) * t[1]);
        if (idx[r] >= 0) ya[idx[r]] += z[r];
      }
      B += 64;
      cs += 2;
    }
    const double* K = nodeTerms_.data();
    for (int i = 0; i < mesh.numOwnedNodes; ++i, K += 6) {
      const LocalNode& n = mesh.nodes[i];
      for (int k = 0; k < 2; ++k)
        if (n.dof[k] >= 0) ya[n.dof[k]] += K[k] * xa[n.dof[k]];
      Assembler::addSlopeBlock(n, K + 2, xa, ya);
    }
  }));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
