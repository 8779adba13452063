// The local element kernel contract: state in, internal force and tangent out.
// A kernel knows nothing about MPI or PETSc; the assembler maps it into the global system.
#pragma once
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "sinew/linalg3.hpp"

namespace sinew {

/// What a node carries. State layout / DOF layout per node:
///   Point3 : state x y z                       | dofs: 3 translations
///   Frame6 : state x y z, R (3x3 row-major)    | dofs: 3 translations, 3 spatial spins (dR = skew(dw) R)
///   Ancf2D : state x y slope_x slope_y         | dofs: the 4 coordinates
/// A Point3 kernel node may sit on a Frame6 node: it sees the position prefix of the state and dofs.
enum class NodeKind : int { Point3 = 0, Frame6 = 1, Ancf2D = 2 };
constexpr int stateSize(NodeKind k) { return k == NodeKind::Point3 ? 3 : (k == NodeKind::Frame6 ? 12 : 4); }
constexpr int dofSize(NodeKind k) { return k == NodeKind::Point3 ? 3 : (k == NodeKind::Frame6 ? 6 : 4); }

struct KernelInput {
  const double* q = nullptr;       ///< node states, concatenated in kernel node order (state layout)
  const double* qdot = nullptr;    ///< time derivatives in DOF layout (spins for Frame6); nullptr in statics
  const double* lambda = nullptr;  ///< multipliers of the kernel's constraints; nullptr when it has none
  double t = 0.0;                  ///< time (dynamics) or load factor (statics)
  /// Optional: translations x - X0 of the kernel's Point3/Frame6 nodes (3 each), taken from the
  /// unknowns without the round-off of x = X0 + u; stiff kernels use it for accurate elongations.
  const double* disp = nullptr;
  /// Optional (Newton with mixed stresses, numMixedStresses() > 0): independent generalized stresses
  /// used in the stress (geometric) part of the tangent instead of the stresses of q. The internal
  /// force f always uses the stresses of q.
  const double* sigmaMixed = nullptr;
};

struct KernelNeeds {
  bool tangent = false;         ///< fill K (d f / d(dofs, lambda))
  bool damping = false;         ///< fill D (d f / d qdot)
  bool splitGeometric = false;  ///< with tangent: K = material part only, Kg = stress-dependent part
};

/// n = numDofs() + numConstraints(). Dense row-major blocks.
struct KernelOutput {
  std::vector<double> f;   ///< [n]: internal force incl. G^T lambda (first numDofs), constraint values (rest)
  std::vector<double> K;   ///< [n*n]: tangent (material part only when splitGeometric)
  std::vector<double> Kg;  ///< [n*n]: geometric (stress-dependent) part, only when splitGeometric
  std::vector<double> D;   ///< [numDofs^2]: damping, only when damping requested and hasDamping()
};

/// One step q0 -> q1 of the energy-momentum scheme (-dynamics_scheme energy_momentum; docs/dynamics.md,
/// "Energy-momentum scheme"): the states at the step's start and end (state layout), their node
/// translations x - X0 (3 per Point3/Frame6 node, for accurate elongations), the multipliers of q1.
struct StepForceInput {
  const double* q0 = nullptr;
  const double* q1 = nullptr;
  const double* disp0 = nullptr;
  const double* disp1 = nullptr;
  const double* lambda = nullptr;
  double h = 0.0;      ///< the step size (strain-rate damping: stresses beta S (eps1 - eps0) / h)
  double decay = 0.0;  ///< energy decay xi >= 0: stresses S (eps0 + eps1) / 2 + xi / 2 S (eps1 - eps0)
};

/// The complete inertia force of a kernel's mass (ElementKernel::inertiaForce), [numDofs] and
/// [numDofs^2] row-major: f, its derivative Kq by the state (translations, spatial spins) at fixed
/// rates, and Dv by the velocities (the derivative by the accelerations is the mass matrix).
struct InertiaOutput {
  std::vector<double> f, Kq, Dv;
};

/// Thrown by ElementKernel::evaluate when a force law gives a value that is not finite (a user
/// function dividing by zero, sqrt(-1), log(0), exp(1000)). law(): the law ("bendingMomentUserFunction
/// \"1/0*curvature\""); returned(): "inf", "-inf", "nan" or "a non-finite derivative ..."; where(): its
/// arguments ("t = 0, axialStrain = 0, curvature = 0"). The assembler adds the property set and element.
class ElementValueError : public std::runtime_error {
 public:
  ElementValueError(std::string law, std::string returned, std::string where)
      : std::runtime_error(law + " returned " + returned + ", " + where),
        law_(std::move(law)), returned_(std::move(returned)), where_(std::move(where)) {}
  const std::string& law() const { return law_; }
  const std::string& returned() const { return returned_; }
  const std::string& where() const { return where_; }

 private:
  std::string law_, returned_, where_;
};

/// The part of a kernel that form finding (Updated Reference Strategy, src/analysis/formfinding_analysis.*)
/// drives; ElementKernel::formFinding() returns it for the kinds that can be form-found (cables, membranes).
class FormFindingKernel {
 public:
  /// How an element enters the shape measures of form finding: a line (direction tensor e e^T) or a
  /// surface (area-weighted normal tensor A n n^T).
  enum class Shape { Line, Surface };
  virtual Shape shapeType() const = 0;
  /// Form finding with homotopy factor lambda (xurs: extended URS, where the kind has it).
  virtual void enterFormFinding(double lambda, bool xurs) = 0;
  /// Back to the elastic problem (form finding and xURS off).
  virtual void leaveFormFinding() = 0;
  /// Stress adaption: lambdaMax > 1 on (<= 1 off), relaxation mueRelax; distortionMax > 1 switches shape
  /// distortion control on where the kind has it.
  virtual void setAdaption(double lambdaMax, double mueRelax, double distortionMax) = 0;
  /// Size at state q: length (line) or area (surface).
  virtual double size(const double* q) const = 0;
  /// Collapsed at state q, given its size at the start of form finding and the model size.
  virtual bool collapsed(const double* q, double initialSize, double modelSize) const = 0;
  /// Shape quality at state q: 1 ideal, 0 degenerate (lines: 1).
  virtual double meshQuality(const double* /*q*/) const { return 1.0; }
  /// URS step: stress adaption (when on) for the step deformation, then reference := q. Throws
  /// std::invalid_argument for a reference it cannot take (degenerate surface).
  virtual void updateReference(const double* q) = 0;
  /// Axis a of the element at q whose a a^T it adds to the shape measure: the unit direction (line),
  /// the area vector divided by the square root of the area (surface: a a^T = A n n^T); 0 when degenerate.
  virtual Vec3 shapeAxis(const double* q) const = 0;
  /// Elastic restart without prestress (DISPLACEMENT, NONE): prestress := 0.
  virtual void clearPrestress() = 0;
  /// Elastic restart from the initial shape (NONE): reference := X (3 coordinates per node).
  virtual void setReference(const double* X) = 0;

  virtual ~FormFindingKernel() = default;
};

/// What an element sensor reads (SensorAnalysis) besides the variable and position.
struct SensorInput {
  const double* q = nullptr;       ///< node states (state layout)
  const double* disp = nullptr;    ///< translations x - X0 of the Point3/Frame6 nodes (3 each)
  const double* qdot = nullptr;    ///< DOF rates; nullptr at rest
  const double* qddot = nullptr;   ///< DOF accelerations; nullptr at rest
  const double* lambda = nullptr;  ///< the kernel's multipliers; nullptr when it has none
  double t = 0.0;                  ///< time
};

class ElementKernel {
 public:
  virtual ~ElementKernel() = default;
  virtual const char* name() const = 0;
  virtual std::span<const NodeKind> nodeKinds() const = 0;
  virtual int numConstraints() const { return 0; }
  virtual bool hasInertia() const { return false; }
  virtual bool hasDamping() const { return false; }

  /// Internal force (and tangents as requested) at the state in `in`. Output vectors are resized here.
  virtual void evaluate(const KernelInput& in, const KernelNeeds& needs, KernelOutput& out) const = 0;
  /// Consistent mass matrix [numDofs^2] at state q (row-major). Only called when hasInertia().
  virtual void mass(const double* q, std::vector<double>& M) const;
  /// The mass matrix when it does not depend on the state ([numDofs^2], row-major, owned by the
  /// kernel, equal to what mass() writes), read by the assemblies without a copy; nullptr: call mass().
  virtual const double* constantMass() const { return nullptr; }
  /// Whether mass() changes with the state (the beams' consistent mass in the element frame); kinds whose
  /// mass is that of the reference configuration return false (the energy-momentum scheme takes them).
  virtual bool massDependsOnState() const { return constantMass() == nullptr; }
  /// The complete inertia force of a state-dependent mass M(q): the Euler-Lagrange force of the kinetic
  /// energy T = 1/2 v^T M(q) v (v: velocities and spatial spins, a: their rates),
  ///   f = M a + dM/dt v - dT/dq - (w x dT/dw on the spin rows)   (Euler-Poincare form on SO(3)),
  /// in place of M(q) a (docs/dynamics.md, "Inertia"). hasInertiaForce(): the kernel has it.
  virtual bool hasInertiaForce() const { return false; }
  virtual void inertiaForce(const double* /*q*/, const double* /*v*/, const double* /*a*/, bool /*tangent*/,
                            InertiaOutput& /*out*/) const {}
  /// Equivalent nodal load [numDofs] of the body force density rho * a (gravity). Only when hasInertia().
  virtual void bodyForce(const double* q, const Vec3& a, std::vector<double>& f) const;
  /// Lumped inertia of the nodes instead of a mass matrix (then hasInertia() is false): per node 7
  /// values, the mass on its translations and its rotary inertia (J00 J01 J02 J11 J12 J22, reference
  /// axes, as nodal mominertia); false when the kernel has none.
  virtual bool lumpedInertia(double* /*mJ*/) const { return false; }
  /// Largest Von Mises stress in the element at state q (0 when the element has no stress measure).
  virtual double vonMisesMax(const double* /*q*/, const double* /*lambda*/) const { return 0.0; }
  /// Mixed-stress Newton (Magisano, Leonetti & Garcea 2017, "MIP"): number of generalized stresses
  /// the kernel can take as independent variables in its tangent (0: none).
  virtual int numMixedStresses() const { return 0; }
  /// The linearized stresses sigma = S (eps(q0) + grad eps(q0) . d), d the step from state q0 to
  /// state q1 (translations x1 - x0, spatial rotation vectors log(R1 R0^T)); with q0 == nullptr the
  /// stresses S eps(q1). Writes numMixedStresses() values. Only called when numMixedStresses() > 0.
  virtual void linearizedStresses(const double* /*q0*/, const double* /*q1*/, double* /*sigma*/) const {}
  /// Strain energy at state q (its gradient is the internal force without the multipliers' part);
  /// false when the kernel does not provide it (energy output then reports the element kinds).
  virtual bool strainEnergy(const double* /*q*/, double* /*energy*/) const { return false; }
  /// Stiffness-proportional damping on the strain rates (Kelvin-Voigt; docs/dynamics.md "Damping"): the
  /// kernel adds beta S epsd, epsd = grad eps . qdot, to its force whenever KernelInput::qdot is given
  /// (with hasDamping() and D), so rigid motion is never damped. Returns false for kinds that do not
  /// (their damping stays beta K0 of the start state, src/dynamics/damping.*); beta = 0 switches it off.
  virtual bool setStrainRateDamping(double /*beta*/) { return false; }
  /// True while the kernel damps its strain rates (beta > 0).
  virtual bool strainRateDamped() const { return false; }
  /// Energy-momentum step force (StepForceInput): true for the kinds that have it. stepForce() writes
  /// the internal force of the step, whose work on the step's increments (translations x1 - x0, the
  /// Cayley rotation vectors of R1 R0^T) is the change of the strain energy, with zero resultant force
  /// and moment about the mid positions (x0 + x1) / 2, and the constraint values at q1; with tangent,
  /// K = its derivative by q1 (translations, spatial spins of R1) and the multipliers.
  virtual bool hasStepForce() const { return false; }
  virtual void stepForce(const StepForceInput& /*in*/, bool /*tangent*/, KernelOutput& /*out*/) const {}
  /// Without a step force: the scene field that keeps the kernel from having one (a force law that is not
  /// a potential, e.g. "axialForceUserFunction"), nullptr when there is none to name.
  virtual const char* stepForceRefusal() const { return nullptr; }
  /// Element force output (cable axial force, membrane resultants n11 n22 n12); empty when none.
  virtual void elementForce(const double* /*q*/, std::vector<double>& out) const { out.clear(); }

  /// Form finding interface (cables, membranes); nullptr when the kind takes no part in form finding.
  virtual FormFindingKernel* formFinding() { return nullptr; }
  /// Element sensors (scene block `sensors` with `element`): true for the kinds that have them (beams,
  /// ANCF cables; virtual methods of the kernel, not a second base: no extra pointer per element).
  virtual bool hasSensors() const { return false; }
  /// A scene element split into numSub equal FE elements: where along it a sensor at axial position x
  /// (length units) or xi (fraction of the scene element) falls, in FE element lengths (0..numSub);
  /// the FE element floor(position) holds it.
  virtual double sensorPosition(double /*x*/, double /*xi*/, int /*numSub*/) const { return 0.0; }
  /// Values per output row of `variable` (3 for vectors, 1 for scalars).
  virtual int sensorValueCount(const std::string& /*variable*/) const { return 0; }
  /// `variable` at s in [0, 1] along this FE element (node 0 to node 1).
  virtual std::vector<double> sensorValue(const std::string& /*variable*/, double /*s*/, const SensorInput& /*in*/) const {
    return {};
  }
  /// Tension-only kernels (cables) can go slack: zero force and tangent (the assembler then keeps the
  /// Newton matrix regular, Assembler::addLoadTangents).
  virtual bool tensionOnly() const { return false; }
  /// A tension-only kernel slack at state q (never in form finding): true, with *axialStiffness the
  /// stiffness of its regularising spring times its reference length (EA, or the prestress force when EA = 0).
  virtual bool slack(const double* /*q*/, double* /*axialStiffness*/) const { return false; }
  /// Reference length of a two-node line element (cables, ANCF cables, beams); 0 for other kinds.
  virtual double referenceLength() const { return 0.0; }

  /// Internal state that analyses change (form finding: reference geometry, adapted prestress), for
  /// checkpoints (output/checkpoint.hpp): size, save into / restore from checkpointSize() values.
  virtual int checkpointSize() const { return 0; }
  virtual void saveCheckpoint(double* /*out*/) const {}
  virtual void loadCheckpoint(const double* /*in*/) {}

  int numDofs() const {
    int n = 0;
    for (NodeKind k : nodeKinds()) n += dofSize(k);
    return n;
  }
  int numStates() const {
    int n = 0;
    for (NodeKind k : nodeKinds()) n += stateSize(k);
    return n;
  }
};

}  // namespace sinew
