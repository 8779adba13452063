// Element-wise application of the tangent (see Assembler::applyTangent).
#include <algorithm>
#include <array>
#include <cmath>

#include "assembly/assembler.hpp"

namespace sinew {

bool Assembler::elementwiseTangentAvailable() const {
  int ok = pressureElems_.empty() && cableElems_.empty();
  MPI_Allreduce(MPI_IN_PLACE, &ok, 1, MPI_INT, MPI_LAND, mesh_.comm);
  return ok != 0;
}

namespace {

/// Vector groups of an element's DOFs that rotate with a rigid rotation: start index, dimension,
/// and whether the group is position-like (moves by omega x p) or rotation-like (moves by omega).
struct Group {
  int start, dim;
  bool position;
};

int groupsOf(std::span<const NodeKind> kinds, std::array<Group, 8>& g) {
  int ng = 0, d = 0;
  for (NodeKind k : kinds) {
    if (k == NodeKind::Ancf2D) {
      g[ng++] = {d, 2, true};      // position
      g[ng++] = {d + 2, 2, true};  // slope (rotates like a position difference)
    } else if (k == NodeKind::Frame6) {
      g[ng++] = {d, 3, true};
      g[ng++] = {d + 3, 3, false};  // spin DOFs
    } else {
      return -1;
    }
    d += dofSize(k);
  }
  return ng;
}

/// r = omega_k x v for unit axis k (3D) or z x v (2D, k = 0).
void spin(int dim, int k, const double* v, double* r) {
  if (dim == 2) {
    r[0] = -v[1];
    r[1] = v[0];
    return;
  }
  const double e[3] = {k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0};
  r[0] = e[1] * v[2] - e[2] * v[1];
  r[1] = e[2] * v[0] - e[0] * v[2];
  r[2] = e[0] * v[1] - e[1] * v[0];
}

/// z = the rigid-motion-free product of one kept block with d (translation-free already; see
/// applyTangent(x, y, true)), fk its rigid-motion data (keepRigid) with NR rotation components
/// (3: 3D, 1: 2D, 0: none, the element uses the plain product). NR known at compile time unrolls the
/// short loops over it; the operations and their order are those of a loop over a run-time nr.
template <int NR>
void rigidFreeProduct(int n, int nt, std::span<const NodeKind> kinds, const std::array<int, 4>& nodeStart,
                      const double* K, const double* fk, double* d, double* z) {
  const double* R = fk + n;
  const double* F = R + static_cast<size_t>(n) * NR;
  const double* E = F + static_cast<size_t>(n) * NR;
  std::array<Group, 8> g;
  const int ng = groupsOf(kinds, g);
  double c[3] = {0, 0, 0};  // rotation of the first node (d is translation-free already)
  for (int k = 0; k < NR; ++k)
    for (int j = 0; j < n; ++j) c[k] += E[k * n + j] * d[j];
  double vr[3] = {0, 0, 0};  // exact moment of K d about the first node: -sum_g d_g x f_g
  for (int gi = 0; gi < ng && NR > 0; ++gi) {
    if (!g[gi].position) continue;
    const double* a = &d[g[gi].start];
    const double* b = fk + g[gi].start;
    if (NR == 1) {
      vr[0] -= a[0] * b[1] - a[1] * b[0];
    } else {
      vr[0] -= a[1] * b[2] - a[2] * b[1];
      vr[1] -= a[2] * b[0] - a[0] * b[2];
      vr[2] -= a[0] * b[1] - a[1] * b[0];
    }
  }
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < NR; ++k) d[j] -= R[j * NR + k] * c[k];
  int r = 0;
  for (; r + 1 < n; r += 2) {  // two rows at a time (d read once for both), each its own sum in order
    const double* K0 = K + static_cast<size_t>(r) * n;
    const double* K1 = K0 + n;
    double s0 = 0.0, s1 = 0.0;
    for (int cc = 0; cc < n; ++cc) {
      s0 += K0[cc] * d[cc];
      s1 += K1[cc] * d[cc];
    }
    for (int k = 0; k < NR; ++k) {
      s0 += F[r * NR + k] * c[k];
      s1 += F[(r + 1) * NR + k] * c[k];
    }
    z[r] = s0;
    z[r + 1] = s1;
  }
  for (; r < n; ++r) {
    double s = 0.0;
    for (int cc = 0; cc < n; ++cc) s += K[r * n + cc] * d[cc];
    for (int k = 0; k < NR; ++k) s += F[r * NR + k] * c[k];
    z[r] = s;
  }
  // balance: resultant force 0 (first node's translation rows), moment vr (E^T)
  double wt[3] = {0, 0, 0}, wr[3] = {0, 0, 0};
  for (size_t i = 0; i < kinds.size(); ++i) {
    const int ni = kinds[i] == NodeKind::Ancf2D ? 2 : 3;
    for (int cc = 0; cc < std::min(nt, ni); ++cc) wt[cc] += z[nodeStart[i] + cc];
  }
  for (int k = 0; k < NR; ++k)
    for (int j = 0; j < n; ++j) wr[k] += R[j * NR + k] * z[j];
  for (int cc = 0; cc < nt; ++cc) z[cc] -= wt[cc];
  for (int k = 0; k < NR; ++k)
    for (int j = 0; j < n; ++j) z[j] += E[k * n + j] * (vr[k] - wr[k]);
}

}  // namespace

// Rigid-motion data of one kept block (see applyTangent(x, y, true)). Rotation about the first node:
// R (n x nr) with position-like groups omega x (p_g - p_1) (ANCF slopes: omega x s), spin groups omega;
// F = K R should be the spin of the internal forces, omega x f_g for every group; E (nr x n) extracts
// the rotation from the first node's DOFs (ANCF: s1 x ds1 / |s1|^2; Frame6: its spin), E R = I.
void Assembler::keepRigid(const LocalElement& el, const double* q, const double* f, const double* K, int n) {
  const auto kinds = el.kernel->nodeKinds();
  std::array<Group, 8> g;
  const int ng = groupsOf(kinds, g);
  const int nr = ng < 0 ? 0 : (kinds[0] == NodeKind::Ancf2D ? 1 : 3);
  bool mixed = false;
  for (NodeKind k : kinds) mixed |= k != kinds[0];
  if (nr == 0 || mixed) {
    rigidInfo_.push_back({0, rigidData_.size()});
    return;
  }
  const size_t off = rigidData_.size();
  rigidData_.resize(off + n + 3 * static_cast<size_t>(n) * nr, 0.0);
  double* fk = rigidData_.data() + off;
  double* R = fk + n;
  double* F = R + static_cast<size_t>(n) * nr;
  double* E = F + static_cast<size_t>(n) * nr;
  const int nd = el.kernel->numDofs();
  for (int r = 0; r < nd; ++r) fk[r] = f[r];
  // states: ANCF (x, y, sx, sy), Frame6 (x, y, z, R[9]); group start in the state layout
  std::array<int, 8> qs{};
  {
    int qo = 0, gi = 0;
    for (NodeKind k : kinds) {
      if (k == NodeKind::Ancf2D) {
        qs[gi++] = qo;
        qs[gi++] = qo + 2;
      } else {
        qs[gi++] = qo;
        qs[gi++] = -1;
      }
      qo += stateSize(k);
    }
  }
  const int dim = g[0].dim;
  for (int k = 0; k < nr; ++k) {
    for (int gi = 0; gi < ng; ++gi) {
      double p[3] = {0, 0, 0}, rr[3], ff[3];
      if (g[gi].position) {
        for (int c = 0; c < dim; ++c) p[c] = q[qs[gi] + c];
        if (gi % 2 == 0)  // a node position: relative to the first node's
          for (int c = 0; c < dim; ++c) p[c] -= q[qs[0] + c];
        spin(dim, k, p, rr);
      } else {
        for (int c = 0; c < dim; ++c) rr[c] = c == k ? 1.0 : 0.0;
      }
      spin(dim, k, f + g[gi].start, ff);
      for (int c = 0; c < dim; ++c) {
        R[(g[gi].start + c) * nr + k] = rr[c];
        F[(g[gi].start + c) * nr + k] = ff[c];
      }
    }
  }
  if (kinds[0] == NodeKind::Ancf2D) {
    const double sx = q[2], sy = q[3], s2 = sx * sx + sy * sy;
    E[2] = -sy / s2;
    E[3] = sx / s2;
  } else {
    for (int k = 0; k < 3; ++k) E[k * n + 3 + k] = 1.0;
  }
  // check K R = F to round-off; otherwise this element uses the translation-free product
  double err = 0, scale = 0;
  for (int r = 0; r < nd; ++r)
    for (int k = 0; k < nr; ++k) {
      double s = 0, a = 0;
      for (int c = 0; c < n; ++c) {
        s += K[r * n + c] * R[c * nr + k];
        a += std::abs(K[r * n + c] * R[c * nr + k]);
      }
      err = std::max(err, std::abs(s - F[r * nr + k]));
      scale = std::max(scale, a);
    }
  rigidInfo_.push_back({err <= 1e-8 * scale ? nr : 0, off});
}

long Assembler::rigidFreeElements() const {
  long c = 0;
  for (const auto& [nr, off] : rigidInfo_) c += nr > 0;
  MPI_Allreduce(MPI_IN_PLACE, &c, 1, MPI_LONG, MPI_SUM, mesh_.comm);
  return c;
}

PetscErrorCode Assembler::elementProduct(Vec x, Vec y, const std::function<void(const double* xa, double* ya)>& body) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(SinewEvents::get().tangentOperator, 0, 0, 0, 0));
  if (!xOp_) {
    PetscCall(createVector(&xOp_));
    PetscCall(VecDuplicate(xOp_, &yOp_));
  }
  PetscCall(loadLocal(x, xOp_));
  Vec xl, yl;
  const PetscScalar* xa;
  PetscScalar* ya;
  PetscCall(VecGhostGetLocalForm(xOp_, &xl));
  PetscCall(VecGhostGetLocalForm(yOp_, &yl));
  PetscCall(VecSet(yl, 0.0));
  PetscCall(VecGetArrayRead(xl, &xa));
  PetscCall(VecGetArray(yl, &ya));
  body(xa, ya);
  PetscCall(VecRestoreArray(yl, &ya));
  PetscCall(VecRestoreArrayRead(xl, &xa));
  PetscCall(VecGhostRestoreLocalForm(yOp_, &yl));
  PetscCall(VecGhostRestoreLocalForm(xOp_, &xl));
  PetscCall(ghostUpdate(yOp_, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecCopy(yOp_, y));
  PetscCall(PetscLogEventEnd(SinewEvents::get().tangentOperator, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void Assembler::addSlopeBlock(const LocalNode& node, const double* K, const double* xa, double* ya) {
  const int r0 = node.dof[2], r1 = node.dof[3];
  const double s0 = r0 >= 0 ? xa[r0] : 0.0, s1 = r1 >= 0 ? xa[r1] : 0.0;
  if (r0 >= 0) ya[r0] += K[0] * s0 + K[1] * s1;
  if (r1 >= 0) ya[r1] += K[2] * s0 + K[3] * s1;
}

PetscErrorCode Assembler::applyTangent(Vec x, Vec y, bool rigidFree) {
  PetscFunctionBeginUser;
  if (rigidFree && rigidInfo_.size() != mesh_.elements.size())
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ORDER, "applyTangent: no rigid-motion data (keepRigidData before jacobian)");
  PetscCall(elementProduct(x, y, [&](const double* xa, double* ya) {
    std::array<int, kMaxElementRows> idx;
    std::array<double, kMaxElementRows> d, z;
    size_t offset = 0, ei = 0;
    for (const LocalElement& el : mesh_.elements) {
      const auto kinds = el.kernel->nodeKinds();
      int n = 0;
      std::array<int, 4> nodeStart{};
      for (size_t i = 0; i < kinds.size(); ++i) {
        const LocalNode& node = mesh_.nodes[el.node[i]];
        nodeStart[i] = n;
        for (int k = 0; k < dofSize(kinds[i]); ++k, ++n) idx[n] = node.dof[k];
      }
      for (int j = 0; j < el.kernel->numConstraints(); ++j, ++n) idx[n] = el.firstMultiplier + j;
      for (int k = 0; k < n; ++k) d[k] = idx[k] >= 0 ? xa[idx[k]] : 0.0;
      // subtract the translation of the first node from every node's translation DOFs
      const int nt = kinds[0] == NodeKind::Ancf2D ? 2 : 3;
      std::array<double, 3> t{};
      for (int c = 0; c < nt; ++c) t[c] = d[c];
      for (size_t i = 0; i < kinds.size(); ++i) {
        const int ni = kinds[i] == NodeKind::Ancf2D ? 2 : 3;
        for (int c = 0; c < std::min(nt, ni); ++c) d[nodeStart[i] + c] -= t[c];
      }
      const double* K = blocks_.data() + offset;
      if (rigidFree) {
        const auto [nr, roff] = rigidInfo_[ei++];
        const double* fk = rigidData_.data() + roff;
        if (nr == 3) rigidFreeProduct<3>(n, nt, kinds, nodeStart, K, fk, d.data(), z.data());
        else if (nr == 1) rigidFreeProduct<1>(n, nt, kinds, nodeStart, K, fk, d.data(), z.data());
        else rigidFreeProduct<0>(n, nt, kinds, nodeStart, K, fk, d.data(), z.data());
        for (int r = 0; r < n; ++r)
          if (idx[r] >= 0) ya[idx[r]] += z[r];
        offset += static_cast<size_t>(n) * n;
        continue;
      }
      for (int r = 0; r < n; ++r) {
        if (idx[r] < 0) continue;
        double s = 0.0;
        for (int c = 0; c < n; ++c) s += K[r * n + c] * d[c];
        ya[idx[r]] += s;
      }
      offset += static_cast<size_t>(n) * n;
    }
    for (const auto& [i, K] : torqueBlocks_) addSlopeBlock(mesh_.nodes[i], K.data(), xa, ya);
  }));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
