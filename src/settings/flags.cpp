#include "settings/flags.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

#include "scene/scene_reader.hpp"
#include "settings/fields.hpp"

namespace sinew {

namespace flag_groups {
const FlagGroup output{"Result file", "README.md"};
const FlagGroup scene{"Scene opt fields (each overrides the field of the scene's opt block)", "docs/scene.md"};
const FlagGroup statics{"Statics and path following (load stepping, Newton)", "docs/beam.md"};
const FlagGroup ancf{"Fine ANCF cables (element-wise tangent, cable coarse space)", "docs/ancf_cable2d.md"};
const FlagGroup check{"Model check (mechanisms, redundant constraints)", "docs/compliance.md"};
const FlagGroup modal{"Frequencies and buckling (SLEPc)", "docs/modal.md"};
const FlagGroup compliance{"Compliance matrices", "docs/compliance.md"};
const FlagGroup dynamics{"Dynamics", "docs/dynamics.md"};
const FlagGroup formfinding{"Form finding", "docs/formfinding.md"};
const FlagGroup accuracy{"Accuracy on demand (opt.target_error)", "docs/accuracy.md"};
}  // namespace flag_groups

const std::vector<const FlagGroup*>& flagGroups() {
  using namespace flag_groups;
  static const std::vector<const FlagGroup*> all = {&scene, &output, &statics, &ancf, &check,
                                                    &modal, &compliance, &dynamics, &formfinding, &accuracy};
  return all;
}

const std::vector<Flag>& sinewFlags() {
  static const std::vector<Flag> flags = [] {
    std::vector<Flag> f;
    // the settings' fields, component by component (fields.cpp)
    forEachFieldTable([&f](const auto& table, auto) {
      for (const auto& d : table) f.push_back({d.flag, d.value, d.group, d.defaultText, d.help, d.developer});
    });
    // Every scene opt field is a flag of the same name (the scene reader checks its value).
    for (const OptionDoc& d : sceneOptionDocs()) {
      FlagValue v;
      v.kind = FlagValue::Kind::SceneOpt;
      v.sceneType = d.type;
      f.push_back({d.name, v, &flag_groups::scene, d.defaultValue, d.help, false});
    }
    return f;
  }();
  return flags;
}

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

/// An optional sign and digits only (PETSc's DEFAULT/DECIDE words are not Sinew values).
bool parseInteger(const std::string& s, double* v) {
  std::size_t i = (!s.empty() && (s[0] == '+' || s[0] == '-')) ? 1 : 0;
  if (i == s.size() || s.size() > 19) return false;
  for (std::size_t k = i; k < s.size(); ++k)
    if (!std::isdigit(static_cast<unsigned char>(s[k]))) return false;
  *v = std::strtod(s.c_str(), nullptr);
  return true;
}

bool parseReal(const std::string& s, double* v) {
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  *v = std::strtod(s.c_str(), &end);
  return end && *end == '\0' && errno == 0 && std::isfinite(*v);
}

bool inRange(const FlagValue& r, double v) {
  return (r.loOpen ? v > r.lo : v >= r.lo) && (r.hiOpen ? v < r.hi : v <= r.hi);
}

}  // namespace

FlagValue integerIn(double lo, double hi) {
  FlagValue v;
  v.kind = FlagValue::Kind::Int;
  v.lo = lo;
  v.hi = hi;
  return v;
}
FlagValue integerAtLeast(double lo) { return integerIn(lo, INT_MAX); }
FlagValue anyInteger() { return integerIn(INT_MIN, INT_MAX); }
FlagValue realIn(double lo, double hi, bool loOpen, bool hiOpen) {
  FlagValue v;
  v.kind = FlagValue::Kind::Real;
  v.lo = lo;
  v.hi = hi;
  v.loOpen = loOpen;
  v.hiOpen = hiOpen;
  return v;
}
FlagValue anyReal() { return realIn(-HUGE_VAL, HUGE_VAL, true, true); }
FlagValue boolean() { return FlagValue{}; }
FlagValue oneOf(std::vector<std::string> choices) {
  FlagValue v;
  v.kind = FlagValue::Kind::Choice;
  v.choices = std::move(choices);
  return v;
}
FlagValue text(std::string what) {
  FlagValue v;
  v.kind = FlagValue::Kind::Text;
  v.what = std::move(what);
  return v;
}

const Flag* findFlag(const std::string& name) {
  const std::string n = lower(name);
  for (const Flag& f : sinewFlags())
    if (f.name == n) return &f;
  return nullptr;
}

std::string repeatedFlag(int argc, const char* const* argv) {
  std::map<std::string, std::vector<std::string>> given;  // flag -> its values in order
  std::vector<std::string> order;
  for (int i = 1; i < argc; ++i) {
    const std::string t = argv[i];
    if (t.size() < 2 || t[0] != '-' || !std::isalpha(static_cast<unsigned char>(t[1]))) continue;  // -1e9 is a value
    const Flag* f = findFlag(t.substr(1));
    if (!f) continue;
    const bool hasValue = i + 1 < argc && !(argv[i + 1][0] == '-' && std::isalpha(static_cast<unsigned char>(argv[i + 1][1])));
    if (given[f->name].empty()) order.push_back(f->name);
    given[f->name].push_back(hasValue ? argv[i + 1] : "");
  }
  for (const std::string& name : order) {
    const std::vector<std::string>& v = given[name];
    if (v.size() < 2) continue;
    std::string values;
    for (const std::string& x : v) values += (values.empty() ? "" : ", ") + (x.empty() ? std::string("(no value)") : x);
    return "-" + name + " is given " + std::to_string(v.size()) + " times (" + values + "); give it once";
  }
  return "";
}

std::string describeAccepted(const FlagValue& v) {
  using K = FlagValue::Kind;
  switch (v.kind) {
    case K::Int:
      if (v.lo <= INT_MIN && v.hi >= INT_MAX) return "an integer";
      if (v.hi >= INT_MAX) return "an integer >= " + number(v.lo);
      return "an integer in " + number(v.lo) + ".." + number(v.hi);
    case K::Real:
      if (std::isinf(v.lo) && std::isinf(v.hi)) return "a finite number";
      return std::string("a finite number in ") + (v.loOpen ? "(" : "[") + number(v.lo) + ", " + number(v.hi) +
             (v.hiOpen ? ")" : "]");
    case K::Bool:
      return "true or false (also yes/no, on/off, 1/0; the flag alone means true)";
    case K::Choice: {
      std::string s = "one of ";
      for (std::size_t i = 0; i < v.choices.size(); ++i) s += (i ? ", " : "") + v.choices[i];
      return s;
    }
    case K::Text:
      return v.what;
    case K::SceneOpt:
      return "a value (" + v.sceneType + ")";
  }
  return "";
}

std::string checkFlagValue(const Flag& flag, const char* value) {
  using K = FlagValue::Kind;
  const FlagValue& v = flag.value;
  const bool given = value && value[0];
  const std::string got = given ? std::string("got ") + value : (value ? "got an empty value" : "got no value");
  const std::string bad = "-" + flag.name + ": expected " + describeAccepted(v) + ", " + got;
  double x = 0;
  switch (v.kind) {
    case K::Int:
      return given && parseInteger(value, &x) && inRange(v, x) ? "" : bad;
    case K::Real:
      return given && parseReal(value, &x) && inRange(v, x) ? "" : bad;
    case K::Bool: {
      if (!given) return "";  // PETSc: a bool flag alone is true
      const std::string s = lower(value);
      for (const char* w : {"true", "false", "yes", "no", "on", "off", "1", "0"})
        if (s == w) return "";
      return bad;
    }
    case K::Choice:
      return given && std::find(v.choices.begin(), v.choices.end(), std::string(value)) != v.choices.end() ? "" : bad;
    case K::Text:
      return given ? "" : bad;
    case K::SceneOpt:
      // An empty value means true to the scene reader (-calcbuck alone): only bool fields may omit it.
      return given || v.sceneType.rfind("bool", 0) == 0 ? "" : bad;
  }
  return "";
}

}  // namespace sinew
