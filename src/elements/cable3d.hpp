// 3D two-node cable (tension only) with Updated Reference Strategy form finding.
//
// Elastic mode (engineering strain, reference length L):
//   N = max(N0 + EA (l/L - 1), 0),   f = N [-e; e],   e = (x_q - x_p)/l
//   K_mat = EA/L [e e^T] (+/- blocks),  K_geo = N/l [I - e e^T] (+/- blocks).
// A slack cable (N0 + EA (l/L - 1) <= 0) returns f = 0, K = 0; isSlack() reports it and the
// assembler deals with the global singularity.
// Strain-rate damping (setStrainRateDamping, -stiffness_damping corotated): with the velocities w =
// v_q - v_p the axial force gains N_d = beta EA/L ld, ld = e . w (the rate of l, so of the strain
// l/L - 1): f_d = N_d [-e; e], D = beta EA/L [e e^T] (+/- blocks) = beta K_mat, and at fixed w
// d f_d/d x = beta EA/(L l) [e w^T P + ld P] (+/- blocks), P = I - e e^T. Rigid motion has ld = 0.
// Like the stiffness it is proportional to, it is zero while the cable is slack, and it leaves the
// geometric stiffness N/l P undamped (a prestressed cable's transverse motion is damped only
// through the stretch it causes).
// Form-finding mode (URS, Bletzinger & Ramm), prescribed force N = N0 (Cauchy, current config):
//   delta W = lambda N delta l + (1 - lambda) A int_L S delta E dL,  S = N/A,  E = (l^2 - L^2)/(2 L^2)
//   => f = [lambda N/l + (1 - lambda) N/L] (x_q - x_p) [-1; 1]        (force density at lambda = 0)
//   K = lambda N/l [I - e e^T] + (1 - lambda) N/L I   (all stress-dependent: material part zero).
// Stress adaption (lagged, at updateReference): s = stretch/clamp(stretch, 1/lambdaMax, lambdaMax),
// stretch = l_new / L_old; N0 <- (1 - mueRelax) s N0 + mueRelax N0.
#pragma once
#include <array>

#include "elements/strain_rate_damped.hpp"

namespace sinew {

class Cable3D final : public StrainRateDampedKernel, public FormFindingKernel {
 public:
  /// Reference positions of the two nodes, cross-section area, Young's modulus, density and
  /// prestress force N0. The reference length is |Xq - Xp| until setReferenceLength().
  Cable3D(const Vec3& Xp, const Vec3& Xq, double area, double emod, double dens, double prestressForce = 0.0);

  const char* name() const override { return "cable3d"; }
  std::span<const NodeKind> nodeKinds() const override;
  bool hasInertia() const override { return dens_ > 0.0; }

  void evaluate(const KernelInput& in, const KernelNeeds& needs, KernelOutput& out) const override;
  /// rho A L/6 [2 1; 1 2] per direction, L = reference length.
  void mass(const double* q, std::vector<double>& M) const override;
  /// rho A L/2 a at each node.
  void bodyForce(const double* q, const Vec3& a, std::vector<double>& f) const override;
  double vonMisesMax(const double* q, const double* lambda) const override;
  /// The mass of the reference length: no state dependence (the energy-momentum scheme takes it).
  bool massDependsOnState() const override { return false; }
  /// U(l) = EA/(2L) (l - l_s)^2 above the slack length l_s = L (1 - N0/EA), 0 below (N0 l when EA = 0).
  bool strainEnergy(const double* q, double* energy) const override;
  // strain-rate damping (file comment; StrainRateDampedKernel): beta (s) on the axial strain rate
  /// Energy-momentum step force (cable3d_step_force.cpp): +-N_bar (d0 + d1)/(l0 + l1) with the
  /// discrete-gradient force N_bar = (U(l1) - U(l0))/(l1 - l0), exact through going slack; strain-rate
  /// damping adds beta/h EA/L (l1 - l0) where taut at either end (dissipating beta/h EA/L (l1 - l0)^2).
  bool hasStepForce() const override { return true; }
  void stepForce(const StepForceInput& in, bool tangent, KernelOutput& out) const override;
  /// {N}: elastic axial force, or the URS force lambda N0 + (1 - lambda) N0 l/L in form finding.
  void elementForce(const double* q, std::vector<double>& out) const override;
  /// Reference length and active prestress force.
  int checkpointSize() const override { return 2; }
  void saveCheckpoint(double* out) const override {
    out[0] = L_;
    out[1] = N0_;
  }
  void loadCheckpoint(const double* in) override {
    L_ = in[0];
    N0_ = in[1];
  }

  FormFindingKernel* formFinding() override { return this; }
  /// Slack when the elastic force N0 + EA (l/L - 1) <= 0 (not in form finding): axialStiffness = EA
  /// (N0 when EA = 0).
  bool tensionOnly() const override { return true; }
  bool slack(const double* q, double* axialStiffness) const override;

  // --- properties
  void setReferenceLength(double L0) { L_ = L0; }
  double referenceLength() const override { return L_; }
  void setEmod(double emod) { E_ = emod; }
  void setPrestressForce(double N0) { N0_ = N0; }
  void setPrestressStress(double s0) { N0_ = s0 * A_; }
  double prestressForce() const { return N0_; }  ///< active prestress (after stress adaption)
  double area() const { return A_; }
  double emod() const { return E_; }
  double dens() const { return dens_; }

  // --- form finding (URS)
  void setFormFinding(bool on, double lambda);
  bool inFormFinding() const { return ff_; }
  double homotopy() const { return lambda_; }
  /// True in form finding: the tangent is purely geometric (material part zero when split).
  bool formFindingGeometricOnly() const { return ff_; }
  /// URS step: reference length := current length (stress adaption applied first when active).
  void updateReference(const double* q) override;
  /// lambdaMax > 1 switches stress adaption on, <= 1 off.
  void setStressAdaption(double lambdaMax, double mueRelax);

  // --- the FormFindingKernel interface (a line; no xURS, no distortion control)
  Shape shapeType() const override { return Shape::Line; }
  void enterFormFinding(double lambda, bool /*xurs*/) override { setFormFinding(true, lambda); }
  void leaveFormFinding() override { setFormFinding(false, 0.0); }
  void setAdaption(double lambdaMax, double mueRelax, double /*distortionMax*/) override { setStressAdaption(lambdaMax, mueRelax); }
  double size(const double* q) const override { return length(q); }
  /// Zero length: l <= 1e-12 of the model size.
  bool collapsed(const double* q, double /*initialSize*/, double modelSize) const override {
    return length(q) <= 1e-12 * modelSize;
  }
  /// Unit chord direction (x_q - x_p)/l.
  Vec3 shapeAxis(const double* q) const override;
  void clearPrestress() override { setPrestressForce(0.0); }
  /// Reference length := |X_q - X_p|.
  void setReference(const double* X) override;

  // --- state queries
  double length(const double* q) const;
  double axialForce(const double* q) const;
  bool isSlack(const double* q) const { return axialForce(q) <= 0.0; }

 private:
  /// Adds the strain-rate damping force (and D, tangent as needed) of the taut cable with chord d.
  void addStrainRateDamping(const double* qdot, const Vec3& d, const KernelNeeds& needs, KernelOutput& out) const;

  double A_, E_, dens_, N0_, L_;
  bool ff_ = false;
  double lambda_ = 0.0;
  double lambdaMax_ = 0.0, mueRelax_ = 0.0;
};

}  // namespace sinew
