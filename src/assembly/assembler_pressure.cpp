// Loads of tensile structures that depend on the current geometry, and the Newton regularization
// of slack cables (Assembler members; see assembler.hpp).
//
// Surface pressure (follower): on a membrane element with nodes x_a and shape functions N_a(xi, eta)
//   f_a = p int N_a (g1 x g2) dxi deta,   g_i = sum_b N_b,i x_b,   p = p_initial + loadFactor p_ramped,
// i.e. the pressure acts along the current normal g1 x g2 (right-hand rule of the node order) on the
// current area. Triangles: one point (exact: g1 x g2 is constant); quads: 2x2 Gauss (exact). The
// load stiffness (Jacobian of the residual f_int - f_ext) is
//   -d f_a / d x_b = -p int N_a [ N_b,eta skew(g1) - N_b,xi skew(g2) ] dxi deta.
// Slack cables: a tension-only kernel (ElementKernel::tensionOnly, an elastic cable with N <= 0) has
// zero force and tangent; a node held only by slack cables would make the Jacobian singular. The
// Jacobian (never the residual) gets k [I -I; -I I], k = slackStiffness * EA / L (N0 / L when EA = 0;
// ElementKernel::slack), so equilibrium states are unchanged.
#include <array>
#include <cmath>

#include "assembly/assembler.hpp"

namespace sinew {

namespace {

/// p * int N_a (g1 x g2) and, when K != nullptr, K = d f / d x (3 nn x 3 nn, row-major).
void pressureElement(int nn, const double* x, double p, double* f, double* K) {
  static constexpr double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  const double g = 1.0 / std::sqrt(3.0);
  const double gp[4][2] = {{-g, -g}, {g, -g}, {g, g}, {-g, g}};
  const int ngp = nn == 3 ? 1 : 4, n = 3 * nn;
  for (int i = 0; i < n; ++i) f[i] = 0.0;
  if (K)
    for (int i = 0; i < n * n; ++i) K[i] = 0.0;
  for (int q = 0; q < ngp; ++q) {
    double N[4], dN[4][2], w;
    if (nn == 3) {
      N[0] = N[1] = N[2] = 1.0 / 3.0;
      dN[0][0] = -1, dN[0][1] = -1, dN[1][0] = 1, dN[1][1] = 0, dN[2][0] = 0, dN[2][1] = 1;
      w = 0.5;
    } else {
      for (int a = 0; a < 4; ++a) {
        N[a] = 0.25 * (1 + sx[a] * gp[q][0]) * (1 + sy[a] * gp[q][1]);
        dN[a][0] = 0.25 * sx[a] * (1 + sy[a] * gp[q][1]);
        dN[a][1] = 0.25 * sy[a] * (1 + sx[a] * gp[q][0]);
      }
      w = 1.0;
    }
    Vec3 g1{}, g2{};
    for (int a = 0; a < nn; ++a)
      for (int k = 0; k < 3; ++k) {
        g1[k] += dN[a][0] * x[3 * a + k];
        g2[k] += dN[a][1] * x[3 * a + k];
      }
    const Vec3 c = cross(g1, g2);
    for (int a = 0; a < nn; ++a)
      for (int k = 0; k < 3; ++k) f[3 * a + k] += p * w * N[a] * c[k];
    if (!K) continue;
    // d(g1 x g2)/dx_b = N_b,xi (-skew(g2)) + N_b,eta skew(g1);  skew(v) = [0 -v3 v2; v3 0 -v1; -v2 v1 0]
    auto skew = [](const Vec3& v, int i, int j) {
      const double S[3][3] = {{0, -v[2], v[1]}, {v[2], 0, -v[0]}, {-v[1], v[0], 0}};
      return S[i][j];
    };
    for (int a = 0; a < nn; ++a)
      for (int b = 0; b < nn; ++b)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            K[n * (3 * a + i) + 3 * b + j] +=
                p * w * N[a] * (dN[b][1] * skew(g1, i, j) - dN[b][0] * skew(g2, i, j));
  }
}
}  // namespace

void Assembler::initLoads() {
  const std::vector<SetLoads>& table = mesh_.setLoads;
  for (size_t e = 0; e < mesh_.elements.size(); ++e) {
    const LocalElement& el = mesh_.elements[e];
    if (el.kernel->tensionOnly()) cableElems_.push_back(static_cast<int>(e));
    if (el.set < 0 || static_cast<size_t>(el.set) >= table.size() || (el.numNodes != 3 && el.numNodes != 4)) continue;
    const SetPressure& sp = table[static_cast<size_t>(el.set)].pressure;
    if (sp.pressure != 0.0 || sp.pressureInitial != 0.0 || sp.pressureOfTime) pressureElems_.emplace_back(static_cast<int>(e), sp);
  }
  int any = pressureElems_.empty() ? 0 : 1;
  MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_LOR, mesh_.comm);
  anyPressure_ = any != 0;
}

double Assembler::addPressureForces(const LoadState& ls, Target target, double* out) {
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx, fidx;
  std::array<double, 12> f;
  double fext2 = 0.0;
  for (const auto& [e, sp] : pressureElems_) {
    const LocalElement& el = mesh_.elements[static_cast<size_t>(e)];
    const double p = sp.at(ls.loadFactor, ls.time);
    if (p == 0.0) continue;
    gatherElement(el, q.data(), nullptr, idx.data(), fidx.data());
    pressureElement(el.numNodes, q.data(), p, f.data(), nullptr);
    ++counters_.pressureLoads;
    const int* map = target == Target::Residual ? idx.data() : fidx.data();
    for (int k = 0; k < 3 * el.numNodes; ++k) {
      fext2 += f[k] * f[k];
      if (map[k] >= 0) out[map[k]] -= f[k];
    }
  }
  return fext2;
}

PetscErrorCode Assembler::addLoadTangents(const LoadState& ls, Mat J) {
  PetscFunctionBeginUser;
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  std::array<double, 12> f;
  std::array<double, 144> K;
  for (const auto& [e, sp] : pressureElems_) {
    const LocalElement& el = mesh_.elements[static_cast<size_t>(e)];
    const double p = sp.at(ls.loadFactor, ls.time);
    if (p == 0.0) continue;
    gatherElement(el, q.data(), nullptr, idx.data(), nullptr);
    pressureElement(el.numNodes, q.data(), -p, f.data(), K.data());  // residual = f_int - f_ext
    const int n = 3 * el.numNodes;
    PetscCall(MatSetValuesLocal(J, n, idx.data(), n, idx.data(), K.data(), ADD_VALUES));
  }
  long slack = 0;
  for (int e : cableElems_) {
    const LocalElement& el = mesh_.elements[static_cast<size_t>(e)];
    const ElementKernel& c = *el.kernel;
    gatherElement(el, q.data(), nullptr, idx.data(), nullptr);
    double axial = 0.0;
    if (!c.slack(q.data(), &axial)) continue;
    ++slack;
    const double k = slackStiffness_ * axial / c.referenceLength();
    if (!(k > 0.0)) continue;
    K.fill(0.0);
    for (int i = 0; i < 3; ++i) {
      K[6 * i + i] = K[6 * (i + 3) + i + 3] = k;
      K[6 * i + i + 3] = K[6 * (i + 3) + i] = -k;
    }
    PetscCall(MatSetValuesLocal(J, 6, idx.data(), 6, idx.data(), K.data(), ADD_VALUES));
  }
  MPI_Allreduce(&slack, &slackCables_, 1, MPI_LONG, MPI_SUM, mesh_.comm);
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
