// The registry of every command-line flag Sinew reads (flags.cpp): name, accepted values, default,
// one-line meaning and -help group. It is made from the settings' field tables (fields.cpp: a new
// flag is a settings field and one line there) and the scene opt fields; the start-up check
// (command_line.cpp) rejects any option that is neither in the registry nor a PETSc/SLEPc option,
// and -help lists the registry.
#pragma once
#include <string>
#include <vector>

namespace sinew {

/// What a flag accepts. Every value check names the flag and the accepted values.
struct FlagValue {
  enum class Kind { Int, Real, Bool, Choice, Text, SceneOpt };
  Kind kind = Kind::Bool;
  double lo = 0, hi = 0;             ///< Int/Real: accepted range
  bool loOpen = false, hiOpen = false;  ///< Real: (lo, ...) / (..., hi) exclude the bound
  std::vector<std::string> choices;  ///< Choice: the accepted words (case-sensitive)
  std::string sceneType;             ///< SceneOpt: the opt field's type ("bool", "integer 1..100000", ...)
  std::string what;                  ///< Text: what the string names
};

/// Value rules, one call each in the registry.
FlagValue integerIn(double lo, double hi);  ///< an integer in [lo, hi]
FlagValue integerAtLeast(double lo);        ///< an integer >= lo (fits a PetscInt)
FlagValue anyInteger();
FlagValue realIn(double lo, double hi, bool loOpen, bool hiOpen);  ///< a finite number in the range
FlagValue anyReal();                                                ///< a finite number
FlagValue boolean();                                                ///< PETSc's true/false words
FlagValue oneOf(std::vector<std::string> choices);
FlagValue text(std::string what);  ///< a non-empty string, described as `what` ("a file name")

/// A -help block: PetscOptionsBegin title and the document it points to.
struct FlagGroup {
  const char* title;
  const char* doc;
};

/// The -help blocks (flagGroups() gives their order).
namespace flag_groups {
extern const FlagGroup output, scene, statics, ancf, check, modal, compliance, dynamics, formfinding, accuracy;
}  // namespace flag_groups

struct Flag {
  std::string name;          ///< without the leading '-'
  FlagValue value;
  const FlagGroup* group;
  std::string defaultValue;  ///< as -help shows it
  std::string help;          ///< meaning; its first clause is the -help line (helpSummary)
  bool developer = false;    ///< listed by -help_dev instead of -help
};

/// Every flag Sinew reads: the settings' fields (its own flags and the PETSc/SLEPc options it reads
/// or documents, fields.cpp) and every scene opt field (sceneOptionDocs(): -loadsteps 40 overrides
/// opt.loadsteps).
const std::vector<Flag>& sinewFlags();
/// The registry entry of `name` (without '-', any case), or nullptr.
const Flag* findFlag(const std::string& name);
/// The -help groups in the order they are printed.
const std::vector<const FlagGroup*>& flagGroups();

/// "" when `value` (nullptr: the flag given without a value) is accepted by the flag, otherwise
/// the message "-name: expected ..., got ...". Scene opt fields are read by the scene reader,
/// which checks their values; here only a missing value of a non-bool field is an error.
std::string checkFlagValue(const Flag& flag, const char* value);

/// "" or the message naming a Sinew flag given more than once on the command line (`-o a.h5 -o b.h5`:
/// PETSc keeps the last one silently). argv[1..argc) as main received it; -options_file and
/// PETSC_OPTIONS may still be overridden by the command line, as in PETSc.
std::string repeatedFlag(int argc, const char* const* argv);

/// "an integer in 0..50", "one of auto, elementwise, assembled", ... for messages and -help.
std::string describeAccepted(const FlagValue& v);

}  // namespace sinew
