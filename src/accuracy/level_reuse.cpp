#include "accuracy/level_reuse.hpp"

#include <cmath>

#include "accuracy/membrane_refinement.hpp"
#include "accuracy/time_refinement.hpp"
#include "mesh/fe_mesh.hpp"
#include "sinew/linalg3.hpp"
#include "sinew/rotation.hpp"

namespace sinew::accuracy {

namespace {

/// The FE nodes along scene element e, from its first node to its last.
std::vector<int> chain(const FeMesh& mesh, int e) {
  const int first = mesh.sceneElementFirst[static_cast<std::size_t>(e)];
  const int count = mesh.sceneElementCount[static_cast<std::size_t>(e)];
  std::vector<int> nodes{mesh.elements[static_cast<std::size_t>(first)].nodes[0]};
  for (int k = 0; k < count; ++k) nodes.push_back(mesh.elements[static_cast<std::size_t>(first + k)].nodes[1]);
  return nodes;
}

Vec3 at(const double* s) { return {s[0], s[1], s[2]}; }

/// The state of the midpoint of the coarse element from node a to node b (states sa, sb) into s.
void midpoint(NodeKind kind, const Vec3& Xa, const Vec3& Xb, const double* sa, const double* sb, double* s) {
  const Vec3 chord = Xb - Xa;
  const double l = std::sqrt(chord[0] * chord[0] + chord[1] * chord[1] + chord[2] * chord[2]);
  if (kind == NodeKind::Ancf2D) {  // r(1/2) = (ra + rb)/2 + l/8 (r'a - r'b), r'(1/2) = 3/(2l) (rb - ra) - (r'a + r'b)/4
    for (int k = 0; k < 2; ++k) {
      s[k] = 0.5 * (sa[k] + sb[k]) + l / 8 * (sa[2 + k] - sb[2 + k]);
      s[2 + k] = 1.5 / l * (sb[k] - sa[k]) - 0.25 * (sa[2 + k] + sb[2 + k]);
    }
    return;
  }
  const Vec3 mid = 0.5 * (at(sa) + at(sb));
  if (kind != NodeKind::Frame6) {  // a cable is linear along its element
    for (int k = 0; k < 3; ++k) s[k] = mid[k];
    return;
  }
  Mat3 Ra, Rb;
  std::copy(sa + 3, sa + 12, Ra.begin());
  std::copy(sb + 3, sb + 12, Rb.begin());
  const Vec3 d = (1.0 / l) * chord;  // the tangents of the deformed element at its ends: R d
  const Vec3 x = mid + (l / 8) * (Ra * d - Rb * d);
  const Mat3 R = expSO3(0.5 * logSO3(Rb * transpose(Ra))) * Ra;
  for (int k = 0; k < 3; ++k) s[k] = x[k];
  for (int k = 0; k < 9; ++k) s[3 + k] = R[static_cast<std::size_t>(k)];
}

}  // namespace

bool reusesStates(const Model& m) {
  if (refinesTime(m)) return !refinesSpace(m);  // levels in time alone: the same mesh (analysis/time_handover.hpp)
  const bool arcLength = !m.opt.continuation || m.opt.continuation->method != "displacement";
  if (m.formfinding) return arcLength && !m.opt.dynamics;  // its load steps or path (accuracy/found_shape_reuse.hpp)
  return !hasMembranes(m) && arcLength;
}

std::vector<LevelState> interpolateStates(const Model& coarse, const Model& fine, const std::vector<LevelState>& record) {
  const FeMesh cm = discretize(coarse), fm = discretize(fine);
  const std::size_t nc = cm.X.size(), nf = fm.X.size();
  if (cm.sceneElementFirst.size() != fm.sceneElementFirst.size()) return {};
  // per fine node: the coarse node it is, or the coarse element (a, b) it is the midpoint of
  std::vector<int> same(nf, -1), midA(nf, -1), midB(nf, -1);
  for (int n = 0; n < cm.numSceneNodes && static_cast<std::size_t>(n) < nf; ++n) same[static_cast<std::size_t>(n)] = n;
  for (std::size_t e = 0; e < cm.sceneElementFirst.size(); ++e) {
    const std::vector<int> c = chain(cm, static_cast<int>(e)), f = chain(fm, static_cast<int>(e));
    const std::size_t n = c.size() - 1, m = f.size() - 1;
    if (m == n) {
      for (std::size_t j = 0; j <= n; ++j) same[static_cast<std::size_t>(f[j])] = c[j];
    } else if (m == 2 * n) {
      for (std::size_t j = 0; j <= n; ++j) same[static_cast<std::size_t>(f[2 * j])] = c[j];
      for (std::size_t j = 0; j < n; ++j)
        midA[static_cast<std::size_t>(f[2 * j + 1])] = c[j], midB[static_cast<std::size_t>(f[2 * j + 1])] = c[j + 1];
    } else {
      return {};
    }
  }
  std::vector<LevelState> out;
  for (const LevelState& st : record) {
    if (st.nodes.size() != 12 * nc) return {};
    LevelState g;
    g.loadFactor = st.loadFactor;
    g.nodes.assign(12 * nf, 0.0);
    for (std::size_t n = 0; n < nf; ++n) {
      double* s = &g.nodes[12 * n];
      if (same[n] >= 0) {
        const double* c = &st.nodes[12 * static_cast<std::size_t>(same[n])];
        std::copy(c, c + 12, s);
      } else if (midA[n] >= 0) {
        const auto a = static_cast<std::size_t>(midA[n]), b = static_cast<std::size_t>(midB[n]);
        midpoint(fm.kind[n], cm.X[a], cm.X[b], &st.nodes[12 * a], &st.nodes[12 * b], s);
      } else {
        return {};
      }
    }
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace sinew::accuracy
