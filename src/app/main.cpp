// sinew: mpirun -n N sinew scene.yaml [-o result.h5] [opt flags] [PETSc flags]
#include <slepcsys.h>

#include "app/command_line.hpp"
#include "app/runner.hpp"

int main(int argc, char** argv) {
  PetscCall(SlepcInitialize(&argc, &argv, nullptr, sinew::usageText()));
  int code = 0;
  bool stop = false;
  PetscCall(sinew::handleCommandLine(PETSC_COMM_WORLD, &stop, &code));
  if (!stop) PetscCall(sinew::runFromCommandLine(argc, argv, &code));
  PetscCall(SlepcFinalize());
  return code;
}
