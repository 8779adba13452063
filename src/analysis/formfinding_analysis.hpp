// Form finding with the Updated Reference Strategy (URS, Bletzinger & Ramm 1999; design.md section 2,
// `formfinding` block with CARAT++ names), then the elastic restart of the load analysis.
//
// Form-found elements: the cable and membrane kernels of the sets in formfinding_elements (every
// cable and membrane set when the list is empty). They run in form-finding mode (prescribed
// prestress, stress-dependent stiffness only, homotopy factor lambda); every other element stays
// elastic with its own reference. Loads during form finding: those of load factor 0, i.e.
// force_initial, moment_initial, displ_initial_*, pressure_initial (ramped loads, gravity and
// `pressure` act in the load analysis only).
// Step k = 1..formfinding_step:
//   1. lambda_k = homotopy_curve[k-1] (the last entry for later steps; 0 without a curve); membranes
//      switch to xURS when x_urs and k >= x_urs_step;
//   2. equilibrium R(u) = 0 with an own SNES (options prefix ff_: -ff_snes_monitor, -ff_ksp_type ...),
//      at most max_iter_equilibrium Newton iterations; converged when
//      ||R|| <= equilibrium_accuracy * max(||f_int||, ||f_ext||) (element-force scale of assembler);
//      reaching max_iter_equilibrium continues with the next step (as CARAT++), but the last step
//      must be in equilibrium;
//   3. shape change s_k = max_nodes |u_k - u_{k-1}| / D, D = diagonal of the bounding box of the
//      initial nodes; s_k > max_shape_change is an error (no equilibrium shape: prestress too low
//      for the loads/edge cables, or a free membrane edge), naming the form-found sets;
//      normal shape change n_k = max_nodes |P_a (u_k - u_{k-1})| / D with the projection P_a onto
//      the shape-relevant directions of node a (the tangential motion of a membrane's nodes within
//      its surface, and of an edge node along its edge cable, leaves the shape unchanged and is not
//      determined by the URS: Bletzinger et al. measure the normal change): P_a = n n^T (n =
//      dominant eigenvector of sum A n n^T of the adjacent form-found membranes: independent of
//      their node order) at membrane nodes without
//      cables, I - t t^T (t = direction of the adjacent collinear form-found cables) at membrane
//      nodes on edge cables, I at all other nodes (cable nets, loaded chains, partly fixed nodes);
//   4. the reference of every form-found kernel := current shape (updateReference, with stress
//      adaption first for the sets in stress_adaption: lambda_max, mue_relax); a membrane whose
//      area drops below 1e-3 of its initial area, or degenerates, is an error (crumpling);
//   5. the step is reported (residual ||R||, s_k, smallest membrane mesh quality); the loop stops
//      early when n_k < formfinding_tolerance (Sinew extension; not given: all formfinding_step
//      steps as CARAT++ runs them, the shape found when n_k < 1e-6 at the end), k >= 2 and
//      s_k <= s_{k-1}: the shape has converged even when the mesh still drifts in the surface (a
//      growing total change is an in-plane collapse, not convergence).
// The solution vector U always holds displacements from the initial geometry.
//
// Elastic restart (elastic_restart_method), afterwards every kernel is elastic:
//   FORCE        found shape = new reference: node reference positions X0 := found positions,
//                U := 0; form-found kernels keep the found shape as reference and the (adapted)
//                form-finding prestress as initial stress (cable N0, membrane S0).
//   DISPLACEMENT found shape as the stress-free reference: form-found kernels keep the found shape
//                as reference with zero initial stress; U (displacements from the initial
//                geometry) and X0 are kept, so displacements continue from form finding.
//   NONE         back to the initial geometry without prestress: U := 0, form-found kernels get
//                their initial reference and zero initial stress.
#pragma once
#include <petscsnes.h>

#include <functional>
#include <string>
#include <vector>

#include "analysis/constraint_check.hpp"
#include "assembly/assembler.hpp"
#include "elements/element_kinds.hpp"  // formFoundSets
#include "settings/settings.hpp"
#include "sinew/model.hpp"
#include "solvers/newton_test.hpp"

namespace sinew {

struct FormFindingStepReport {
  int step = 0;
  double lambda = 0;          ///< homotopy factor
  bool xurs = false;
  int newtonIterations = 0;
  double residualNorm = 0;    ///< ||R|| after the equilibrium iterations
  bool equilibrium = false;   ///< equilibrium_accuracy reached
  double shapeChange = 0;     ///< max nodal displacement change / model size
  double shapeChangeNormal = 0;  ///< max nodal shape-relevant change / model size (stop criterion)
  double meshQuality = 1;     ///< smallest membrane mesh quality after the step (1 without membranes)
};

class FormFindingAnalysis {
 public:
  /// eprops: the model's property sets (names in messages, which sets are form-found). settings:
  /// -ff_mat_mumps_icntl_7.
  FormFindingAnalysis(Assembler& assembler, const FormFinding& ff, const std::vector<ElementSet>& eprops,
                      const FormFindingSettings& settings);
  ~FormFindingAnalysis();
  FormFindingAnalysis(const FormFindingAnalysis&) = delete;
  FormFindingAnalysis& operator=(const FormFindingAnalysis&) = delete;

  using StepCallback = std::function<PetscErrorCode(const FormFindingStepReport&, Vec U)>;
  /// Runs the form-finding steps from U (displacements from the initial geometry). Collective.
  PetscErrorCode run(Vec U, const StepCallback& onStep, bool* ok);
  /// The loop ends after the step whose onStep set *stop (an interrupt or a failed result file);
  /// the run is then neither converged nor failed here: the caller knows why it stopped.
  void setStopFlag(const bool* stop) { stop_ = stop; }
  /// Continues after the steps of `history` (a checkpoint; the kernels' references and prestress,
  /// and U, restored by the caller): run() starts at step history.size() + 1, or stops at once when
  /// the last of them met the stop criterion.
  void resume(std::vector<FormFindingStepReport> history) { reports_ = std::move(history); }

  /// The causes of a collapse or of a too large shape change that this model has (issue 10 item 17:
  /// the messages name only these), e.g. "3 membrane edges are free (...)"; set by the caller, which
  /// knows the whole scene. Empty: the generic hint.
  void setFailureHint(std::string hint) { hint_ = std::move(hint); }

  /// Switches every form-found kernel to elastic as elastic_restart_method says (see file comment).
  PetscErrorCode restart(Vec U);

  const std::vector<FormFindingStepReport>& reports() const { return reports_; }
  const std::string& failureMessage() const { return failure_; }
  double modelSize() const { return size_; }
  double initialMeshQuality() const { return quality0_; }
  long numFormFoundElements() const { return nff_; }
  SNES snes() const { return snes_; }

 private:
  static PetscErrorCode formFunction(SNES, Vec U, Vec F, void* ctx);
  static PetscErrorCode formJacobian(SNES, Vec U, Mat J, Mat P, void* ctx);
  static PetscErrorCode convergenceTest(SNES, PetscInt it, PetscReal xnorm, PetscReal snorm, PetscReal fnorm,
                                        SNESConvergedReason* reason, void* ctx);
  void setMode(double lambda, bool xurs);
  /// Updates the references; returns 0 or the 1-based scene element that degenerated (collective max).
  PetscErrorCode updateReferences(Vec U, long* badElement, double* quality);
  PetscErrorCode shapeChange(Vec U, Vec Uprev, double* change);
  /// Shape-relevant part of the step's nodal motion (file comment, step 3): normal component at
  /// membrane nodes, component across the edge cable at membrane edge nodes, full elsewhere.
  PetscErrorCode normalShapeChange(Vec U, Vec Uprev, double* change);
  std::string setNames() const;

  Assembler& asm_;
  const bool* stop_ = nullptr;
  FormFinding ff_;
  /// The Newton test: SNES's default test, or the residual below equilibrium_accuracy times the force scale.
  NewtonTest newtonTest_;
  std::vector<ElementSet> eprops_;
  std::vector<int> ffSets_;
  std::vector<int> elems_;                       // local elements that are form-found
  std::vector<std::array<double, 12>> initial_;  // their initial state (NONE restart)
  std::vector<double> size0_;                    // their initial size (length or area)
  SNES snes_ = nullptr;
  Mat J_ = nullptr;
  Vec F_ = nullptr;
  Vec nrm_ = nullptr, nrmOff_ = nullptr;  // nodal membrane normal tensors sum A n n^T (diagonal, off-diagonal)
  Vec mdiag_ = nullptr, moff_ = nullptr;  // nodal cable direction tensors
  LoadState ls_;
  double size_ = 1.0, quality0_ = 1.0;
  long nff_ = 0;
  std::vector<FormFindingStepReport> reports_;
  std::string failure_;
  std::string hint_;
};

/// Mechanisms and redundant constraints of the form-finding problem (collective): the tangent at the
/// initial geometry (load factor 0) with the form-found kernels in the mode of step 1 (homotopy
/// factor, xURS), i.e. the stiffness form finding itself solves with: prestress-only (geometric)
/// stiffness of the form-found cables and membranes (in the reference problem, lambda = 0, a cable
/// acts as its force density N0/L in every direction and a membrane as sigma grad u . grad v),
/// elastic stiffness of every other element. A node no element holds in some direction, a net
/// without supports (rigid translation), a mast free to swing about the corner it carries, are
/// null directions of this tangent. The kernels are elastic again afterwards. denseMaxUnknowns:
/// -dense_max_unknowns (checkConstraints).
PetscErrorCode checkFormFindingConstraints(Assembler& assembler, const Model& model, const ModelCheckSettings& settings,
                                           int denseMaxUnknowns, ConstraintReport* report);

}  // namespace sinew
