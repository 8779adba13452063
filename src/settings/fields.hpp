// The field tables of the settings structs (settings.hpp): per field its flag, accepted values,
// -help group, default as -help shows it, help text and member. The flag registry (flags.cpp) lists
// these tables in order, the options reader (read_settings.cpp) fills the members from them. Plain
// C++ (no PETSc): the unit tests compile it with the registry.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "settings/flags.hpp"
#include "settings/settings.hpp"

namespace sinew {

/// An enum field chosen by the flag's words: the enum's values follow the words in order.
template <class S>
struct ChoiceRef {
  std::function<void(S&, int)> set;                   ///< sets the value of word `index`
  std::function<std::optional<int>(const S&)> get;    ///< the word index (nullopt: left to the model)
};

/// A field recording whether an option was given at all; PETSc/SLEPc read its value themselves.
template <class S>
struct GivenRef {
  bool S::*member;
};

/// Where a flag's value goes; std::monostate: nowhere in Sinew (a PETSc/SLEPc option documented in -help).
template <class S>
using FieldRef = std::variant<std::monostate, bool S::*, int S::*, double S::*, std::string S::*, std::optional<bool> S::*,
                              std::optional<int> S::*, std::optional<double> S::*, std::optional<std::string> S::*,
                              ChoiceRef<S>, GivenRef<S>>;

template <class S>
struct Field {
  const char* flag;         ///< without the leading '-'
  FlagValue value;          ///< accepted values (a choice flag's words name the enum's values in order)
  const FlagGroup* group;   ///< -help block
  const char* defaultText;  ///< as -help shows it
  const char* help;         ///< meaning: its first clause (up to " (" or "; ") is the -help line
  FieldRef<S> ref;
  bool developer = false;   ///< a testing aid or solver internal: listed by -help_dev, not -help
};

template <class S, class E>
ChoiceRef<S> choiceOf(E S::*m) {
  return {[m](S& s, int i) { s.*m = static_cast<E>(i); }, [m](const S& s) -> std::optional<int> { return static_cast<int>(s.*m); }};
}

template <class S, class E>
ChoiceRef<S> choiceOf(std::optional<E> S::*m) {
  return {[m](S& s, int i) { s.*m = static_cast<E>(i); },
          [m](const S& s) -> std::optional<int> {
            if (!(s.*m)) return std::nullopt;
            return static_cast<int>(*(s.*m));
          }};
}

const std::vector<Field<OutputSettings>>& outputFields();
const std::vector<Field<StaticsSettings>>& staticsFields();
const std::vector<Field<ContinuationSettings>>& continuationFields();
const std::vector<Field<AncfSettings>>& ancfFields();
const std::vector<Field<ModelCheckSettings>>& modelCheckFields();
const std::vector<Field<EigenSettings>>& eigenFields();
const std::vector<Field<ComplianceSettings>>& complianceFields();
const std::vector<Field<DynamicsSettings>>& dynamicsFields();
const std::vector<Field<FormFindingSettings>>& formFindingFields();
const std::vector<Field<AccuracySettings>>& accuracyFields();

/// Calls f(table, &Settings::component) for every component, in the registry's order.
template <class F>
void forEachFieldTable(F&& f) {
  f(outputFields(), &Settings::output);
  f(staticsFields(), &Settings::statics);
  f(continuationFields(), &Settings::continuation);
  f(ancfFields(), &Settings::ancf);
  f(modelCheckFields(), &Settings::check);
  f(eigenFields(), &Settings::eigen);
  f(complianceFields(), &Settings::compliance);
  f(dynamicsFields(), &Settings::dynamics);
  f(formFindingFields(), &Settings::formfinding);
  f(accuracyFields(), &Settings::accuracy);
}

}  // namespace sinew
