// Preconditioner of a kept Newton matrix turned with the nodes of an ANCF cable (useNodeRotatedPC).
#pragma once

#include <petscksp.h>

#include "solvers/ancf/corotated_newton_matrix.hpp"

namespace sinew {

/// Makes ksp's preconditioner R B^-1 R^T while *active (B^-1 alone otherwise): B^-1 is the
/// preconditioner of the returned inner KSP (configure it: its PC is applied directly, set up with
/// ksp's preconditioning matrix B, the Newton matrix as built and factored once), and R turns each
/// ANCF node's position and slope pair by the node's turn since B was built
/// (CorotatedNewtonMatrix::turnToIterate, rotateNodes). By objectivity an element block at a state
/// turned rigidly by Q is Q B_e Q^T, so R B R^T is the Newton matrix of a cable that turned with its
/// nodes; it misses the difference of the turns of an element's two nodes (1e-7 rad where the
/// elements of A1g at 65536 elements turned by 1e-3 rad) and the elements' deformation, not the turn.
/// A registered PCType (PCNODEROTATED): the inner KSP takes the options -<prefix>rotated_<option>.
PetscErrorCode useNodeRotatedPC(KSP ksp, const CorotatedNewtonMatrix& turns, const bool* active, KSP* inner);

/// The PC type name of the node-rotated kept Newton matrix.
#define PCNODEROTATED "noderotated"

/// PCRegister of PCNODEROTATED (main() at start-up; useNodeRotatedPC again, for library users).
PetscErrorCode registerNodeRotatedPC();

}  // namespace sinew
