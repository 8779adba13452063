#include "python/python_scene.hpp"

#include <charconv>
#include <cmath>
#include <string>

namespace py = pybind11;

namespace sinew::python {

void emitScene(YAML::Emitter& out, const py::handle& v) {
  if (py::isinstance<py::dict>(v)) {
    out << YAML::BeginMap;
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(v)) {
      out << YAML::Key;
      emitScene(out, key);
      out << YAML::Value;
      emitScene(out, value);
    }
    out << YAML::EndMap;
  } else if (py::hasattr(v, "tolist") && !py::isinstance<py::str>(v)) {  // numpy arrays and scalars
    emitScene(out, v.attr("tolist")());
  } else if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    out << YAML::Flow << YAML::BeginSeq;
    for (const py::handle item : v) emitScene(out, item);
    out << YAML::EndSeq;
  } else if (v.is_none()) {
    out << YAML::Null;
  } else if (py::isinstance<py::bool_>(v)) {
    out << (v.cast<bool>() ? "true" : "false");
  } else if (py::isinstance<py::float_>(v)) {
    const double x = v.cast<double>();
    out << (std::isnan(x) ? std::string(".nan") : std::isinf(x) ? std::string(x > 0 ? ".inf" : "-.inf") : py::repr(v).cast<std::string>());
  } else if (py::isinstance<py::int_>(v)) {
    out << py::str(v).cast<std::string>();
  } else {
    out << py::str(v).cast<std::string>();
  }
}

namespace {

/// Where a scalar stands in emitScene's text: the emitter's choice of plain or quoted depends on
/// whether it is inside a flow collection; a probe puts the string where it stands.
enum class Place { Document, BlockKey, BlockValue, FlowItem, FlowKey, FlowValue };

bool isAsciiWordChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.';
}

/// Strings the emitter writes plain in every place inside a collection and YAML reads back as
/// themselves: words and numbers ([A-Za-z0-9_.], then also + and -; a leading - only before a
/// digit or '.'), but not the null words.
bool plainEverywhere(const std::string& s) {
  if (s.empty()) return false;
  const char c0 = s[0];
  if (!isAsciiWordChar(c0) && !(c0 == '-' && s.size() > 1 && (std::isdigit(static_cast<unsigned char>(s[1])) || s[1] == '.')))
    return false;
  for (std::size_t i = 1; i < s.size(); ++i)
    if (!isAsciiWordChar(s[i]) && s[i] != '+' && s[i] != '-') return false;
  return s != "null" && s != "Null" && s != "NULL";
}

class TreeBuilder {
 public:
  bool exact = true;  // every string read back as itself

  /// v as a node at `place` (containers are filled after they are attached: one node memory).
  YAML::Node node(const py::handle& v, Place place) {
    if (PyDict_Check(v.ptr())) {
      YAML::Node map(YAML::NodeType::Map);
      fillMap(map, v, flow(place));
      return map;
    }
    if (PyList_CheckExact(v.ptr()) || PyTuple_CheckExact(v.ptr())) {
      YAML::Node seq(YAML::NodeType::Sequence);
      fillSeq(seq, v);
      return seq;
    }
    if (PyFloat_CheckExact(v.ptr())) return scalar(floatText(PyFloat_AS_DOUBLE(v.ptr())), place);
    if (PyBool_Check(v.ptr())) return scalar(v.ptr() == Py_True ? "true" : "false", place);
    if (PyLong_CheckExact(v.ptr())) return scalar(intText(v), place);
    if (PyUnicode_CheckExact(v.ptr())) return scalar(strText(v), place);
    if (v.is_none()) return YAML::Node(YAML::NodeType::Null);
    // other types, in emitScene's order
    if (py::hasattr(v, "tolist") && !py::isinstance<py::str>(v)) return node(v.attr("tolist")(), place);
    if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
      YAML::Node seq(YAML::NodeType::Sequence);
      fillSeq(seq, v);
      return seq;
    }
    if (py::isinstance<py::float_>(v)) {
      const double x = v.cast<double>();
      return scalar(std::isnan(x) || std::isinf(x) ? floatText(x) : py::repr(v).cast<std::string>(), place);
    }
    if (py::isinstance<py::int_>(v)) return scalar(py::str(v).cast<std::string>(), place);
    return scalar(py::str(v).cast<std::string>(), place);
  }

 private:
  static bool flow(Place p) { return p == Place::FlowItem || p == Place::FlowKey || p == Place::FlowValue; }

  void fillMap(YAML::Node& map, const py::handle& v, bool inFlow) {
    map.SetTag("?");
    map.SetStyle(inFlow ? YAML::EmitterStyle::Flow : YAML::EmitterStyle::Block);
    PyObject *key = nullptr, *value = nullptr;
    Py_ssize_t pos = 0;
    while (PyDict_Next(v.ptr(), &pos, &key, &value)) {
      const py::handle k(key), x(value);
      YAML::Node keyNode = node(k, inFlow ? Place::FlowKey : Place::BlockKey);
      const Place at = inFlow ? Place::FlowValue : Place::BlockValue;
      if (PyDict_Check(value)) {  // attached first, then filled
        YAML::Node child(YAML::NodeType::Map);
        map.force_insert(keyNode, child);
        fillMap(child, x, inFlow);
      } else if (PyList_CheckExact(value) || PyTuple_CheckExact(value)) {
        YAML::Node child(YAML::NodeType::Sequence);
        map.force_insert(keyNode, child);
        fillSeq(child, x);
      } else {
        map.force_insert(keyNode, node(x, at));
      }
    }
  }

  void fillSeq(YAML::Node& seq, const py::handle& v) {
    seq.SetTag("?");
    seq.SetStyle(YAML::EmitterStyle::Flow);
    for (const py::handle item : v) {
      if (PyDict_Check(item.ptr())) {
        YAML::Node child(YAML::NodeType::Map);
        seq.push_back(child);
        fillMap(child, item, true);
      } else if (PyList_CheckExact(item.ptr()) || PyTuple_CheckExact(item.ptr())) {
        YAML::Node child(YAML::NodeType::Sequence);
        seq.push_back(child);
        fillSeq(child, item);
      } else {
        seq.push_back(node(item, Place::FlowItem));
      }
    }
  }

  /// Python's repr of a float (shortest round-trip digits, ".0" added), .nan/.inf/-.inf.
  static std::string floatText(double x) {
    if (std::isnan(x)) return ".nan";
    if (std::isinf(x)) return x > 0 ? ".inf" : "-.inf";
    char* s = PyOS_double_to_string(x, 'r', 0, Py_DTSF_ADD_DOT_0, nullptr);
    if (!s) throw py::error_already_set();
    std::string text(s);
    PyMem_Free(s);
    return text;
  }

  static std::string intText(const py::handle& v) {
    int overflow = 0;
    const long long i = PyLong_AsLongLongAndOverflow(v.ptr(), &overflow);
    if (overflow || (i == -1 && PyErr_Occurred())) {
      PyErr_Clear();
      return py::str(v).cast<std::string>();
    }
    char buf[32];
    return std::string(buf, std::to_chars(buf, buf + sizeof buf, i).ptr);
  }

  static std::string strText(const py::handle& v) {
    Py_ssize_t n = 0;
    const char* s = PyUnicode_AsUTF8AndSize(v.ptr(), &n);
    if (!s) {
      PyErr_Clear();
      return py::str(v).cast<std::string>();  // raises as emitScene does
    }
    return std::string(s, static_cast<std::size_t>(n));
  }

  /// A scalar as the reader sees it: a word or number is plain (tag "?"); any other string is
  /// emitted at its place and read back (its tag says whether the emitter quoted it).
  YAML::Node scalar(const std::string& s, Place place) {
    if (place != Place::Document && plainEverywhere(s)) {  // a lone "..." would end the document
      YAML::Node n(s);
      n.SetTag("?");
      return n;
    }
    YAML::Node n = probe(s, place);
    if (!n.IsScalar() || n.Scalar() != s) {
      exact = false;
      return YAML::Node(s);
    }
    return n;
  }

  static YAML::Node probe(const std::string& s, Place place) {
    YAML::Emitter out;
    switch (place) {
      case Place::Document: out << s; break;
      case Place::BlockKey: out << YAML::BeginMap << YAML::Key << s << YAML::Value << YAML::Null << YAML::EndMap; break;
      case Place::BlockValue: out << YAML::BeginMap << YAML::Key << "k" << YAML::Value << s << YAML::EndMap; break;
      case Place::FlowItem: out << YAML::Flow << YAML::BeginSeq << s << YAML::EndSeq; break;
      case Place::FlowKey:
        out << YAML::Flow << YAML::BeginSeq << YAML::BeginMap << YAML::Key << s << YAML::Value << YAML::Null << YAML::EndMap
            << YAML::EndSeq;
        break;
      case Place::FlowValue:
        out << YAML::Flow << YAML::BeginSeq << YAML::BeginMap << YAML::Key << "k" << YAML::Value << s << YAML::EndMap
            << YAML::EndSeq;
        break;
    }
    try {
      const YAML::Node doc = YAML::Load(out.c_str());
      const YAML::Node map = place == Place::FlowKey || place == Place::FlowValue ? doc[0] : doc;
      switch (place) {
        case Place::Document: return doc;
        case Place::FlowItem: return doc[0];
        case Place::BlockKey:
        case Place::FlowKey: return map.begin()->first;
        default: return map.begin()->second;
      }
    } catch (const YAML::Exception&) {
      return YAML::Node();
    }
  }
};

}  // namespace

std::optional<YAML::Node> sceneTree(const py::handle& v) {
  TreeBuilder builder;
  YAML::Node root = builder.node(v, Place::Document);
  if (!builder.exact) return std::nullopt;
  return root;
}

}  // namespace sinew::python
