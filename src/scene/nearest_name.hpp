// Edit distance and "did you mean" suggestions for scene keys and names.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace sinew::scene {

/// Levenshtein distance (insert, delete, substitute; each cost 1), case-sensitive.
std::size_t editDistance(const std::string& a, const std::string& b);

/// The candidate nearest to `name` by edit distance (ties: first in the list), or "" when
/// no candidate is close enough to be a plausible misspelling.
std::string nearestName(const std::string& name, const std::vector<std::string>& candidates);

/// " (did you mean 'x'?)" or, when nothing is close, " (valid: a, b, c)"; "" without candidates.
std::string suggestion(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace sinew::scene
