// Accuracy on demand (opt.target_error, docs/accuracy.md): the scene solved on levels of refinement,
// level L with every line element set's nbeams times 2^L (beams, 3D cables, ANCF cables), until the
// Richardson estimate (accuracy/richardson.hpp) of every watched quantity is trusted and, times a
// safety factor 1.25, at most the target. The levels run through a LevelRunner (the app's sinew::run): in memory, except a level that
// may be the last (the estimates of the level before, divided by 2^order, meet the target), which
// writes the run's result file; a reported level that ran in memory is run again into the file.
#pragma once
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "accuracy/quantities.hpp"
#include "accuracy/richardson.hpp"
#include "analysis/statics_handover.hpp"
#include "sinew/model.hpp"
#include "sinew/result_store.hpp"

namespace sinew::accuracy {

/// One level's run, as the runner returns it.
struct LevelRun {
  int exitCode = 0;
  std::string message;  ///< Sinew's error lines when exitCode != 0
  std::string output;   ///< what the run printed (header, progress, summary)
  RunResults results;   ///< the datasets the quantities read (also for a run to the file)
  long unknowns = 0;
  double seconds = 0;   ///< wall time of the level's run
};
/// Runs `model` (level `level`); toFile: into the run's result file, else in memory. `datasets`: what
/// the quantities read, which a run to the file reads back from it. `handover`: the coarser level's
/// states for this level's statics and the record of its own (Settings::accuracy.handover), or nullptr.
using LevelRunner = std::function<LevelRun(const Model& model, int level, bool toFile, const std::set<std::string>& datasets,
                                           const std::shared_ptr<StaticsHandover>& handover)>;

struct LevelRecord {
  int level = 0;
  long factor = 1;     ///< nbeams multiplier 2^level
  long unknowns = 0;   ///< with opt.dynamics: unknowns x time steps
  double seconds = 0;
  long newtonIterations = -1;  ///< every phase's Newton iterations of the level's run (-1: none reported)
  int guessesUsed = 0;         ///< load increments (path steps) that started from the coarser level's state (path)
  long pathSteps = -1;         ///< a path's accepted steps (its points; -1: no path)
  long rejectedSteps = -1;     ///< a path's steps cut or repeated shorter (-1: no path)
  int plannedSteps = 0;        ///< a path's steps that followed the coarser level's steps as their plan
  bool toFile = false;
  std::vector<std::vector<double>> values;  ///< per quantity
  std::vector<Estimate> estimates;          ///< per quantity, from this level and the two before (level >= 2)
  double worst = -1;                        ///< largest estimated error (-1: no estimate yet)
  int limiting = -1;                        ///< quantity of the worst estimate (an erratic one first)
  bool erratic = false;                     ///< some quantity's observed order is not trusted
};

struct StudyResult {
  double target = 0;
  std::vector<QuantityDef> quantities;
  std::vector<LevelRecord> levels;
  bool met = false;         ///< the reported (last) level's estimates are trusted and within the target
  std::string stopReason;   ///< why the levels ended ("target met", "next level ... unknowns > ...", a failure)
  bool time = false;        ///< the levels halve dt (StudyOptions::time)
  bool space = true;        ///< the levels refine the elements (StudyOptions::space)
  LevelRun finalRun;        ///< the reported level's run to the result file (its output and exit code)
  double totalSeconds = 0;  ///< every level's run, the repeated one included
};

/// The model of level `level`, target_error off: nbeams x 2^level for the sets of 2-node elements, or
/// with membranes every element split `level` times (accuracy/membrane_refinement.hpp), and/or with
/// opt.dynamics dt / 2^level (accuracy/time_refinement.hpp; opt.accuracy_refine chooses: time by
/// default, space, or both).
Model refinedModel(const Model& base, int level);

struct StudyOptions {
  double target = 0;        ///< opt.target_error
  long maxUnknowns = 0;     ///< -accuracy_max_unknowns
  bool lumpedMass = false;  ///< -beam_mass lumped (frequencies converge as h^2)
  bool membranes = false;   ///< the scene has membranes: levels split every element, unknowns grow 4x, orders h^2
  ElementOrders orders;     ///< the elements' theoretical orders (elementOrders)
  bool time = false;        ///< levels halve dt (accuracy/time_refinement.hpp)
  bool space = true;        ///< levels refine the elements (nbeams x 2, membranes split)
  bool dynamics = false;    ///< opt.dynamics: a level's unknowns are counted as unknowns x time steps
  bool reuse = true;        ///< -accuracy_reuse: a level's load steps start from the coarser level's states
};

/// The lowest theoretical orders of the model's element kinds (ElementKind::nodalOrder, modalOrder).
ElementOrders elementOrders(const Model& m);
/// The options of a study of `m`: its kinds' orders, membranes, what the levels refine, reuse.
StudyOptions studyOptions(const Model& m, double target, long maxUnknowns, bool lumpedMass, bool reuse);
/// "nbeams x4", "dt / 4" or "nbeams x4, dt / 4": how level `level` of the study refines the scene.
std::string levelName(int level, bool time, bool space);
/// The theoretical order of a time history (docs/accuracy.md "Dynamics"): the time scheme's in dt,
/// the elements' nodal order in h (h^2 with membranes), the lower of the two when both are refined.
double historyOrder(const StudyOptions& options);

/// The Newton iterations a run's summary reports (the sum over its phases; -1: none).
long newtonIterationsOf(const std::string& output);

/// A path's accepted steps and its rejected ones (cut, or repeated shorter after turning the path too far)
/// from a run's summary; -1 each without a path.
void pathStepsOf(const std::string& output, long* steps, long* rejected);

/// Runs the levels. print: one progress line per level (rank 0's text, printed by the caller).
StudyResult runRefinementStudy(const Model& base, const StudyOptions& options, const LevelRunner& run,
                               const std::function<void(const std::string&)>& print);

}  // namespace sinew::accuracy
