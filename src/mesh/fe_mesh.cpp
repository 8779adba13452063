#include "mesh/fe_mesh.hpp"

#include <cmath>
#include <string>

namespace sinew {

ElementType elementTypeOf(const Model& model, int e) {
  const int set = model.elementSet[e];
  return set < 0 ? ElementType::Beam : model.eprops[set].type();
}

static NodeKind kindOf(ElementType t) {
  switch (t) {
    case ElementType::Beam: return NodeKind::Frame6;
    case ElementType::AncfCable2D: return NodeKind::Ancf2D;
    default: return NodeKind::Point3;
  }
}

FeMesh discretize(const Model& model) {
  FeMesh mesh;
  const int nn = static_cast<int>(model.nodes.size());
  mesh.numSceneNodes = nn;
  mesh.X = model.nodes;
  mesh.kind.assign(nn, NodeKind::Point3);
  std::vector<char> connected(nn, 0);
  const int ne = static_cast<int>(model.elements.size());
  mesh.sceneElementFirst.resize(ne);
  mesh.sceneElementCount.resize(ne);
  for (int e = 0; e < ne; ++e) {
    const auto& en = model.elements[e];
    const int set = model.elementSet[e];
    const ElementType type = elementTypeOf(model, e);
    const NodeKind nk = kindOf(type);
    for (int n : en) {
      connected[n] = 1;
      if (nk == NodeKind::Frame6 || (nk == NodeKind::Ancf2D)) mesh.kind[n] = nk;
    }
    const bool line = en.size() == 2;
    const int nsub = (line && set >= 0) ? model.eprops[set].nbeams : 1;
    mesh.sceneElementFirst[e] = static_cast<int>(mesh.elements.size());
    mesh.sceneElementCount[e] = nsub;
    if (nsub == 1) {
      FeElement fe{e, set, static_cast<int>(en.size()), {}};
      for (size_t i = 0; i < en.size(); ++i) fe.nodes[i] = en[i];
      mesh.elements.push_back(fe);
      continue;
    }
    // Straight-line generator: nsub - 1 interior nodes at equal spacing.
    const Vec3 a = model.nodes[en[0]], b = model.nodes[en[1]];
    int prev = en[0];
    for (int k = 1; k <= nsub; ++k) {
      int next = en[1];
      if (k < nsub) {
        const double s = static_cast<double>(k) / nsub;
        next = static_cast<int>(mesh.X.size());
        mesh.X.push_back(a + s * (b - a));
        mesh.kind.push_back(nk);
      }
      mesh.elements.push_back(FeElement{e, set, 2, {prev, next, 0, 0}});
      prev = next;
    }
  }
  // trailing unconnected nodes (after the last connected one) are allowed, as in SPACAR Light: they
  // are held fixed (distributeMesh); any other unconnected node is an error
  int last = -1;
  for (int n = 0; n < nn; ++n)
    if (connected[n]) last = n;
  for (int n = 0; n < last; ++n)
    if (!connected[n])
      throw SceneError(indexedPath("nodes", static_cast<std::size_t>(n)),
                       "node " + std::to_string(n + 1) + " is not connected to any element");
  mesh.connected.assign(mesh.X.size(), 1);
  for (int n = last + 1; n < nn; ++n) mesh.connected[n] = 0;

  // ANCF reference slopes: unit average of the chord directions of the adjacent elements
  // (the tangent of the circle through three consecutive nodes of a regular polygon).
  const int nfe = static_cast<int>(mesh.X.size());
  mesh.slope.assign(nfe, {0.0, 0.0});
  for (const FeElement& fe : mesh.elements) {
    if (elementTypeOf(model, fe.sceneElement) != ElementType::AncfCable2D) continue;
    const Vec3 d = mesh.X[fe.nodes[1]] - mesh.X[fe.nodes[0]];
    const double l = norm(d);
    for (int i = 0; i < 2; ++i) {
      mesh.slope[fe.nodes[i]][0] += d[0] / l;
      mesh.slope[fe.nodes[i]][1] += d[1] / l;
    }
  }
  for (int n = 0; n < nfe; ++n) {
    auto& s = mesh.slope[n];
    const double l = std::hypot(s[0], s[1]);
    if (l > 0) s = {s[0] / l, s[1] / l};
    else s = {1.0, 0.0};
  }
  // nprops slope: the given reference slope of an ANCF scene node (not normalized: |r'| != 1 is
  // a reference axial stretch, as with Exudyn's initial coordinates)
  for (const auto& [node, np] : model.nprops)
    if (np.slope && mesh.kind[node] == NodeKind::Ancf2D) mesh.slope[node] = *np.slope;
  return mesh;
}

}  // namespace sinew
