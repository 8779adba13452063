// Direct solver for a distributed matrix whose ranks are coupled by few entries, such as a chain of
// cable elements cut into contiguous pieces (see useCutCorrectedLU).
#pragma once

#include <petscksp.h>

#include "mesh/distributed_mesh.hpp"

namespace sinew {

/// Coupling unknowns (columns of other ranks in the local rows: the ghost unknowns) of all ranks
/// together up to which useCutCorrectedLU pays: each one costs a local solve per factorization and an
/// entry of the reductions per solve.
constexpr long kCutCorrectedMaxCoupling = 64;

/// Total number of ghost unknowns over all ranks (collective).
long couplingUnknowns(const DistributedMesh& mesh);

/// Makes ksp's preconditioner an exact solve of its (MPIAIJ) matrix A from rank-local factors: every
/// rank factors its diagonal block D_r with PETSc's LU in reverse Cuthill-McKee order (options prefix
/// cut_), and the entries coupling the ranks, A - D = W S^T (S: the m unit vectors of the unknowns
/// that are columns of other ranks' rows, W: those columns of A - D), are corrected by the Woodbury
/// identity
///   A^-1 = D^-1 - D^-1 W (I + S^T D^-1 W)^-1 S^T D^-1,
/// its m x m capacitance matrix factored (LAPACK) on every rank. A factorization costs the local LU
/// and one local solve per coupling column of the rank; a solve costs one local solve, one reduction
/// of m numbers and m local vector updates. Nothing is gathered: against PCREDUNDANT (every rank
/// gathers and factors the whole matrix) the ranks share the work. One process: plain LU.
/// A registered PCType (PCCUTLU, -pc_type cutlu): options -<prefix>pc_cutlu_max_coupling and the
/// local LU's -<prefix>cut_<KSP/PC option>.
PetscErrorCode useCutCorrectedLU(KSP ksp);

/// The PC type name of the cut-corrected LU.
#define PCCUTLU "cutlu"

/// PCRegister of PCCUTLU (main() at start-up; useCutCorrectedLU again, for library users).
PetscErrorCode registerCutCorrectedLU();

}  // namespace sinew
