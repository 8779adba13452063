// Micro benchmark of the dynamic residual of an ANCF cantilever (A1: EA = 1e6, EI = 833.33, rhoA = 78,
// L = 2) per element, at the sizes given (not a test; `cmake --build build --target bench_residual`,
// run on one process). Each size: Assembler::dynamicResidual at a fixed bent state, repeated for
// 0.3 s of CPU time of the process (the machine is shared: wall time counts other jobs' slices), the
// best of 7 such rounds; prints ns per element and evaluation.
// Sizes of up to 4096 elements fit in this machine's caches, larger ones do not: the difference is
// what the residual's memory layout costs (docs/performance.md).
#include <petscsys.h>
#include <petscvec.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <string>

#include "assembly/assembler.hpp"
#include "assembly/kernel_factory.hpp"
#include "mesh/distributed_mesh.hpp"
#include "mesh/fe_mesh.hpp"
#include "scene/scene_reader.hpp"

namespace {

PetscErrorCode bench(long n) {
  PetscFunctionBeginUser;
  const std::string scene = R"({"nodes": [[0, 0], [2.0, 0]], "elements": [[1, 2]], "nprops": {1: {"fix_coords": [1, 1, 0, 1]}},
    "eprops": [{"elems": [1], "type": "ancf_cable2d", "physicsMassPerLength": 78.0, "physicsBendingStiffness": 833.3333333333333,
                "physicsAxialStiffness": 1000000.0, "nbeams": )" + std::to_string(n) + R"(}],
    "opt": {"loadsteps": 1, "calcfreq": false, "gravity": [0, -9.81]}})";
  const sinew::Model model = sinew::parseScene(scene, ".");
  const sinew::FeMesh fe = sinew::discretize(model);
  sinew::DistributedMesh mesh = sinew::distributeMesh(PETSC_COMM_WORLD, model, fe, sinew::makeKernelFactory(model, sinew::DynamicsSettings{}.beamMassInUse()));
  sinew::Assembler a(mesh, model.opt.gravity, sinew::StaticsSettings{}.assemblyCoo);
  Vec U, V, A, F;
  PetscCall(a.createVector(&U));
  PetscCall(VecDuplicate(U, &V));
  PetscCall(VecDuplicate(U, &A));
  PetscCall(VecDuplicate(U, &F));
  PetscInt lo, hi;
  PetscCall(VecGetOwnershipRange(U, &lo, &hi));
  for (PetscInt i = lo; i < hi; ++i) {
    PetscCall(VecSetValue(U, i, 1e-4 * std::sin(1e-3 * static_cast<double>(i)), INSERT_VALUES));
    PetscCall(VecSetValue(V, i, 1e-2 * std::cos(1e-3 * static_cast<double>(i)), INSERT_VALUES));
    PetscCall(VecSetValue(A, i, std::sin(2e-3 * static_cast<double>(i)), INSERT_VALUES));
  }
  for (Vec v : {U, V, A}) {
    PetscCall(VecAssemblyBegin(v));
    PetscCall(VecAssemblyEnd(v));
  }
  sinew::LoadState ls;
  ls.loadFactor = 1.0;
  ls.timeFunctions = true;
  double best = HUGE_VAL;
  for (int round = 0; round < 7; ++round) {
    int reps = 0;
    const std::clock_t t0 = std::clock();
    double t = 0;
    do {
      PetscCall(a.dynamicResidual(U, V, A, ls, F));
      ++reps;
      t = static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
    } while (t < 0.3);
    best = std::min(best, t / reps);
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%8ld elements: %7.1f ns per element and evaluation\n", n, 1e9 * best / static_cast<double>(n)));
  for (Vec* v : {&U, &V, &A, &F}) PetscCall(VecDestroy(v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

int main(int argc, char** argv) {
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] != '-') PetscCall(bench(std::atol(argv[i])));
  PetscCall(PetscFinalize());
  return 0;
}
