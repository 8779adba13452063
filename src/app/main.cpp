// sinew: mpirun -n N sinew scene.yaml [-o result.h5] [opt flags] [PETSc flags]
#include <slepcsys.h>

#include <csignal>

#include "app/command_line.hpp"
#include "app/interrupt.hpp"
#include "app/runner.hpp"
#include "solvers/ancf/cable_coarse_space.hpp"
#include "solvers/ancf/node_rotated_pc.hpp"
#include "solvers/cut_corrected_lu.hpp"
#include "solvers/dense_lu.hpp"

int main(int argc, char** argv) {
  sinew::quickSingletonStart();
  std::signal(SIGXFSZ, SIG_IGN);  // a file-size limit (ulimit -f) becomes a write error, also in MPI_Init
  // -help, -help_dev, -version are Sinew's: taken out before PETSc would print its banners for them
  const sinew::StartRequest request = sinew::takeStartRequest(&argc, argv);
  PetscCall(SlepcInitialize(&argc, &argv, nullptr, sinew::usageText()));
  // Sinew's preconditioners are PETSc PC types: -pc_type cutlu / noderotated / denselu name them like PETSc's own
  PetscCall(sinew::registerCutCorrectedLU());
  PetscCall(sinew::registerNodeRotatedPC());
  PetscCall(sinew::registerCableCoarsePC());
  PetscCall(sinew::registerDenseLU());
  sinew::installInterruptHandlers();  // after PETSc's, which would abort on SIGTERM/SIGUSR1
  int code = 0;
  bool stop = false;
  PetscCall(sinew::handleCommandLine(PETSC_COMM_WORLD, request, argc, argv, &stop, &code));
  if (!stop) PetscCall(sinew::runFromCommandLine(argc, argv, &code));
  PetscCall(SlepcFinalize());
  return code;
}
