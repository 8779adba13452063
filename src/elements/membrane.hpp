// 3-node triangle / 4-node quadrilateral membrane (St. Venant-Kirchhoff, plane stress) with
// prestress and Updated Reference Strategy (URS) form finding.
//
// Kinematics (total Lagrangian w.r.t. the reference configuration X, settable): at each integration
// point the reference tangent plane carries the orthonormal prestress frame (E1, E2) of
// PrestressFrame; X^1, X^2 are Cartesian coordinates along E1, E2. With f_i = dx/dX^i = sum_a N_a,i x_a
//   E_ij = (f_i . f_j - delta_ij)/2,            S = S0 + C : E   (S0 = [s11 s22 s12] in (E1, E2))
//   C = emod/(1 - nu^2) [1 nu 0; nu 1 0; 0 0 (1 - nu)/2]   (Voigt, engineering shear)
//   delta W_int = t int_A S : delta E dA = t int_A sum_i P_i . delta f_i dA,   P_i = sum_j S_ij f_j
//   K_mat = t int B^T C B dA,   K_geo = t int (sum_ij S_ij N_a,i N_b,j) I dA.
// Strain-rate damping (setStrainRateDamping, -stiffness_damping corotated; elastic mode only): the
//   Green-Lagrange rate Ed = B(x) v = [f1.v1, f2.v2, f1.v2 + f2.v1], v_i = sum_a N_a,i v_a (reference
//   frame, frame-indifferent: zero for v = w x x + c) adds S_d = beta C Ed to S. So
//   f_d = t int B^T S_d dA, D = beta t int B^T C B dA = beta K_mat, and at fixed v the tangent gains
//   beta t int B^T C B(v) dA (B with f_i -> v_i) plus S_d in the geometric part. The prestress's
//   geometric stiffness is not damped (out-of-plane motion of a prestressed membrane is damped only
//   through the stretch it causes).
// Form finding (URS, Bletzinger & Ramm 1999; Wuechner & Bletzinger 2005), homotopy factor lambda:
//   delta W = lambda t int_a sigma : delta e da + (1 - lambda) t int_A S : delta E dA
//   current term: sigma = s_kl e_k (x) e_l in the CURRENT prestress frame (e1, e2) of the current
//     tangent plane; pulled back: t int_A J sigma f^i . delta f_i dA, J = |f_1 x f_2|, f^i dual basis.
//   reference term: S = prescribed components [s11 s22 s12] in the REFERENCE prestress frame (no
//     material law: S is prescribed), i.e. P_i = sum_j S_ij f_j, linear in x.
//   Only stress-dependent stiffness exists: the exact tangent is returned as the geometric part
//   (K = 0, Kg = tangent when splitGeometric). It is computed by forward automatic differentiation
//   of the force (exact to round-off, frame rotation included). It is symmetric for lambda = 0;
//   for lambda > 0 with anisotropic prestress the current term is not conservative and K is
//   (slightly) nonsymmetric.
// xURS (setXurs): the reference term uses S~ = R^T sigma_c R instead of the fixed reference
//   components, with F = R U the polar decomposition of the in-plane deformation gradient
//   (F: reference plane -> current tangent plane) and sigma_c the prescribed Cauchy stress in the
//   current prestress frame. The stretch response (in-plane, U) is that of the stabilised reference
//   problem; the orientation of the stress (which follows the out-of-plane rotation R of the surface)
//   is taken from the current configuration. For isotropic prestress S~ = S0 (identical to URS);
//   at a form-found state (x = X) F = R = I and S~ = S0, so URS and xURS share their solutions.
// Stress adaption (distortion control, lagged: applied in updateReference, constant within a step):
//   at the element centre C = F^T F = sum_k lambda_k^2 N_k N_k^T of the step deformation (old
//   reference -> new), s_k = lambda_k / clamp(lambda_k, 1/lambdaMax, lambdaMax),
//   W = sum_k sqrt(s_k) N_k N_k^T,  S_act <- (1 - mueRelax) W S_act W + mueRelax S_act.
//   So the prestress along a principal direction stretched beyond lambdaMax grows by
//   lambda_k/lambdaMax (compressed below 1/lambdaMax: shrinks), components stay attached to the
//   prestress frame. Within the bounds nothing changes. This limits the distortion a step ADDS; it
//   cannot repair a distorted initial mesh: with lambda = 0 the reference problem of a flat patch is
//   the cotangent Laplacian of the reference mesh, which reproduces the reference exactly (linear
//   precision), so the step deformation is the identity and nothing is adapted.
// Shape distortion control (setDistortionControl(muMax), Sinew; applied in updateReference after the
//   reference is set to q, non-cumulative): the element's distortion is measured against its ideal
//   shape (equilateral triangle / square with the element's node order): B = dX/dY maps ideal
//   coordinates Y to the reference prestress-frame coordinates X at the centre,
//   M = B B^T / det B = sum_k mu_k^2 n_k n_k^T (det M = 1, mu_1 = 1/mu_2 >= 1: shape only, size and
//   rotation drop out). With w_k = mu_k / clamp(mu_k, 1/muMax, muMax), Wd = sum_k w_k n_k n_k^T:
//     S_act = Wd S_base Wd,   S_base = prescribed prestress (after step-stretch adaption).
//   For isotropic S_base = s I and muMax -> 1 the reference term t int_A S_act : dE dA becomes the
//   Dirichlet energy of the map from the ideal element (= 2 x current area + conformal distortion),
//   whose minimiser pulls the element toward its ideal shape; elements with mu <= muMax keep the
//   prescribed stress. At a converged shape (x = X) the element carries sigma = Wd S_base Wd (the
//   prescribed stress where the mesh is good, anisotropic where it had to be regularised).
#pragma once
#include <array>
#include <span>

#include "elements/prestress_frame.hpp"
#include "elements/strain_rate_damped.hpp"

namespace sinew {

struct MembraneProps {
  double thickness = 1.0;
  double emod = 0.0;
  double nu = 0.0;
  double dens = 0.0;
  std::array<double, 3> prestress{};  ///< [s11, s22, s12] (stress) in the prestress frame
};

class Membrane final : public StrainRateDampedKernel, public FormFindingKernel {
 public:
  /// X: 3 (triangle) or 4 (quad, counter-clockwise) reference node positions.
  Membrane(std::span<const Vec3> X, const MembraneProps& props, const PrestressFrame& frame = {});

  const char* name() const override { return nn_ == 3 ? "membrane3" : "membrane4"; }
  std::span<const NodeKind> nodeKinds() const override;
  bool hasInertia() const override { return props_.dens > 0.0; }

  void evaluate(const KernelInput& in, const KernelNeeds& needs, KernelOutput& out) const override;
  /// Consistent mass on the reference configuration (triangle rho t A/12 [2 1 1; 1 2 1; 1 1 2],
  /// quad 2x2 Gauss) per direction.
  void mass(const double* q, std::vector<double>& M) const override;
  void bodyForce(const double* q, const Vec3& a, std::vector<double>& f) const override;
  /// Plane-stress Von Mises of the Cauchy stress, max over integration points.
  double vonMisesMax(const double* q, const double* lambda) const override;
  /// Cauchy stress resultants n11 n22 n12 (force/length) in the current prestress frame at the centre.
  void elementForce(const double* q, std::vector<double>& out) const override;
  /// Reference positions (4 x 3, unused corner 0), prescribed, base and active prestress (3 each).
  int checkpointSize() const override { return 21; }
  void saveCheckpoint(double* out) const override;
  void loadCheckpoint(const double* in) override;

  FormFindingKernel* formFinding() override { return this; }

  int numNodes() const { return nn_; }
  const MembraneProps& props() const { return props_; }
  const PrestressFrame& frame() const { return frame_; }

  // --- reference configuration and prestress
  void setReference(const double* X) override;  ///< 3*numNodes coordinates
  const std::array<Vec3, 4>& reference() const { return X_; }
  void setPrestress(const std::array<double, 3>& s0);  ///< resets the active (adapted) prestress
  const std::array<double, 3>& activePrestress() const { return sAct_; }
  /// Second Piola-Kirchhoff stress [S11 S22 S12] (elastic law) at the centre, reference frame.
  std::array<double, 3> secondPK(const double* q) const;

  // --- form finding
  void setFormFinding(bool on, double lambda);
  bool inFormFinding() const { return ff_; }
  double homotopy() const { return lambda_; }
  bool formFindingGeometricOnly() const { return ff_; }
  /// URS step: apply stress adaption (when on) for the step deformation, then reference := q.
  void updateReference(const double* q) override;
  /// lambdaMax > 1 switches stress adaption on, <= 1 off.
  void setStressAdaption(double lambdaMax, double mueRelax);
  /// muMax > 1 switches shape distortion control on (see the file comment), <= 1 off.
  /// Takes effect at once on the current reference (so the first form-finding step is controlled).
  void setDistortionControl(double muMax);
  /// Principal stretch mu_1 >= 1 of the reference element relative to its ideal shape (1 = ideal).
  double shapeDistortion() const;
  void setXurs(bool on) { xurs_ = on; }
  bool xurs() const { return xurs_; }

  /// Shape quality at state q: minimum corner sine normalised so that the equilateral triangle and
  /// the square give 1 (0 = degenerate). For quads the corner sines are those of the four corners.
  double meshQuality(const double* q) const override;

  // --- the FormFindingKernel interface (a surface)
  Shape shapeType() const override { return Shape::Surface; }
  void enterFormFinding(double lambda, bool xurs) override {
    setFormFinding(true, lambda);
    setXurs(xurs);
  }
  void leaveFormFinding() override {
    setFormFinding(false, 0.0);
    setXurs(false);
  }
  void setAdaption(double lambdaMax, double mueRelax, double distortionMax) override {
    setStressAdaption(lambdaMax, mueRelax);
    setDistortionControl(distortionMax);
  }
  /// Area at q (a quad: half the cross product of its diagonals).
  double size(const double* q) const override;
  /// Area at most 1e-3 of the initial area.
  bool collapsed(const double* q, double initialSize, double /*modelSize*/) const override {
    return !(size(q) > 1e-3 * initialSize);
  }
  /// Area vector a (quad: from the diagonals) divided by sqrt(|a|).
  Vec3 shapeAxis(const double* q) const override;
  void clearPrestress() override { setPrestress({0.0, 0.0, 0.0}); }

  /// The mass of the reference configuration: no state dependence (the energy-momentum scheme takes it).
  bool massDependsOnState() const override { return false; }
  /// U = t int (S0 . E + 1/2 E . C E) dA over the reference (elastic; false in form finding).
  bool strainEnergy(const double* q, double* energy) const override;
  // strain-rate damping (file comment; StrainRateDampedKernel): beta (s) on the Green-Lagrange strain rate

  /// Energy-momentum step force (membrane_step_force.cpp): the St. Venant-Kirchhoff force with the mean
  /// stress S0 + C (E0 + E1)/2 on the mid deformation gradient (exact for the quadratic strains), plus
  /// beta/h C (E1 - E0) with strain-rate damping.
  bool hasStepForce() const override { return true; }
  void stepForce(const StepForceInput& in, bool tangent, KernelOutput& out) const override;

  /// Internal force of the form-finding weak form (T = double or an AD scalar).
  template <class T> void ffForce(const T* x, T* f) const;

 private:
  struct Point {
    double N[4] = {};
    double dN[4][2] = {};  ///< dN_a / dX^i (reference prestress-frame coordinates)
    double wJ0 = 0.0;      ///< weight * reference area Jacobian
    double A[2][2] = {};   ///< A[i][alpha] = dX^i / dxi^alpha (prestress-frame coordinates)
  };
  /// Principal directions n_k (rows) and stretches mu_k of M = B B^T / det B (shape distortion).
  void distortion(double n[2][2], double mu[2]) const;
  void applyDistortionControl();  ///< sAct_ := Wd sBase_ Wd (sBase_ when off)
  template <int M> void ffTangent(const double* q, double* f, double* K) const;
  void cauchyAt(const double* q, int p, double sig[3]) const;

  int nn_ = 3, ngp_ = 1;
  std::array<Vec3, 4> X_{};
  std::array<Point, 5> pts_{};  ///< integration points, then the centre (index ngp_)
  MembraneProps props_;
  PrestressFrame frame_;
  std::array<double, 3> sAct_{};
  std::array<double, 3> sBase_{};  ///< prestress after step-stretch adaption, before distortion control
  double C_[3][3] = {};
  bool ff_ = false, xurs_ = false;
  double lambda_ = 0.0, lambdaMax_ = 0.0, mueRelax_ = 0.0, muMax_ = 0.0;
};

}  // namespace sinew
