// What changed between the scene of an earlier run and this one, field by field, for a refused
// restart: "eprops(2).emod changed: 2.1e11 -> 2e11" (1-based paths as in every message).
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace sinew {

/// The fields of the model blocks (nodes, elements, mesh, eprops, nprops, formfinding, opt.rls,
/// opt.gravity) that differ between the scene texts `before` and `after`, in scene order: changed
/// values, added and removed keys, lists of another length. `keep(key)` selects the fields by their
/// key (the last map key on the path); an empty result when a text does not parse.
std::vector<std::string> sceneFieldChanges(const std::string& before, const std::string& after,
                                           const std::function<bool(const std::string& key)>& keep);

}  // namespace sinew
