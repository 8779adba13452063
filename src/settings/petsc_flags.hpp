// Which command-line options belong to PETSc/SLEPc (they pass through Sinew's flag check).
#pragma once
#include <string>
#include <vector>

namespace sinew {

/// The options prefixes Sinew gives its own solvers (SNES ff_ and coarse_snes_, KSP compl_,
/// coarse_, fine_, constraint_check_ and init_, EPS buck_): -buck_eps_tol is SLEPc's -eps_tol.
const std::vector<std::string>& sinewSolverPrefixes();
/// The solver prefix `name` starts with (the longest), or "".
std::string sinewSolverPrefix(const std::string& name);

/// True when `name` (without '-', lower case) is a PETSc 3.18 / SLEPc 3.18 option: after one of
/// Sinew's solver prefixes is stripped, it is a generic PETSc option (-help, -log_view,
/// -options_left, -malloc_debug, ...) or starts with the prefix of a PETSc/SLEPc class
/// (snes_, ksp_, pc_, mat_, eps_, st_, ts_, ...), directly or after a nested prefix such as
/// mg_levels_1_ or sub_ (-mg_levels_1_ksp_type, -fieldsplit_0_pc_type).
bool isPetscFlag(const std::string& name);

}  // namespace sinew
