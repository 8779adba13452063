// sinew: mpirun -n N sinew scene.yaml [-o result.h5] [opt flags] [PETSc flags]
#include <slepcsys.h>

#include "app/command_line.hpp"
#include "app/runner.hpp"

namespace {

const char* const kHelp =
    "Sinew: parallel finite elements for flexures, cables and membranes.\n"
    "Usage: mpirun -n N sinew scene.yaml [-o result.h5] [-<opt field> value ...] [Sinew flags] [PETSc options]\n"
    "Sinew's flags are listed below in the blocks titled 'Sinew: ...', each with its current and default\n"
    "value (<now ... : formerly ...>) and the values it accepts; every scene opt field is also a flag.\n"
    "A flag that is neither Sinew's nor PETSc's/SLEPc's is an error (exit 2). sinew -version prints the version.\n";

}  // namespace

int main(int argc, char** argv) {
  PetscCall(SlepcInitialize(&argc, &argv, nullptr, kHelp));
  int code = 0;
  bool stop = false;
  PetscCall(sinew::handleCommandLine(PETSC_COMM_WORLD, &stop, &code));
  if (!stop) PetscCall(sinew::runFromCommandLine(argc, argv, &code));
  PetscCall(SlepcFinalize());
  return code;
}
