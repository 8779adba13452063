#include "app/phases/library_accuracy.hpp"

#include <petscsys.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "accuracy/accuracy_output.hpp"
#include "accuracy/refinement_study.hpp"
#include "app/phases/run_accuracy.hpp"
#include "parallel/collective_error.hpp"
#include "scene/scene_reader.hpp"
#include "scene/scene_tree.hpp"
#include "settings/read_settings.hpp"

namespace sinew {
namespace {

/// Whether the source names target_error at all (only then is the scene read here first).
bool namesTargetError(const SceneSource& scene, const Settings& settings) {
  if (settings.sceneOpt.count("target_error")) return true;
  if (scene.model) return scene.model->opt.target_error > 0;
  if (!scene.path.empty()) {
    std::ifstream in(scene.path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str().find("target_error") != std::string::npos;
  }
  if (scene.tree) return treeMentions(*scene.tree, "target_error");
  return scene.text.find("target_error") != std::string::npos;
}

/// The scene's model as SceneRun reads it (nullopt when it cannot be read).
std::optional<Model> readModel(const SceneSource& scene, const Settings& settings) {
  try {
    if (scene.model) {
      Model m = *scene.model;
      checkBuiltModel(m);
      return m;
    }
    if (!scene.path.empty()) return readScene(scene.path, sceneOverrides(settings));
    if (scene.tree) {  // the levels' result file holds the scene text
      Model m = parseSceneTree(*scene.tree, scene.baseDir, sceneOverrides(settings));
      if (settings.output.file) m.sceneText = sceneTreeText(*scene.tree);
      return m;
    }
    return parseScene(scene.text, scene.baseDir, sceneOverrides(settings));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::optional<RunOutput> runTargetErrorInLibrary(MPI_Comm comm, const SceneSource& scene, const Settings& settings,
                                                 bool echo) {
  if (!namesTargetError(scene, settings)) return std::nullopt;
  std::optional<Model> model = readModel(scene, settings);
  int unreadable = model ? 0 : 1;  // a scene error: the ordinary run reports it
  MPI_Allreduce(MPI_IN_PLACE, &unreadable, 1, MPI_INT, MPI_MAX, comm);
  if (unreadable || model->opt.target_error <= 0) return std::nullopt;
  if (const std::string why = targetErrorLimit(*model, settings); !why.empty())
    throw RunError(2, "error: opt.target_error: " + why);
  const std::string h5 = settings.output.file.value_or("");
  const double target = model->opt.target_error;
  const bool silent = model->opt.silent;
  RunOutput out;
  auto say = [&](const std::string& line) {
    if (silent) return;
    out.output += line + "\n";
    if (echo) PetscPrintf(comm, "%s\n", line.c_str());
  };
  const BeamMass beamMass = settings.dynamics.beamMassInUse();
  const bool h2Frequencies = beamMass == BeamMass::Lumped || beamMass == BeamMass::Linear;  // constant-mass beams
  const accuracy::StudyOptions options =
      accuracy::studyOptions(*model, target, settings.accuracy.maxUnknowns, h2Frequencies,
                               settings.accuracy.reuse);
  char head[160];
  std::snprintf(head, sizeof head, "accuracy on demand: -target_error %g, levels up to -accuracy_max_unknowns %ld", target,
                options.maxUnknowns);
  say(head);
  accuracy::StudyResult study = accuracy::runRefinementStudy(
      *model, options,
      [&](const Model& m, int, bool toFile, const std::set<std::string>& datasets,
          const std::shared_ptr<StaticsHandover>& handover) {
        return runAccuracyLevel(comm, settings, scene.path, h5, m, toFile && !h5.empty(), datasets, handover);
      },
      say);
  accuracy::LevelRun& fin = study.finalRun;
  out.output += fin.output;
  if (echo) PetscPrintf(comm, "%s", fin.output.c_str());
  if (fin.exitCode != 0)  // a level failed: no level is reported
    throw RunError(fin.exitCode, fin.message + "\nerror: -target_error: " + study.stopReason + "; no level is reported",
                   out.output);
  if (!h5.empty()) {  // the reported level's file, with /accuracy (rank 0 adds it to the closed file)
    if (const RunFailure f = writeAccuracyToFile(comm, h5, study))
      throw RunError(f.exitCode, f.message, out.output);
    out.file = h5;
  } else {
    out.results = std::move(fin.results);
    RunResults acc = accuracy::accuracyResults(study);
    for (auto& [name, a] : acc.datasets) out.results.datasets[name] = std::move(a);
    out.results.groupTexts["accuracy"] = std::move(acc.groupTexts["accuracy"]);
  }
  say(accuracy::accuracyTable(study));
  if (!study.met) {
    const accuracy::LevelRecord& best = study.levels.back();
    char worst[32] = "none (fewer than 3 levels)";
    if (best.worst >= 0) std::snprintf(worst, sizeof worst, "%.2e", best.worst);
    out.exitCode = 3;
    out.message = "error: -target_error " + std::to_string(target) + " not reached: " + study.stopReason +
                  "; the results are level " + std::to_string(best.level) + " (" +
                  accuracy::levelName(best.level, study.time, study.space) + "), worst estimate " + worst;
    out.output += out.message + "\n";
    if (echo) PetscPrintf(comm, "%s\n", out.message.c_str());
  }
  return out;
}

}  // namespace sinew
