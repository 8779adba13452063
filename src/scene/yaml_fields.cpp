#include "scene/yaml_fields.hpp"

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <set>

#include "scene/nearest_name.hpp"

namespace sinew::scene {

std::string childPath(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string indexPath(const std::string& path, std::size_t i) { return indexedPath(path, i); }

std::string numberedPath(const std::string& path, const std::string& key) {
  const bool number = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) { return c >= '0' && c <= '9'; });
  return number ? path + "(" + key + ")" : childPath(path, key);
}

std::string fmt(double v) {
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

std::string describe(const YAML::Node& n) {
  if (!n.IsDefined() || n.IsNull()) return "nothing";
  if (n.IsMap()) return "a map";
  if (n.IsSequence()) return "a list of " + std::to_string(n.size());
  const std::string s = n.Scalar();
  if (n.Tag() == "!") return "the string '" + s + "'";
  if (isNumber(n)) return s;
  return "'" + s + "'";
}

void fail(const std::string& path, const std::string& message) { throw SceneError(path, message); }

bool isPresent(const YAML::Node& n) { return n.IsDefined(); }

bool isNumber(const YAML::Node& n) {
  if (!n.IsDefined() || !n.IsScalar() || n.Tag() == "!") return false;
  double v = 0;
  return YAML::convert<double>::decode(n, v) && std::isfinite(v);
}

namespace {

/// Why a scalar that is not a finite number was refused ("" when it is no number at all).
std::string nonFiniteReason(const YAML::Node& n) {
  if (!n.IsDefined() || !n.IsScalar() || n.Tag() == "!") return "";
  double v = 0;
  if (YAML::convert<double>::decode(n, v) && !std::isfinite(v)) return "a finite number";
  const std::string& s = n.Scalar();
  if (s.empty() || s.size() > 400) return "";
  errno = 0;
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || errno != ERANGE || s.find_first_of("xXnN") != std::string::npos) return "";
  return x == 0 ? "a number (" + s + " underflows a double)" : "a number (" + s + " is beyond the range of a double)";
}

std::string bounds(const Magnitude& mag) {
  std::string s(1, '[');
  s.append(fmt(mag.min)).append(", ").append(fmt(mag.max)).push_back(']');
  return s;
}

}  // namespace

void checkMagnitude(double v, const std::string& path, const Magnitude& mag, const std::string& label) {
  if (!std::isfinite(v)) fail(path, label + "expected a finite number, got " + fmt(v));
  const double a = std::abs(v);
  if (v != 0 && (a < mag.min || a > mag.max))
    fail(path, label + "expected 0 or " + mag.what + " of magnitude in " + bounds(mag) + ", got " + fmt(v));
}

namespace {

/// A MATLAB user's scalar: a 1-element list [x] is the number x (and x is the list [x]).
bool isSingleton(const YAML::Node& n) { return n.IsDefined() && n.IsSequence() && n.size() == 1 && n[0].IsScalar(); }

double finiteNumber(const YAML::Node& node, const std::string& path) {
  const YAML::Node n = isSingleton(node) ? node[0] : node;
  if (!isNumber(n)) {
    const std::string why = nonFiniteReason(n);
    fail(path, "expected " + (why.empty() ? std::string("a number") : why) + ", got " + describe(n));
  }
  const double v = n.as<double>();
  if (v == 0) {  // a nonzero literal that underflows to 0 (1e-999)
    const std::string why = nonFiniteReason(n);
    if (!why.empty()) fail(path, "expected " + why + ", got " + describe(n));
  }
  return v;
}

}  // namespace

double getNumber(const YAML::Node& n, const std::string& path, const Magnitude& mag) {
  const double v = finiteNumber(n, path);
  checkMagnitude(v, path, mag);
  return v;
}

double getPositive(const YAML::Node& n, const std::string& path, const Magnitude& mag) {
  const double v = finiteNumber(n, path);
  if (!(v > 0)) fail(path, "expected a number > 0, got " + fmt(v));
  if (v < mag.min || v > mag.max) fail(path, "expected " + std::string(mag.what) + " in " + bounds(mag) + ", got " + fmt(v));
  return v;
}

double getNonNegative(const YAML::Node& n, const std::string& path, const Magnitude& mag) {
  const double v = finiteNumber(n, path);
  if (v < 0) fail(path, "expected a number >= 0, got " + fmt(v));
  if (v != 0 && (v < mag.min || v > mag.max))
    fail(path, "expected 0 or " + std::string(mag.what) + " in " + bounds(mag) + ", got " + fmt(v));
  return v;
}

double getInRange(const YAML::Node& n, const std::string& path, double lo, double hi, bool hiOpen) {
  const double v = getNumber(n, path);
  if (v < lo || v > hi || (hiOpen && v == hi))
    fail(path, "expected a number in [" + fmt(lo) + ", " + fmt(hi) + (hiOpen ? ")" : "]") + ", got " + fmt(v));
  return v;
}

int getInt(const YAML::Node& node, const std::string& path) {
  const YAML::Node n = isSingleton(node) ? node[0] : node;
  if (!isNumber(n)) fail(path, "expected an integer, got " + describe(n));
  const double v = n.as<double>();
  if (v != std::floor(v)) fail(path, "expected an integer, got " + n.Scalar());
  if (std::abs(v) > std::numeric_limits<int>::max())
    fail(path, "expected an integer of magnitude at most " + std::to_string(std::numeric_limits<int>::max()) + ", got " + n.Scalar());
  return static_cast<int>(v);
}

int getIntAtLeast(const YAML::Node& n, const std::string& path, int min) {
  const int v = getInt(n, path);
  if (v < min) fail(path, "expected an integer >= " + std::to_string(min) + ", got " + std::to_string(v));
  return v;
}

bool getBool(const YAML::Node& n, const std::string& path) {
  if (n.IsDefined() && n.IsScalar() && n.Tag() != "!") {
    bool b = false;
    if (YAML::convert<bool>::decode(n, b)) return b;
    if (n.Scalar() == "0") return false;
    if (n.Scalar() == "1") return true;
  }
  fail(path, "expected true or false, got " + describe(n));
}

std::string getString(const YAML::Node& n, const std::string& path) {
  if (!n.IsDefined() || !n.IsScalar()) fail(path, "expected a string, got " + describe(n));
  return n.Scalar();
}

std::string getChoice(const YAML::Node& n, const std::string& path, const std::vector<std::string>& choices) {
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : " | ") + c;
  if (!n.IsDefined() || !n.IsScalar()) fail(path, "expected one of " + list + ", got " + describe(n));
  const std::string s = n.Scalar();
  if (std::find(choices.begin(), choices.end(), s) != choices.end()) return s;
  const std::string near = nearestName(s, choices);
  fail(path, "expected one of " + list + ", got '" + s + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)"));
}

void requireMap(const YAML::Node& n, const std::string& path) {
  if (!n.IsDefined() || !n.IsMap()) fail(path, "expected a map, got " + describe(n));
}

void requireList(const YAML::Node& n, const std::string& path) {
  if (!n.IsDefined() || !n.IsSequence()) fail(path, "expected a list, got " + describe(n));
}

std::vector<double> getNumbers(const YAML::Node& n, const std::string& path, const Magnitude& mag) {
  if (n.IsDefined() && n.IsScalar() && isNumber(n)) return {getNumber(n, path, mag)};  // x = [x]
  if (!n.IsDefined() || !n.IsSequence()) fail(path, "expected a list of numbers, got " + describe(n));
  std::vector<double> v;
  v.reserve(n.size());
  for (std::size_t i = 0; i < n.size(); ++i) v.push_back(getNumber(n[i], indexPath(path, i), mag));
  return v;
}

std::vector<double> getNumbers(const YAML::Node& n, const std::string& path, std::size_t count, const Magnitude& mag) {
  const std::string what = "expected " + std::to_string(count) + (count == 1 ? " number" : " numbers");
  if (count == 1 && n.IsDefined() && n.IsScalar()) return {getNumber(n, path, mag)};  // x = [x]
  if (!n.IsDefined() || !n.IsSequence()) fail(path, what + ", got " + describe(n));
  if (n.size() != count) fail(path, what + ", got " + std::to_string(n.size()));
  return getNumbers(n, path, mag);
}

Vec3 getVec3(const YAML::Node& n, const std::string& path, bool allow2, const Magnitude& mag) {
  const std::string what = allow2 ? "expected 3 numbers (or 2 in a 2D model)" : "expected 3 numbers";
  if (!n.IsDefined() || !n.IsSequence()) fail(path, what + ", got " + describe(n));
  if (n.size() != 3 && !(allow2 && n.size() == 2)) fail(path, what + ", got " + std::to_string(n.size()));
  const auto v = getNumbers(n, path, mag);
  return {v[0], v[1], v.size() == 3 ? v[2] : 0.0};
}

std::vector<int> getInts(const YAML::Node& n, const std::string& path, bool scalarOk) {
  if (scalarOk && n.IsDefined() && n.IsScalar()) return {getInt(n, path)};
  if (!n.IsDefined() || !n.IsSequence()) fail(path, "expected a list of integers, got " + describe(n));
  std::vector<int> v;
  v.reserve(n.size());
  for (std::size_t i = 0; i < n.size(); ++i) v.push_back(getInt(n[i], indexPath(path, i)));
  return v;
}

std::vector<std::string> getStrings(const YAML::Node& n, const std::string& path) {
  if (n.IsDefined() && n.IsScalar()) return {n.Scalar()};
  if (!n.IsDefined() || !n.IsSequence()) fail(path, "expected a list of strings, got " + describe(n));
  std::vector<std::string> v;
  for (std::size_t i = 0; i < n.size(); ++i) v.push_back(getString(n[i], indexPath(path, i)));
  return v;
}

std::string keyString(const YAML::Node& key, const std::string& path) {
  if (!key.IsScalar()) fail(path, "expected scalar keys, got " + describe(key) + " as a key");
  return key.Scalar();
}

void checkKeys(const YAML::Node& n, const std::string& path, const std::vector<std::string>& allowed) {
  requireMap(n, path);
  std::set<std::string> seen;
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string k = keyString(it->first, path);
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end())
      fail(childPath(path, k), "unknown key '" + k + "'" + suggestion(k, allowed));
    if (!seen.insert(k).second) fail(childPath(path, k), "key '" + k + "' is given twice");
  }
}

}  // namespace sinew::scene
