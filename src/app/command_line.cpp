#include "app/command_line.hpp"

#include <hdf5.h>
#include <metis.h>
#include <slepcsys.h>

#include <cctype>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "scene/nearest_name.hpp"
#include "settings/flags.hpp"
#include "settings/help_text.hpp"
#include "settings/petsc_flags.hpp"
#include "settings/read_settings.hpp"
#include "sinew/petsc_compat.hpp"

#if !defined(SINEW_VERSION) || !defined(SINEW_YAMLCPP_VERSION)
#error "SINEW_VERSION and SINEW_YAMLCPP_VERSION come from CMakeLists.txt"
#endif

namespace sinew {

const char* sinewVersion() { return SINEW_VERSION; }

// Measured with hyperfine (`sinew -version`, one run, minimum of 12 starts, machine under load): 0.49 s
// by default, 0.36 s without the daemon (ess_singleton_isolated), 0.28 s also without the network
// probing. A user's own OMPI_MCA_* settings win (setenv does not overwrite); under mpirun/srun
// nothing changes.
void quickSingletonStart() {
  if (std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") || std::getenv("PMI_RANK") ||
      std::getenv("SLURM_PROCID"))
    return;
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  setenv("OMPI_MCA_pml", "ob1", 0);
  setenv("OMPI_MCA_btl", "self,vader", 0);
  // An isolated singleton's session directory is always <tmp>/ompi.<host>.<uid>/jf.0/1, made at
  // MPI_Init and removed at exit: two runs started side by side (a parameter sweep, xargs -P, a test
  // running three at a time) race on it, and the loser aborts in MPI_Init ("A call to mkdir was
  // unable to create the desired directory: .../jf.0/1"; seen under load). One directory per process,
  // removed by Open MPI at exit as before (tests/cases/test_singleton_start.py).
  const char* tmp = std::getenv("TMPDIR");
  const std::string session = std::string(tmp && *tmp ? tmp : "/tmp") + "/ompi.sinew." + std::to_string(getpid());
  setenv("OMPI_MCA_orte_jobfam_session_dir", session.c_str(), 0);
}

const char* usageText() {
  return "Sinew: parallel finite elements for flexures, cables and membranes.\n"
         "Usage: mpirun -n N sinew scene.yaml [-o result.h5] [-<opt field> value ...] [Sinew flags] [PETSc options]\n"
         "Sinew's own flags: sinew -help. Below: PETSc's and SLEPc's options (with a scene: its solvers').\n";
}

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::string optionProblem(const std::string& given, const char* value) {
  const std::string name = lower(given);
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

namespace {

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

/// -version: Sinew's version, then one line per library it runs on (as linked, where the library
/// can say so at run time).
PetscErrorCode printVersions(MPI_Comm comm) {
  PetscFunctionBeginUser;
  PetscInt p[4], s[4];
  PetscCall(PetscGetVersionNumber(&p[0], &p[1], &p[2], &p[3]));
  PetscCall(SlepcGetVersionNumber(&s[0], &s[1], &s[2], &s[3]));
  char mpi[MPI_MAX_LIBRARY_VERSION_STRING] = "";
  int len = 0;
  MPI_Get_library_version(mpi, &len);
  std::string mpiName(mpi, static_cast<std::size_t>(len));
  mpiName = mpiName.substr(0, mpiName.find_first_of(",\n"));  // "Open MPI v4.1.4, package: ..." -> "Open MPI v4.1.4"
  unsigned h[3] = {0, 0, 0};
  H5get_libversion(&h[0], &h[1], &h[2]);
  std::ostringstream out;
  out << "Sinew " << sinewVersion() << "\n"
      << "PETSc " << p[0] << "." << p[1] << "." << p[2] << "\n"
      << "SLEPc " << s[0] << "." << s[1] << "." << s[2] << "\n"
      << mpiName << "\n"
      << "HDF5 " << h[0] << "." << h[1] << "." << h[2] << "\n"
      << "METIS " << METIS_VER_MAJOR << "." << METIS_VER_MINOR << "." << METIS_VER_SUBMINOR << "\n"
      << "yaml-cpp " << SINEW_YAMLCPP_VERSION << "\n";
  PetscCall(PetscPrintf(comm, "%s", out.str().c_str()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

/// "-help", "-h", "--help": Sinew's help words ("-help_petsc" is PETSc's).
bool isHelpWord(const std::string& a) { return a == "-help" || a == "-h" || a == "--help"; }

StartRequest takeStartRequest(int* argc, char** argv) {
  StartRequest r;
  int kept = 1;
  for (int i = 1; i < *argc; ++i) {
    const std::string a = argv[i];
    if (isHelpWord(a)) {
      r.kind = StartRequest::Kind::Help;
      // -help <flag>: the next word names a registered flag ("max_cuts" or "-max_cuts")
      if (i + 1 < *argc) {
        std::string next = argv[i + 1];
        if (!next.empty() && next[0] == '-') next.erase(0, 1);
        if (findFlag(next) || (argv[i + 1][0] != '-' && next.find('.') == std::string::npos && !next.empty())) {
          r.kind = StartRequest::Kind::HelpFlag;
          r.flag = next;
          ++i;
        }
      }
    } else if (a == "-help_dev") {
      r.kind = StartRequest::Kind::HelpDev;
    } else if (a == "-version" || a == "--version") {
      r.kind = StartRequest::Kind::Version;
    } else if (a == "-help_petsc") {
      static char petscHelp[] = "-help";
      argv[kept++] = petscHelp;
    } else {
      argv[kept++] = argv[i];
    }
  }
  argv[kept] = nullptr;
  *argc = kept;
  return r;
}

PetscErrorCode petscHelpRequested(PetscBool* help) {
  PetscFunctionBeginUser;
  PetscCall(readPetscHelp(help));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode handleCommandLine(MPI_Comm comm, const StartRequest& request, int argc, const char* const* argv, bool* stop,
                                 int* exitCode) {
  PetscFunctionBeginUser;
  *stop = false;
  *exitCode = 0;
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
  using K = StartRequest::Kind;
  *stop = request.kind != K::Run;
  if (request.kind == K::Version) {
    PetscCall(printVersions(comm));
  } else if (request.kind == K::Help || request.kind == K::HelpDev) {
    PetscCall(PetscPrintf(comm, "%s", helpText(sinewVersion(), request.kind == K::HelpDev).c_str()));
  } else if (request.kind == K::HelpFlag) {
    if (const Flag* f = findFlag(request.flag)) {
      PetscCall(PetscPrintf(comm, "%s", flagDetail(*f).c_str()));
    } else {
      std::vector<std::string> names;
      for (const Flag& g : sinewFlags()) names.push_back(g.name);
      const std::string near = scene::nearestName(lower(request.flag), names);
      PetscCall(PetscPrintf(comm, "error: -help %s: no such Sinew flag%s\n", request.flag.c_str(),
                            near.empty() ? " (sinew -help lists them)" : ("; did you mean " + near + "?").c_str()));
      *exitCode = 2;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
