#include "accuracy/level_reuse.hpp"

#include <algorithm>
#include <cmath>

#include "accuracy/membrane_refinement.hpp"
#include "accuracy/time_refinement.hpp"
#include "mesh/fe_mesh.hpp"
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
void midpoint(NodeKind kind, const Vec3& Xa, const Vec3& Xb, const double* sa, const double* sb, BeamMidRotation rot,
              double* s) {
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
  Mat3 R = expSO3(0.5 * logSO3(Rb * transpose(Ra))) * Ra;
  if (rot == BeamMidRotation::HermiteTangent) {  // turned by the least rotation from R d to the shape's tangent
    // x'(1/2) / l = 3/(2l) (xb - xa) - (Ra d + Rb d)/4: exact for a cubic deflection, so for a quadratic rotation
    const Vec3 tangent = (1.5 / l) * (at(sb) - at(sa)) - 0.25 * (Ra * d + Rb * d), t = R * d;
    const Vec3 axis = cross(t, tangent);
    const double sine = norm(axis);
    if (sine > 0) R = expSO3((std::atan2(sine, dot(t, tangent)) / sine) * axis) * R;
  }
  for (int k = 0; k < 3; ++k) s[k] = x[k];
  for (int k = 0; k < 9; ++k) s[3 + k] = R[static_cast<std::size_t>(k)];
}

}  // namespace

bool reusesStates(const Model& m) {
  if (m.opt.dynamics) return true;  // time steps: the same nodes, or mapped by LevelNodeMap (analysis/time_handover.hpp)
  const bool arcLength = !m.opt.continuation || m.opt.continuation->method != "displacement";
  if (m.formfinding) return arcLength;  // its load steps or path (accuracy/found_shape_reuse.hpp)
  return !hasMembranes(m) && arcLength;
}

LevelNodeMap::LevelNodeMap(const Model& coarse, const Model& fine, BeamMidRotation rotation) : rotation_(rotation) {
  const FeMesh cm = discretize(coarse), fm = discretize(fine);
  nc_ = cm.X.size();
  const std::size_t nf = fm.X.size();
  kind_ = fm.kind;
  same_.assign(nf, -1), midA_.assign(nf, -1), midB_.assign(nf, -1);
  if (hasMembranes(coarse)) {  // one split: the coarse nodes keep their numbers, the new nodes follow
    const auto point = [](NodeKind k) { return k == NodeKind::Point3; };
    if (!std::all_of(cm.kind.begin(), cm.kind.end(), point) || !std::all_of(fm.kind.begin(), fm.kind.end(), point)) return;
    if (nc_ != coarse.nodes.size()) return;  // split cables with inner FE nodes (nbeams > 1)
    parents_ = splitParents(coarse);
    if (nf != nc_ + parents_.size()) return;
    for (std::size_t n = 0; n < nc_; ++n) same_[n] = static_cast<int>(n);
    valid_ = true;
    return;
  }
  if (cm.sceneElementFirst.size() != fm.sceneElementFirst.size()) return;
  Xc_ = cm.X;
  for (int n = 0; n < cm.numSceneNodes && static_cast<std::size_t>(n) < nf; ++n) same_[static_cast<std::size_t>(n)] = n;
  for (std::size_t e = 0; e < cm.sceneElementFirst.size(); ++e) {
    const std::vector<int> c = chain(cm, static_cast<int>(e)), f = chain(fm, static_cast<int>(e));
    const std::size_t n = c.size() - 1, m = f.size() - 1;
    if (m == n) {
      for (std::size_t j = 0; j <= n; ++j) same_[static_cast<std::size_t>(f[j])] = c[j];
    } else if (m == 2 * n) {
      for (std::size_t j = 0; j <= n; ++j) same_[static_cast<std::size_t>(f[2 * j])] = c[j];
      for (std::size_t j = 0; j < n; ++j)
        midA_[static_cast<std::size_t>(f[2 * j + 1])] = c[j], midB_[static_cast<std::size_t>(f[2 * j + 1])] = c[j + 1];
    } else {
      return;
    }
  }
  for (std::size_t n = 0; n < nf; ++n)
    if (same_[n] < 0 && midA_[n] < 0) return;
  valid_ = true;
}

std::vector<double> LevelNodeMap::apply(const std::vector<double>& coarse) const {
  if (!valid_ || coarse.size() != 12 * nc_) return {};
  const std::size_t nf = kind_.size();
  std::vector<double> out(12 * nf, 0.0);
  for (std::size_t n = 0; n < nf; ++n) {
    double* s = &out[12 * n];
    if (same_[n] >= 0) {
      const double* c = &coarse[12 * static_cast<std::size_t>(same_[n])];
      std::copy(c, c + 12, s);
    } else if (midA_[n] >= 0) {
      const auto a = static_cast<std::size_t>(midA_[n]), b = static_cast<std::size_t>(midB_[n]);
      midpoint(kind_[n], Xc_[a], Xc_[b], &coarse[12 * a], &coarse[12 * b], rotation_, s);
    } else {  // a split membrane's new node: the mean of its parents' positions
      const std::vector<int>& p = parents_[n - nc_];
      const double w = 1.0 / static_cast<double>(p.size());
      for (int q : p)
        for (std::size_t k = 0; k < 3; ++k) s[k] += w * coarse[12 * static_cast<std::size_t>(q) + k];
    }
  }
  return out;
}

std::vector<LevelState> interpolateStates(const Model& coarse, const Model& fine, const std::vector<LevelState>& record) {
  if (hasMembranes(coarse)) return {};  // lines alone (split membranes: accuracy/found_shape_reuse.hpp)
  const LevelNodeMap map(coarse, fine);
  if (!map.valid()) return {};
  return map.apply(record);
}

std::vector<LevelState> LevelNodeMap::apply(const std::vector<LevelState>& record) const {
  std::vector<LevelState> out;
  for (const LevelState& st : record) {
    LevelState g;
    g.loadFactor = st.loadFactor;
    g.nodes = apply(st.nodes);
    if (g.nodes.empty()) return {};
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace sinew::accuracy
