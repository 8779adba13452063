// The text of -help, -help_dev and -help <flag>, made from the flag registry (flags.hpp): Sinew's
// flags group by group, one line each (under 100 characters) with its default; the full meaning,
// accepted values and document of one flag on request. Plain C++ (unit-tested without PETSc).
#pragma once
#include <string>

#include "settings/flags.hpp"

namespace sinew {

/// Longest line of the flag lists (-help, -help_dev), characters.
constexpr std::size_t kHelpWidth = 99;

/// The -help line's text of a flag: its help up to the first " (" or "; " (the clause a reader
/// scans for), the rest is -help <flag>'s.
std::string helpSummary(const std::string& help);

/// -help (developer false): usage, then every user flag by group, "  -name default   meaning".
/// -help_dev (developer true): the testing aids and solver internals the same way.
std::string helpText(const std::string& version, bool developer);

/// -help <flag>: the flag in full (default, accepted values, meaning, group and document).
std::string flagDetail(const Flag& flag);

}  // namespace sinew
