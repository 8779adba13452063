#include "app/command_line.hpp"

#include <slepcsys.h>

#include <cctype>
#include <string>
#include <vector>

#include "scene/nearest_name.hpp"
#include "settings/flags.hpp"
#include "settings/petsc_flags.hpp"
#include "settings/read_settings.hpp"
#include "sinew/petsc_compat.hpp"

#ifndef SINEW_VERSION
#error "SINEW_VERSION is the CMake project version (CMakeLists.txt)"
#endif

namespace sinew {

const char* sinewVersion() { return SINEW_VERSION; }

const char* usageText() {
  return "Sinew: parallel finite elements for flexures, cables and membranes.\n"
         "Usage: mpirun -n N sinew scene.yaml [-o result.h5] [-<opt field> value ...] [Sinew flags] [PETSc options]\n"
         "  -help: this help; Sinew's flags are in the blocks titled 'Sinew: ...' below, each with its current and\n"
         "         default value (<now ... : formerly ...>) and the values it accepts; every scene opt field is a flag\n"
         "  -h: the same\n"
         "  -version: Sinew's, PETSc's and SLEPc's versions\n"
         "A flag that is neither Sinew's nor PETSc's/SLEPc's is an error (exit 2).\n";
}

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// "" when the option is a Sinew flag with an accepted value or a PETSc/SLEPc option.
std::string optionProblem(const std::string& given, const char* value) {
  const std::string name = lower(given);
  if (name == "h") return "";  // -help's short form (helpRequested)
  if (const Flag* f = findFlag(name)) return checkFlagValue(*f, value);
  if (isPetscFlag(name)) return "";
  std::vector<std::string> names;
  for (const Flag& f : sinewFlags()) names.push_back(f.name);
  const std::string near = scene::nearestName(name, names);
  if (!near.empty()) return "unknown flag -" + given + "; did you mean -" + near + "?";
  if (const std::string p = sinewSolverPrefix(name); !p.empty())
    return "unknown flag -" + given + ": " + name.substr(p.size()) + " is not a PETSc/SLEPc option (options of the solver with prefix " +
           p + " are -" + p + "<PETSc option>, e.g. -" + p + "ksp_view)";
  return "unknown flag -" + given + " (neither a Sinew flag nor a PETSc/SLEPc option; sinew -help lists them)";
}

/// Every option no one has read yet: at start-up, all but the few PETSc's initialization reads
/// (-help, -version, -options_file, -log_view, ...), which are PETSc's own.
PetscErrorCode databaseProblems(std::vector<std::string>* problems) {
  PetscFunctionBeginUser;
  PetscInt n = 0;
  char **names = nullptr, **values = nullptr;
  PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  for (PetscInt i = 0; i < n; ++i) {
    std::string name = names[i];
    if (!name.empty() && name[0] == '-') name.erase(0, 1);
    const std::string p = optionProblem(name, values[i]);
    if (!p.empty()) problems->push_back(p);
  }
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode printVersion(MPI_Comm comm) {
  PetscFunctionBeginUser;
  PetscInt p[4], s[4];
  PetscCall(PetscGetVersionNumber(&p[0], &p[1], &p[2], &p[3]));
  PetscCall(SlepcGetVersionNumber(&s[0], &s[1], &s[2], &s[3]));
  PetscCall(PetscPrintf(comm, "Sinew %s (PETSc %d.%d.%d, SLEPc %d.%d.%d)\n", sinewVersion(), static_cast<int>(p[0]),
                        static_cast<int>(p[1]), static_cast<int>(p[2]), static_cast<int>(s[0]), static_cast<int>(s[1]),
                        static_cast<int>(s[2])));
  PetscFunctionReturn(PETSC_SUCCESS);
}

bool isInteger(const std::string& s, PetscInt* v) {
  try {
    std::size_t end = 0;
    *v = static_cast<PetscInt>(std::stol(s, &end));
    return end == s.size();
  } catch (...) {
    return false;
  }
}

bool isReal(const std::string& s, PetscReal* v) {
  try {
    std::size_t end = 0;
    *v = std::stod(s, &end);
    return end == s.size();
  } catch (...) {
    return false;
  }
}

/// One PETSc options block per group, so -help shows Sinew's flags like PETSc's own:
/// "  -max_cuts <now 10 : formerly 10>: halvings ... [an integer in 0..50] (docs/beam.md)".
/// Values were checked before: no call below can fail on a user's value.
PetscErrorCode printGroup(MPI_Comm comm, const FlagGroup& g) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, g.title, nullptr);
  for (const Flag& f : sinewFlags()) {
    if (f.group != &g) continue;
    const std::string opt = "-" + f.name;
    const std::string accepted = f.value.kind == FlagValue::Kind::Bool       ? "true or false"
                                 : f.value.kind == FlagValue::Kind::SceneOpt ? f.value.sceneType
                                                                             : describeAccepted(f.value);
    const std::string help = f.help + " [" + accepted + "]";
    using K = FlagValue::Kind;
    PetscBool set = PETSC_FALSE;
    PetscInt i = 0;
    PetscReal r = 0;
    if (f.value.kind == K::Int && isInteger(f.defaultValue, &i)) {
      PetscCall(PetscOptionsInt(opt.c_str(), help.c_str(), g.doc, i, &i, &set));
    } else if (f.value.kind == K::Real && isReal(f.defaultValue, &r)) {
      PetscCall(PetscOptionsReal(opt.c_str(), help.c_str(), g.doc, r, &r, &set));
    } else if (f.value.kind == K::Bool) {
      PetscBool b = f.defaultValue == "true" ? PETSC_TRUE : PETSC_FALSE;
      PetscCall(PetscOptionsBool(opt.c_str(), help.c_str(), g.doc, b, &b, &set));
    } else if (f.value.kind == K::Choice) {
      std::vector<const char*> list;
      for (const std::string& c : f.value.choices) list.push_back(c.c_str());
      PetscCall(PetscOptionsEList(opt.c_str(), f.help.c_str(), g.doc, list.data(), static_cast<PetscInt>(list.size()),
                                  f.defaultValue.c_str(), &i, &set));
    } else {  // text, scene opt fields, and numbers whose default depends on the model ("auto")
      char buf[PETSC_MAX_PATH_LEN] = "";
      PetscCall(PetscOptionsString(opt.c_str(), help.c_str(), g.doc, f.defaultValue.c_str(), buf, sizeof buf, &set));
    }
  }
  PetscOptionsEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

PetscErrorCode helpRequested(PetscBool* help) {
  PetscFunctionBeginUser;
  StartupRequests asked;
  PetscCall(PetscOptionsHasHelp(nullptr, help));
  PetscCall(readStartupRequests(&asked));
  const bool h = asked.shortHelp;
  if (h && !*help) {  // as -help: the usage text, then Sinew's and PETSc's objects' options
    PetscCall(PetscOptionsSetValue(nullptr, "-help", nullptr));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s", usageText()));
  }
  *help = static_cast<PetscBool>(*help || h);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode handleCommandLine(MPI_Comm comm, int argc, const char* const* argv, bool* stop, int* exitCode) {
  PetscFunctionBeginUser;
  *stop = false;
  *exitCode = 0;
  PetscBool help = PETSC_FALSE;
  StartupRequests asked;
  PetscCall(readStartupRequests(&asked));
  if (asked.version) {  // PETSc and SLEPc have printed their banners; no run
    PetscCall(printVersion(comm));
    *stop = true;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  // Every rank checks its own database (the same on every rank); rank 0 prints, all exit 2.
  std::vector<std::string> problems;
  PetscCall(databaseProblems(&problems));
  if (const std::string twice = repeatedFlag(argc, argv); !twice.empty()) problems.push_back(twice);
  int bad = problems.empty() ? 0 : 1;
  MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPI_INT, MPI_MAX, comm);
  if (bad) {
    if (problems.empty()) problems.push_back("the command-line options differ between ranks");
    for (const std::string& p : problems) PetscCall(PetscPrintf(comm, "error: %s\n", p.c_str()));
    *stop = true;
    *exitCode = 2;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(helpRequested(&help));
  if (help)
    for (const FlagGroup* g : flagGroups()) PetscCall(printGroup(comm, *g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
