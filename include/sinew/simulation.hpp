// Sinew as a library: run a scene on the ranks of a communicator and get its results in memory.
//
//   sinew::initialize();                                   // PETSc and SLEPc, once per process
//   sinew::Settings settings;                              // every flag's default ("settings/settings.hpp")
//   settings.sceneOpt["loadsteps"] = "5";                  // an opt field, as -loadsteps 5 would
//   sinew::RunOutput out = sinew::run(MPI_COMM_WORLD, sinew::SceneSource::file("runs/crosshinge.yaml"), settings);
//   const sinew::ResultArray& p = out.results.datasets.at("node/p");   // [ns, nn, 3], on every rank
//
// A run writes no file unless settings.output.file names one (then the HDF5 file and its XDMF are
// written as by the command line, and out.results stays empty). Errors that leave no results (a
// scene error, a mechanism found before the run, a PETSc error) throw RunError with Sinew's
// message and exit code; a run whose analysis failed returns its converged steps with exitCode 3
// and converged = 0. Nothing aborts the process.
#pragma once
#include <mpi.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sinew/model.hpp"
#include "sinew/result_store.hpp"

namespace YAML {
class Node;
}

namespace sinew {

/// Every flag's setting, with its default (src/settings/settings.hpp: include it to fill one in code).
struct Settings;

/// The scene of a run: a scene file, YAML text, or a Model built in code.
struct SceneSource {
  std::string path;           ///< a scene file (messages name it; opt.filename defaults to its stem)
  std::string text;           ///< YAML text (when no path)
  /// The scene's YAML tree instead of text (when no path), read as YAML::Load would give it from
  /// the text (sinew._core builds it from a dict); the text is made only for a result file.
  std::shared_ptr<const YAML::Node> tree;
  std::string baseDir = ".";  ///< where the text's relative paths (mesh:) are read from
  /// A model built in code, as the scene reader makes it (nodes, elements 0-based, elementSet,
  /// connectedNodes, nprops, eprops, opt); flags of opt fields (settings.sceneOpt) do not apply.
  std::optional<Model> model;
  static SceneSource file(std::string path);
  static SceneSource yaml(std::string text, std::string baseDir = ".");
  static SceneSource yamlTree(const YAML::Node& root, std::string baseDir = ".");
  static SceneSource fromModel(Model model);
};

/// A run that produced no results: exitCode as the command line's (1 output or other error, 2 scene,
/// flag or model error, 4 PETSc/SLEPc error); what() is Sinew's message ("error: ..." lines).
class RunError : public std::runtime_error {
 public:
  RunError(int exitCode, const std::string& message, std::string output = "");
  int exitCode() const { return exitCode_; }
  const std::string& output() const { return output_; }  ///< what the run printed

 private:
  int exitCode_;
  std::string output_;
};

/// A run that got as far as its analyses.
struct RunOutput {
  RunResults results;   ///< every dataset, on every rank (empty for a run to a file)
  int exitCode = 0;     ///< 0 converged; 3 an analysis failed (the converged steps are kept); 2 a
                        ///< mechanism found by a failed step; 5 stopped (-stop_after_step); 1 output error
  std::string message;  ///< Sinew's error lines when exitCode != 0
  std::string output;   ///< what the run printed on rank 0 (the same text on every rank)
  std::string file;     ///< the result file written (settings.output.file), or ""
  bool converged() const { return exitCode == 0; }
};

/// PETSc and SLEPc (and MPI) for the library: initialised when not yet done, with Sinew's PC types
/// registered, once per process; nothing is finalised per run. argc/argv: PETSc options (may be null).
void initialize(int* argc = nullptr, char*** argv = nullptr);
/// Finalises SLEPc/PETSc if initialize() started them (e.g. at interpreter exit, before MPI ends).
void finalize();

/// Runs `scene` with `settings` on the ranks of `comm` (collective). echo: the run's stdout text
/// (header, progress, summary) is printed as well as kept in RunOutput::output.
RunOutput run(MPI_Comm comm, const SceneSource& scene, const Settings& settings, bool echo = false);

/// A command-line flag: name without '-' ("loadsteps", "snes_max_it") and value ("" for a flag given alone).
using Flag = std::pair<std::string, std::string>;

/// As run(), with settings from command-line flags ({"loadsteps", "5"}, {"snes_monitor", ""}: Sinew's
/// flags, opt fields and PETSc/SLEPc options): each is checked as the command line checks it (an
/// unknown flag, a bad value or a flag given twice: RunError exit 2), put into PETSc's options
/// database for this run only, and the settings are read from there (-o names a result file).
RunOutput run(MPI_Comm comm, const SceneSource& scene, const std::vector<Flag>& flags, bool echo = false);

}  // namespace sinew
