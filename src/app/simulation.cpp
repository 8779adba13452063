// The library entry point (sinew/simulation.hpp): PETSc/SLEPc once per process, one SceneRun per
// call with its results in a ResultStore, the run's printed text kept, errors as RunError.
#include "sinew/simulation.hpp"

#include <slepcsys.h>
#include <yaml-cpp/yaml.h>

#include <cstdarg>
#include <cstdio>
#include <set>
#include <sstream>

#include "app/command_line.hpp"
#include "app/phases/library_accuracy.hpp"
#include "app/scene_run.hpp"
#include "output/collective_agreement.hpp"
#include "parallel/collective_error.hpp"
#include "settings/read_settings.hpp"
#include "solvers/ancf/cable_coarse_space.hpp"
#include "solvers/ancf/node_rotated_pc.hpp"
#include "solvers/cut_corrected_lu.hpp"
#include "solvers/dense_lu.hpp"

namespace sinew {

SceneSource SceneSource::file(std::string path) {
  SceneSource s;
  s.path = std::move(path);
  return s;
}

SceneSource SceneSource::yaml(std::string text, std::string baseDir) {
  SceneSource s;
  s.text = std::move(text);
  s.baseDir = std::move(baseDir);
  return s;
}

SceneSource SceneSource::yamlTree(const YAML::Node& root, std::string baseDir) {
  SceneSource s;
  s.tree = std::make_shared<const YAML::Node>(root);
  s.baseDir = std::move(baseDir);
  return s;
}

SceneSource SceneSource::fromModel(Model model) {
  SceneSource s;
  s.model = std::move(model);
  return s;
}

RunError::RunError(int exitCode, const std::string& message, std::string output)
    : std::runtime_error(message), exitCode_(exitCode), output_(std::move(output)) {}

namespace {

bool gStartedSlepc = false;  // initialize() started SLEPc (and finalize() ends it)

/// Keeps what PETSc prints to stdout (PetscPrintf, rank 0) in `text` for its lifetime; echo: also
/// prints it.
class OutputCapture {
 public:
  OutputCapture(std::string* text, bool echo) {
    previous_ = PetscVFPrintf;
    text_ = text;
    echo_ = echo;
    PetscVFPrintf = &print;
  }
  ~OutputCapture() {
    PetscVFPrintf = previous_;
    text_ = nullptr;
  }
  OutputCapture(const OutputCapture&) = delete;
  OutputCapture& operator=(const OutputCapture&) = delete;

 private:
  static PetscErrorCode print(FILE* fd, const char format[], va_list args) {
    if (fd != PETSC_STDOUT || !text_) return previous_(fd, format, args);
    va_list copy;
    va_copy(copy, args);
    const int n = std::vsnprintf(nullptr, 0, format, copy);
    va_end(copy);
    if (n > 0) {
      std::string s(static_cast<std::size_t>(n) + 1, '\0');
      va_copy(copy, args);
      std::vsnprintf(s.data(), s.size(), format, copy);
      va_end(copy);
      s.pop_back();
      text_->append(s);
    }
    return echo_ ? previous_(fd, format, args) : PETSC_SUCCESS;
  }
  static inline std::string* text_ = nullptr;
  static inline bool echo_ = false;
  static inline PetscErrorCode (*previous_)(FILE*, const char[], va_list) = nullptr;
};

/// Sinew's message of a failed run: its "error" lines, else its last line.
std::string errorLines(const std::string& output) {
  std::istringstream in(output);
  std::string line, errors, last;
  while (std::getline(in, line)) {
    if (line.rfind("error", 0) == 0) errors += (errors.empty() ? "" : "\n") + line;
    if (!line.empty()) last = line;
  }
  return errors.empty() ? last : errors;
}

}  // namespace

void initialize(int* argc, char*** argv) {
  PetscBool done = PETSC_FALSE;
  if (SlepcInitialized(&done) || done) return;
  int mpi = 0;
  MPI_Initialized(&mpi);
  if (!mpi) quickSingletonStart();
  if (SlepcInitialize(argc, argv, nullptr, nullptr)) throw RunError(4, "error: PETSc/SLEPc could not be initialised");
  gStartedSlepc = true;
  // Sinew's preconditioners are PETSc PC types, as in main()
  if (registerCutCorrectedLU() || registerNodeRotatedPC() || registerCableCoarsePC() || registerDenseLU())
    throw RunError(4, "error: Sinew's preconditioners could not be registered");
}

void finalize() {
  if (!gStartedSlepc) return;
  gStartedSlepc = false;
  int ended = 0;
  MPI_Finalized(&ended);  // ended by another owner of MPI (mpi4py at interpreter exit): nothing left to end
  if (!ended) SlepcFinalize();
}

RunOutput run(MPI_Comm comm, const SceneSource& scene, const Settings& settings, bool echo) {
  initialize();
  // opt.target_error: levels of refinement, each a run of this function (docs/accuracy.md)
  if (std::optional<RunOutput> study = runTargetErrorInLibrary(comm, scene, settings, echo)) return std::move(*study);
  RunOutput out;
  const bool toFile = settings.output.file.has_value();
  bool ran = false;  // the analyses ran: their results come back
  {
    OutputCapture capture(&out.output, echo);
    SolverErrorGuard guard(comm, 10.0);
    PetscErrorCode ierr = PETSC_SUCCESS;
    try {
      SceneRun run(comm, scene, settings, toFile);
      ierr = run.setUp();
      if (!ierr && run.ready()) {
        ierr = run.runAnalyses();
        if (!ierr) ierr = run.finish();
        else run.closeResults();  // an error every rank returned: the converged steps stay, converged = 0
        ran = true;
      }
      out.exitCode = run.exitCode();
      if (ran) {
        out.results = run.takeResults();
        if (toFile) out.file = run.resultPath();
      }
    } catch (const SolverCallError& e) {  // a constructor's PETSc call failed (SinewCallThrow)
      ierr = e.code();
    } catch (const std::exception& e) {  // the command line would end here; the library reports it
      PetscPrintf(comm, "error: %s\n", e.what());
      out.exitCode = 1;
    }
    if (ierr) out.exitCode = reportRunFailure(comm, ierr);
  }
  out.output = collective::broadcastString(comm, out.output);  // rank 0's text, on every rank
  if (out.exitCode != 0) out.message = errorLines(out.output);
  if (!ran && out.exitCode != 0) throw RunError(out.exitCode, out.message, out.output);
  return out;
}

RunOutput run(MPI_Comm comm, const SceneSource& scene, const std::vector<Flag>& flags, bool echo) {
  initialize();
  std::string problems;
  std::set<std::string> seen;
  for (const auto& [name, value] : flags) {
    std::string p = optionProblem(name, value.empty() ? nullptr : value.c_str());
    if (p.empty() && !seen.insert(name).second) p = "flag -" + name + " given twice";
    if (!p.empty()) problems += (problems.empty() ? "error: " : "\nerror: ") + p;
  }
  if (!problems.empty()) throw RunError(2, problems);
  for (const auto& [name, value] : flags)
    if (PetscOptionsSetValue(nullptr, ("-" + name).c_str(), value.empty() ? nullptr : value.c_str()))
      throw RunError(2, "error: flag -" + name + " not accepted by PETSc");
  // the flags hold for this run only
  struct Clear {
    const std::vector<Flag>& flags;
    ~Clear() {
      for (const auto& f : flags) PetscOptionsClearValue(nullptr, ("-" + f.first).c_str());
    }
  } clear{flags};
  Settings settings;
  if (readSettings(nullptr, &settings)) throw RunError(2, "error: the flags could not be read (a word outside a flag's choices?)");
  return run(comm, scene, settings, echo);
}

}  // namespace sinew
