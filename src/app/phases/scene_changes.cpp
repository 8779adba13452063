#include "app/phases/scene_changes.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>

#include "scene/yaml_fields.hpp"

namespace sinew {
namespace {

/// A value as the scene gives it (flow YAML), shortened for a message.
std::string shown(const YAML::Node& n) {
  YAML::Emitter e;
  e << YAML::Flow << n;
  std::string s = e.c_str();
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  return s;
}

/// Equal values: equal numbers however written (0 and 0.0, 210e9 and 2.1e11), else the same text.
bool sameValue(const YAML::Node& a, const YAML::Node& b) {
  if (a.IsScalar() && b.IsScalar()) {
    double x = 0, y = 0;
    if (YAML::convert<double>::decode(a, x) && YAML::convert<double>::decode(b, y)) return x == y;
  }
  return shown(a) == shown(b);
}

struct Differ {
  const std::function<bool(const std::string&)>& keep;
  std::vector<std::string> out;

  void node(const YAML::Node& a, const YAML::Node& b, const std::string& path, const std::string& key) {
    if (a.IsMap() && b.IsMap()) return map(a, b, path);
    if (a.IsSequence() && b.IsSequence() && a.size() == b.size()) {
      for (std::size_t i = 0; i < a.size(); ++i) node(a[i], b[i], scene::indexPath(path, i), key);
      return;
    }
    if (!keep(key)) return;
    if (a.IsSequence() && b.IsSequence())
      out.push_back(path + " changed: " + std::to_string(a.size()) + " entries -> " + std::to_string(b.size()));
    else if (!sameValue(a, b))
      out.push_back(path + " changed: " + shown(a) + " -> " + shown(b));
  }

  void map(const YAML::Node& a, const YAML::Node& b, const std::string& path) {
    const auto sub = [&](const std::string& k) {
      return path == "nprops" || path == "opt.rls" ? scene::numberedPath(path, k) : scene::childPath(path, k);
    };
    for (auto it = b.begin(); it != b.end(); ++it) {  // changed and added keys, in the new scene's order
      const std::string k = it->first.as<std::string>();
      const YAML::Node old = a[k];
      if (!old.IsDefined()) {
        if (it->second.IsMap()) map(YAML::Node(YAML::NodeType::Map), it->second, sub(k));
        else if (keep(k)) out.push_back(sub(k) + " added: " + shown(it->second));
        continue;
      }
      node(old, it->second, sub(k), k);
    }
    for (auto it = a.begin(); it != a.end(); ++it) {  // removed keys
      const std::string k = it->first.as<std::string>();
      if (b[k].IsDefined()) continue;
      if (it->second.IsMap()) map(it->second, YAML::Node(YAML::NodeType::Map), sub(k));
      else if (keep(k)) out.push_back(sub(k) + " removed (was " + shown(it->second) + ")");
    }
  }
};

}  // namespace

std::vector<std::string> sceneFieldChanges(const std::string& before, const std::string& after,
                                           const std::function<bool(const std::string& key)>& keep) {
  YAML::Node a, b;
  try {
    a = YAML::Load(before);
    b = YAML::Load(after);
  } catch (const YAML::Exception&) {
    return {};
  }
  if (!a.IsMap() || !b.IsMap()) return {};
  Differ d{keep, {}};
  const auto block = [&](const YAML::Node& x, const YAML::Node& y, const std::string& path, const std::string& key) {
    if (x.IsDefined() && y.IsDefined()) d.node(x, y, path, key);
    else if (y.IsDefined()) d.out.push_back(path + " added");
    else if (x.IsDefined()) d.out.push_back(path + " removed");
  };
  for (const char* k : {"nodes", "elements", "mesh", "eprops", "nprops", "formfinding"}) block(a[k], b[k], k, k);
  const YAML::Node ao = a["opt"], bo = b["opt"];
  for (const char* k : {"rls", "gravity"}) {
    const YAML::Node x = ao.IsMap() ? ao[k] : YAML::Node(), y = bo.IsMap() ? bo[k] : YAML::Node();
    block(x, y, std::string("opt.") + k, k);
  }
  return d.out;
}

}  // namespace sinew
