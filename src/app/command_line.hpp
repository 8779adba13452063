// Start-up handling of the command line, before the scene is read: -help, -help_dev, -help <flag>,
// -version (taken from argv before PETSc starts, so no PETSc banner hides Sinew's text), the check of
// every option against Sinew's flag registry and PETSc's options, and -help_petsc (PETSc's -help).
#pragma once
#include <petscsys.h>

#include <string>

namespace sinew {

/// What the command line asks for besides a run.
struct StartRequest {
  enum class Kind { Run, Help, HelpDev, HelpFlag, Version };
  Kind kind = Kind::Run;
  std::string flag;  ///< HelpFlag: the flag asked about (without '-')
};

/// Before SlepcInitialize: removes -help [flag], -h, -help_dev and -version from argv and says
/// which was given (the last one wins); -help_petsc becomes PETSc's -help. Plain argv, no MPI.
StartRequest takeStartRequest(int* argc, char** argv);

/// "" when the option `name` (without '-') is a Sinew flag with an accepted value or a PETSc/SLEPc
/// option, else the message ("unknown flag -loadstep; did you mean -loadsteps?"). Local.
std::string optionProblem(const std::string& name, const char* value);

/// Collective on comm. Every option in the database (command line, -options_file, PETSC_OPTIONS,
/// .petscrc) must be a Sinew flag with an accepted value or a PETSc/SLEPc option; otherwise rank 0
/// prints one line per wrong flag ("error: unknown flag -loadstep; did you mean -loadsteps?") and
/// *stop with exit 2 on every rank. Then the request: rank 0 prints the help text or the versions,
/// *stop, exit 0 (-help <flag> of no flag: exit 2). A Sinew flag given twice on the command line
/// (argv) is an error too.
PetscErrorCode handleCommandLine(MPI_Comm comm, const StartRequest& request, int argc, const char* const* argv, bool* stop,
                                 int* exitCode);

/// PETSc's -help (given as -help_petsc, or in an options file or PETSC_OPTIONS): PETSc lists its
/// options and those of the solvers a scene creates.
PetscErrorCode petscHelpRequested(PetscBool* help);

/// The text SlepcInitialize prints first under -help_petsc.
const char* usageText();

/// Before MPI starts: started without a launcher (`sinew scene.yaml`, `python3 study.py`: an MPI
/// singleton), Open MPI would fork a helper daemon and probe every network transport at MPI_Init,
/// for one process that talks to nobody; this sets Open MPI's variables that avoid both.
void quickSingletonStart();

/// Sinew's version (CMake project version).
const char* sinewVersion();

}  // namespace sinew
