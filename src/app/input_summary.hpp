// What an input-only run (opt.showinputonly, SPACAR Light's input check) prints: what was read
// (nodes, elements, property sets, supports, prescribed motions, loads, masses) and how to draw
// it. No analyses, no result tables.
#pragma once
#include <string>
#include <vector>

#include "sinew/model.hpp"

namespace sinew {

struct InputCounts {
  long feNodes = 0, feElements = 0, unknowns = 0, ndof = 0;
};

/// "1, 2, 5 and 12 more": 0-based numbers shown 1-based, the first `shown` of them.
std::string oneBasedList(const std::vector<int>& v, std::size_t shown);

/// The summary text (rank 0 prints it); lists are cut after a few entries ("and 12 more").
std::string inputSummary(const Model& model, const InputCounts& counts);

}  // namespace sinew
