// The settings structs and their field tables (src/settings/settings.hpp, fields.cpp), without
// PETSc: the structs' defaults are the defaults -help shows, every registered Sinew flag is a field,
// and settings are built in code with chosen values (the reader from an options database:
// test_settings_reader.cpp).
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>

#include "scene/scene_reader.hpp"
#include "settings/fields.hpp"
#include "settings/flags.hpp"

using namespace sinew;

namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

template <class T>
struct FieldOf;
template <class S>
struct FieldOf<Field<S>> {
  using type = S;
};

std::string firstWord(const std::string& s) { return s.substr(0, s.find(' ')); }

/// "" when the default of field f in s agrees with its -help default text, else what differs.
template <class S>
std::string defaultMismatch(const Field<S>& f, const S& s) {
  const std::string text = f.defaultText, word = firstWord(text);
  return std::visit(
      Overloaded{
          [](std::monostate) { return std::string(); },  // PETSc's own option, documented only
          [](const GivenRef<S>&) { return std::string(); },
          [&](const ChoiceRef<S>& c) {
            const std::optional<int> i = c.get(s);
            // left open: the scene (opt.) or another flag (" with -flag") decides
            const bool open = text.find("(opt.") != std::string::npos || text.find(" with -") != std::string::npos;
            if (!i) return open ? std::string() : "no choice, default text " + text;
            return f.value.choices.at(static_cast<std::size_t>(*i)) == word ? std::string()
                                                                             : "choice " + f.value.choices[*i] + " vs " + text;
          },
          [&](auto member) {
            using M = std::remove_cv_t<std::remove_reference_t<decltype(s.*member)>>;
            const M& v = s.*member;
            std::ostringstream got;
            if constexpr (std::is_same_v<M, bool>) {
              got << (v ? "true" : "false");
              return got.str() == word ? std::string() : got.str() + " vs " + text;
            } else if constexpr (std::is_same_v<M, int>) {
              return std::to_string(v) == word ? std::string() : std::to_string(v) + " vs " + text;
            } else if constexpr (std::is_same_v<M, double>) {
              return std::strtod(word.c_str(), nullptr) == v ? std::string() : std::to_string(v) + " vs " + text;
            } else if constexpr (std::is_same_v<M, std::string>) {
              return v.empty() && text == "none" ? std::string() : "'" + v + "' vs " + text;
            } else {  // std::optional: the model or scene decides (auto)
              return v ? "a value where the default is left open (" + text + ")" : std::string();
            }
          },
      },
      f.ref);
}

}  // namespace

TEST(Settings, DefaultsAreTheRegistryDefaults) {
  const Settings defaults;
  int fields = 0;
  forEachFieldTable([&](const auto& table, auto component) {
    for (const auto& f : table) {
      ++fields;
      EXPECT_EQ(defaultMismatch(f, defaults.*component), "") << "-" << f.flag;
    }
  });
  EXPECT_EQ(fields, 60);
}

TEST(Settings, RegistryIsTheFieldTablesThenTheSceneOptFields) {
  std::vector<std::string> expected;
  forEachFieldTable([&](const auto& table, auto) {
    for (const auto& f : table) {
      expected.push_back(f.flag);
      const Flag* r = findFlag(f.flag);
      ASSERT_NE(r, nullptr) << f.flag;
      EXPECT_EQ(r->group, f.group);
      EXPECT_EQ(r->help, f.help);
      EXPECT_EQ(r->defaultValue, f.defaultText);
      // an enum field is a choice flag (its words name the enum's values) and a choice flag an enum
      using S = typename FieldOf<std::decay_t<decltype(f)>>::type;
      EXPECT_EQ(std::holds_alternative<ChoiceRef<S>>(f.ref), f.value.kind == FlagValue::Kind::Choice) << f.flag;
    }
  });
  for (const OptionDoc& d : sceneOptionDocs()) expected.push_back(d.name);
  std::vector<std::string> registered;
  for (const Flag& f : sinewFlags()) registered.push_back(f.name);
  EXPECT_EQ(registered, expected);
}

TEST(Settings, ChoiceWordsMapToTheEnumsInOrder) {
  Settings s;
  const auto& dyn = dynamicsFields();
  for (const auto& f : dyn) {
    if (std::string(f.flag) != "dynamics_scheme") continue;
    const auto& c = std::get<ChoiceRef<DynamicsSettings>>(f.ref);
    ASSERT_EQ(f.value.choices, (std::vector<std::string>{"arnold_bruls", "tsalpha2", "midpoint", "energy_momentum"}));
    c.set(s.dynamics, 3);
    EXPECT_EQ(s.dynamics.scheme, DynamicsScheme::EnergyMomentum);
    c.set(s.dynamics, 2);
    EXPECT_EQ(s.dynamics.scheme, DynamicsScheme::Midpoint);
    c.set(s.dynamics, 1);
    EXPECT_EQ(s.dynamics.scheme, DynamicsScheme::TSAlpha2);
  }
  for (const auto& f : dyn) {
    if (std::string(f.flag) != "dynamics_adapt") continue;
    const auto& c = std::get<ChoiceRef<DynamicsSettings>>(f.ref);
    EXPECT_FALSE(c.get(s.dynamics).has_value());  // opt.dynamics.adaptive.control decides
    c.set(s.dynamics, 2);
    EXPECT_EQ(s.dynamics.adapt, TimeStepControl::Error);
  }
  for (const auto& f : staticsFields()) {
    if (std::string(f.flag) == "tangent_operator") {
      EXPECT_EQ(f.value.choices, (std::vector<std::string>{"auto", "elementwise", "assembled"}));
    }
  }
  for (const auto& f : complianceFields()) {
    if (std::string(f.flag) == "compliance_method") {
      EXPECT_EQ(f.value.choices, (std::vector<std::string>{"selinv", "sparse", "dense"}));
    }
  }
}

TEST(Settings, BuiltInCodeWithChosenValues) {
  // what an analysis is given: no options database involved
  Settings s;
  s.statics.maxCuts = 3;
  s.statics.predictor = false;
  s.statics.tangentOperator = OperatorChoice::Assembled;
  s.ancf.coarseRatio = 0;
  s.dynamics.scheme = DynamicsScheme::Midpoint;
  s.dynamics.dtMin = 1e-3;
  s.eigen.freqShiftRel = 1e-6;
  s.sceneOpt["loadsteps"] = "40";
  EXPECT_NE(s, Settings{});
  EXPECT_EQ(s.statics.maxCuts, 3);
  EXPECT_EQ(s.statics.predictor, std::optional<bool>(false));
  EXPECT_EQ(s.continuation, ContinuationSettings{});  // the others keep their defaults
  EXPECT_EQ(s.dynamics.dtMax, std::nullopt);
  EXPECT_EQ(s.dynamics.beamMass, std::nullopt);
  EXPECT_EQ(s.dynamics.beamMassInUse(), BeamMass::Consistent);
  EXPECT_EQ(s.dynamics.stiffnessDamping, StiffnessDamping::Corotated);
}

TEST(Settings, BeamMassFollowsTheSchemeUnlessGiven) {
  // energy_momentum takes the constant (energy-exact) linear beam mass unless -beam_mass was given
  DynamicsSettings d;
  d.scheme = DynamicsScheme::EnergyMomentum;
  EXPECT_EQ(d.beamMassInUse(), BeamMass::Linear);
  EXPECT_TRUE(d.linearMassByScheme());
  d.beamMass = BeamMass::Consistent;
  EXPECT_EQ(d.beamMassInUse(), BeamMass::Consistent);
  EXPECT_FALSE(d.linearMassByScheme());
  d.scheme = DynamicsScheme::Midpoint;
  d.beamMass = std::nullopt;
  EXPECT_EQ(d.beamMassInUse(), BeamMass::Consistent);
  d.beamMass = BeamMass::Linear;
  EXPECT_EQ(d.beamMassInUse(), BeamMass::Linear);
}
