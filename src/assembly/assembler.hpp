// Maps element kernels into distributed PETSc objects. The unknowns are free node DOFs
// (translations; incremental rotation vectors theta with R = exp(theta) R_ref; ANCF coordinate
// increments) and the multipliers of rigid deformation modes. Residual rows of rotations are
// spin (moment) balances, so the exact Jacobian is K_spin * T(theta) column-wise.
#pragma once
#include <petscmat.h>
#include "sinew/petsc_compat.hpp"
#include <petscvec.h>

#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "mesh/distributed_mesh.hpp"

namespace sinew {

/// VecGhostUpdateBegin/End of a ghosted vector; nothing on one process, where a ghosted vector has
/// no ghosts (its PetscSF calls cost about 1 us each: 4 per residual, A3 with 1 element).
inline PetscErrorCode ghostUpdate(Vec v, InsertMode im, ScatterMode sm) {
  PetscFunctionBeginUser;
  PetscMPIInt size = 1;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm(reinterpret_cast<PetscObject>(v)), &size));
  if (size == 1) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecGhostUpdateBegin(v, im, sm));
  PetscCall(VecGhostUpdateEnd(v, im, sm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

struct RotaryMomentumStep;  // elements/rotary_momentum.hpp

/// Largest element block: 4 nodes of 6 DOFs and 6 rigid-mode multipliers (index and work arrays).
inline constexpr int kMaxElementRows = 4 * 6 + 6;

struct LoadState {
  double loadFactor = 0.0;     ///< ramps `force`, `moment`, `displ_*`, `rot`, gravity
  double time = 0.0;           ///< passed to kernels (user functions)
  bool gravityRamped = true;   ///< gravity scaled by the load factor (statics)
  double initialFactor = 1.0;  ///< scales the initial loads (`force_initial`, `displ_initial`, ...); path following ramps it to 1 first
  /// Dynamics: nodal loads and prescribed motions given as functions of time are evaluated at `time`
  /// (and the prescribed velocities/accelerations from their derivatives); otherwise (statics) they
  /// act with their values at t = 0, ramped by the load factor like constant ones.
  bool timeFunctions = false;
  /// Dynamics: the time of the configuration, when it is not `time` (energy-momentum: the step's end
  /// t_{n+1}, loads at t_{n+1/2}): prescribed motions take their values at motionTime, their velocities
  /// and accelerations stay those at `time`. NaN: `time`.
  double motionTime = std::numeric_limits<double>::quiet_NaN();
};

/// Counters that prove which phases ran (also visible as PetscLogEvents in -log_view).
struct AssemblyCounters {
  long residuals = 0, jacobians = 0, masses = 0, splitTangents = 0, stressRecoveries = 0;
  long dampingMatrices = 0;  ///< element damping matrices D evaluated (dynamics, hasDamping() only)
  long pressureLoads = 0;    ///< follower pressure element loads evaluated (membranes with pressure only)
};

/// Receives what Assembler::dynamicJacobian computes, block by block: start(shiftA), every element's
/// Newton block K_e + shiftV D_e + shiftA M_e at its state q_e, then nodeTerms() with the iterate's
/// node states loaded. A sink that setsMatrix() sets J itself (setMatrix, after the loop) instead of
/// the assembler's MatSetValuesLocal per block.
class NewtonBlockSink {
 public:
  virtual ~NewtonBlockSink() = default;
  virtual bool setsMatrix() const = 0;
  virtual void start(double shiftA) = 0;
  virtual void element(std::size_t e, const LocalElement& el, const double* q, const double* K) = 0;
  virtual void nodeTerms(const LoadState& ls) = 0;
  virtual PetscErrorCode setMatrix(Mat J) = 0;
};

class Assembler {
 public:
  /// cooAssembly: the Jacobian assembled by COO where the model allows it (-assembly_coo,
  /// StaticsSettings::assemblyCoo), else by MatSetValuesLocal.
  Assembler(DistributedMesh& mesh, const std::optional<Vec3>& gravity, bool cooAssembly);
  ~Assembler();
  Assembler(const Assembler&) = delete;
  Assembler& operator=(const Assembler&) = delete;

  DistributedMesh& mesh() { return mesh_; }
  const DistributedMesh& mesh() const { return mesh_; }
  /// Ghosted vector of unknowns (the layout of every solution/residual vector).
  PetscErrorCode createVector(Vec* v) const;
  /// Ghosted vector over every node DOF (constrained included).
  PetscErrorCode createFullVector(Vec* v) const;
  /// AIJ matrix over the unknowns with exact preallocation from the element graph.
  PetscErrorCode createMatrix(Mat* A) const;

  /// F = f_int(U) - f_ext at the unknowns (constraint rows: constraint values).
  PetscErrorCode residual(Vec U, const LoadState& ls, Vec F);
  /// J = dF/dU. J = nullptr: only the kept element blocks (keepTangentBlocks) are updated.
  PetscErrorCode jacobian(Vec U, const LoadState& ls, Mat J);
  /// Material and geometric parts of the tangent (spin columns, used at converged states).
  PetscErrorCode splitTangent(Vec U, const LoadState& ls, Mat Km, Mat Kg);
  /// Consistent mass of elements and nodes over the unknowns (zero rows for multipliers).
  PetscErrorCode mass(Vec U, const LoadState& ls, Mat M);
  /// f_int - f_ext over every node DOF of owned nodes (reactions at constrained DOFs).
  PetscErrorCode fullResidual(Vec U, const LoadState& ls, Vec Ffull);
  /// Largest Von Mises stress per local element (order of mesh().elements).
  PetscErrorCode elementStress(Vec U, const LoadState& ls, std::vector<double>& stress);

  /// Node state (x, R or ANCF coordinates) of local node i, valid after any evaluation.
  const double* nodeState(int i) const { return &state_[12 * static_cast<size_t>(i)]; }
  /// Evaluates node states from U (ghosts updated inside) without assembling.
  PetscErrorCode updateStates(Vec U, const LoadState& ls);
  /// Moves rotation increments into the reference rotations: R_ref = exp(theta) R_ref, theta = 0.
  PetscErrorCode absorbRotations(Vec U);
  /// Newton's start that follows the rotation (-dynamics_predictor rotation): each Frame6 node
  /// moves as a rigid body with its spatial spin w and velocity v of V over h: theta = h w,
  /// x += h T(h w) v (T: left Jacobian of exp; exact for a rigid screw motion at constant w, v).
  /// U holds q_n (rotations absorbed) and is changed on those nodes' free DOFs (owned entries).
  PetscErrorCode rigidMotionPredictor(Vec V, double h, Vec U) const;
  /// W <- exp(theta) W on the spins of the free Frame6 nodes (theta from U; owned entries).
  PetscErrorCode rotateSpins(Vec U, Vec W) const;
  /// Midpoint rule (DynamicAnalysis): while set (h > 0), the rotary inertia of free nodes in
  /// dynamicResidual is the momentum change ((J_s w)_{n+1} - (J_s w)_n) / h, R_n = the reference
  /// rotations, R_{n+1} = exp(theta(u1)) R_n (elements/rotary_momentum.hpp), and dynamicJacobian's
  /// rotary block twice its exact derivative; u1, w0: owned arrays of U_{n+1} and V_n.
  /// cayley (energy-momentum scheme): w_{n+1} = 2 theta_c / h - exp(theta) w_n with the Cayley vector
  /// theta_c of theta (rotaryCayleyStep), and the rotary block its exact derivative (not doubled).
  struct RotaryMomentum {
    const double *u1 = nullptr, *w0 = nullptr;
    double h = 0;
    bool cayley = false;
  };
  void setRotaryMomentum(const RotaryMomentum& m) { momentum_ = m; }
  /// Energy-momentum scheme (DynamicAnalysis): keeps the node states of U_n under ls (rotations
  /// absorbed) as the start of the step whose end the next assemblies evaluate.
  PetscErrorCode setStepStart(Vec Un, const LoadState& ls);
  /// While set (h > 0), the element loops of dynamicResidual and dynamicJacobian take the kernels'
  /// step force (ElementKernel::stepForce) from the kept start states to the current ones, with the
  /// energy decay xi, instead of evaluate().
  struct StepForces {
    double h = 0, decay = 0;
  };
  void setStepForces(const StepForces& s) { stepForces_ = s; }
  /// W <- U with the rotation increment theta of every free Frame6 node (owned entries) replaced by its
  /// Cayley vector 2 tan(|theta| / 2) theta / |theta| (elements/rotary_momentum.hpp).
  PetscErrorCode cayleyIncrements(Vec U, Vec W) const;
  /// While on, dynamicJacobian leaves out the kernels that damp their strain rates (the damping's
  /// beta K0 of the other kinds).
  void setSkipStrainRateDamped(bool on) { skipStrainRateDamped_ = on; }
  /// Restores/saves the reference rotations (for retrying a failed load increment).
  std::vector<Mat3> referenceRotations() const { return Rref_; }
  void setReferenceRotations(const std::vector<Mat3>& r) { Rref_ = r; }

  // ---- Newton with mixed stresses (statics; Magisano, Leonetti & Garcea 2017)
  /// From now on jacobian() builds the stress part of the tangent of kernels with
  /// numMixedStresses() > 0 from the linearized stresses sigma = S (eps(q_ref) + grad eps(q_ref) . d)
  /// (d: the step from the reference state to the current one) instead of S eps(q): Newton on the
  /// Hellinger-Reissner form, whose residual is the ordinary one, so its solution is unchanged; the
  /// tangent no longer carries the spurious axial forces a large rotation step creates in a stiff
  /// beam. The reference is the state of the previous jacobian(), or the one set below.
  void setMixedStressNewton(bool on) { mixedNewton_ = on; }
  bool mixedStressNewton() const { return mixedNewton_; }
  /// Some rank has an element kernel with mixed stresses (beams). Collective.
  bool hasMixedStressKernels() const;
  /// The reference state for the next jacobian(): the node states of U under ls (a converged state).
  PetscErrorCode setMixedReference(Vec U, const LoadState& ls);

  // ---- building blocks for analyses that run their own element loops (dynamics, form finding)
  /// Ghost-updated local form of U (owned entries, then ghosts) with the node states evaluated;
  /// pair with endLocal(). Indices from gather() address this array.
  PetscErrorCode beginLocal(Vec U, const LoadState& ls, const double** u);
  PetscErrorCode endLocal(const double** u);
  /// Element state q (kernel layout) and local unknown indices (-1 = constrained; multipliers
  /// after the node DOFs) after beginLocal() or any evaluation.
  void gather(const LocalElement& el, double* q, int* idx) const { gatherElement(el, q, nullptr, idx, nullptr); }
  /// Multiplies the spin columns of a dense n x n element tangent by T(theta) (exact Jacobian columns).
  void applyRotationColumns(const LocalElement& el, int n, double* K) const { rotationColumns(el, n, K); }
  ISLocalToGlobalMapping localToGlobal() const { return l2g_; }
  /// Rigid-body motions in the unknowns' layout (orthonormal): the near-null space for -pc_type gamg.
  PetscErrorCode rigidBodyModes(MatNullSpace* nsp) const;
  AssemblyCounters& mutableCounters() { return counters_; }

  // ---- dynamics (assembler_dynamics.cpp); V, A in the unknowns layout, constrained DOFs at rest
  /// F = M A + f_int(U, V, t) - f_ext(t) (kernels see the velocities: damping, user functions).
  PetscErrorCode dynamicResidual(Vec U, Vec V, Vec A, const LoadState& ls, Vec F);
  /// J = K(U, V) + shiftV D(U, V) + shiftA M; D only from kernels with hasDamping(). With the
  /// complete inertia on, A (may be null: at rest) gives the frame terms d(M(q) A)/dq of its kernels.
  PetscErrorCode dynamicJacobian(Vec U, Vec V, Vec A, const LoadState& ls, double shiftV, double shiftA, Mat J);
  /// While on, the kernels with ElementKernel::inertiaForce (the complete consistent beam mass) give
  /// their inertia force and its tangent in dynamicResidual, dynamicJacobian and the dynamic
  /// reactions instead of M(q) qdd (the Arnold-Bruls scheme; docs/dynamics.md, "Inertia").
  void setCompleteInertia(bool on) { completeInertia_ = on; }
  /// Hands every element block and the node terms of each dynamicJacobian() to `sink` (nullptr: none;
  /// the corotated Newton matrix of ANCF cables, solvers/ancf/corotated_newton_matrix.hpp).
  void setNewtonBlockSink(NewtonBlockSink* sink) { sink_ = sink; }
  /// y = the element-by-element product that body adds into ya from xa (local ghosted forms of x and
  /// y; ghost contributions summed to their owners). Logged as SinewTangentOp.
  PetscErrorCode elementProduct(Vec x, Vec y, const std::function<void(const double* xa, double* ya)>& body);
  /// ya += K xa on node's two slope unknowns (K: 2 x 2, row-major).
  static void addSlopeBlock(const LocalNode& node, const double* K, const double* xa, double* ya);
  /// Owned node i's 2 x 2 slope-torque tangent at the current states (false: none).
  bool slopeTorqueBlock(int i, const LoadState& ls, double* K) const;
  /// The element's mass matrix at q: the kernel's constantMass() when it has one, else mass(q) into buf.
  const double* elementMass(const LocalElement& el, const double* q, std::vector<double>& buf) const;
  /// Dynamics output: while set (V, Qdd in the unknowns layout), fullResidual() adds the inertia
  /// M qdd (elements, nodal mass and mominertia; prescribed DOFs with their prescribed accelerations),
  /// so the reactions at supports and prescribed DOFs are the dynamic ones. nullptr: statics.
  void setReactionRates(Vec V, Vec Qdd) {
    reactionV_ = V;
    reactionA_ = Qdd;
  }
  /// Kinetic energy 1/2 V^T M V (global).
  PetscErrorCode kineticEnergy(Vec U, Vec V, const LoadState& ls, double* T);

  /// Body-force acceleration on element el: gravity plus its set's massProportionalLoad, scaled by
  /// the load factor when ls.gravityRamped. False when the element has neither (or no inertia).
  bool bodyAcceleration(const LocalElement& el, const LoadState& ls, Vec3* a) const;

  // ---- element-wise tangent operator (tangent_operator.cpp)
  /// From now on jacobian() also keeps every element block (and the slope-torque node blocks), so
  /// that applyTangent() can apply the same tangent element by element.
  void keepTangentBlocks(bool on) { keepBlocks_ = on; }
  /// With keepTangentBlocks: jacobian() also keeps, per element, the rigid-motion data that
  /// applyTangent(x, y, true) needs (the element's internal forces and its infinitesimal rotation about
  /// its first node). Used by the eigenvalue analyses (docs/modal.md, "Eigenvalues on fine meshes").
  void keepRigidData(bool on) { keepRigid_ = on; }
  /// keepTangentBlocks and keepRigidData on for the jacobian() calls of one scope (an eigenvalue
  /// analysis' tangent at the converged state), the previous settings back after it: the Newton
  /// iterations of the statics in between keep no blocks they would not use.
  class KeptBlocksScope {
   public:
    explicit KeptBlocksScope(Assembler& a) : a_(a), blocks_(a.keepBlocks_), rigid_(a.keepRigid_) {
      a.keepBlocks_ = a.keepRigid_ = true;
    }
    ~KeptBlocksScope() {
      a_.keepBlocks_ = blocks_;
      a_.keepRigid_ = rigid_;
    }
    KeptBlocksScope(const KeptBlocksScope&) = delete;
    KeptBlocksScope& operator=(const KeptBlocksScope&) = delete;

   private:
    Assembler& a_;
    bool blocks_, rigid_;
  };
  /// y = J x from the kept blocks of the last jacobian(), each block applied to its element's part
  /// of x minus the translation of the element's first node (a rigid translation is in the null space
  /// of every element tangent). The assembled matrix applies the same J, but its products carry
  /// round-off eps * |J| * |x|; here it is eps * |J_e| * |x_e - t_e|, which matters when element
  /// stiffnesses are huge and x is a large, locally almost rigid motion (fine ANCF cables: bending
  /// stiffness EI/h^3 against a soft global mode). Logged as SinewTangentOp.
  PetscErrorCode applyTangent(Vec x, Vec y) { return applyTangent(x, y, false); }
  /// rigidFree (needs keepRigidData before the jacobian()): each element block is applied to its part
  /// of x minus the rigid motion (translation and infinitesimal rotation) of the element's first node,
  /// d = d' + R c, as K_e d' + F c with F = K_e R the spin of the element's internal forces (exact by
  /// objectivity: f(Q q) = Q f(q)); the output is then balanced so that its resultant force and moment
  /// about the first node are the exact ones (zero force, moment -sum d_g x f_g). Round-off is then
  /// eps |K_e| |d'| with d' the element's deformation: the products stay accurate for smooth modes of
  /// fine meshes, where the translation-free product loses eps n^2 of a soft mode's energy
  /// (elements whose block fails the check K_e R = F fall back to the translation-free product).
  PetscErrorCode applyTangent(Vec x, Vec y, bool rigidFree);
  /// Elements whose kept block passed the rigid-motion check (all ranks).
  long rigidFreeElements() const;  /// applyTangent() reproduces jacobian(): no rank has pressure loads or cables (their load and
  /// regularization tangents are not element blocks). Collective.
  bool elementwiseTangentAvailable() const;
  /// The kept block of the element whose block starts at `offset` (sum of n^2 over the elements
  /// before it, in mesh().elements order).
  const double* tangentBlock(size_t offset) const { return blocks_.data() + offset; }

  const AssemblyCounters& counters() const { return counters_; }
  bool hasInertia() const { return hasInertia_; }
  bool hasGravity() const { return gravity_.has_value(); }
  /// Characteristic force of the current external loads (for relative convergence tests).
  double externalForceNorm() const { return fextNorm_; }
  /// Largest |reference coordinate| of the model: positions carry round-off eps times this.
  double coordinateScale() const { return coordMax_; }
  double internalForceNorm() const { return fintNorm_; }
  /// Some local or remote membrane carries a pressure (then residual and Jacobian have load terms).
  bool hasPressure() const { return anyPressure_; }
  /// true (default): a non-finite force law ends the run at the end of the assembly (exit 3).
  /// false: it is agreed on and kept in nonFiniteLaw() (the message, "" when none), the element's
  /// contribution zero; for a probe of the reference state whose time t = 0 the analysis never uses.
  void setNonFiniteLawsFatal(bool fatal) {
    nonFiniteLawsFatal_ = fatal;
    nonFiniteLaw_.clear();
  }
  const std::string& nonFiniteLaw() const { return nonFiniteLaw_; }
  /// Newton regularization of slack cables in elastic analyses: k = slackStiffness * EA / L (or
  /// * N0 / L when EA = 0) added to the Jacobian only (the residual, hence the solution, is exact).
  void setSlackStiffness(double s) { slackStiffness_ = s; }
  double slackStiffness() const { return slackStiffness_; }
  /// Number of slack cables (elastic, zero force) at the last Jacobian, summed over ranks.
  long slackCables() const { return slackCables_; }

 private:
  enum class Target { Residual, Full };
  PetscErrorCode loadLocal(Vec U, Vec local);
  void computeStates(const double* u, const LoadState& ls);
  void gatherElement(const LocalElement& el, double* q, const double* u, int* idx, int* fullIdx) const;
  void rotationColumns(const LocalElement& el, int n, double* K) const;
  /// Element state (kernel layout) from a node-state array laid out like state_.
  void gatherStates(const LocalElement& el, const double* states, double* q) const;
  PetscErrorCode assembleForces(const double* u, const LoadState& ls, Target target, double* out);
  /// The frame of residual(), fullResidual() and dynamicResidual(): U into uWork_, node states
  /// computed, `add(u, f)` fills the zeroed local form of `work` (rows of `target`), the ghost
  /// contributions summed to their owners, copied to `out`; then the element value agreement.
  PetscErrorCode forceVector(Vec U, const LoadState& ls, Vec work, Vec out,
                             const std::function<PetscErrorCode(const double* u, double* f)>& add);
  /// el.kernel->evaluate into out_; a force law that is not finite (ElementValueError) is recorded
  /// (the first element of this rank) and out_ holds zeros of the right sizes.
  void evaluateElement(const LocalElement& el, const KernelInput& in, const KernelNeeds& needs);
  /// Collective, at the end of every assembly: a non-finite force law on any rank ends the run on
  /// every rank (exit 3, the message of the lowest such element: the same on any number of ranks).
  PetscErrorCode agreeElementValues();
  // assembler_pressure.cpp: surface pressure (follower) and slack-cable regularization
  void initLoads();
  double addPressureForces(const LoadState& ls, Target target, double* out);
  PetscErrorCode addLoadTangents(const LoadState& ls, Mat J);
  PetscErrorCode addSlopeTorqueTangent(const LoadState& ls, Mat J);
  /// Element velocities (kernel DOF layout) from vLocal_, or nullptr in statics.
  const double* gatherVelocity(const LocalElement& el, const int* idx, double* qdot) const;
  /// R J0 R^T of node i's mominertia at its current rotation (state_); hasRotaryInertia: a free
  /// Frame6 node with nonzero mominertia.
  Mat3 spatialInertia(int i) const;
  bool hasRotaryInertia(int i) const;
  /// Velocities and accelerations of element el's prescribed DOFs (kernel DOF layout) from the time
  /// functions evaluated by computeStates (0 elsewhere); false (nothing written) when no node of el moves
  /// by a function of time.
  bool prescribedRates(const LocalElement& el, double* v, double* a) const;
  /// Adds the nodal inertia (point masses, rotary inertia) to `out` (local form) by the rows of
  /// `target`; a = local form of the accelerations of the unknowns, v = of the velocities (gyroscopic
  /// moments). The elements' M_e qdd_e come from the force loop (assembleForces with aLocal_ set:
  /// addElementInertia).
  void addNodeInertia(const double* v, const double* a, Target target, double* out);
  /// out += M_e qdd_e of one element (idx, fidx from gatherElement; prescribed DOFs with their
  /// prescribed accelerations).
  void addElementInertia(const LocalElement& el, const double* q, const int* idx, const int* fidx, const double* a,
                         Target target, double* out, std::vector<double>& MeBuf) const;

  /// -beam_mass lumped: the kernels' lumpedInertia into the nodes' mass and mominertia (once per mesh)
  PetscErrorCode addLumpedInertia();
  DistributedMesh& mesh_;
  std::optional<Vec3> gravity_;
  bool hasInertia_ = false;
  Vec uWork_ = nullptr, fWork_ = nullptr, fullWork_ = nullptr;
  ISLocalToGlobalMapping l2g_ = nullptr;
  PetscErrorCode preallocationCounts() const;
  mutable bool countsReady_ = false;
  mutable Mat structure_ = nullptr;  // every element block and the diagonal, zeros (createMatrix copies it)
  PetscErrorCode buildStructure(Mat* A) const;
  mutable std::vector<PetscInt> dnnz_, onnz_;  // nonzeros per owned row (diagonal / off-diagonal block)
  std::vector<double> state_;  // 12 per local node
  bool mixedNewton_ = false;
  bool mixedRefValid_ = false;
  std::vector<double> mixedRef_;  // node states (12 per local node) of the mixed-stress reference
  /// Mixed-stress Newton (jacobian(), dynamicJacobian()): when the element has mixed stresses, its
  /// stresses linearized from the reference (the current state without one) into sigma, set in `in`.
  void linearizeMixedStresses(const LocalElement& el, const double* q, std::array<double, 6>& sigma, KernelInput& in) const;
  /// The current node states become the reference of the next linearization.
  void keepMixedReference() {
    mixedRef_ = state_;
    mixedRefValid_ = true;
  }
  std::vector<double> disp_;   // 3 per local node: translations x - X0 exactly as in the unknowns
  mutable std::array<double, 12> elemDisp_{};  // disp_ of the element being evaluated (kernel order)
  std::vector<Mat3> Rref_, T_;
  std::vector<char> hasTheta_;
  KernelOutput out_;
  std::string elementValueError_;  // first non-finite force law of the current assembly on this rank
  long elementValueErrorAt_ = -1;  // its global FE element index
  bool elementValueErrorKnown_ = false, anyElementValueError_ = false;  // set by assembleForces' reduction
  bool nonFiniteLawsFatal_ = true;
  std::string nonFiniteLaw_;
  RotaryMomentum momentum_;
  StepForces stepForces_;
  std::vector<double> startState_, startDisp_;  // setStepStart: node states and translations of U_n
  bool skipStrainRateDamped_ = false;
  /// rotaryMomentumStep of free Frame6 node i under momentum_ (its mominertia, R_n = Rref_, theta from u1).
  RotaryMomentumStep midpointMomentum(int i) const;
  const double* vLocal_ = nullptr;  // local form of the velocities while a dynamic evaluation runs
  const double* inertiaV_ = nullptr;  // velocities of the complete inertia force (residual and reactions)
  bool completeInertia_ = false;
  mutable InertiaOutput inertiaOut_;
  /// The element's velocities and accelerations (kernel layout; prescribed DOFs from their time
  /// functions, other constrained ones 0) from the local forms v (may be null) and a (may be null).
  void elementRates(const LocalElement& el, const int* idx, const double* v, const double* a, double* ve, double* ae) const;
  const double* aLocal_ = nullptr;  // and of the accelerations while dynamicResidual or a dynamic fullResidual runs (element inertia in the force loop)
  // prescribed motions as functions of time (computeStates with ls.timeFunctions): per local node
  // 6 velocities, then 6 accelerations (dof layout; spatial angular rates for rot)
  std::vector<double> presRate_;
  bool presRatesActive_ = false;
  Vec reactionV_ = nullptr, reactionA_ = nullptr;  // setReactionRates
  AssemblyCounters counters_;
  double fextNorm_ = 0, fintNorm_ = 0;
  double coordMax_ = 0;
  // COO assembly of element tangents (MatSetPreallocationCOO / MatSetValuesCOO): the index pattern
  // is set once per matrix, each Jacobian then only fills cooValues_ in element order.
  bool cooAssembly_ = true;
  std::vector<PetscScalar> cooValues_;
  PetscErrorCode prepareCOO(Mat J, bool* sums);  ///< *sums: J is filled by setValuesFromCooSums
  // splitTangent on one rank: where each element block entry goes in the AIJ value array, and the pattern
  // (row starts, columns) these positions belong to
  std::vector<PetscInt> splitPositions_, splitRowStart_, splitCols_;
  PetscErrorCode elementBlockPositions(Mat A, bool* ok);
  bool cooApplies() const;
  // One process: the sums MatSetValuesCOO would form, kept once per assembler (cooSums_), so that a
  // matrix with the same nonzero pattern (every copy of structure_) needs no MatSetPreallocationCOO:
  // nonzero p of the CSR (cooRow_, cooCol_) is 0 + the values cooPerm_[cooJmap_[p] .. cooJmap_[p+1]) in turn.
  struct CooSums {
    bool built = false, usable = false;
    PetscCount entries = 0;  // COO entries (cooValues_), negative indices included
    std::vector<PetscInt> row, col;
    std::vector<PetscCount> jmap, perm;
  };
  CooSums cooSums_;
  void cooIndices(std::vector<PetscInt>* ci, std::vector<PetscInt>* cj) const;
  PetscErrorCode buildCooSums(const std::vector<PetscInt>& ci, const std::vector<PetscInt>& cj);
  PetscErrorCode matchesCooSums(Mat J, bool* match) const;
  PetscErrorCode setValuesFromCooSums(Mat J) const;
  // kept tangent blocks (keepTangentBlocks): element blocks in element order, then 2x2 slope-torque
  // blocks of owned ANCF nodes (node index, K row-major)
  bool keepBlocks_ = false;
  std::vector<double> blocks_;
  std::vector<std::pair<int, std::array<double, 4>>> torqueBlocks_;
  // rigid-motion data of the kept blocks (keepRigidData): per element nr = 0 (translation-free only),
  // 1 (ANCF 2D) or 3 (Frame6) rotations, offset into rigidData_ = [f (n), R (n x nr), F (n x nr), E (nr x n)]
  bool keepRigid_ = false;
  std::vector<std::pair<int, size_t>> rigidInfo_;
  std::vector<double> rigidData_;
  void keepRigid(const LocalElement& el, const double* q, const double* f, const double* K, int n);
  Vec xOp_ = nullptr, yOp_ = nullptr;  // ghosted work vectors of elementProduct
  NewtonBlockSink* sink_ = nullptr;  ///< setNewtonBlockSink
  std::vector<std::pair<int, SetPressure>> pressureElems_;  // local element index, pressure
  bool anyPressure_ = false;
  std::vector<int> cableElems_;  // local elements with a tension-only kernel (cables)
  double slackStiffness_ = 1e-8;
  long slackCables_ = 0;
};

/// PetscLogEvents of Sinew's phases (registered once).
struct SinewEvents {
  PetscLogEvent setup, residual, jacobian, mass, splitTangent, stress, eigen, compliance, output, dynamics, formfinding, constraintCheck;
  PetscLogEvent jacobianElements;  ///< the element loop of SinewJacobian (kernels + MatSetValuesLocal)
  PetscLogEvent tangentOperator;   ///< Assembler::applyTangent (element-wise products with the tangent)
  PetscLogEvent cooSetup;          ///< one-time COO pattern of a matrix (inside SinewJacobian)
  PetscLogEvent coarseSpace;       ///< set-up of the cable coarse space (fine LU + coarse matrix)
  PetscLogEvent corotatedJacobian; ///< CorotatedNewtonMatrix::assemble (kept blocks rotated, assembled)
  static const SinewEvents& get();
};

}  // namespace sinew
