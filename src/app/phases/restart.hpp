// -restart old.h5: continue a run from the checkpoint of an earlier run of the same scene
// (restart/checkpoint.hpp; docs/results.md "Restart"). The new result file starts with copies of
// the earlier run's step rows (0 .. rows - 1 of its checkpoint), then the analysis continues:
//   form finding  from the next URS step (or, when form finding had ended, with the load analysis),
//   statics       from the next load step; the load factor of step k stays that of the earlier run
//                 (its loadsteps and opt.load_ramp: StaticAnalysis::stepFactor), so -loadsteps N
//                 beyond it continues the ramp past load factor 1 (another opt.load_ramp is refused),
//   dynamics      from the next time step to the scene's (possibly later) tend,
//   path following after the last path point (its step size, increment, points and critical points).
// A scene that differs from the earlier one (nodes, elements, eprops, supports, form-finding block) is
// refused (exit 2) naming what differs. Other loads are accepted after form finding: from a
// checkpoint written during form finding, or else from /checkpoint_formfinding (the found shape),
// so that the load analysis starts anew from the found shape with the new loads.
// -stop_after_step k (a testing aid) stops a run as SIGTERM would once its file holds k step rows
// (copied rows included): that step and its checkpoint are written, the file is closed with
// converged = 0 and the exit code is 5.
#pragma once
#include <algorithm>
#include <memory>
#include <string>

#include "analysis/continuation_analysis.hpp"
#include "analysis/formfinding_analysis.hpp"
#include "analysis/static_analysis.hpp"
#include "app/phases/run_context.hpp"
#include "dynamics/dynamic_analysis.hpp"
#include "restart/checkpoint.hpp"

namespace sinew {

/// The scene's fingerprint: lines "what: value" (counts and hashes of nodes, elements, eprops,
/// supports, loads, form-finding block) that a restart compares.
std::string sceneFingerprint(const Model& model, long feNodes, long feElements);

class Restart {
 public:
  /// Opens the checkpoint of `path` and checks it against
  /// this run: fingerprint, analysis kind, dynamics dt and spectral radius. When the source is
  /// the output file itself (or its .part), it is read from a copy. Throws SceneError (exit 2)
  /// for a refused restart or an unreadable source. scheme: this run's -dynamics_scheme.
  Restart(MPI_Comm comm, const std::string& path, const std::string& output, const std::string& fingerprint,
          const Model& model, const Plan& plan, DynamicsScheme scheme);
  ~Restart();

  CheckpointPhase phase() const { return reader_->phase(); }
  const CheckpointReader& reader() const { return *reader_; }
  const std::string& source() const { return reader_->path(); }

  /// Copies the earlier run's step rows (and its form-finding arrays when form finding had ended)
  /// into ctx.file (rows of this run's layout; the caller commits), restores node reference
  /// positions/rotations, element states and ctx.U. Collective; throws std::runtime_error
  /// (ResultFileError) when the source cannot be read or the new file written.
  void restore(RunContext& ctx, const ResultLayout& layout);
  /// The restored checkpoint (scalars, U, the phase's other vectors in `work`, to be destroyed by the
  /// caller), for writing it into the new file at once.
  PetscErrorCode restoredState(RunContext& ctx, CheckpointData& d, std::vector<Vec>* work) const;
  /// Form finding: the history of the earlier steps and the kernels' states after them.
  void resumeFormFinding(RunContext& ctx, FormFindingAnalysis& analysis) const;
  /// Statics: progress, last increment; the ramp's loadsteps stay those of the earlier run.
  PetscErrorCode resumeStatics(RunContext& ctx, StaticAnalysis& statics) const;
  /// Dynamics: progress and rates; energy0/maxDrift/external work and power of -dynamics_energy.
  PetscErrorCode resumeDynamics(RunContext& ctx, DynamicAnalysis& dyn, double* energy0, double* maxDrift, double* work,
                                double* power) const;
  /// Dynamics with damping: the damping rebuilt at the start state of the interrupted run
  /// (/checkpoint_dynamics_start; copied into the new file); older files: a warning, the damping
  /// of the resumed state. V, A, Q: work vectors (overwritten).
  PetscErrorCode resumeDamping(RunContext& ctx, DynamicAnalysis& dyn, Vec V, Vec A, Vec Q) const;
  /// Path following: its state after the last point, the last increment.
  PetscErrorCode resumeContinuation(RunContext& ctx, ContinuationAnalysis& path) const;
  /// loadsteps of the earlier run's ramp (statics checkpoints).
  int rampLoadsteps() const { return static_cast<int>(reader_->scalars()[kCkLoadsteps]); }
  /// The last load step of the restarted run: one that continues load stepping goes on to the end
  /// of the earlier run's ramp, or to the scene's later opt.loadsteps, unless -loadsteps is given
  /// (loadstepsGiven: then opt.loadsteps is the last step, before or after the ramp's end).
  int lastLoadStep(int sceneLoadsteps, bool loadstepsGiven) const {
    return phase() == CheckpointPhase::Statics && !loadstepsGiven ? std::max(rampLoadsteps(), sceneLoadsteps) : sceneLoadsteps;
  }

 private:
  void check(MPI_Comm comm, const std::string& src, const std::string& path, const std::string& fingerprint,
             const Model& model, const Plan& plan, DynamicsScheme scheme);
  void removeCopy();
  /// A new vector in the unknowns layout holding the checkpoint's vector `name` (the caller destroys it).
  PetscErrorCode loadedVector(RunContext& ctx, const char* name, Vec* v) const;
  MPI_Comm comm_;
  std::string copy_;  ///< temporary copy of the source (removed at the end), or ""
  std::unique_ptr<CheckpointReader> reader_;
};

/// The last load step the run executes: opt.loadsteps, or on a restart that continues load stepping
/// restart->lastLoadStep (to the end of the earlier ramp unless -loadsteps is given).
int lastLoadStepOf(const Restart* restart, const Model& model, const Settings& settings);

/// Form-finding reports as rows of /checkpoint/formfinding and back.
std::vector<double> formfindingRows(const std::vector<FormFindingStepReport>& reports);
std::vector<FormFindingStepReport> formfindingReports(const std::vector<double>& rows);

}  // namespace sinew
