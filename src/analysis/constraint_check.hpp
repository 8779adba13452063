// Singular models, SPACAR Light style: before the first load step (and when Newton's linear
// solve fails) the tangent J = [K G^T; G 0] (K: stiffness over the free node DOFs, G: rigid-mode
// constraint Jacobian, multipliers as unknowns) is checked for a null space:
//   (a) over-constraint: G^T lambda = 0 for some lambda != 0 (dependent constraint rows), the
//       null vector lives on the multipliers -> the elements and modes carrying it are named;
//   (b) mechanism: K u = 0 with G u = 0 (missing supports, released modes), the null vector
//       lives on the node DOFs -> the nodes/DOFs that move and the nearby releases are named.
// Null vectors come from subspace inverse iteration on the shifted pencil (J + sigma D) x = D y,
// D = diag(|J_ii|) on node rows and -||G_i||^2 / mean(diag K) on multiplier rows, factored
// once with MUMPS (works in parallel), then Rayleigh-Ritz on that subspace: a direction is null
// when ||J v|| <= tol ||D v||, counted independently of the start vectors (and the rank count).
// A mechanism in a model with a huge element stiffness ratio names the ratio (stiffness_spread.hpp).
#pragma once
#include <petscvec.h>

#include <string>

#include "assembly/assembler.hpp"
#include "settings/settings.hpp"
#include "sinew/model.hpp"

namespace sinew {

struct ConstraintReport {
  bool singular = false;
  int mechanisms = 0, redundant = 0;  ///< null directions on node DOFs / on multipliers
  std::string message;               ///< rank 0: what is wrong and what to fix (empty when regular)
};

/// Collective. Checks the tangent at state U (load state ls). settings: -constraint_check_tol,
/// -constraint_check_vectors (subspace size); denseMaxUnknowns: -dense_max_unknowns (useDirectSolver).
/// tangent: the caller's Assembler::jacobian at (U, ls) if it has one (used, not changed); else assembled here.
PetscErrorCode checkConstraints(Assembler& assembler, const Model& model, Vec U, const LoadState& ls,
                                const ModelCheckSettings& settings, int denseMaxUnknowns, ConstraintReport* report,
                                Mat tangent = nullptr);

}  // namespace sinew
