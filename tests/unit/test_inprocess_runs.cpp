// Runs of whole scenes in one process (issue 23: app/ is a library, sinew_app, whose phases can be
// run in-process; issue 25 builds its library entry on this). PETSc and SLEPc are initialised once;
// the test then runs, through sinew::runFromCommandLine with options set in PETSc's database as a
// caller would:
//  (1) the cross-flexure hinge (statics, frequencies, buckling, compliance): exit 0, converged;
//  (2) a scene file that does not exist: exit 2 (a scene error), the process goes on;
//  (3) a scene whose Newton cannot converge (-snes_max_it 2 -max_cuts 0): exit 3, the process goes on;
//  (4) the hinge again: /node/p, /freq, /buck and /node/CMglob equal run (1)'s bit for bit, so no state
//      of a run (options, log events, error handlers, registered PC types, static tables) leaks
//      into the next;
//  (5) a path-following scene and a dynamics scene after them: exit 0.
// On the ranks it is started with (ctest: 1 and 2). Exit status 0 only when every check passed.
#include <hdf5.h>
#include <slepcsys.h>

#include <cstdio>
#include <string>
#include <vector>

#include "app/runner.hpp"
#include "solvers/ancf/node_rotated_pc.hpp"
#include "solvers/cut_corrected_lu.hpp"

#ifndef SINEW_SOURCE_DIR
#error "SINEW_SOURCE_DIR: the source tree (tests/CMakeLists.txt)"
#endif

namespace {

int failures = 0;

void expect(bool ok, const std::string& what) {
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (!ok) ++failures;
  if (rank == 0) std::printf("%s %s\n", ok ? "ok  " : "FAIL", what.c_str());
}

/// One run of `scene` with the options `opts` (name, value) set in the global database for it.
int run(const std::string& scene, const std::vector<std::pair<std::string, std::string>>& opts) {
  for (const auto& [k, v] : opts) PetscOptionsSetValue(nullptr, k.c_str(), v.empty() ? nullptr : v.c_str());
  std::string exe = "sinew", path = scene;
  char* argv[] = {exe.data(), path.data(), nullptr};
  int code = -1;
  if (sinew::runFromCommandLine(2, argv, &code) != PETSC_SUCCESS) code = -2;
  for (const auto& [k, v] : opts) PetscOptionsClearValue(nullptr, k.c_str());
  return code;
}

/// A dataset of the result file as doubles (rank 0 reads; every rank gets nothing else to compare).
std::vector<double> readDataset(const std::string& file, const char* name) {
  std::vector<double> out;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return out;
  const hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
  if (d >= 0) {
    const hid_t s = H5Dget_space(d);
    out.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(s)));
    if (H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0) out.clear();
    H5Sclose(s);
    H5Dclose(d);
  }
  H5Fclose(f);
  return out;
}

int convergedAttribute(const std::string& file) {
  int value = -1;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return value;
  const hid_t a = H5Aopen(f, "converged", H5P_DEFAULT);
  if (a >= 0) {
    H5Aread(a, H5T_NATIVE_INT, &value);
    H5Aclose(a);
  }
  H5Fclose(f);
  return value;
}

}  // namespace

int main(int argc, char** argv) {
  PetscCall(SlepcInitialize(&argc, &argv, nullptr, nullptr));
  PetscCall(sinew::registerCutCorrectedLU());
  PetscCall(sinew::registerNodeRotatedPC());
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  const std::string src = SINEW_SOURCE_DIR, tag = std::to_string(size);
  const std::string hinge = src + "/runs/crosshinge.yaml";
  const std::string first = "inprocess_first_" + tag + ".h5", again = "inprocess_again_" + tag + ".h5";
  const std::vector<std::pair<std::string, std::string>> quiet = {{"-silent", "true"}};

  int code = run(hinge, {{"-o", first}, {"-silent", "true"}});
  expect(code == 0 && convergedAttribute(first) == 1, "(1) crosshinge in-process: exit " + std::to_string(code));
  code = run(src + "/runs/no_such_scene.yaml", quiet);
  expect(code == 2, "(2) a missing scene file: exit " + std::to_string(code) + " (2 expected), the process goes on");
  code = run(hinge, {{"-o", "inprocess_fail_" + tag + ".h5"}, {"-silent", "true"}, {"-snes_max_it", "2"},
                     {"-max_cuts", "0"}, {"-calccompl", "false"}, {"-calcbuck", "false"}});
  expect(code == 3, "(3) a Newton that cannot converge: exit " + std::to_string(code) + " (3 expected)");
  code = run(hinge, {{"-o", again}, {"-silent", "true"}});
  expect(code == 0, "(4) crosshinge again: exit " + std::to_string(code));
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0) {
    for (const char* name : {"/node/p", "/freq", "/buck", "/node/CMglob"}) {
      const std::vector<double> a = readDataset(first, name), b = readDataset(again, name);
      expect(!a.empty() && a == b, std::string("(4) ") + name + " of the second run equals the first's bit for bit (" +
                                       std::to_string(a.size()) + " values)");
    }
  }
  code = run(src + "/runs/lee_frame.yaml", {{"-o", "inprocess_path_" + tag + ".h5"}, {"-silent", "true"}});
  expect(code == 0, "(5) path following (runs/lee_frame.yaml) after them: exit " + std::to_string(code));
  code = run(src + "/runs/ancf_userfunction.yaml", {{"-o", "inprocess_dyn_" + tag + ".h5"}, {"-silent", "true"}});
  expect(code == 0, "(5) ANCF dynamics (runs/ancf_userfunction.yaml) after them: exit " + std::to_string(code));

  MPI_Allreduce(MPI_IN_PLACE, &failures, 1, MPI_INT, MPI_SUM, PETSC_COMM_WORLD);
  PetscCall(SlepcFinalize());
  return failures == 0 ? 0 : 1;
}
