// Exudyn's ObjectANCFCable2D as a pure local kernel: a planar Bernoulli-Euler cable with cubic
// Hermite (ANCF) interpolation, axial strain eps = |r'| - 1 and the material measure of curvature
// K = (r' x r'')_z / |r'|^2 (Gerstmayr & Irschik 2008; Exudyn theDoc, ObjectANCFCable2D).
//
// Coordinates per node: x, y, slope_x, slope_y (absolute, reference + displacement).
// Element vector q = [r0, r0', r1, r1'] (8), r(x) = S(x) q with
//   S1 = 1 - 3 xi^2 + 2 xi^3, S2 = x - 2 x^2/L + x^3/L^2, S3 = 3 xi^2 - 2 xi^3, S4 = -x^2/L + x^3/L^2.
// Virtual work: dW = int_0^L (N d eps + M d K) dx with
//   N = EA (eps - eps_ref) + (d_eps + beta EA) eps_t,   M = EI (K - K_ref) + (d_K + beta EI) K_t,
//   eps_ref = physicsReferenceAxialStrain + f_ref (|r'_ref| - 1),
//   K_ref   = physicsReferenceCurvature   + f_ref K(reference configuration),
// f_ref = strainIsRelativeToReference; user functions replace N and M and receive Exudyn's arguments.
// beta: the scene's stiffness-proportional damping on the strain rates (-stiffness_damping corotated,
// setStrainRateDamping; docs/dynamics.md "Damping"), 0 with user functions (they keep beta K0).
// Integration (useReducedOrderIntegration): 0 -> axial Gauss 5 points, bending Gauss 3 points;
// 1 -> Gauss 4 / Gauss 2; 2 -> Lobatto 3 (0, L/2, L) / Gauss 2.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "elements/strain_rate_damped.hpp"
#include "math/expression.hpp"
#include "sinew/element_kernel.hpp"
#include "sinew/element_properties.hpp"

namespace sinew {

struct AncfCable2DParameters {
  double physicsMassPerLength = 0.0;         ///< rhoA [kg/m]
  double physicsBendingStiffness = 0.0;      ///< EI [N m^2]
  double physicsAxialStiffness = 0.0;        ///< EA [N]
  double physicsBendingDamping = 0.0;        ///< d_K [N m^2 s]
  double physicsAxialDamping = 0.0;          ///< d_eps [N s]
  double physicsReferenceAxialStrain = 0.0;  ///< eps_0
  double physicsReferenceCurvature = 0.0;    ///< K_0 [1/m]
  double strainIsRelativeToReference = 0.0;  ///< f_ref in [0, 1]
  int useReducedOrderIntegration = 0;        ///< 0, 1 or 2
  /// Optional compiled force laws; when set they replace N (resp. M), damping included.
  std::shared_ptr<const Expression> axialForceUserFunction;
  std::shared_ptr<const Expression> bendingMomentUserFunction;
};

/// Parameters of a scene property set (compiles its user-function expressions; throws
/// std::invalid_argument with the expression, column and caret on a syntax error).
AncfCable2DParameters ancfCable2DParameters(const AncfCable2DProperties& set);

class AncfCable2D : public StrainRateDampedKernel {
 public:
  /// qRef: both nodes' reference coordinates [x0, y0, sx0, sy0, x1, y1, sx1, sy1]; L: reference length.
  AncfCable2D(const std::array<double, 8>& qRef, double L, const AncfCable2DParameters& p);
  /// The same with the parameters shared by the elements of a set (one copy per eprops set: a fine
  /// cable's elements then fit in fewer cache lines; the kernel factory uses this).
  AncfCable2D(const std::array<double, 8>& qRef, double L, std::shared_ptr<const AncfCable2DParameters> p);

  const char* name() const override { return "ancf_cable2d"; }
  std::span<const NodeKind> nodeKinds() const override;
  bool hasInertia() const override { return params_->physicsMassPerLength > 0.0; }
  bool hasDamping() const override { return hasDamping_ || beta_ > 0.0; }
  /// beta on the strain rates (N += beta EA eps_t, M += beta EI K_t); refused (false, beta K0 instead)
  /// with a user force law, which has no stiffness EA, EI of its own.
  bool setStrainRateDamping(double beta) override;
  /// The energy-momentum step force (ancf_cable2d_step_force.cpp); not with user force laws (not potentials).
  bool hasStepForce() const override { return !userForceLaw(); }
  void stepForce(const StepForceInput& in, bool tangent, KernelOutput& out) const override;
  /// The scene field of a user force law of this kernel ("axialForceUserFunction" or
  /// "bendingMomentUserFunction"), nullptr without one.
  const char* userForceLaw() const;
  const char* stepForceRefusal() const override { return userForceLaw(); }

  /// f = Q_e(q, qdot, t) (elastic + viscous generalized forces, Exudyn's ODE2 LHS);
  /// K = df/dq; D = df/dqdot. With splitGeometric, K holds the terms with derivatives of the
  /// force laws (N_eps deps x deps + ...) and Kg the stress terms N d2eps/dq2 + M d2K/dq2.
  void evaluate(const KernelInput& in, const KernelNeeds& needs, KernelOutput& out) const override;
  /// Constant consistent mass rhoA int S^T S dx (8x8).
  void mass(const double* q, std::vector<double>& M) const override;
  const double* constantMass() const override { return geo_->M.data(); }
  /// Consistent load of a mass-proportional body force: rhoA int S^T a dx (Exudyn LoadMassProportional).
  void bodyForce(const double* q, const Vec3& a, std::vector<double>& f) const override;
  /// Axial force N (static part, no damping, user function at t = 0) at x = 0, L/2, L.
  void elementForce(const double* q, std::vector<double>& out) const override;

  /// Exudyn output variable at axial position x in [0, L] on the axis (local y = 0):
  ///   Position, Displacement, Velocity, VelocityLocal, Acceleration, Director1 -> 3 values (z = 0);
  ///   AngularVelocity, AngularAcceleration -> 3 values [0, 0, w];
  ///   Rotation, StrainLocal, CurvatureLocal, ForceLocal, TorqueLocal -> 1 value.
  /// qdot / qddot may be nullptr (zero). ForceLocal / TorqueLocal include damping and user functions.
  /// Throws std::invalid_argument for an unknown name (message lists the valid ones).
  std::vector<double> output(const std::string& variable, double x, const double* q, const double* qdot,
                             const double* qddot, double t) const;
  static const std::vector<std::string>& outputVariables();

  // --- element sensors: output() at x = s L
  bool hasSensors() const override { return true; }
  /// x / (L numSub) numSub: the sensors' axial position x counts along the split scene element.
  double sensorPosition(double x, double /*xi*/, int numSub) const override { return x / (L_ * numSub) * numSub; }
  /// 3 for the vector variables (Position, ..., AngularAcceleration), 1 for the scalars.
  int sensorValueCount(const std::string& variable) const override;
  std::vector<double> sensorValue(const std::string& variable, double s, const SensorInput& in) const override {
    return output(variable, s * L_, in.q, in.qdot, in.qddot, in.t);
  }

  // Strain measures at x, exposed for tests and sensors.
  double axialStrain(const double* q, double x) const;
  double curvature(const double* q, double x) const;
  /// eps_ref(x) and K_ref(x) as used by the force laws (reference values blended by f_ref).
  double axialStrainRef(double x) const;
  double curvatureRef(double x) const;

  double length() const { return L_; }
  double referenceLength() const override { return L_; }
  /// int EA/2 (eps - eps_ref)^2 + EI/2 (K - K_ref)^2 dx with the rules of evaluate (its gradient is
  /// the internal force); false with user force laws (no energy given).
  bool strainEnergy(const double* q, double* energy) const override;
  const AncfCable2DParameters& parameters() const { return *params_; }
  const std::array<double, 8>& referenceCoordinates() const { return qRef_; }

  /// Force-law evaluations of all AncfCable2D kernels of this process so far: user-function calls,
  /// and integration-point evaluations with a damping term (d_eps eps_t or d_K K_t with a nonzero
  /// damping parameter, or a user function that reads axialStrain_t / curvature_t). Zero when the
  /// scene gives no user function (resp. no damping): nothing runs that was not asked for.
  struct EvaluationCounts {
    long userFunctions = 0, dampingTerms = 0;
  };
  static EvaluationCounts evaluationCounts();

  static std::array<double, 4> shape(double x, double L);
  static std::array<double, 4> shape_x(double x, double L);
  static std::array<double, 4> shape_xx(double x, double L);

 private:
  static constexpr int kMaxIp = 5;
  struct IntegrationPoint {
    double x = 0, w = 0;              ///< axial position and weight (includes L/2)
    double xiNorm = 0;                ///< x / L (axialPositionNormalized)
    std::array<double, 4> Sx{}, Sxx{};
  };
  /// What depends only on (L, integration rule, rhoA): the integration points, the mass matrix and
  /// the body-force integral. Kernels with equal values share one copy (geometry()): an assembly over
  /// a uniform mesh reads it from cache instead of ~1.6 kB per element.
  struct Geometry {
    int nAxial = 0, nBending = 0;
    std::array<IntegrationPoint, kMaxIp> axial{}, bending{};
    std::array<double, 64> M{};                 ///< rhoA int S^T S dx
    std::array<double, 4> massShapeIntegral{};  ///< rhoA int S_j dx (bodyForce)
  };
  static std::shared_ptr<const Geometry> geometry(double L, int rule, double rhoA);
  struct PointRef {
    double strain = 0, curvature = 0;  ///< eps_ref, K_ref at an integration point
  };
  struct Law;  // force law evaluation helper

  double axialForceAt(const double* q, const double* qdot, double x, double t) const;
  double bendingMomentAt(const double* q, const double* qdot, double x, double t) const;

  std::array<double, 8> qRef_;
  double L_;
  std::shared_ptr<const AncfCable2DParameters> params_;  ///< shared by the elements of a set
  bool hasDamping_ = false;
  bool axialNeedsCurvature_ = false, bendingNeedsStrain_ = false;
  std::shared_ptr<const Geometry> geo_;
  /// eps_ref and K_ref at the integration points of an element whose reference shape enters them
  /// (f_ref != 0); null when they are the constants of the parameters
  struct ReferenceTable {
    std::array<PointRef, kMaxIp> axial{}, bending{};
  };
  std::shared_ptr<const ReferenceTable> ref_;
  PointRef axialRef(int ip) const {
    return ref_ ? ref_->axial[ip] : PointRef{params_->physicsReferenceAxialStrain, params_->physicsReferenceCurvature};
  }
  PointRef bendingRef(int ip) const {
    return ref_ ? ref_->bending[ip] : PointRef{params_->physicsReferenceAxialStrain, params_->physicsReferenceCurvature};
  }
};

}  // namespace sinew
