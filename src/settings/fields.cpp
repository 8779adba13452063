// The field tables of the settings structs: one line per flag (name, accepted values, -help group,
// default as -help shows it, meaning, member). A new flag is a field of its component's struct
// (settings.hpp) and one line here; the registry, -help, the start-up check and the reader follow.
// A choice flag's words name its enum's values in order.
#include "settings/fields.hpp"

namespace sinew {

const std::vector<Field<OutputSettings>>& outputFields() {
  static const std::vector<Field<OutputSettings>> fields = {
      {"o", text("a file name"), &flag_groups::output, "<filename>.h5", "result file (HDF5; the XDMF file for ParaView is written beside it)", &OutputSettings::file},
      {"output_fsync_interval", realIn(0, 1e9, false, true), &flag_groups::output, "10", "seconds between forced disk commits; one process: commits of the result file forced to the disk (fsync; 0: every commit; several processes: every commit). A killed run never loses committed steps; a machine crash loses at most this interval", &OutputSettings::fsyncInterval},
      {"restart", text("a result file"), &flag_groups::output, "none", "continue the run of this result file; from its last written step (same scene; docs/results.md, Restart)", &OutputSettings::restart},
      {"checkpoint", boolean(), &flag_groups::output, "true", "write /checkpoint (the restart state) with every written step; false: the run cannot be continued", &OutputSettings::checkpoint},
      {"stop_after_step", integerAtLeast(0), &flag_groups::output, "0 (off)", "testing aid: stop as on SIGTERM after this many rows; once the result file holds them (exit 5)", &OutputSettings::stopAfterStep, true},
      {"verbose", boolean(), &flag_groups::output, "false", "the summary also prints the developer counters (assemblies, result-file commits, element force-law evaluations)", &OutputSettings::verbose},
  };
  return fields;
}

const std::vector<Field<StaticsSettings>>& staticsFields() {
  static const std::vector<Field<StaticsSettings>> fields = {
      {"force_rtol", realIn(0, 1, true, true), &flag_groups::statics, "1e-11", "equilibrium tolerance; residual relative to the element forces (dynamics: default 1e-10)", &StaticsSettings::forceRtol},
      {"max_cuts", integerIn(0, 50), &flag_groups::statics, "10", "halvings of a failing load increment (dynamics: of a failing time step)", &StaticsSettings::maxCuts},
      {"predictor", boolean(), &flag_groups::statics, "auto (true; false for beams under the mixed-stress Newton)", "secant predictor from the last converged increment", &StaticsSettings::predictor},
      {"newton_mixed_stresses", boolean(), &flag_groups::statics, "true", "beams, statics and dynamics: Newton with mixed stresses (stress part of the tangent from linearized stresses; docs/beam.md)", &StaticsSettings::mixedStresses, true},
      {"newton_diverged_its", integerAtLeast(0), &flag_groups::statics, "auto (6 for beams under the mixed-stress Newton, else 0)", "Newton iterations before a diverging increment is cut; an increment still above its start residual after this many Newton iterations is cut (0: never)", &StaticsSettings::divergedIts},
      {"adaptive_increments", boolean(), &flag_groups::statics, "true", "grow a cut increment again; after a cut, when Newton converges quickly", &StaticsSettings::adaptiveIncrements},
      {"increment_grow_its", integerAtLeast(0), &flag_groups::statics, "5", "Newton iterations that count as quick (the next increment doubles)", &StaticsSettings::incrementGrowIts},
      {"tangent_operator", oneOf({"auto", "elementwise", "assembled"}), &flag_groups::statics, "auto", "Newton systems: element-wise GMRES or LU; GMRES on the element-wise tangent preconditioned by LU, or the LU alone (auto: element-wise for ANCF cables)", choiceOf(&StaticsSettings::tangentOperator)},
      {"assembly_coo", boolean(), &flag_groups::statics, "true", "COO assembly of the Jacobian (false: MatSetValuesLocal)", &StaticsSettings::assemblyCoo, true},
      {"dense_max_unknowns", integerAtLeast(0), &flag_groups::statics, "200", "dense LU of the tangent up to this many unknowns; the statics Newton, constraint-check and time-step solves (on several processes every process factoring the whole matrix) and on one process the compliance, by LAPACK (getrf with partial pivoting) instead of MUMPS (0: always MUMPS; docs/performance.md)", &StaticsSettings::denseMaxUnknowns},
  };
  return fields;
}

const std::vector<Field<ContinuationSettings>>& continuationFields() {
  static const std::vector<Field<ContinuationSettings>> fields = {
      {"continuation_rtol", realIn(0, 1, true, true), &flag_groups::statics, "1e-9", "path following: residual tolerance; relative to |dR/dlambda| max(1, |lambda|) (docs/continuation.md)", &ContinuationSettings::rtol},
      {"continuation_max_it", integerAtLeast(1), &flag_groups::statics, "15", "path following: corrector iterations before a step is cut", &ContinuationSettings::maxIt},
      {"continuation_desired_its", integerAtLeast(1), &flag_groups::statics, "5", "path following: corrector iterations aimed at; by the adaptive step", &ContinuationSettings::desiredIts},
      {"continuation_inertia", boolean(), &flag_groups::statics, "true", "path following: tangent inertia per point; the count of the tangent's negative eigenvalues at every point (MUMPS LDL^T)", &ContinuationSettings::inertia},
      {"continuation_initial_steps", integerAtLeast(1), &flag_groups::statics, "10", "path following: increments of the initial loads; in which the initial loads (force_initial, displ_initial, ...) are applied before the path starts from their equilibrium", &ContinuationSettings::initialSteps},
      {"branch_switch", boolean(), &flag_groups::statics, "false", "path following: switch branch at a bifurcation; at the first bifurcation, onto the bifurcated branch along the critical eigenvector (symmetric bifurcations; docs/continuation.md)", &ContinuationSettings::branchSwitch},
      {"continuation_lowest_eigenvalue", boolean(), &flag_groups::statics, "false", "path following: also the tangent's eigenvalue closest to 0 (lowest of 4, SLEPc shift-and-invert) per point, /path/lowest_eigenvalue", &ContinuationSettings::lowestEigenvalue},
  };
  return fields;
}

const std::vector<Field<AncfSettings>>& ancfFields() {
  static const std::vector<Field<AncfSettings>> fields = {
      {"ancf_coarse_ratio", integerAtLeast(0), &flag_groups::ancf, "auto", "fine ANCF elements per coarse element; of the two-level preconditioner (0: none; auto: ~2 sqrt(n) from 1024 elements per scene element)", &AncfSettings::coarseRatio, true},
      {"ancf_coarse_predictor", boolean(), &flag_groups::ancf, "true", "predict each increment by a nonlinear coarse solve (SNES prefix coarse_snes_)", &AncfSettings::coarsePredictor, true},
  };
  return fields;
}

const std::vector<Field<ModelCheckSettings>>& modelCheckFields() {
  static const std::vector<Field<ModelCheckSettings>> fields = {
      {"constraint_check", boolean(), &flag_groups::check, "true", "mechanism / redundant constraint check before solving", &ModelCheckSettings::enabled},
      {"constraint_check_max_unknowns", integerAtLeast(0), &flag_groups::check, "200000", "skip the check above this many unknowns", &ModelCheckSettings::maxUnknowns, true},
      {"constraint_check_tol", realIn(0, 1, true, true), &flag_groups::check, "1e-11", "null vectors: ||J v|| <= tol ||D v||", &ModelCheckSettings::tol, true},
      {"constraint_check_vectors", integerAtLeast(1), &flag_groups::check, "3", "null vectors looked for and reported", &ModelCheckSettings::vectors, true},
  };
  return fields;
}

const std::vector<Field<EigenSettings>>& eigenFields() {
  static const std::vector<Field<EigenSettings>> fields = {
      {"eigen_operator", oneOf({"auto", "elementwise", "assembled"}), &flag_groups::modal, "auto", "frequencies and buckling: element-wise or assembled K; K applied element by element (rigid-motion free) with GMRES + LU inner solves, or the assembled K and its LU alone (auto: element-wise where available)", choiceOf(&EigenSettings::eigenOperator)},
      {"freq_shift_rel", realIn(0, 1, true, false), &flag_groups::modal, "1e-8", "shift-and-invert target -freq_shift_rel * min diag(K)/diag(M)", &EigenSettings::freqShiftRel},
      {"eps_nev", integerAtLeast(1), &flag_groups::modal, "nfreq", "(SLEPc) frequencies computed; overrides opt.nfreq", std::monostate{}},
      {"eps_target", anyReal(), &flag_groups::modal, "automatic", "(SLEPc) shift-and-invert target; of the frequency analysis, replaces -freq_shift_rel", GivenRef<EigenSettings>{&EigenSettings::userTarget}},
      {"eigen_dense_max_unknowns", integerAtLeast(0), &flag_groups::modal, "120", "dense eigensolver up to this many unknowns; frequencies and buckling by LAPACK: the same shift-and-invert problem as SLEPc's, gathered and solved dense on rank 0 (0: always SLEPc; docs/performance.md)", &EigenSettings::denseMaxUnknowns},
      {"buck_eps_nev", integerAtLeast(1), &flag_groups::modal, "automatic", "(SLEPc) buckling multipliers computed (default: grown until nbuck positive ones)", GivenRef<EigenSettings>{&EigenSettings::userBucklingNev}},
  };
  return fields;
}

const std::vector<Field<ComplianceSettings>>& complianceFields() {
  static const std::vector<Field<ComplianceSettings>> fields = {
      {"compliance_method", oneOf({"selinv", "sparse", "dense"}), &flag_groups::compliance, "selinv", "how the compliance blocks of the inverse tangent are computed", choiceOf(&ComplianceSettings::method)},
      {"compliance_batch", integerAtLeast(1), &flag_groups::compliance, "96", "unit-load columns per solve (sparse, dense)", &ComplianceSettings::batch, true},
      {"compl_mat_mumps_icntl_27", anyInteger(), &flag_groups::compliance, "2048", "(MUMPS) right-hand sides per block; columns per block of the compliance solve", &ComplianceSettings::mumpsBlockColumns, true},
  };
  return fields;
}

const std::vector<Field<DynamicsSettings>>& dynamicsFields() {
  static const std::vector<Field<DynamicsSettings>> fields = {
      {"dynamics_scheme", oneOf({"arnold_bruls", "tsalpha2", "midpoint", "energy_momentum"}), &flag_groups::dynamics, "arnold_bruls", "time integration scheme; Exudyn's generalized-alpha loop, PETSc TS alpha2, the implicit midpoint rule (Lie group; linear and angular momentum exact, no numerical damping), or the energy-momentum scheme (beams with the linear mass, its default, or the lumped one; cables, ANCF cables, membranes: energy and momenta exact)", choiceOf(&DynamicsSettings::scheme)},
      {"dynamics_modified_newton", oneOf({"auto", "true", "false"}), &flag_groups::dynamics, "auto", "keep the factored Jacobian; across Newton iterations and time steps while each iteration halves the residual (false: a new Jacobian at every iteration; auto: true from 200 unknowns)", choiceOf(&DynamicsSettings::modifiedNewton)},
      {"dynamics_corotated_jacobian", boolean(), &flag_groups::dynamics, "true", "ANCF, modified Newton: rotate a stalled kept Jacobian; a kept Jacobian that stops contracting is first rebuilt from its element blocks rotated with the elements (no element kernel), a fresh one only if that does not help (docs/dynamics.md)", &DynamicsSettings::corotatedJacobian, true},
      {"dynamics_refine", oneOf({"auto", "true", "false"}), &flag_groups::dynamics, "auto", "ANCF, modified Newton: refine each linear solve element-wise; each Newton step's linear solve refined with the Newton matrix applied element by element (the smooth modes of fine cables to full accuracy: 2 Newton iterations per step at 65536 elements instead of 3.75; docs/dynamics.md); true: once; auto: one more refinement (up to 3) each time Newton's updates on one matrix contract by less than 1e-3", choiceOf(&DynamicsSettings::refine), true},
      {"dynamics_node_rotation", oneOf({"auto", "true", "false"}), &flag_groups::dynamics, "auto", "ANCF, modified Newton: turn the kept matrix with the nodes; the kept factored Newton matrix B preconditions as R B^-1 R^T, R turning each node's position and slope by the node's turn since B was built, and refined solves apply the kept element blocks turned to the iterate (fine cables keep a matrix for several steps instead of rebuilding it in every one: 65536 elements, 20 steps: 8 matrices against 18; docs/dynamics.md); auto: when the first kept matrix that stalls does so at an element turn below 2e-3 rad (fine cables; coarser ones rebuild cheaply)", choiceOf(&DynamicsSettings::nodeRotation), true},
      {"dynamics_chain_lu", oneOf({"auto", "cut", "redundant"}), &flag_groups::dynamics, "auto", "ANCF cables on several ranks: cut or redundant chain LU; rank-local LU with an exact correction of the unknowns coupling the ranks (cut), or every rank factoring the whole chain (redundant); auto: cut when at most 64 unknowns couple the ranks", choiceOf(&DynamicsSettings::chainLU), true},
      {"mat_mumps_icntl_14", anyInteger(), &flag_groups::dynamics, "100 (when dynamics factors with MUMPS, else MUMPS' own)", "(MUMPS) extra workspace for pivoting, percent; dynamics reserves 100 so wild Newton iterates do not fail the factorization (INFOG(1) = -9)", &DynamicsSettings::mumpsWorkspace, true},
      {"dynamics_predictor", oneOf({"auto", "acceleration", "state", "rotation"}), &flag_groups::dynamics, "auto", "Newton's start of a time step; q_n + h qd_n + h^2/2 a_n (acceleration), q_n (state; the extrapolation of a fine mesh's unresolved stiff modes lands far off) or q_n moved by each beam node's rigid motion at its velocity and spin (rotation: fast rotation); auto: state from 200 unknowns and for beams", choiceOf(&DynamicsSettings::predictor)},
      {"dt_grow_after", integerAtLeast(0), &flag_groups::dynamics, "3", "steps before a halved time step doubles; after a halving, double the time step after this many successes (0: never)", &DynamicsSettings::dtGrowAfter},
      {"dynamics_adapt", oneOf({"none", "newton", "error"}), &flag_groups::dynamics, "none (opt.dynamics.adaptive.control)", "time-step control; fixed dt (none), from the Newton iteration count (newton) or a local error estimate (error); docs/dynamics.md", choiceOf(&DynamicsSettings::adapt)},
      {"dynamics_dt_min", realIn(0, 1e300, true, false), &flag_groups::dynamics, "dt/1e4 (opt.dynamics.adaptive.dt_min)", "adaptive steps: smallest step", &DynamicsSettings::dtMin},
      {"dynamics_dt_max", realIn(0, 1e300, true, false), &flag_groups::dynamics, "dt*output_every (opt.dynamics.adaptive.dt_max)", "adaptive steps: largest step", &DynamicsSettings::dtMax},
      {"dynamics_adapt_its", integerAtLeast(1), &flag_groups::dynamics, "4 (opt.dynamics.adaptive.target_iterations)", "adaptive steps by Newton: iterations per step aimed at", &DynamicsSettings::adaptIts},
      {"dynamics_adapt_tol", realIn(0, 1e300, true, false), &flag_groups::dynamics, "1e-4 (opt.dynamics.adaptive.tolerance)", "adaptive steps by error: local error accepted per step; estimate / largest displacement", &DynamicsSettings::adaptTol},
      {"beam_mass", oneOf({"consistent", "lumped", "consistent_frozen", "linear"}), &flag_groups::dynamics, "consistent (linear with -dynamics_scheme energy_momentum)", "beam inertia: consistent, lumped or linear mass; the complete consistent mass in the current element frame (with its convective, gyroscopic and frame terms), lumped on the nodes (rhoA l/2 and the section's rotary inertia with its exact gyroscopic moment: momentum-exact with -dynamics_scheme midpoint), linear: Simo and Vu-Quoc's constant mass of linearly interpolated velocities on the translations (rhoA l/6 [2 1; 1 2] per direction) with the section's rotary inertia lumped on the nodes (energy- and momentum-exact with -dynamics_scheme energy_momentum), or consistent_frozen: M(q) qdd alone (before issue 27)", choiceOf(&DynamicsSettings::beamMass)},
      {"stiffness_damping", oneOf({"corotated", "initial"}), &flag_groups::dynamics, "corotated", "stiffness-proportional damping of beams, cables, membranes; beta S on each element's strain rates (rigid motion undamped), or beta K0 with the tangent of the start state (ANCF cables with user force laws: always K0)", choiceOf(&DynamicsSettings::stiffnessDamping)},
      {"dynamics_energy", boolean(), &flag_groups::dynamics, "false", "write energies and momenta per output step; /energy/{kinetic,strain,external_work,total} and /momentum/{linear,angular} (beams, ANCF)", &DynamicsSettings::energy},
      {"dynamics_energy_decay", realIn(0, 1, true, true), &flag_groups::dynamics, "0", "energy_momentum: energy decay xi; stresses S (eps_n + eps_n+1)/2 + xi/2 S (eps_n+1 - eps_n): the energy decreases at every step, most in the modes with omega h >> 1 (0: conserved)", &DynamicsSettings::energyDecay},
  };
  return fields;
}

const std::vector<Field<FormFindingSettings>>& formFindingFields() {
  static const std::vector<Field<FormFindingSettings>> fields = {
      {"ff_mat_mumps_icntl_7", integerIn(0, 7), &flag_groups::formfinding, "3", "(MUMPS) form-finding ordering; fill-reducing ordering of the form-finding factorization (3: SCOTCH)", &FormFindingSettings::mumpsOrdering, true},
  };
  return fields;
}

const std::vector<Field<AccuracySettings>>& accuracyFields() {
  static const std::vector<Field<AccuracySettings>> fields = {
      {"accuracy_max_unknowns", integerAtLeast(1), &flag_groups::accuracy, "1000000", "largest level of -target_error, in unknowns; a target that needs a finer level stops at the best level reached with its estimate (exit 3; docs/accuracy.md)", &AccuracySettings::maxUnknowns},
      {"accuracy_reuse", boolean(), &flag_groups::accuracy, "true", "-target_error levels start from the coarser level's states; each level's load steps start Newton from the coarser level's converged states, interpolated onto its nodes (after form finding: its own found shape plus the coarser level's displacement), an arc-length path's steps predict from the coarser level's path and follow its steps as their plan (-accuracy_path_plan), and a level that halves dt starts each time step from the coarser level's time steps (cubic Hermite in time between them); false: every level from the unloaded state (statics, dynamics: the same results to Newton's tolerance; a path's points move with its step sizes; docs/accuracy.md)", &AccuracySettings::reuse},
      {"accuracy_path_plan", boolean(), &flag_groups::accuracy, "true", "a level's arc-length path follows the coarser level's steps (with -accuracy_reuse: its accepted steps as the plan, the last step landed on stop_displacement or stop_load_factor; false: the level's own step control, for comparison; docs/accuracy.md)", &AccuracySettings::pathPlan, true},
  };
  return fields;
}

}  // namespace sinew
