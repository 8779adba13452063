#include "accuracy/found_shape_reuse.hpp"

#include "accuracy/level_reuse.hpp"
#include "accuracy/membrane_refinement.hpp"
#include "mesh/fe_mesh.hpp"

namespace sinew::accuracy {

namespace {

bool positionsOnly(const FeMesh& mesh) {
  for (NodeKind k : mesh.kind)
    if (k != NodeKind::Point3) return false;
  return true;
}

/// The split membranes' levels: the fine level is one split of the coarse one, its FE nodes its nodes.
std::vector<LevelState> splitDisplacements(const Model& coarse, const FeMesh& cm, const FeMesh& fm,
                                           const std::vector<LevelState>& disp) {
  const std::size_t nc = cm.X.size(), nf = fm.X.size();
  if (nc != coarse.nodes.size()) return {};  // split cables with inner FE nodes (nbeams > 1)
  const std::vector<std::vector<int>> parents = splitParents(coarse);
  if (nf != nc + parents.size()) return {};
  std::vector<LevelState> out;
  for (const LevelState& d : disp) {
    LevelState g;
    g.loadFactor = d.loadFactor;
    g.nodes.assign(12 * nf, 0.0);
    std::copy(d.nodes.begin(), d.nodes.end(), g.nodes.begin());  // the coarse nodes keep their numbers
    for (std::size_t i = 0; i < parents.size(); ++i) {
      double* s = &g.nodes[12 * (nc + i)];
      const double w = 1.0 / static_cast<double>(parents[i].size());
      for (int p : parents[i])
        for (std::size_t k = 0; k < 3; ++k) s[k] += w * d.nodes[12 * static_cast<std::size_t>(p) + k];
    }
    out.push_back(std::move(g));
  }
  return out;
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
  // a cable's midpoint is its chord's (linear in the end positions, so in the displacements too)
  return hasMembranes(coarse) ? splitDisplacements(coarse, cm, fm, disp) : interpolateStates(coarse, fine, disp);
}

}  // namespace sinew::accuracy
