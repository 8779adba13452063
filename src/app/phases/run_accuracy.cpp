#include "app/phases/run_accuracy.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "accuracy/accuracy_output.hpp"
#include "accuracy/membrane_refinement.hpp"
#include "accuracy/path_quantities.hpp"
#include "accuracy/refinement_study.hpp"
#include "accuracy/time_refinement.hpp"
#include "parallel/collective_error.hpp"
#include "scene/scene_reader.hpp"
#include "settings/read_settings.hpp"
#include "settings/settings.hpp"
#include "sinew/simulation.hpp"

namespace sinew {
namespace {

/// Whether the scene file names target_error at all (only then is it read here before its run).
bool mentionsTargetError(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str().find("target_error") != std::string::npos;
}

/// What -target_error cannot refine yet: "" or the reason (a scene error, exit 2).
std::string unsupported(const Model& m, const Settings& settings) {
  if (const std::string why = accuracy::timeRefinementLimit(m); !why.empty()) return why;  // dt / 2^level
  if (accuracy::refinesSpace(m) && accuracy::hasMembranes(m))
    if (const std::string why = accuracy::membraneRefinementLimit(m); !why.empty()) return why;
  if (const std::string why = accuracy::pathRefinementLimit(m); !why.empty()) return why;
  if (m.opt.showinputonly) return "opt.showinputonly solves nothing to estimate";
  if (!settings.output.restart.empty()) return "-restart continues one run; it does not combine with -target_error";
  return "";
}

/// One level through the library entry: in memory, or into `h5` and read back from there.
accuracy::LevelRun runLevel(MPI_Comm comm, const Settings& settings, const std::string& scenePath, const std::string& h5,
                            const Model& model, bool toFile, const std::set<std::string>& datasets,
                            const std::shared_ptr<StaticsHandover>& handover) {
  accuracy::LevelRun r;
  Settings s = settings;
  s.accuracy.handover = handover;
  s.sceneOpt.clear();  // applied when the scene was read
  s.output.file = toFile ? std::optional<std::string>(h5) : std::nullopt;
  const double t0 = MPI_Wtime();
  try {
    SceneSource source = SceneSource::fromModel(model);
    source.path = scenePath;  // named in the header and messages; the model is what runs
    RunOutput out = run(comm, source, s, false);
    r.exitCode = out.exitCode;
    r.message = out.message;
    r.output = out.output;
    r.results = accuracy::atPathStop(model, std::move(out.results));  // a path's end state at its stop value
  } catch (const RunError& e) {
    r.exitCode = e.exitCode();
    r.message = e.what();
    r.output = e.output();
  }
  r.seconds = MPI_Wtime() - t0;
  if (toFile && r.exitCode == 0) {  // the file is published when run() returns on every rank
    MPI_Barrier(comm);
    std::string error;
    try {
      std::set<std::string> read = datasets;
      for (const std::string& d : accuracy::pathStopDatasets(model)) read.insert(d);
      r.results = accuracy::atPathStop(model, accuracy::readResultDatasets(h5, read));
    } catch (const std::exception& e) {
      error = std::string("error: reading back the level's results: ") + e.what();
    }
    if (const RunFailure f = agreeOnFailure(comm, RunFailure{error.empty() ? 0 : 1, error})) {
      r.exitCode = f.exitCode;
      r.message = f.message;
    }
  }
  return r;
}

}  // namespace

PetscErrorCode runWithTargetError(int argc, char** argv, bool* handled, int* exitCode) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PETSC_COMM_WORLD;
  *handled = false;
  if (argc < 2 || argv[1][0] == '-') PetscFunctionReturn(PETSC_SUCCESS);
  Settings settings;
  PetscCall(readSettings(nullptr, &settings));
  const std::string path = argv[1];
  if (!settings.sceneOpt.count("target_error") && !mentionsTargetError(path)) PetscFunctionReturn(PETSC_SUCCESS);
  Model model;
  RunFailure failure;
  int unreadable = 0;  // a scene error: the usual run reports it
  try {
    model = readScene(path, sceneOverrides(settings));
    if (model.opt.target_error > 0) {
      if (const std::string why = unsupported(model, settings); !why.empty()) failure = {2, "error: opt.target_error: " + why};
      if (settings.output.file && settings.output.file->empty()) failure = {2, "error: -o needs a file name (-o result.h5)"};
    }
  } catch (const std::exception&) {
    unreadable = 1;
  }
  MPI_Allreduce(MPI_IN_PLACE, &unreadable, 1, MPI_INT, MPI_MAX, comm);
  if (unreadable) PetscFunctionReturn(PETSC_SUCCESS);
  failure = agreeOnFailure(comm, failure);
  if (model.opt.target_error <= 0 && !failure) PetscFunctionReturn(PETSC_SUCCESS);
  *handled = true;
  if (failure) {
    PetscCall(PetscPrintf(comm, "%s\n", failure.message.c_str()));
    *exitCode = failure.exitCode;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  const std::string h5 = settings.output.file ? *settings.output.file : model.opt.filename + ".h5";
  const bool silent = model.opt.silent;
  const double target = model.opt.target_error;
  const BeamMass beamMass = settings.dynamics.beamMassInUse();
  const bool h2Frequencies = beamMass == BeamMass::Lumped || beamMass == BeamMass::Linear;  // constant-mass beams
  const accuracy::StudyOptions options =
      accuracy::studyOptions(model, target, settings.accuracy.maxUnknowns, h2Frequencies,
                             settings.accuracy.reuse);
  const std::string space = options.membranes ? "every element split (membranes in four)" : "nbeams x 2";
  const std::string levels = !options.space     ? "dt / 2 (the mesh as written)"
                             : options.time     ? space + " and dt / 2"
                             : options.dynamics ? space + " (dt as written)"
                                                : space;
  if (!silent)
    PetscCall(PetscPrintf(comm, "accuracy on demand: -target_error %g, levels of %s up to -accuracy_max_unknowns %d\n", target,
                          levels.c_str(), settings.accuracy.maxUnknowns));
  const accuracy::StudyResult study = accuracy::runRefinementStudy(
      model, options,
      [&](const Model& m, int, bool toFile, const std::set<std::string>& datasets,
          const std::shared_ptr<StaticsHandover>& handover) {
        return runLevel(comm, settings, path, h5, m, toFile, datasets, handover);
      },
      [&](const std::string& line) {
        if (!silent) PetscPrintf(comm, "%s\n", line.c_str());
      });
  const accuracy::LevelRun& fin = study.finalRun;
  PetscCall(PetscPrintf(comm, "%s", fin.output.c_str()));
  if (fin.exitCode != 0) {  // a level failed (its message was printed with its output)
    PetscCall(PetscPrintf(comm, "error: -target_error: %s; no level is reported\n", study.stopReason.c_str()));
    *exitCode = fin.exitCode;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (const RunFailure f = writeAccuracyToFile(comm, h5, study)) {
    PetscCall(PetscPrintf(comm, "%s\n", f.message.c_str()));
    *exitCode = f.exitCode;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (!silent) PetscCall(PetscPrintf(comm, "%s", accuracy::accuracyTable(study).c_str()));
  *exitCode = 0;
  if (!study.met) {
    const accuracy::LevelRecord& best = study.levels.back();
    char worst[32] = "none (fewer than 3 levels)";
    if (best.worst >= 0) std::snprintf(worst, sizeof worst, "%.2e", best.worst);
    PetscCall(PetscPrintf(comm, "error: -target_error %g not reached: %s; %s holds level %d (%s), worst estimate %s\n", target,
                          study.stopReason.c_str(), h5.c_str(), best.level, accuracy::levelName(best.level, study.time, study.space).c_str(),
                          worst));
    *exitCode = 3;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::string targetErrorLimit(const Model& model, const Settings& settings) { return unsupported(model, settings); }

accuracy::LevelRun runAccuracyLevel(MPI_Comm comm, const Settings& settings, const std::string& scenePath,
                                    const std::string& h5, const Model& model, bool toFile,
                                    const std::set<std::string>& datasets,
                                    const std::shared_ptr<StaticsHandover>& handover) {
  return runLevel(comm, settings, scenePath, h5, model, toFile, datasets, handover);
}

RunFailure writeAccuracyToFile(MPI_Comm comm, const std::string& h5, const accuracy::StudyResult& study) {
  std::string error;
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0) {
    try {
      accuracy::writeAccuracyGroup(h5, study);
    } catch (const std::exception& e) {
      error = std::string("error: writing /accuracy: ") + e.what();
    }
  }
  return agreeOnFailure(comm, RunFailure{error.empty() ? 0 : 1, error});
}

}  // namespace sinew
