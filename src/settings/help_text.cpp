#include "settings/help_text.hpp"

#include <sstream>

namespace sinew {

namespace {

/// Column where the meaning starts in the flag lists.
constexpr std::size_t kMeaningColumn = 38;

const char* usage() {
  return "Usage: mpirun -n N sinew scene.yaml [-o result.h5] [-flag value ...] [PETSc/SLEPc options]\n"
         "Every scene opt field is a flag (-loadsteps 40 overrides opt.loadsteps); a flag that is neither\n"
         "Sinew's nor PETSc's/SLEPc's is an error (exit 2). Below: each flag with its default.\n"
         "  -help <flag>     one flag in full (accepted values, meaning, document)\n"
         "  -help_dev        testing aids and solver internals\n"
         "  -help_petsc      PETSc's and SLEPc's options (with a scene: those of the solvers it creates)\n"
         "  -version         Sinew's version and those of the libraries it runs on\n";
}

std::string flagLine(const Flag& f) {
  std::string line = "  -" + f.name + " " + helpSummary(f.defaultValue);
  line += line.size() + 2 <= kMeaningColumn ? std::string(kMeaningColumn - line.size(), ' ') : "  ";
  return line + helpSummary(f.help);
}

}  // namespace

std::string helpSummary(const std::string& help) {
  std::size_t end = help.size();
  for (const char* stop : {" (", "; "}) end = std::min(end, help.find(stop));
  return help.substr(0, end);
}

std::string helpText(const std::string& version, bool developer) {
  std::ostringstream out;
  out << "Sinew " << version << ": parallel finite elements for flexures, cables and membranes\n" << usage();
  if (developer) out << "Testing aids and solver internals (their defaults are the tested ones):\n";
  for (const FlagGroup* g : flagGroups()) {
    bool title = false;
    for (const Flag& f : sinewFlags()) {
      if (f.group != g || f.developer != developer) continue;
      if (!title) out << "\n" << g->title << " [" << g->doc << "]\n";
      title = true;
      out << flagLine(f) << "\n";
    }
  }
  return out.str();
}

std::string flagDetail(const Flag& f) {
  std::ostringstream out;
  const std::string accepted = f.value.kind == FlagValue::Kind::SceneOpt ? f.value.sceneType : describeAccepted(f.value);
  out << "-" << f.name << (f.developer ? " (testing aid or solver internal)" : "") << "\n"
      << "  default:  " << f.defaultValue << "\n"
      << "  accepts:  " << accepted << "\n"
      << "  meaning:  " << f.help << "\n"
      << "  group:    " << f.group->title << " [" << f.group->doc << "]\n";
  return out.str();
}

}  // namespace sinew
