// Compatibility with PETSc 3.18 (Debian bookworm).
#pragma once
#include <petscversion.h>
#if PETSC_VERSION_LT(3, 19, 0)
#define PETSC_SUCCESS 0
#endif
