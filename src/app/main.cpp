// sinew: mpirun -n N sinew scene.yaml [-o result.h5] [opt flags] [PETSc flags]
#include <slepcsys.h>

#include <csignal>
#include <cstdlib>
#include <string>

#include <unistd.h>

#include "app/command_line.hpp"
#include "app/interrupt.hpp"
#include "app/runner.hpp"
#include "solvers/ancf/cable_coarse_space.hpp"
#include "solvers/ancf/node_rotated_pc.hpp"
#include "solvers/cut_corrected_lu.hpp"

namespace {
// Started without a launcher (`sinew scene.yaml`: an MPI singleton), Open MPI would fork a helper
// daemon and probe every network transport at MPI_Init, for one process that talks to nobody.
// Measured with hyperfine (`sinew -version`, one run, minimum of 12 starts, machine under load): 0.49 s
// by default, 0.36 s without
// the daemon (ess_singleton_isolated), 0.28 s also without the network probing. A user's own
// OMPI_MCA_* settings win (setenv does not overwrite); under mpirun/srun nothing changes.
void quickSingletonStart() {
  if (std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") || std::getenv("PMI_RANK") ||
      std::getenv("SLURM_PROCID"))
    return;
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  setenv("OMPI_MCA_pml", "ob1", 0);
  setenv("OMPI_MCA_btl", "self,vader", 0);
  // An isolated singleton's session directory is always <tmp>/ompi.<host>.<uid>/jf.0/1, made at
  // MPI_Init and removed at exit: two runs started side by side (a parameter sweep, xargs -P, a test
  // running three at a time) race on it, and the loser aborts in MPI_Init ("A call to mkdir was
  // unable to create the desired directory: .../jf.0/1"; seen under load). One directory per process,
  // removed by Open MPI at exit as before.
  const char* tmp = std::getenv("TMPDIR");
  const std::string session = std::string(tmp && *tmp ? tmp : "/tmp") + "/ompi.sinew." + std::to_string(getpid());
  setenv("OMPI_MCA_orte_jobfam_session_dir", session.c_str(), 0);
}
}  // namespace

int main(int argc, char** argv) {
  quickSingletonStart();
  std::signal(SIGXFSZ, SIG_IGN);  // a file-size limit (ulimit -f) becomes a write error, also in MPI_Init
  // -help, -help_dev, -version are Sinew's: taken out before PETSc would print its banners for them
  const sinew::StartRequest request = sinew::takeStartRequest(&argc, argv);
  PetscCall(SlepcInitialize(&argc, &argv, nullptr, sinew::usageText()));
  // Sinew's preconditioners are PETSc PC types: -pc_type cutlu / noderotated name them like PETSc's own
  PetscCall(sinew::registerCutCorrectedLU());
  PetscCall(sinew::registerNodeRotatedPC());
  PetscCall(sinew::registerCableCoarsePC());
  sinew::installInterruptHandlers();  // after PETSc's, which would abort on SIGTERM/SIGUSR1
  int code = 0;
  bool stop = false;
  PetscCall(sinew::handleCommandLine(PETSC_COMM_WORLD, request, argc, argv, &stop, &code));
  if (!stop) PetscCall(sinew::runFromCommandLine(argc, argv, &code));
  PetscCall(SlepcFinalize());
  return code;
}
