#include "scene/scene_tree.hpp"

namespace sinew {
namespace {

void emitTree(YAML::Emitter& out, const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Map:
      out << YAML::BeginMap;
      for (auto it = n.begin(); it != n.end(); ++it) {
        out << YAML::Key;
        emitTree(out, it->first);
        out << YAML::Value;
        emitTree(out, it->second);
      }
      out << YAML::EndMap;
      break;
    case YAML::NodeType::Sequence:
      out << YAML::Flow << YAML::BeginSeq;
      for (auto it = n.begin(); it != n.end(); ++it) emitTree(out, *it);
      out << YAML::EndSeq;
      break;
    case YAML::NodeType::Scalar:
      out << n.Scalar();
      break;
    default:  // null (an undefined node is no entry of a map or list)
      out << YAML::Null;
  }
}

const char* kindName(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Scalar: return "a scalar";
    case YAML::NodeType::Null: return "null";
    default: return "undefined";
  }
}

}  // namespace

std::string sceneTreeText(const YAML::Node& root) {
  YAML::Emitter out;
  emitTree(out, root);
  return out.c_str();
}

bool treeMentions(const YAML::Node& n, const std::string& word) {
  if (n.IsScalar()) return n.Scalar().find(word) != std::string::npos;
  if (n.IsSequence())
    for (auto it = n.begin(); it != n.end(); ++it)
      if (treeMentions(*it, word)) return true;
  if (n.IsMap())
    for (auto it = n.begin(); it != n.end(); ++it)
      if (treeMentions(it->first, word) || treeMentions(it->second, word)) return true;
  return false;
}

std::string treeDifference(const YAML::Node& a, const YAML::Node& b, const std::string& path) {
  const std::string where = path.empty() ? "the root" : path;
  if (a.Type() != b.Type()) return where + ": " + kindName(a) + " against " + kindName(b);
  if (a.Tag() != b.Tag()) return where + ": tag '" + a.Tag() + "' against '" + b.Tag() + "'";
  if (a.IsScalar() && a.Scalar() != b.Scalar()) return where + ": '" + a.Scalar() + "' against '" + b.Scalar() + "'";
  if (!a.IsMap() && !a.IsSequence()) return "";
  if (a.size() != b.size())
    return where + ": " + std::to_string(a.size()) + " entries against " + std::to_string(b.size());
  auto j = b.begin();
  std::size_t i = 0;
  for (auto it = a.begin(); it != a.end(); ++it, ++j, ++i) {
    const std::string at = path + "[" + std::to_string(i) + "]";
    if (a.IsSequence()) {
      if (std::string d = treeDifference(*it, *j, at); !d.empty()) return d;
      continue;
    }
    if (std::string d = treeDifference(it->first, j->first, at + " key"); !d.empty()) return d;
    const std::string key = it->first.IsScalar() ? it->first.Scalar() : at;
    if (std::string d = treeDifference(it->second, j->second, path.empty() ? key : path + "." + key); !d.empty()) return d;
  }
  return "";
}

}  // namespace sinew
