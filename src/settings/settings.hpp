// Sinew's settings: every command-line flag the code acts on, as typed fields of one struct per
// component. The defaults written here are the defaults; a field whose default depends on the model
// ("auto") is a std::optional or an enum with Auto, resolved by the component that knows the model.
// Each field's flag, accepted values, -help group, default text and help are in its component's
// field table (src/settings/fields.cpp), from which the flag registry (sinewFlags()) and -help are
// made. The runner reads every field once from PETSc's options database (readSettings,
// src/settings/read_settings.hpp) after the command line was checked; a test or a tool builds the
// structs in code instead.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace sinew {

struct StaticsHandover;

/// Word lists of the choice flags. Each enum's values follow its flag's words in order (fields.cpp).
enum class OperatorChoice { Auto, Elementwise, Assembled };  ///< auto, elementwise, assembled
enum class AutoSwitch { Auto, On, Off };                     ///< auto, true, false
enum class DynamicsScheme { ArnoldBruls, TSAlpha2, Midpoint, EnergyMomentum };  ///< arnold_bruls, tsalpha2, midpoint, energy_momentum
enum class ChainLU { Auto, Cut, Redundant };                 ///< auto, cut, redundant
enum class DynamicsPredictor { Auto, Acceleration, State, Rotation };  ///< auto, acceleration, state, rotation
enum class TimeStepControl { None, Newton, Error };          ///< none, newton, error
enum class BeamMass { Consistent, Lumped, ConsistentFrozen, Linear };  ///< consistent, lumped, consistent_frozen, linear
enum class StiffnessDamping { Corotated, Initial };          ///< corotated, initial
enum class ComplianceMethod { SelectedInverse, SparseRhs, DenseRhs };  ///< selinv, sparse, dense

/// The result file and checkpoints.
struct OutputSettings {
  std::optional<std::string> file;  ///< -o (nullopt: <opt.filename or scene stem>.h5)
  double fsyncInterval = 10;        ///< -output_fsync_interval [s]
  std::string restart;              ///< -restart: the result file to continue ("": none)
  bool checkpoint = true;           ///< -checkpoint
  int stopAfterStep = 0;            ///< -stop_after_step (0: off)
  bool verbose = false;             ///< -verbose: the summary also prints the developer counters
  bool operator==(const OutputSettings&) const = default;
};

/// Load-stepped statics, and the Newton settings dynamics and path following share with it.
struct StaticsSettings {
  std::optional<double> forceRtol;   ///< -force_rtol (nullopt: 1e-11 in statics, 1e-10 in dynamics)
  int maxCuts = 10;                  ///< -max_cuts (statics, path following, dynamics)
  std::optional<bool> predictor;     ///< -predictor (nullopt: off for beams under the mixed-stress Newton)
  bool mixedStresses = true;         ///< -newton_mixed_stresses (statics and dynamics)
  std::optional<int> divergedIts;    ///< -newton_diverged_its (nullopt: 6 for beams under the mixed-stress Newton, else 0)
  bool adaptiveIncrements = true;    ///< -adaptive_increments
  int incrementGrowIts = 5;          ///< -increment_grow_its
  OperatorChoice tangentOperator = OperatorChoice::Auto;  ///< -tangent_operator
  bool assemblyCoo = true;           ///< -assembly_coo (the assembler's Jacobian assembly)
  int denseMaxUnknowns = 200;        ///< -dense_max_unknowns: one process up to this many unknowns: dense LU of the tangent
  bool operator==(const StaticsSettings&) const = default;
};

/// Path following (opt.continuation).
struct ContinuationSettings {
  double rtol = 1e-9;             ///< -continuation_rtol
  int maxIt = 15;                 ///< -continuation_max_it
  int desiredIts = 5;             ///< -continuation_desired_its
  bool inertia = true;            ///< -continuation_inertia
  int initialSteps = 10;          ///< -continuation_initial_steps
  bool branchSwitch = false;      ///< -branch_switch
  bool lowestEigenvalue = false;  ///< -continuation_lowest_eigenvalue
  bool operator==(const ContinuationSettings&) const = default;
};

/// The statics solver of fine ANCF cables.
struct AncfSettings {
  std::optional<int> coarseRatio;  ///< -ancf_coarse_ratio (nullopt: CableCoarseSpace::defaultRatio)
  bool coarsePredictor = true;     ///< -ancf_coarse_predictor
  bool operator==(const AncfSettings&) const = default;
};

/// The model check for mechanisms and redundant constraints.
struct ModelCheckSettings {
  bool enabled = true;       ///< -constraint_check
  int maxUnknowns = 200000;  ///< -constraint_check_max_unknowns
  double tol = 1e-11;        ///< -constraint_check_tol
  int vectors = 3;           ///< -constraint_check_vectors
  bool operator==(const ModelCheckSettings&) const = default;
};

/// Frequencies and buckling.
struct EigenSettings {
  OperatorChoice eigenOperator = OperatorChoice::Auto;  ///< -eigen_operator
  double freqShiftRel = 1e-8;   ///< -freq_shift_rel
  bool userTarget = false;      ///< -eps_target given: SLEPc's target (EPSSetFromOptions) replaces the automatic one
  bool userBucklingNev = false;  ///< -buck_eps_nev given: SLEPc's count, not grown until nbuck positive ones
  int denseMaxUnknowns = 120;   ///< -eigen_dense_max_unknowns: dense LAPACK solve up to this many unknowns (0: always SLEPc)
  bool operator==(const EigenSettings&) const = default;
};

/// Compliance matrices.
struct ComplianceSettings {
  ComplianceMethod method = ComplianceMethod::SelectedInverse;  ///< -compliance_method
  int batch = 96;                 ///< -compliance_batch
  int mumpsBlockColumns = 2048;   ///< -compl_mat_mumps_icntl_27 (MUMPS ICNTL(27) of the selected inverse)
  bool operator==(const ComplianceSettings&) const = default;
};

/// Time integration (opt.dynamics). The step-control fields override opt.dynamics.adaptive (nullopt: the scene's).
struct DynamicsSettings {
  DynamicsScheme scheme = DynamicsScheme::ArnoldBruls;  ///< -dynamics_scheme
  AutoSwitch modifiedNewton = AutoSwitch::Auto;          ///< -dynamics_modified_newton
  bool corotatedJacobian = true;                          ///< -dynamics_corotated_jacobian
  AutoSwitch refine = AutoSwitch::Auto;                  ///< -dynamics_refine
  AutoSwitch nodeRotation = AutoSwitch::Auto;            ///< -dynamics_node_rotation
  ChainLU chainLU = ChainLU::Auto;                        ///< -dynamics_chain_lu
  int mumpsWorkspace = 100;  ///< -mat_mumps_icntl_14 where dynamics factors with MUMPS (applySolverOptionDefault)
  DynamicsPredictor predictor = DynamicsPredictor::Auto;  ///< -dynamics_predictor
  int dtGrowAfter = 3;                                    ///< -dt_grow_after
  std::optional<TimeStepControl> adapt;                   ///< -dynamics_adapt
  std::optional<double> dtMin, dtMax;                     ///< -dynamics_dt_min, -dynamics_dt_max
  std::optional<int> adaptIts;                            ///< -dynamics_adapt_its
  std::optional<double> adaptTol;                         ///< -dynamics_adapt_tol
  std::optional<BeamMass> beamMass;  ///< -beam_mass (nullopt: not given; beamMassInUse() resolves it)
  StiffnessDamping stiffnessDamping = StiffnessDamping::Corotated;  ///< -stiffness_damping (Damping)
  bool energy = false;                                    ///< -dynamics_energy
  double energyDecay = 0.0;                               ///< -dynamics_energy_decay
  bool operator==(const DynamicsSettings&) const = default;
  /// The beams' mass (the kernel factory): -beam_mass as given, else linear under -dynamics_scheme
  /// energy_momentum (constant, so its step is energy-exact) and consistent otherwise.
  BeamMass beamMassInUse() const {
    return beamMass.value_or(scheme == DynamicsScheme::EnergyMomentum ? BeamMass::Linear : BeamMass::Consistent);
  }
  /// -dynamics_scheme energy_momentum chose the linear beam mass (no -beam_mass given).
  bool linearMassByScheme() const { return !beamMass && scheme == DynamicsScheme::EnergyMomentum; }
};

/// Form finding.
struct FormFindingSettings {
  int mumpsOrdering = 3;  ///< -ff_mat_mumps_icntl_7 (MUMPS ICNTL(7); 3: SCOTCH)
  bool operator==(const FormFindingSettings&) const = default;
};

/// Accuracy on demand (opt.target_error, docs/accuracy.md).
struct AccuracySettings {
  int maxUnknowns = 1000000;  ///< -accuracy_max_unknowns: no level of refinement above this many unknowns
  bool reuse = true;          ///< -accuracy_reuse: a level's statics (arc-length path, time steps) start (predict) from the coarser level's states (path, steps)
  bool pathPlan = true;       ///< -accuracy_path_plan (developer): with reuse, a level's path follows the coarser level's steps
  /// Not a flag: set by a -target_error study on the run of one level (analysis/statics_handover.hpp);
  /// its statics records its states there and starts from the guesses it holds. nullptr: none.
  std::shared_ptr<StaticsHandover> handover;
  bool operator==(const AccuracySettings&) const = default;
};

/// Every setting of a run.
struct Settings {
  OutputSettings output;
  StaticsSettings statics;
  ContinuationSettings continuation;
  AncfSettings ancf;
  ModelCheckSettings check;
  EigenSettings eigen;
  ComplianceSettings compliance;
  DynamicsSettings dynamics;
  FormFindingSettings formfinding;
  AccuracySettings accuracy;
  /// Scene opt fields given as flags (-loadsteps 40): field name -> value as given (the scene
  /// reader checks it and overrides the scene's opt block, sceneOverrides()).
  std::map<std::string, std::string> sceneOpt;
  bool operator==(const Settings&) const = default;
};

}  // namespace sinew
