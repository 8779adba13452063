// Dense LU with partial pivoting (LAPACK getrf/getrs) of a small one-process matrix, as a PETSc PC
// type (PCDENSELU, -pc_type denselu): the default direct solver of one-process models up to
// -dense_max_unknowns (useDirectSolver in solver_defaults.hpp). For a tangent of some tens of
// unknowns a MUMPS call costs mostly its fixed work per call (analysis, structure walks, a
// communicator duplicated per call); here a factorization is a copy of the rows into a column-major
// array and one getrf, a solve one getrs (docs/performance.md, "Designs from Python").
#pragma once

#include <petscksp.h>

namespace sinew {

/// The PC type name of the dense LU.
#define PCDENSELU "denselu"

/// PCRegister of PCDENSELU (main() and sinew::initialize at start-up; useDenseLU again, for library users).
PetscErrorCode registerDenseLU();

/// Makes ksp a dense LU solve of its operator's preconditioning matrix (KSPPREONLY + PCDENSELU).
/// The matrix must live on one process; a zero pivot fails the PC (PC_FACTOR_NUMERIC_ZEROPIVOT),
/// as a failed MUMPS factorization does.
PetscErrorCode useDenseLU(KSP ksp);

/// Factorizations made by PCDENSELU in this process (tests: proof that the dense path ran).
long denseLUFactorizations();

}  // namespace sinew
