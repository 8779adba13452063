// Typed access to YAML scene fields. Every getter takes the field's path (e.g. "eprops(2).dim")
// and throws sinew::SceneError(path, "expected ..., got ...") when the value does not fit.
// Paths: map keys joined with '.', list positions 1-based in parentheses as in SPACAR Light
// (MATLAB): eprops(2).dim(1), nodes(3,2) (indexedPath, sinew/model.hpp); nprops(4) for node 4.
#pragma once
#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>
#include <vector>

#include "scene/value_bounds.hpp"
#include "sinew/model.hpp"

namespace sinew::scene {

std::string childPath(const std::string& path, const std::string& key);
/// path(i + 1): list entry i (0-based) of path, 1-based as SPACAR Light numbers it.
std::string indexPath(const std::string& path, std::size_t i);
/// The entry of a map keyed by numbers (nprops by node, opt.rls by element): path(key) for a number
/// ("nprops(4)"), path.key for a name (a Gmsh physical group: "nprops.edge").
std::string numberedPath(const std::string& path, const std::string& key);

/// Short description of a value for messages: "a map", "a list of 2", "nothing", "'abc'", "3.5".
std::string describe(const YAML::Node& n);
/// Number formatted for messages (shortest round-trip form).
std::string fmt(double v);

[[noreturn]] void fail(const std::string& path, const std::string& message);

bool isNumber(const YAML::Node& n);  ///< plain scalar holding a finite number
bool isPresent(const YAML::Node& n);  ///< defined (a key given with an empty value counts as present)

/// A finite number that is 0 or has |v| in [mag.min, mag.max] (value_bounds.hpp).
double getNumber(const YAML::Node& n, const std::string& path, const Magnitude& mag = kAnyNumber);
double getPositive(const YAML::Node& n, const std::string& path, const Magnitude& mag = kAnyNumber);     ///< in [min, max]
double getNonNegative(const YAML::Node& n, const std::string& path, const Magnitude& mag = kAnyNumber);  ///< 0 or in [min, max]
/// Number in [lo, hi] (or [lo, hi) with hiOpen).
double getInRange(const YAML::Node& n, const std::string& path, double lo, double hi, bool hiOpen = false);
int getInt(const YAML::Node& n, const std::string& path);
int getIntAtLeast(const YAML::Node& n, const std::string& path, int min);
/// true/false (also yes/no/on/off) or 0/1.
bool getBool(const YAML::Node& n, const std::string& path);
std::string getString(const YAML::Node& n, const std::string& path);
/// One of `choices` (message lists them and suggests the nearest).
std::string getChoice(const YAML::Node& n, const std::string& path, const std::vector<std::string>& choices);

void requireMap(const YAML::Node& n, const std::string& path);
void requireList(const YAML::Node& n, const std::string& path);

/// A list of numbers of any length.
std::vector<double> getNumbers(const YAML::Node& n, const std::string& path, const Magnitude& mag = kAnyNumber);
/// A list of exactly `count` numbers.
std::vector<double> getNumbers(const YAML::Node& n, const std::string& path, std::size_t count, const Magnitude& mag = kAnyNumber);
/// [x, y, z]; with allow2, also [x, y] (z = 0) for 2D models.
Vec3 getVec3(const YAML::Node& n, const std::string& path, bool allow2 = false, const Magnitude& mag = kAnyNumber);
/// A value computed from scene numbers (e.g. a coordinate from the Gmsh file) checked like getNumber.
void checkMagnitude(double v, const std::string& path, const Magnitude& mag, const std::string& label = "");
/// A list of integers; a single integer is accepted as a list of one when scalarOk.
std::vector<int> getInts(const YAML::Node& n, const std::string& path, bool scalarOk = false);
/// A list of strings; a single string is accepted as a list of one.
std::vector<std::string> getStrings(const YAML::Node& n, const std::string& path);

/// Every key of map `n` must be in `allowed` and appear once; otherwise
/// "unknown key 'emodd' (did you mean 'emod'?)" at path.key.
void checkKeys(const YAML::Node& n, const std::string& path, const std::vector<std::string>& allowed);
/// The key text of a map entry (scalar keys only).
std::string keyString(const YAML::Node& key, const std::string& path);

}  // namespace sinew::scene
