// Start-up handling of the options database, before the scene is read: -version, the check of
// every option against Sinew's flag registry and PETSc's options, and -help's Sinew blocks.
#pragma once
#include <petscsys.h>

namespace sinew {

/// Collective on comm. -version: prints Sinew's, PETSc's and SLEPc's versions, *stop, exit 0.
/// Every option in the database (command line, -options_file, PETSC_OPTIONS, .petscrc) must be a
/// Sinew flag with an accepted value or a PETSc/SLEPc option; otherwise rank 0 prints one line per
/// wrong flag ("error: unknown flag -loadstep; did you mean -loadsteps?") and *stop with exit 2
/// on every rank. -help: prints Sinew's flags with their defaults in PETSc's options blocks.
/// A Sinew flag given twice on the command line (argv) is an error too.
PetscErrorCode handleCommandLine(MPI_Comm comm, int argc, const char* const* argv, bool* stop, int* exitCode);

/// -help, or its short form -h (Sinew's: PETSc 3.18 knows only -help; -h prints the usage text
/// and then acts as -help).
PetscErrorCode helpRequested(PetscBool* help);

/// The text -help prints first (SlepcInitialize's help message).
const char* usageText();

/// Sinew's version (CMake project version).
const char* sinewVersion();

}  // namespace sinew
