#include "accuracy/found_shape_reuse.hpp"

#include "accuracy/level_reuse.hpp"
#include "mesh/fe_mesh.hpp"

namespace sinew::accuracy {

namespace {

bool positionsOnly(const FeMesh& mesh) {
  for (NodeKind k : mesh.kind)
    if (k != NodeKind::Point3) return false;
  return true;
}

}  // namespace

std::vector<LevelState> interpolateDisplacements(const Model& coarse, const Model& fine, const std::vector<LevelState>& record,
                                                 const LevelState& start) {
  const FeMesh cm = discretize(coarse), fm = discretize(fine);
  if (!positionsOnly(cm) || !positionsOnly(fm)) return {};
  const std::size_t nc = cm.X.size();
  if (start.nodes.size() != 12 * nc) return {};
  std::vector<LevelState> disp;  // the coarse level's displacements from its found shape
  for (const LevelState& st : record) {
    if (st.nodes.size() != 12 * nc) return {};
    LevelState d;
    d.loadFactor = st.loadFactor;
    d.nodes.assign(12 * nc, 0.0);
    for (std::size_t n = 0; n < nc; ++n)
      for (std::size_t k = 0; k < 3; ++k) d.nodes[12 * n + k] = st.nodes[12 * n + k] - start.nodes[12 * n + k];
    disp.push_back(std::move(d));
  }
  // a cable's midpoint is its chord's and a split membrane's new node the mean of its parents (linear in
  // the positions, so in the displacements too)
  return LevelNodeMap(coarse, fine).apply(disp);
}

}  // namespace sinew::accuracy
