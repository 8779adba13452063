#include "scene/gmsh_reader.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <istream>
#include <map>
#include <sstream>
#include <unordered_map>

namespace sinew {
namespace {

/// Whitespace-separated tokens with line numbers; sections are read token by token.
class Lexer {
 public:
  Lexer(std::istream& in, std::string file) : in_(in), file_(std::move(file)) {}

  [[noreturn]] void error(const std::string& message, int line = -1) const {
    throw SceneError("mesh", file_ + ":" + std::to_string(line < 0 ? line_ : line) + ": " + message);
  }

  /// Next token, or "" at end of file.
  std::string next() {
    while (pos_ >= tokens_.size()) {
      if (!readLine()) return "";
    }
    tokenLine_ = line_;
    return tokens_[pos_++];
  }

  std::string expectToken(const std::string& what) {
    std::string t = next();
    if (t.empty()) error("unexpected end of file, expected " + what);
    return t;
  }

  long long integer(const std::string& what) {
    const std::string t = expectToken(what);
    long long v = 0;
    auto res = std::from_chars(t.data(), t.data() + t.size(), v);
    if (res.ec != std::errc() || res.ptr != t.data() + t.size()) error("expected " + what + ", got '" + t + "'", tokenLine_);
    return v;
  }

  double real(const std::string& what) {
    const std::string t = expectToken(what);
    std::istringstream s(t);
    double v = 0;
    s >> v;
    if (!s || !s.eof()) error("expected " + what + ", got '" + t + "'", tokenLine_);
    return v;
  }

  /// Drop what is left of the current line (e.g. parametric coordinates).
  void skipRestOfLine() { pos_ = tokens_.size(); }

  /// The whole next non-empty line (for quoted names), or "" at end of file.
  std::string rawLine() {
    skipRestOfLine();
    std::string s;
    while (std::getline(in_, s)) {
      ++line_;
      if (!s.empty() && s.back() == '\r') s.pop_back();
      if (s.find_first_not_of(" \t") != std::string::npos) return s;
    }
    return "";
  }

  /// Skip to the line `$End<name>`.
  void skipSection(const std::string& name) {
    const int start = line_;
    for (;;) {
      std::string s = rawLine();
      if (s.empty()) error("missing $End" + name + " for the section started here", start);
      if (s.rfind("$End" + name, 0) == 0) return;
    }
  }

  void expectEnd(const std::string& name) {
    const std::string t = next();
    if (t != "$End" + name) error("expected $End" + name + ", got '" + t + "'", tokenLine_);
  }

  int line() const { return line_; }
  int tokenLine() const { return tokenLine_; }

 private:
  bool readLine() {
    std::string s;
    if (!std::getline(in_, s)) return false;
    ++line_;
    tokens_.clear();
    pos_ = 0;
    std::istringstream ss(s);
    for (std::string t; ss >> t;) tokens_.push_back(t);
    return true;
  }

  std::istream& in_;
  std::string file_;
  std::vector<std::string> tokens_;
  std::size_t pos_ = 0;
  int line_ = 0, tokenLine_ = 0;
};

std::string typeName(int type) {
  switch (type) {
    case 1: return "2-node line";
    case 2: return "3-node triangle";
    case 3: return "4-node quadrangle";
    case 4: return "4-node tetrahedron";
    case 5: return "8-node hexahedron";
    case 6: return "6-node prism";
    case 7: return "5-node pyramid";
    case 8: return "3-node line";
    case 9: return "6-node triangle";
    case 10: return "9-node quadrangle";
    case 11: return "10-node tetrahedron";
    case 15: return "point";
    case 16: return "8-node quadrangle";
    default: return "type " + std::to_string(type);
  }
}

using EntityKey = std::pair<int, int>;  // (dim, tag)

}  // namespace

int gmshNodesPerElement(int type) {
  switch (type) {
    case 1: return 2;
    case 2: return 3;
    case 3: return 4;
    case 15: return 1;
    default: return 0;
  }
}

const GmshPhysicalGroup* GmshMesh::findGroup(const std::string& name) const {
  for (const auto& g : groups)
    if (g.name == name) return &g;
  return nullptr;
}

std::vector<std::string> GmshMesh::groupNames() const {
  std::vector<std::string> names;
  for (const auto& g : groups) names.push_back(g.name);
  return names;
}

GmshMesh parseGmsh(std::istream& in, const std::string& file) {
  Lexer lex(in, file);
  GmshMesh mesh;
  mesh.file = file;
  bool haveFormat = false, haveNodes = false, haveElements = false;
  bool v41 = true;
  std::map<EntityKey, std::string> physicalNames;        // (dim, physical tag) -> name
  std::map<EntityKey, std::vector<int>> entityPhysicals;  // (dim, entity tag) -> physical tags
  std::unordered_map<std::size_t, int> nodeIndex;

  for (;;) {
    const std::string section = lex.next();
    if (section.empty()) break;
    if (section.size() < 2 || section[0] != '$') lex.error("expected a section like $Nodes, got '" + section + "'", lex.tokenLine());
    const std::string name = section.substr(1);
    if (name == "MeshFormat") {
      mesh.version = lex.expectToken("the format version");
      const long long fileType = lex.integer("the file type");
      lex.integer("the data size");
      if (mesh.version.empty() || mesh.version[0] != '4')
        lex.error("Gmsh format " + mesh.version + " is not supported; save as format 4 (gmsh -format msh4)", lex.tokenLine());
      if (fileType != 0) lex.error("binary .msh files are not supported; save as ASCII (Mesh.Binary = 0)", lex.tokenLine());
      v41 = mesh.version != "4" && mesh.version != "4.0";
      lex.expectEnd(name);
      haveFormat = true;
    } else if (name == "PhysicalNames") {
      const long long count = lex.integer("the number of physical names");
      for (long long i = 0; i < count; ++i) {
        const std::string line = lex.rawLine();
        std::istringstream ss(line);
        int dim = 0, tag = 0;
        if (!(ss >> dim >> tag)) lex.error("expected 'dim tag \"name\"', got '" + line + "'");
        std::string rest;
        std::getline(ss, rest);
        const auto a = rest.find('"'), b = rest.rfind('"');
        if (a == std::string::npos || b == a) lex.error("expected a quoted physical name, got '" + line + "'");
        physicalNames[{dim, tag}] = rest.substr(a + 1, b - a - 1);
      }
      lex.expectEnd(name);
    } else if (name == "Entities") {
      long long count[4];
      for (auto& c : count) c = lex.integer("the number of entities");
      for (int dim = 0; dim < 4; ++dim) {
        for (long long i = 0; i < count[dim]; ++i) {
          const int tag = static_cast<int>(lex.integer("an entity tag"));
          const int nbox = (dim == 0 && v41) ? 3 : 6;
          for (int k = 0; k < nbox; ++k) lex.real("a coordinate");
          const long long nphys = lex.integer("the number of physical tags");
          auto& phys = entityPhysicals[{dim, tag}];
          for (long long k = 0; k < nphys; ++k) phys.push_back(static_cast<int>(std::abs(lex.integer("a physical tag"))));
          if (dim > 0) {
            const long long nbound = lex.integer("the number of bounding entities");
            for (long long k = 0; k < nbound; ++k) lex.integer("a bounding entity tag");
          }
        }
      }
      lex.expectEnd(name);
    } else if (name == "Nodes") {
      if (!haveFormat) lex.error("$Nodes before $MeshFormat");
      const long long blocks = lex.integer("the number of node blocks");
      const long long total = lex.integer("the number of nodes");
      if (v41) {
        lex.integer("the minimum node tag");
        lex.integer("the maximum node tag");
      }
      mesh.nodes.reserve(static_cast<std::size_t>(std::clamp(total, 0LL, 1LL << 20)));
      for (long long b = 0; b < blocks; ++b) {
        long long dim = 0, tag = 0;
        if (v41) {
          dim = lex.integer("the entity dimension");
          tag = lex.integer("the entity tag");
        } else {
          tag = lex.integer("the entity tag");
          dim = lex.integer("the entity dimension");
        }
        (void)dim;
        (void)tag;
        const long long parametric = lex.integer("the parametric flag");
        const long long n = lex.integer("the number of nodes in the block");
        std::vector<std::size_t> tags;
        std::vector<int> lines;
        if (v41) {
          for (long long k = 0; k < n; ++k) {
            tags.push_back(static_cast<std::size_t>(lex.integer("a node tag")));
            lines.push_back(lex.tokenLine());
          }
        }
        for (long long k = 0; k < n; ++k) {
          if (!v41) {
            tags.push_back(static_cast<std::size_t>(lex.integer("a node tag")));
            lines.push_back(lex.tokenLine());
          }
          Vec3 x;
          for (auto& c : x) c = lex.real("a node coordinate");
          if (parametric) lex.skipRestOfLine();
          const std::size_t t = tags[static_cast<std::size_t>(k)];
          if (!nodeIndex.emplace(t, static_cast<int>(mesh.nodes.size())).second)
            lex.error("node tag " + std::to_string(t) + " appears twice", lines[static_cast<std::size_t>(k)]);
          mesh.nodes.push_back(x);
          mesh.nodeTags.push_back(t);
          mesh.nodeLines.push_back(lex.tokenLine());
        }
      }
      if (static_cast<long long>(mesh.nodes.size()) != total)
        lex.error("$Nodes announces " + std::to_string(total) + " nodes but holds " + std::to_string(mesh.nodes.size()));
      lex.expectEnd(name);
      haveNodes = true;
    } else if (name == "Elements") {
      if (!haveNodes) lex.error("$Elements before $Nodes");
      const long long blocks = lex.integer("the number of element blocks");
      const long long total = lex.integer("the number of elements");
      if (v41) {
        lex.integer("the minimum element tag");
        lex.integer("the maximum element tag");
      }
      for (long long b = 0; b < blocks; ++b) {
        long long dim = 0, tag = 0;
        if (v41) {
          dim = lex.integer("the entity dimension");
          tag = lex.integer("the entity tag");
        } else {
          tag = lex.integer("the entity tag");
          dim = lex.integer("the entity dimension");
        }
        const int type = static_cast<int>(lex.integer("the element type"));
        const int blockLine = lex.tokenLine();
        const long long n = lex.integer("the number of elements in the block");
        const int nn = gmshNodesPerElement(type);
        if (nn == 0)
          lex.error("element type " + std::to_string(type) + " (" + typeName(type) +
                        ") is not supported: use first-order lines, triangles or quadrangles (Mesh.ElementOrder = 1)",
                    blockLine);
        for (long long k = 0; k < n; ++k) {
          GmshElement e;
          e.type = type;
          e.dim = static_cast<int>(dim);
          e.entityTag = static_cast<int>(tag);
          e.tag = static_cast<std::size_t>(lex.integer("an element tag"));
          e.line = lex.tokenLine();
          for (int j = 0; j < nn; ++j) {
            const auto t = static_cast<std::size_t>(lex.integer("a node tag of element " + std::to_string(e.tag)));
            auto it = nodeIndex.find(t);
            if (it == nodeIndex.end()) lex.error("element " + std::to_string(e.tag) + " refers to node tag " + std::to_string(t) + ", which is not in $Nodes", lex.tokenLine());
            e.nodes.push_back(it->second);
          }
          mesh.elements.push_back(std::move(e));
        }
      }
      if (static_cast<long long>(mesh.elements.size()) != total)
        lex.error("$Elements announces " + std::to_string(total) + " elements but holds " + std::to_string(mesh.elements.size()));
      lex.expectEnd(name);
      haveElements = true;
    } else {
      lex.skipSection(name);
    }
  }
  if (!haveFormat) lex.error("no $MeshFormat section: not a Gmsh file");
  if (!haveNodes) lex.error("no $Nodes section");
  if (!haveElements) lex.error("no $Elements section");

  // Physical groups: an element belongs to the physical groups of its entity.
  std::map<EntityKey, int> groupIndex;
  for (const auto& [entity, phys] : entityPhysicals) {
    for (int p : phys) {
      const EntityKey key{entity.first, p};
      if (groupIndex.count(key)) continue;
      GmshPhysicalGroup g;
      g.dim = entity.first;
      g.tag = p;
      auto nm = physicalNames.find(key);
      g.name = nm != physicalNames.end() ? nm->second : std::to_string(p);
      groupIndex[key] = static_cast<int>(mesh.groups.size());
      mesh.groups.push_back(std::move(g));
    }
  }
  for (std::size_t i = 0; i < mesh.elements.size(); ++i) {
    auto& e = mesh.elements[i];
    auto it = entityPhysicals.find({e.dim, e.entityTag});
    if (it == entityPhysicals.end()) continue;
    for (int p : it->second) {
      const int g = groupIndex.at({e.dim, p});
      e.groups.push_back(g);
      mesh.groups[static_cast<std::size_t>(g)].elements.push_back(static_cast<int>(i));
      auto& nodes = mesh.groups[static_cast<std::size_t>(g)].nodes;
      nodes.insert(nodes.end(), e.nodes.begin(), e.nodes.end());
    }
  }
  for (auto& g : mesh.groups) {
    std::sort(g.nodes.begin(), g.nodes.end());
    g.nodes.erase(std::unique(g.nodes.begin(), g.nodes.end()), g.nodes.end());
  }
  return mesh;
}

GmshMesh readGmsh(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw SceneError("mesh", "'" + path + "' is a directory, not a Gmsh mesh file");
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw SceneError("mesh", "'" + path + "' is not a regular file (a device or a pipe), not a Gmsh mesh file");
  std::ifstream in(path);
  if (!in) throw SceneError("mesh", "cannot open mesh file '" + path + "'");
  return parseGmsh(in, path);
}

}  // namespace sinew
