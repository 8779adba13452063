// Checkpoint of a run inside its result file (group /checkpoint, docs/results.md "Restart"):
// the complete state an analysis needs to continue from the last written step (-restart), in a
// rank-independent order (global FE node id, global FE element id), so that a run can be continued
// on any number of ranks.
//   /checkpoint/scalars        [kNumScalars]   phase, rows written, step counters, load factor/time,
//                                              the analysis' own step-size state (names: attribute `names`)
//   /checkpoint/node_<vs>      [nfe, 12 + 6 nv]  per FE node: reference position X0 (changed by a FORCE
//                                              elastic restart), reference rotation R_ref (9, row-major;
//                                              identity without rotations), then each vector v at the
//                                              node DOFs (6 columns, 0 where constrained)
//   /checkpoint/element_<vs>   [nfe_el, 6 nv + k] per FE element: each vector's constraint multipliers
//                                              (6 columns), then the element's internal state
//                                              (ElementKernel::saveCheckpoint, k columns)
//   /checkpoint/formfinding    [steps, 9]      form-finding history (step reports)
//   /checkpoint/path           [n]             path following: step state, points, critical points
//                                              (ContinuationAnalysis::checkpointState)
// with vs = the phase's vectors joined by "_" (checkpointVectors: U_dU for statics), v = U (state), dU (statics: last increment, the secant predictor), V, A, Qdd (dynamics:
// velocities, generalized-alpha auxiliary and true accelerations). Attribute `fingerprint` holds
// the scene's fingerprint (SceneFingerprint) to refuse a restart with another scene.
// /checkpoint_formfinding has the same layout: the state at the end of form finding (the found shape
// before the elastic restart), written once, so that a load analysis with other loads can restart there.
// /checkpoint_dynamics_start has the same layout too: the state a damped dynamics run started from
// (time step 0: U with the start rotations R_ref, written once; a -restart rebuilds the damping there).
// Every dataset has a fixed size and is overwritten in place at every written step: the group
// costs (3 + 9 + 6 nv) doubles per FE node and 6 nv (+ k) per FE element, nv = vectors of the phase.
#pragma once
#include <petscvec.h>

#include <array>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "assembly/assembler.hpp"
#include "sinew/result_file.hpp"

namespace sinew {

/// What a checkpoint's scalars say (slots of /checkpoint/scalars).
enum CheckpointScalar : int {
  kCkPhase,          ///< CheckpointPhase
  kCkRows,           ///< step rows of the result file this state belongs to
  kCkStep,           ///< steps done in the phase: form-finding steps, load steps, time steps
  kCkStepValue,      ///< load factor or time of the last row
  kCkLoadsteps,      ///< statics: loadsteps of the ramp (load factor of step k: StaticAnalysis::stepFactor)
  kCkLambda,         ///< statics: load factor reached
  kCkDlPrev,         ///< statics: last converged increment (secant predictor)
  kCkDlAdapt,        ///< statics: adaptive increment carried to the next step
  kCkFintConverged,  ///< statics: ||f_int|| of the last converged state (convergence test)
  kCkTime,           ///< dynamics: time reached
  kCkSubstep,        ///< dynamics: current (sub-)step size h
  kCkSuccesses,      ///< dynamics: successful halved sub-steps in a row (growth rule)
  kCkDt,             ///< dynamics: dt of the run
  kCkSpectralRadius, ///< dynamics: spectral radius of the run
  kCkEnergy0,        ///< dynamics with -dynamics_energy: initial T + S - W
  kCkMaxDrift,       ///< dynamics with -dynamics_energy: largest energy change so far
  kCkFormFinding,    ///< 1 when the run had a form-finding phase
  kCkLoadRamp,       ///< statics: opt.load_ramp of the run (0 spacar: (k-1)/(n-1), 1 uniform: k/n)
  kCkExternalWork,   ///< dynamics with -dynamics_energy: work of the external loads so far
  kCkExternalPower,  ///< dynamics with -dynamics_energy: their power at the last time step
  kCkAdaptScale,     ///< dynamics with adaptive steps: displacement scale of the error estimate (largest |U| so far)
  kNumScalars
};

/// Group of the start state of a damped dynamics run (opt.dynamics damping, docs/dynamics.md "Damping").
inline constexpr const char* kDynamicsStartGroup = "checkpoint_dynamics_start";

enum class CheckpointPhase : int { FormFinding = 1, Statics = 2, Dynamics = 3, Continuation = 4 };
const char* phaseName(CheckpointPhase p);
/// The vectors a phase's checkpoint holds, in column order: U (form finding); U, dU (statics);
/// U, V, A, Qdd (dynamics); U, dU (path following: the last path increment).
std::vector<std::string> checkpointVectors(CheckpointPhase p);

/// Columns of /checkpoint/formfinding (one form-finding step report per row).
inline constexpr int kFormFindingColumns = 9;

struct CheckpointData {
  std::array<double, kNumScalars> scalars{};
  std::vector<std::pair<std::string, Vec>> vectors;  ///< unknowns-layout vectors by name
  std::vector<double> formfinding;                   ///< rank 0: rows of kFormFindingColumns
  long formfindingRows = 0;                          ///< fixed row count (capacity) of /checkpoint/formfinding
  std::vector<double> path;                          ///< path following: ContinuationAnalysis::checkpointState
  long pathSize = 0;                                 ///< its fixed size (0: no /checkpoint/path)
};

/// Writes the checkpoint group of a result file (collective; ResultFileError on HDF5 errors). The
/// data become visible with the next ResultFile::commit(), together with the step they belong to.
class CheckpointWriter {
 public:
  /// fingerprint: SceneFingerprint text, stored once.
  CheckpointWriter(Assembler& assembler, std::string fingerprint);
  /// group: "checkpoint" (the last written step) or "checkpoint_formfinding" (the found shape,
  /// written once when form finding ends).
  void write(ResultFile& file, const CheckpointData& data, const std::string& group = "checkpoint");

 private:
  Assembler& asm_;
  std::string fingerprint_;
  long numFeElements_ = 0;
  int kernelColumns_ = 0;
  std::set<std::string> groups_;  ///< groups whose attributes are written
};

/// Reads a checkpoint on every rank (read-only, independent of the rank count that wrote it).
/// Throws std::runtime_error with a message naming the file and what is missing.
class CheckpointReader {
 public:
  CheckpointReader(MPI_Comm comm, const std::string& path, const std::string& group = "checkpoint");
  ~CheckpointReader();
  CheckpointReader(const CheckpointReader&) = delete;
  CheckpointReader& operator=(const CheckpointReader&) = delete;

  const std::string& path() const { return path_; }
  const std::string& group() const { return group_; }
  const std::array<double, kNumScalars>& scalars() const { return scalars_; }
  CheckpointPhase phase() const { return static_cast<CheckpointPhase>(static_cast<int>(scalars_[kCkPhase])); }
  int rows() const { return static_cast<int>(scalars_[kCkRows]); }
  const std::string& fingerprint() const { return fingerprint_; }
  /// The scene text of the run that wrote the file (root attribute `scene`); empty when it has none.
  std::string sceneText() const;
  long feNodes() const { return feNodes_; }
  long feElements() const { return feElements_; }
  /// Form-finding history rows (kFormFindingColumns each); empty when none.
  std::vector<double> formfinding() const;
  /// Path-following state (/checkpoint/path); empty when none.
  std::vector<double> pathState() const;
  bool hasVector(const std::string& name) const;

  /// Sets this rank's entries of the unknowns-layout vector v from /checkpoint/{node,element}_<name>
  /// (ghosts updated). Collective.
  PetscErrorCode loadVector(const std::string& name, Assembler& assembler, Vec v) const;
  /// Node reference positions and rotations of every local node (ghosts included).
  void loadNodes(Assembler& assembler) const;
  /// Element internal states (ElementKernel::loadCheckpoint) of the local elements.
  void loadKernels(Assembler& assembler) const;
  /// Every step-indexed dataset (unlimited along the step axis) with its name, for copying rows.
  std::vector<std::string> stepDatasets() const;
  /// Step row `step` of dataset `name`, restricted to the rows rows2 of its second axis (a node,
  /// element or mesh table; nullptr: the whole row), in that order; inner = dims after the step axis.
  std::vector<double> readStepRow(const std::string& name, int step, const std::vector<long>* rows2,
                                  std::vector<long>* inner) const;
  /// A dataset written once (formfinding/residual ...): its values and shape.
  std::vector<double> readArray(const std::string& name, std::vector<long>* shape) const;
  bool exists(const std::string& name) const;
  /// Dataset `name` has one row per step-analysis row (its attribute rows = "step_analysis_rows",
  /// ResultFile::beginAnalysisRow), not one per step.
  bool onAnalysisRows(const std::string& name) const;
  /// Dimensions of dataset `name`.
  std::vector<long> datasetShape(const std::string& name) const;

 private:
  /// Columns [first, first + m) of the rows `rows` of table `name`.
  std::vector<double> readRows(const std::string& name, const std::vector<long>& rows, int first, int m) const;
  /// Every scalar finite, every count an integer in its range (throws std::runtime_error naming it).
  void checkScalars() const;
  /// Name of the node or element table of the checkpoint's phase ("checkpoint/node_U_dU").
  std::string table(const char* kind) const;
  MPI_Comm comm_;
  std::string path_, group_;
  long long file_ = -1;
  std::array<double, kNumScalars> scalars_{};
  std::string fingerprint_;
  long feNodes_ = 0, feElements_ = 0;
};

}  // namespace sinew
