// The time-integration schemes of DynamicAnalysis as objects that own their parameters and state
// (as MFEM's SecondOrderODESolver subclasses do): what a checkpoint stores and a restart puts back.
//   GeneralizedAlphaScheme (generalized_alpha_scheme.hpp): Arnold & Brüls (2007), Exudyn's loop
//   MidpointScheme (midpoint_scheme.hpp): the implicit midpoint rule, spins by Simo & Wong (1991)
//   EnergyMomentumScheme (energy_momentum_scheme.hpp): energy and momenta exact (Simo & Tarnow 1992)
//   TSAlpha2Scheme (tsalpha2_scheme.hpp): PETSc's TSALPHA2 (Chung-Hulbert), its state inside TS
// The first three are StepSchemes: DynamicAnalysis solves their step equation for q_{n+1} with its own
// Newton loop, asking the scheme for the rates of an iterate and where to evaluate the equations of
// motion M qdd + f_int(q, qd, t) = f_ext(t).
#pragma once
#include <petscmat.h>
#include <petscvec.h>

#include "sinew/petsc_compat.hpp"

namespace sinew {

class Assembler;

/// The state of a scheme at a step start t_n (views, owned by the scheme): q_n, qd_n, the
/// algorithmic accelerations a_n (generalized alpha; the midpoint rule keeps (qd_n - qd_{n-1})/h
/// there) and the accelerations qdd_n. Null where the scheme does not expose a vector (TS).
struct SchemeState {
  Vec q = nullptr, qd = nullptr, a = nullptr, qdd = nullptr;
};

/// Where a step scheme evaluates the equations of motion for an iterate q_{n+1}: the residual is
/// r(q, qd, qdd, t_{n+1} + timeShift), its derivative by q_{n+1} is
/// jacobianScale (K + shiftV C + shiftA M) at (q, qd), with shiftV = d qd/d q, shiftA = d qdd/d q.
struct EvaluationPoint {
  Vec q = nullptr, qd = nullptr, qdd = nullptr;
  double timeShift = 0.0;
  double shiftV = 0.0, shiftA = 0.0;
  double jacobianScale = 1.0;
  /// midpoint rule: the rotary inertia is the momentum change over the step (Assembler::setRotaryMomentum),
  /// and the constraints of the multipliers hold at the step's end
  bool midStep = false;
  /// energy-momentum scheme: the elements' step forces from q_n to q (Assembler::setStepForces) and the
  /// rotary inertia as the momentum change with Cayley spins
  bool stepForces = false;
};

/// The equations of motion the schemes discretize, r(q, qd, qdd, t) = M qdd + f_int(q, qd, t) - f_ext(t)
/// (with damping C qd), and their tangent K + shiftV C + shiftA M.
class MotionEquations {
 public:
  virtual ~MotionEquations() = default;
  virtual PetscErrorCode motionResidual(double t, Vec q, Vec qd, Vec qdd, Vec F) = 0;
  virtual PetscErrorCode motionTangent(double t, Vec q, Vec qd, double shiftV, double shiftA, Mat P) = 0;
};

/// A time-integration scheme with its parameters and state.
class TimeScheme {
 public:
  virtual ~TimeScheme() = default;
  /// The state can be copied out and put back (checkpoint, -restart); false for PETSc's TS.
  virtual bool restartable() const = 0;
  /// The state of the last converged step (views; see SchemeState).
  virtual SchemeState state() const = 0;
};

/// A one-step scheme whose step equation for q_{n+1} DynamicAnalysis solves by Newton. It holds the
/// step start q_n, qd_n, a_n, qdd_n and the rates qd_{n+1}, a_{n+1}, qdd_{n+1} of the current iterate.
class StepScheme : public TimeScheme {
 public:
  /// `like`: a vector of the unknowns' layout. `multipliers`: 1 on coordinates, 0 on Lagrange
  /// multipliers (index-3 unknowns without rates; null without multipliers; kept by the caller).
  /// `rotations`: the assembler whose Frame6 rotation unknowns are spatial increments from R_n (Lie-group
  /// form); null when the unknowns form a vector space.
  StepScheme(Vec like, Vec multipliers, Assembler* rotations);
  ~StepScheme() override;
  StepScheme(const StepScheme&) = delete;
  StepScheme& operator=(const StepScheme&) = delete;

  bool restartable() const override { return true; }
  SchemeState state() const override { return {qn_, vn_, an_, qddn_}; }
  /// The rates of the last iterate given to rates(): qd_{n+1}, a_{n+1}, qdd_{n+1} (q_{n+1} is the iterate).
  SchemeState iterateRates() const { return {nullptr, v1_, a1_, qdd1_}; }
  /// Puts back a state (a checkpoint's q_n, qd_n, a_n, qdd_n; copied).
  PetscErrorCode restore(const SchemeState& s);
  /// Copies the state into `to` (vectors of the same layout).
  PetscErrorCode copyState(const SchemeState& to) const;

  /// A step of size h from the state: its fixed parts (before predict and rates).
  virtual PetscErrorCode beginStep(double h) = 0;
  /// Newton's start that extrapolates the motion (q_n is the other start, DynamicAnalysis's choice).
  virtual PetscErrorCode predict(Vec q) const = 0;
  /// qd_{n+1}, a_{n+1}, qdd_{n+1} of the iterate q_{n+1} (and what evaluation() needs).
  virtual PetscErrorCode rates(Vec q) = 0;
  /// Where the equations of motion are evaluated for the iterate q_{n+1} (after rates(q)).
  virtual EvaluationPoint evaluation(Vec q) const = 0;
  /// The converged iterate q_{n+1} (rates computed) becomes the step start; multipliers keep no rates.
  PetscErrorCode commit(Vec q);
  double stepSize() const { return h_; }

 protected:
  /// The midpoint-type rates of the iterate q: qd_{n+1} = 2 (qEnd - q_n) / h - exp(theta) qd_n (the
  /// spins of qd_n turned by q's rotation increments theta; qEnd = q, or q with Cayley vectors in place
  /// of theta), a_{n+1} = qdd_{n+1} = (qd_{n+1} - qd_n) / h. Uses work_.
  PetscErrorCode midpointRates(Vec q, Vec qEnd);
  Vec keep_ = nullptr;           ///< multipliers (not owned)
  Assembler* rotations_ = nullptr;
  double h_ = 0.0;               ///< the step size of beginStep
  Vec qn_ = nullptr, vn_ = nullptr, an_ = nullptr, qddn_ = nullptr;  ///< step start
  Vec v1_ = nullptr, a1_ = nullptr, qdd1_ = nullptr;                  ///< rates of the iterate
  Vec work_ = nullptr;  ///< generalized alpha: the predictor part of q_{n+1}; midpoint: turned spins
};

}  // namespace sinew
