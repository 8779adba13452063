// Geometrically nonlinear 3D beam (SPACAR Light style; Jonker 1989): six deformation modes of a
// two-node Frame6 element, Timoshenko stiffness on the flexible ones, exact constraints on the
// rigid ones (one Lagrange multiplier each), released ones free.
//
// Sign conventions (local axes ex0 = chord, ey0 = orien, ez0 = ex0 x ey0; theta_y, theta_z are
// rotations about the local y / z axes, slopes w' = -theta_y and v' = theta_z):
//   e1 = |l| - l0                                   elongation
//   e2 = l0 (nz^p . ny^q - ny^p . nz^q) / 2         torsion, = l0 (phi_q - phi_p) for small angles
//   e3 = -l0 nz^p . lhat ~ -l0 theta_y^p,  e4 = l0 nz^q . lhat ~ l0 theta_y^q
//   e5 =  l0 ny^p . lhat ~ -l0 theta_z^p,  e6 = -l0 ny^q . lhat ~ l0 theta_z^q
// so pure bending (end rotations -+theta/2) gives e3 = e4 (resp. e5 = e6) = l0 sin(theta/2).
// eps1 = e1 + (2 e3^2 + e3 e4 + 2 e4^2 + 2 e5^2 + e5 e6 + 2 e6^2) / (30 l0), eps_i = e_i otherwise.
#pragma once
#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "elements/beam_section.hpp"
#include "elements/strain_rate_damped.hpp"

namespace sinew {

enum class BeamMode { Flexible, Rigid, Released };

class BeamCorotational : public StrainRateDampedKernel {
 public:
  /// Xp, Xq: initial node positions; orien: local y direction (default global z, or global y when the
  /// chord is parallel to z); modes: per deformation mode 1..6; constraintScale multiplies every
  /// constraint row/column (rows are constraintScale * eps_i of the rigid modes).
  BeamCorotational(const Vec3& Xp, const Vec3& Xq, const std::optional<Vec3>& orien, const BeamSection& s,
                   std::array<BeamMode, 6> modes, bool hasInertia, double constraintScale);

  const char* name() const override { return "beam_corotational"; }
  std::span<const NodeKind> nodeKinds() const override;
  int numConstraints() const override { return nRigid_; }
  bool hasInertia() const override { return hasInertia_ && !lumped_; }
  /// -beam_mass lumped: no element mass matrix; each node gets rhoA l0 / 2 on its translations and
  /// l0 / 2 (rho Ip ex0 ex0^T + rho Iy ey0 ey0^T + rho Iz ez0 ez0^T) as its rotary inertia.
  void setLumpedMass(bool lumped) { lumped_ = lumped; }
  /// -beam_mass linear (Simo & Vu-Quoc): the translations' mass of linearly interpolated velocities,
  /// rhoA l0 / 6 [2 I, I; I, 2 I] (isotropic blocks: the same in every frame, constant), and the rotary
  /// inertia lumped on the nodes as -beam_mass lumped gives it (lumpedInertia with no nodal mass).
  void setLinearMass(bool linear);
  const double* constantMass() const override { return linear_ ? linearMass_.data() : nullptr; }
  bool lumpedInertia(double* mJ) const override;

  void evaluate(const KernelInput& in, const KernelNeeds& needs, KernelOutput& out) const override;
  /// Consistent mass at the current configuration in the current element frame (chord, averaged triad);
  /// -beam_mass linear: the constant translation mass.
  void mass(const double* q, std::vector<double>& M) const override;
  /// The complete consistent mass (default; -beam_mass consistent_frozen switches it off): the
  /// Euler-Lagrange force of T = 1/2 v^T M(q) v with the rotating element frame (beam_inertia.cpp).
  void setCompleteMass(bool complete) { complete_ = complete; }
  bool hasInertiaForce() const override { return hasInertia() && complete_ && !linear_; }
  void inertiaForce(const double* q, const double* v, const double* a, bool tangent, InertiaOutput& out) const override;
  /// Lumped: rhoA l0 a / 2 on each node's translations, zero moments.
  void bodyForce(const double* q, const Vec3& a, std::vector<double>& f) const override;
  /// Max Von Mises stress over both end sections (normal stress from N, My, Mz; shear from torsion).
  double vonMisesMax(const double* q, const double* lambda) const override;
  /// 1/2 eps^T S eps (flexible modes; f = S eps . grad eps is its gradient).
  bool strainEnergy(const double* q, double* energy) const override;
  /// The six generalized stresses (rigid and released ones come out 0: rigid modes carry multipliers).
  int numMixedStresses() const override { return 6; }
  void linearizedStresses(const double* q0, const double* q1, double* sigma) const override;

  // Stiffness-proportional damping on the strain rates (Kelvin-Voigt, docs/dynamics.md "Damping";
  // StrainRateDampedKernel): sigma_d = beta S epsd with epsd = grad eps . qdot, f_d = grad eps^T sigma_d;
  // zero for every rigid velocity field at the current state (the strains are invariant under rigid motion).

  /// Energy-momentum step force (beam_step_force.cpp): f = B^T sigma with B (x1 - x0, theta_c) =
  /// eps(q1) - eps(q0) exactly (products of averaged vectors; theta_c the Cayley rotation vector) and
  /// sigma = S (eps0 + eps1) / 2 + (xi / 2 + beta / h) S (eps1 - eps0) on flexible modes, the
  /// multipliers on rigid ones; exact tangent by dual numbers.
  bool hasStepForce() const override { return true; }
  void stepForce(const StepForceInput& in, bool tangent, KernelOutput& out) const override;

  /// eps_1..eps_6 at state q.
  std::array<double, 6> generalizedStrains(const double* q) const;
  /// sigma_i = dU/d eps_i for flexible modes, constraintScale * lambda_k for rigid ones, 0 for released.
  /// disp (optional): node translations x - X0 (6 values), for a cancellation-free elongation.
  std::array<double, 6> generalizedStresses(const double* q, const double* lambda, const double* disp = nullptr) const;

  double l0() const { return l0_; }
  double referenceLength() const override { return l0_; }
  const Vec3& ey0() const { return ey0_; }
  const Vec3& ez0() const { return ez0_; }
  /// Effective 6x6 stiffness of the generalized strains (released modes condensed out, rigid ones zero).
  const std::array<double, 36>& stiffness() const { return S_; }

  /// Sensors along the element (Exudyn's SensorBody; src/elements/beam_corotational_sensor.cpp):
  /// variable at s in [0, 1] from node p (s = 0) to node q (s = 1), 3 values. Position,
  /// Displacement (disp: node translations x - X0, 6 values), Rotation (rotation vector of the
  /// section frame) interpolate in the current element frame: chord linear, transverse cubic
  /// Hermite (Timoshenko: the element's own field) from the end rotations, torsion linear.
  /// Velocity and AngularVelocity are their time derivatives along the nodal rates (rates:
  /// velocities and spatial spins in the 12-DOF layout, nullptr = at rest). ForceLocal (N, Qy,
  /// Qz) and TorqueLocal (T, My, Mz) are the section forces from the generalized stresses (lambda:
  /// the rigid modes' multipliers), in the element frame. Throws std::invalid_argument otherwise.
  std::array<double, 3> sensorValue(const std::string& variable, double s, const double* q, const double* disp,
                                    const double* rates, const double* lambda) const;
  static const std::vector<std::string>& sensorVariables();
  // --- element sensors: sensorValue above at s (the sensors' xi counts along the split scene element)
  bool hasSensors() const override { return true; }
  double sensorPosition(double /*x*/, double xi, int numSub) const override { return xi * numSub; }
  int sensorValueCount(const std::string& /*variable*/) const override { return 3; }
  std::vector<double> sensorValue(const std::string& variable, double s, const SensorInput& in) const override {
    const std::array<double, 3> r = sensorValue(variable, s, in.q, in.disp, in.qdot, in.lambda);
    return {r.begin(), r.end()};
  }
  /// Current element frame (columns: chord, averaged rotated local y made normal to it, their cross product).
  Mat3 currentFrame(const double* q) const;

 private:
  struct Kinematics;
  /// disp (optional, 6 values): node translations x - X0, for a cancellation-free elongation.
  void kinematics(const double* q, Kinematics& k, const double* disp = nullptr) const;
  /// The consistent mass in the element frame (12 x 12, row-major; mass() turns it with the frame).
  void localMass(double* Ml) const;
  void stresses(const Kinematics& k, const double* lambda, double* sig) const;
  /// The step force's B rows and stresses for scalar type T (double or Dual<12>; beam_step_force.cpp).
  template <class T>
  void stepForceT(const Kinematics& k0, const Kinematics& k1, const double* q1, const StepForceInput& in, T* f,
                  T (*B)[12]) const;

  /// G += sum_i sig_i d(grad eps_i)/dq (the stress part of the tangent; n: leading dimension).
  void addStressTangent(const Kinematics& k, const double* sig, double* G, int n) const;
  /// Sensor field at s: the section's offset from the chord point and its rotation (sensor file).
  void sectionField(const double* q, double s, Vec3& offset, Mat3& R) const;

  double l0_ = 0;
  Vec3 ex0_{}, ey0_{}, ez0_{};
  BeamSection sec_;
  std::array<BeamMode, 6> modes_{};
  bool hasInertia_ = false;
  bool lumped_ = false;
  bool linear_ = false;
  std::vector<double> linearMass_;  ///< -beam_mass linear: the constant 12 x 12 mass (row-major)
  bool complete_ = true;  ///< complete consistent mass (inertiaForce) in dynamics
  double scale_ = 1.0;
  int nRigid_ = 0;
  std::array<int, 6> rigidIndex_{};  ///< mode index of constraint k
  std::array<double, 36> S_{};       ///< sigma = S eps on flexible modes
  std::array<double, 8> Qh_{};       ///< Hessians of the arc-minus-chord quadratic, pairs (e3,e4), (e5,e6)
};

}  // namespace sinew
