// The flag registry (src/settings/flags.*): value checks, and which names count as PETSc/SLEPc options.
#include <gtest/gtest.h>

#include <set>

#include "settings/flags.hpp"
#include "settings/petsc_flags.hpp"

using namespace sinew;

namespace {
std::string check(const char* name, const char* value) {
  const Flag* f = findFlag(name);
  EXPECT_NE(f, nullptr) << name;
  return f ? checkFlagValue(*f, value) : "no such flag";
}
}  // namespace

TEST(Flags, RegistryNamesAreUniqueLowerCaseAndNotShadowingPetsc) {
  std::set<std::string> seen;
  for (const Flag& f : sinewFlags()) {
    EXPECT_TRUE(seen.insert(f.name).second) << "-" << f.name << " registered twice";
    for (char c : f.name) EXPECT_TRUE((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_') << f.name;
    EXPECT_FALSE(f.help.empty()) << f.name;
    EXPECT_FALSE(f.defaultValue.empty()) << f.name;
    // Sinew's own flags must not look like PETSc options; the PETSc/SLEPc/MUMPS options Sinew
    // reads itself say so at the start of their help.
    if (f.help[0] != '(') {
      EXPECT_FALSE(isPetscFlag(f.name)) << "-" << f.name;
    }
  }
  EXPECT_NE(findFlag("loadsteps"), nullptr);  // scene opt fields are flags
  EXPECT_NE(findFlag("Max_Cuts"), nullptr);   // PETSc option names are case-insensitive
  EXPECT_EQ(findFlag("loadstep"), nullptr);
}

TEST(Flags, ValueChecks) {
  EXPECT_EQ(check("max_cuts", "0"), "");
  EXPECT_EQ(check("max_cuts", "-1"), "-max_cuts: expected an integer in 0..50, got -1");
  EXPECT_NE(check("max_cuts", "3.5"), "");
  EXPECT_NE(check("max_cuts", "1e3"), "");
  EXPECT_NE(check("max_cuts", nullptr), "");
  EXPECT_EQ(check("force_rtol", "1e-9"), "");
  EXPECT_EQ(check("force_rtol", "nan"), "-force_rtol: expected a finite number in (0, 1), got nan");
  EXPECT_NE(check("force_rtol", "inf"), "");
  EXPECT_NE(check("force_rtol", "0"), "");
  EXPECT_NE(check("force_rtol", "1e-9x"), "");
  EXPECT_EQ(check("ancf_coarse_ratio", "0"), "");
  EXPECT_EQ(check("ancf_coarse_ratio", "-3"), "-ancf_coarse_ratio: expected an integer >= 0, got -3");
  EXPECT_NE(check("ancf_coarse_ratio", "99999999999"), "");  // beyond a 32-bit PetscInt
  EXPECT_EQ(check("tangent_operator", "assembled"), "");
  EXPECT_EQ(check("tangent_operator", "bogus"),
            "-tangent_operator: expected one of auto, elementwise, assembled, got bogus");
  EXPECT_EQ(check("predictor", nullptr), "");  // a bool flag alone is true
  EXPECT_EQ(check("predictor", "NO"), "");
  EXPECT_NE(check("predictor", "maybe"), "");
  EXPECT_EQ(check("o", "out.h5"), "");
  EXPECT_EQ(check("o", nullptr), "-o: expected a file name, got no value");
  EXPECT_EQ(check("o", ""), "-o: expected a file name, got an empty value");
  EXPECT_EQ(check("filename", nullptr), "-filename: expected a value (string), got no value");
  EXPECT_EQ(check("calcbuck", nullptr), "");  // bool opt field alone: true
  EXPECT_EQ(check("loadsteps", "abc"), "");   // opt values are checked by the scene reader
  EXPECT_NE(check("loadsteps", nullptr), "");
  EXPECT_EQ(check("eps_target", "-3.5"), "");
  EXPECT_NE(check("eps_nev", "0"), "");
}

TEST(Flags, PetscOptionsPassSinewTyposDoNot) {
  for (const char* n : {"help", "version", "log_view", "options_left", "options_file", "malloc_debug", "info", "snes_monitor",
                        "ksp_type", "pc_factor_mat_solver_type", "mat_mumps_icntl_14", "eps_tol", "st_ksp_type",
                        "buck_eps_nev", "buck_st_pc_type", "ff_snes_max_it", "compl_ksp_view", "coarse_snes_snes_max_it",
                        "coarse_pc_type", "fine_ksp_monitor", "constraint_check_ksp_type", "init_ksp_type",
                        "mg_levels_1_ksp_type", "sub_pc_type", "fieldsplit_0_pc_type", "ts_adapt_type", "vec_view",
                        "on_error_abort", "fp_trap", "no_signal_handler", "petsc_ci", "bv_type", "ds_method", "rg_type",
                        "fn_type", "svd_nsv", "dm_plex_view"})
    EXPECT_TRUE(isPetscFlag(n)) << "-" << n;
  for (const char* n : {"loadstep", "force_rtl", "maxcuts", "tangent_operators", "constraint_check_tool", "compl_batch",
                        "coarse_ratio", "foo_bar", "o_", "coarse_snes_max_it"})
    EXPECT_FALSE(isPetscFlag(n)) << "-" << n;
  EXPECT_EQ(sinewSolverPrefix("coarse_snes_max_it"), "coarse_snes_");
  EXPECT_EQ(sinewSolverPrefix("coarse_pc_type"), "coarse_");
  EXPECT_EQ(sinewSolverPrefix("loadsteps"), "");
}
