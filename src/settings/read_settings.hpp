// The one place that reads Sinew's settings from PETSc's options database (command line,
// -options_file, PETSC_OPTIONS), and puts Sinew's defaults of PETSc solver options into it.
#pragma once
#include <petscsys.h>

#include "scene/scene_reader.hpp"
#include "settings/settings.hpp"
#include "sinew/petsc_compat.hpp"

namespace sinew {

/// Every field of every component (fields.cpp), and every scene opt field given as a flag, from
/// `options` (nullptr: the global database). Values are not checked here: the start-up check
/// (handleCommandLine) has done that; a word outside a choice flag's list is a PETSc error.
PetscErrorCode readSettings(PetscOptions options, Settings* settings);

/// The scene reader's view of settings.sceneOpt: opt field name -> value given on the command line.
OptionOverride sceneOverrides(const Settings& settings);

/// PETSc's -help in the database (-help_petsc, an options file or PETSC_OPTIONS; command_line.cpp).
PetscErrorCode readPetscHelp(PetscBool* help);

/// Sinew's default of a PETSc solver option (e.g. -mat_mumps_icntl_14 100): puts `-name value`
/// into the global options database unless the user gave -name (then the user's value stays), for
/// the solver objects' SetFromOptions to find.
PetscErrorCode applySolverOptionDefault(const char* name, int value);

}  // namespace sinew
