// sinew: mpirun -n N sinew scene.yaml [-o result.h5] [opt flags] [PETSc flags]
#include <slepcsys.h>

#include <csignal>

#include "app/command_line.hpp"
#include "app/interrupt.hpp"
#include "app/runner.hpp"

int main(int argc, char** argv) {
  std::signal(SIGXFSZ, SIG_IGN);  // a file-size limit (ulimit -f) becomes a write error, also in MPI_Init
  PetscCall(SlepcInitialize(&argc, &argv, nullptr, sinew::usageText()));
  sinew::installInterruptHandlers();  // after PETSc's, which would abort on SIGTERM/SIGUSR1
  int code = 0;
  bool stop = false;
  PetscCall(sinew::handleCommandLine(PETSC_COMM_WORLD, &stop, &code));
  if (!stop) PetscCall(sinew::runFromCommandLine(argc, argv, &code));
  PetscCall(SlepcFinalize());
  return code;
}
