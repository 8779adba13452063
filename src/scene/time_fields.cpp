#include "scene/time_fields.hpp"

#include <cmath>
#include <stdexcept>

#include "math/expression.hpp"

namespace sinew::scene {

double checkTimeFunction(const std::string& text, const std::string& path) {
  Expression e;
  try {
    e = Expression::compile(text, "function of time");
  } catch (const std::invalid_argument& ex) {
    throw SceneError(path, ex.what());
  }
  for (int v = 0; v < kNumUfVars; ++v)
    if (v != static_cast<int>(UfVar::t) && e.uses(static_cast<UfVar>(v)))
      throw SceneError(path, "a function of time may only use t, got '" + std::string(ufVarName(static_cast<UfVar>(v))) +
                                 "' (a force-law argument of ancf_cable2d user functions) in '" + text + "'");
  const Expression::TimeJet j = e.timeJet(0.0);
  if (!std::isfinite(j.f)) throw SceneError(path, "the function of time '" + text + "' is not finite at t = 0");
  return j.f;
}

double getNumberOrTimeFunction(const YAML::Node& n, const std::string& path, const Magnitude& mag, std::string* text) {
  text->clear();
  if (n.IsDefined() && n.IsScalar() && !isNumber(n) && !n.Scalar().empty()) {
    double v = 0;
    // a non-finite number (.inf, 1e999) stays getNumber's error, not an expression
    if (!YAML::convert<double>::decode(n, v)) {
      *text = n.Scalar();
      return checkTimeFunction(*text, path);
    }
  }
  return getNumber(n, path, mag);
}

Vec3 getVec3OrTimeFunctions(const YAML::Node& n, const std::string& path, bool allow2, const Magnitude& mag,
                            std::array<std::string, 3>& texts) {
  const std::string what = allow2 ? "expected 3 numbers (or 2 in a 2D model)" : "expected 3 numbers";
  if (!n.IsDefined() || !n.IsSequence())
    fail(path, what + " (each may be a function of time, a string such as \"10*sin(2*pi*t)\"), got " + describe(n));
  if (n.size() != 3 && !(allow2 && n.size() == 2)) fail(path, what + ", got " + std::to_string(n.size()));
  Vec3 v{};
  for (std::size_t k = 0; k < n.size(); ++k) v[k] = getNumberOrTimeFunction(n[k], indexPath(path, k), mag, &texts[k]);
  return v;
}

}  // namespace sinew::scene
