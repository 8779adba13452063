#include "settings/read_settings.hpp"

#include <string>
#include <type_traits>
#include <vector>

#include "settings/fields.hpp"

namespace sinew {

namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

/// The value of -name as the field's type; *set tells whether it was given.
template <class T>
PetscErrorCode readValue(PetscOptions db, const std::string& name, T* value, PetscBool* set) {
  PetscFunctionBeginUser;
  if constexpr (std::is_same_v<T, bool>) {
    PetscBool b = *value ? PETSC_TRUE : PETSC_FALSE;
    PetscCall(PetscOptionsGetBool(db, nullptr, name.c_str(), &b, set));
    *value = b;
  } else if constexpr (std::is_same_v<T, int>) {
    PetscInt i = *value;
    PetscCall(PetscOptionsGetInt(db, nullptr, name.c_str(), &i, set));
    *value = static_cast<int>(i);
  } else if constexpr (std::is_same_v<T, double>) {
    PetscReal r = *value;
    PetscCall(PetscOptionsGetReal(db, nullptr, name.c_str(), &r, set));
    *value = r;
  } else {
    static_assert(std::is_same_v<T, std::string>);
    char buf[PETSC_MAX_PATH_LEN] = "";
    PetscCall(PetscOptionsGetString(db, nullptr, name.c_str(), buf, sizeof buf, set));
    if (*set) *value = buf;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

template <class S>
PetscErrorCode readField(PetscOptions db, const Field<S>& f, S* s) {
  PetscFunctionBeginUser;
  const std::string name = std::string("-") + f.flag;
  PetscBool set = PETSC_FALSE;
  PetscErrorCode ierr = PETSC_SUCCESS;
  std::visit(Overloaded{
                 [](std::monostate) {},  // read by PETSc/SLEPc themselves
                 [&](const GivenRef<S>& g) {
                   ierr = PetscOptionsHasName(db, nullptr, name.c_str(), &set);
                   s->*g.member = set;
                 },
                 [&](const ChoiceRef<S>& c) {
                   std::vector<const char*> words;
                   for (const std::string& w : f.value.choices) words.push_back(w.c_str());
                   PetscInt which = 0;
                   ierr = PetscOptionsGetEList(db, nullptr, name.c_str(), words.data(), static_cast<PetscInt>(words.size()),
                                               &which, &set);
                   if (!ierr && set) c.set(*s, static_cast<int>(which));
                 },
                 [&](auto member) {
                   using M = std::remove_reference_t<decltype(s->*member)>;
                   if constexpr (std::is_same_v<M, bool> || std::is_same_v<M, int> || std::is_same_v<M, double> ||
                                 std::is_same_v<M, std::string>) {
                     ierr = readValue(db, name, &(s->*member), &set);
                   } else {  // std::optional<T>: set only when given
                     typename M::value_type v{};
                     ierr = readValue(db, name, &v, &set);
                     if (!ierr && set) s->*member = v;
                   }
                 },
             },
             f.ref);
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

PetscErrorCode readSettings(PetscOptions db, Settings* settings) {
  PetscFunctionBeginUser;
  PetscErrorCode ierr = PETSC_SUCCESS;
  forEachFieldTable([&](const auto& table, auto component) {
    for (const auto& f : table)
      if (!ierr) ierr = readField(db, f, &(settings->*component));
  });
  PetscCall(ierr);
  // opt fields given as flags (-loadsteps 40) override the scene
  settings->sceneOpt.clear();
  for (const OptionDoc& d : sceneOptionDocs()) {
    char buf[4096] = "";
    PetscBool set = PETSC_FALSE;
    PetscCall(PetscOptionsGetString(db, nullptr, ("-" + d.name).c_str(), buf, sizeof(buf), &set));
    if (set) settings->sceneOpt[d.name] = buf;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

OptionOverride sceneOverrides(const Settings& settings) {
  return [given = settings.sceneOpt](const std::string& name) -> std::optional<std::string> {
    const auto it = given.find(name);
    if (it == given.end()) return std::nullopt;
    return it->second;
  };
}

PetscErrorCode readPetscHelp(PetscBool* help) {
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, help));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode applySolverOptionDefault(const char* name, int value) {
  PetscFunctionBeginUser;
  PetscBool given = PETSC_FALSE;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, name, &given));
  if (!given) PetscCall(PetscOptionsSetValue(nullptr, name, std::to_string(value).c_str()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
