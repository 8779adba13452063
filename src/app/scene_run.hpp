// One run of a scene, in its three stages: set-up (scene -> model -> distributed mesh -> plan, the
// result file or in-memory store, the model check), the analyses (form finding, statics, path
// following, dynamics with their step analyses) and the end (closing the results, the summary).
// The command line (runner.cpp) and the library entry (sinew/simulation.hpp) both run scenes with it.
#pragma once
#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

#include "app/phases/model_checks.hpp"
#include "app/phases/run_context.hpp"
#include "app/plan.hpp"
#include "app/summary.hpp"
#include "mesh/distributed_mesh.hpp"
#include "output/output_target.hpp"
#include "settings/settings.hpp"
#include "sinew/model.hpp"
#include "sinew/result_store.hpp"
#include "sinew/simulation.hpp"

namespace sinew {

class Restart;
class CheckpointWriter;

class SceneRun {
 public:
  /// toFile: the HDF5 result file (-o, else <opt.filename or scene stem>.h5) as on the command
  /// line; otherwise the results stay in memory (ResultStore, no checkpoints; -restart refused).
  SceneRun(MPI_Comm comm, SceneSource scene, const Settings& settings, bool toFile);
  ~SceneRun();
  SceneRun(const SceneRun&) = delete;
  SceneRun& operator=(const SceneRun&) = delete;

  /// Scene -> model -> distributed mesh -> plan, warnings and header, the result file (checked and
  /// locked) or store, -restart, the constraint check. A failure prints its message (rank 0) and
  /// sets exitCode() (1 output, 2 scene or model error) on every rank; nothing is run then.
  PetscErrorCode setUp();
  /// The procedures the plan asks for, each writing its converged steps.
  PetscErrorCode runAnalyses();
  /// Closes the results (converged when every analysis converged) and prints the summary; sets
  /// exitCode() to 0, 3 (an analysis failed), 2 (a mechanism found on the way), 5 (interrupted) or
  /// 1 (writing the results failed).
  PetscErrorCode finish();

  /// After a PETSc error that every rank returned from runAnalyses(): closes the results with
  /// converged = 0 (the steps written so far are kept), as the file's destructor does.
  void closeResults();

  int exitCode() const { return exitCode_; }
  /// Whether setUp() got as far as the results (the analyses can run).
  bool ready() const { return ctx_ != nullptr; }
  /// The in-memory results (after finish(); empty for a run to a file).
  RunResults takeResults();
  /// The result file's path (runs to a file).
  const std::string& resultPath() const { return h5_; }

 private:
  PetscErrorCode fail(int exitCode, const std::string& message);
  void readModel();
  void fillLayout(ResultLayout& layout);
  PetscErrorCode createResults(const ResultLayout& layout);
  PetscErrorCode restoreRestart(const ResultLayout& layout);
  PetscErrorCode printSummary();

  MPI_Comm comm_;
  SceneSource scene_;
  Settings settings_;
  bool toFile_;
  int exitCode_ = 0;
  Timings times_;
  double t0_ = 0;
  Model model_;
  std::unique_ptr<DistributedMesh> dmesh_;
  Plan plan_;
  std::string fingerprint_;  // of the scene, stored with every checkpoint (app/phases/restart.hpp)
  std::string h5_;
  OutputLock outputLock_;
  std::unique_ptr<Restart> restart_;
  std::unique_ptr<Assembler> assembler_;
  std::unique_ptr<StepResults> results_;
  std::string inputText_;  // opt.showinputonly: what was read (before the global arrays go)
  std::vector<Vec3> initialPositions_;
  ConstraintCheckSetting check_;
  std::unique_ptr<ResultFile> file_;
  Hdf5ResultFile* hdf5_ = nullptr;  // file_ when the results go to a file
  ResultStore* store_ = nullptr;    // file_ when they stay in memory
  std::unique_ptr<RunContext> ctx_;
  std::unique_ptr<CheckpointWriter> checkpointWriter_;
  bool modelError_ = false;  // a singular tangent found when Newton's linear solve failed
};

/// A PETSc error that every rank returned (a rank that could not reach the others was ended by the
/// solver error handler): rank 0 prints the recorded message; returns the run's exit code.
int reportRunFailure(MPI_Comm comm, PetscErrorCode ierr);

}  // namespace sinew
