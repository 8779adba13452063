#include "scene/nearest_name.hpp"

#include <algorithm>
#include <cctype>

namespace sinew::scene {

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t subst = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

namespace {
std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}
}  // namespace

std::string nearestName(const std::string& name, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t bestDistance = static_cast<std::size_t>(-1);
  for (const auto& c : candidates) {
    // A case-only difference counts as half an edit, so `Emod` prefers `emod`.
    const std::size_t d = 2 * editDistance(lower(name), lower(c)) + (name == c ? 0 : lower(name) == lower(c) ? 1 : 0);
    if (d < bestDistance) {
      bestDistance = d;
      best = c;
    }
  }
  // Plausible misspelling: at most about a third of the longer name changed (at least 2 edits).
  const std::size_t limit = std::max<std::size_t>(2, (std::max(name.size(), best.size()) + 2) / 3);
  if (!best.empty() && bestDistance <= 2 * limit) return best;
  // Otherwise a long form or abbreviation of a candidate ("rectangle" -> "rect").
  for (const auto& c : candidates) {
    const std::string a = lower(name), b = lower(c);
    if (std::min(a.size(), b.size()) >= 3 && (a.rfind(b, 0) == 0 || b.rfind(a, 0) == 0)) return c;
  }
  return "";
}

std::string suggestion(const std::string& name, const std::vector<std::string>& candidates) {
  if (candidates.empty()) return "";
  const std::string near = nearestName(name, candidates);
  if (!near.empty()) return " (did you mean '" + near + "'?)";
  std::string list;
  for (const auto& c : candidates) list += (list.empty() ? "" : ", ") + c;
  return " (valid: " + list + ")";
}

}  // namespace sinew::scene
