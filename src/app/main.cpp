// sinew: mpirun -n N sinew scene.yaml [-o result.h5] [opt flags] [PETSc flags]
#include <slepcsys.h>

#include <csignal>
#include <string>

#include "app/interrupt.hpp"
#include "app/runner.hpp"
#include "scene/scene_reader.hpp"

namespace {

std::string helpText() {
  std::string h =
      "Sinew: parallel finite elements for flexures, cables and membranes.\n"
      "Usage: mpirun -n N sinew scene.yaml [-o result.h5] [-<opt field> value ...] [PETSc options]\n"
      "Scene opt fields (each can be given as a flag of the same name):\n";
  for (const auto& d : sinew::sceneOptionDocs())
    h += "  -" + d.name + " <" + d.type + "> (default " + d.defaultValue + "): " + d.help + "\n";
  h += "Sinew flags: -o <file.h5> result file (checked and locked before the analysis; see docs/results.md); -force_rtol <1e-11> equilibrium tolerance relative to the\n"
       "  element forces; -max_cuts <10> halvings of a failing load increment; -predictor <true> secant\n"
       "  predictor from the last converged increment; -constraint_check <true> mechanism / redundant constraint\n"
       "  check before solving, for models up to -constraint_check_max_unknowns <200000>; -tangent_operator\n"
       "  <auto|elementwise|assembled> Newton systems of statics solved by GMRES on the element-wise tangent\n"
       "  (auto: for models with ANCF cables) or by the LU of the assembled tangent alone; -ancf_coarse_ratio <r>\n"
       "  fine ANCF elements per coarse element of the two-level preconditioner (0: none; default ~2 sqrt(n) from\n"
       "  1024 elements per scene element); -ancf_coarse_predictor <true> nonlinear coarse solve per increment.\n";
  return h;
}

}  // namespace

int main(int argc, char** argv) {
  static const std::string help = helpText();
  std::signal(SIGXFSZ, SIG_IGN);  // a file-size limit (ulimit -f) becomes a write error, also in MPI_Init
  PetscCall(SlepcInitialize(&argc, &argv, nullptr, help.c_str()));
  sinew::installInterruptHandlers();  // after PETSc's, which would abort on SIGTERM/SIGUSR1
  int code = 0;
  PetscCall(sinew::runFromCommandLine(argc, argv, &code));
  PetscCall(SlepcFinalize());
  return code;
}
