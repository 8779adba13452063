// The lists below come from the option names compiled into libpetsc 3.18.5 and libslepc 3.18.2
// (`strings lib*.so | grep '^-'`: 2303 names) and PETSc's -help output.
#include "settings/petsc_flags.hpp"

#include <algorithm>

namespace sinew {

namespace {

/// Class prefixes of PETSc/SLEPc objects: their options may follow a user or nested prefix
/// (-sub_pc_type, -mg_levels_ksp_type, -st_ksp_type, -fieldsplit_u_pc_type).
const std::vector<std::string> kObjectPrefixes = {
    "ksp",  "pc",  "snes", "ts",  "tao", "mat", "vec", "dm",  "da",  "is",  "sf",  "ao",  "pf",  "eps",
    "st",   "bv",  "ds",   "rg",  "fn",  "svd", "pep", "nep", "mfn", "lme", "draw", "viewer", "npc", "fas",
    "stag", "dmplex", "dmsnes", "dmts", "dmnetwork", "dmcomposite", "matis", "petscfe", "petscfv", "petscds",
    "petscspace", "petscdualspace", "petscsection", "petsclimiter", "petscpartitioner", "petscsf"};

/// Prefixes of PETSc's system options (only at the start of a name).
const std::vector<std::string> kSystemPrefixes = {
    "log",       "malloc",     "options",   "info",       "debugger", "device",  "root",       "mpi",
    "on",        "error",      "dll",       "random",     "petsc",    "slepc",   "saws",       "glvis",
    "psubcomm",  "vecscatter", "vecstash",  "vecload",    "matstash", "matload", "matptap",    "matmatmult",
    "matmatmatmult", "matrart", "matconvert", "mattransposematmult", "matmattransmult", "matden2sp",
    "islocaltoglobalmapping", "adaptor", "adapt", "convest", "cuda", "hip", "kokkos", "sycl", "nvshmem",
    "sub", "gdsw", "sol", "ssls", "orientation", "petscpartititoner"};  // (sic: PETSc 3.18 spells one option so)

/// Whole option names of PETSc's system options.
const std::vector<std::string> kSystemOptions = {
    "help",          "version",         "info",          "log",           "malloc",          "history",
    "display",       "nox",             "nox_warning",   "fp_trap",       "python",          "citations",
    "checkfunctionlist", "check_pointer_intensity", "no_signal_handler", "objects_dump", "mpidump",
    "memory_view",   "get_total_flops", "skip_petscrc",  "start_in_debugger", "stop_for_debugger",
    "debug_terminal", "disable_sse",    "library_preload", "tmp",          "shared_tmp",      "not_shared_tmp",
    "noshared",      "x_virtual",       "use_gpu_aware_mpi", "build_twosided", "viewfromoptions", "popen_machine",
    "prefix_push",   "prefix_pop",      "default_device_type", "use_fast_submatrix", "splitreduction_async",
    "drawaxis_hold", "lg_marker_type",  "lg_use_markers", "bar_sort",     "check_saddlepoint", "pid",
    // DMPlex / PCBDDC / TAO diagnostics
    "check_extrude", "cones_view", "edge_global_section_view", "field_fe_view", "geometry", "global_section_view",
    "interp_root_degree_view", "islocaltoglobalmappinggetinfo_debug", "lag_view", "lumped_mass_inv_view",
    "misk_aggregation_view", "noise_test", "overlap_view", "overwrite_hessian", "parents_view", "partition_view",
    "preconditioned", "press_view", "print_vecs", "rdm_view", "recompute_w", "section_view",
    "vertex_global_section_view", "view_isolated_separators"};

bool startsWithWord(const std::string& name, const std::string& word) {
  return name.size() > word.size() && name.compare(0, word.size(), word) == 0 && name[word.size()] == '_';
}

bool containsWord(const std::string& name, const std::string& word) {
  return name.find("_" + word + "_") != std::string::npos;
}

}  // namespace

const std::vector<std::string>& sinewSolverPrefixes() {
  // longest first: coarse_snes_ before coarse_
  static const std::vector<std::string> prefixes = {"constraint_check_", "continuation_", "coarse_snes_", "coarse_",
                                                    "compl_", "fine_", "buck_", "init_", "ff_", "rotated_", "cut_"};
  return prefixes;
}

std::string sinewSolverPrefix(const std::string& name) {
  for (const std::string& p : sinewSolverPrefixes())
    if (name.size() > p.size() && name.compare(0, p.size(), p) == 0) return p;
  return "";
}

bool isPetscFlag(const std::string& full) {
  const std::string name = full.substr(sinewSolverPrefix(full).size());
  if (std::find(kSystemOptions.begin(), kSystemOptions.end(), name) != kSystemOptions.end()) return true;
  for (const std::string& w : kSystemPrefixes)
    if (startsWithWord(name, w)) return true;
  for (const std::string& w : kObjectPrefixes)
    if (startsWithWord(name, w) || containsWord(name, w)) return true;
  return false;
}

}  // namespace sinew
