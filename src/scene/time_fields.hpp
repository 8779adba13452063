// Scene fields that may be functions of time (nprops force, moment, displ_x/y/z, rot): a number, or
// an expression string of t in the language of the ANCF user functions (src/math/expression.hpp).
#pragma once
#include <array>
#include <string>

#include "scene/yaml_fields.hpp"
#include "sinew/model.hpp"

namespace sinew::scene {

/// Compiles `text` as a function of time for the field at `path` and returns its value at t = 0.
/// SceneError (naming the field) on a syntax error, a name other than t (the force-law arguments
/// of the ANCF user functions mean nothing here) or a non-finite value at t = 0.
double checkTimeFunction(const std::string& text, const std::string& path);

/// A number, or a string = a function of time (its text goes to *text, its value at t = 0 is returned).
double getNumberOrTimeFunction(const YAML::Node& n, const std::string& path, const Magnitude& mag, std::string* text);

/// 3 entries (2 in a 2D model when allow2), each a number or a function of time (texts[k], "" for numbers).
Vec3 getVec3OrTimeFunctions(const YAML::Node& n, const std::string& path, bool allow2, const Magnitude& mag,
                            std::array<std::string, 3>& texts);

}  // namespace sinew::scene
