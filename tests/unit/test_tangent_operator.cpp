// Assembler::applyTangent (element-wise tangent operator) against the assembled tangent, on the
// ranks it is started with (ctest: 1 and 2). Exit status 0 only when every check passed.
//  (1) A deformed free ANCF cable (no supports) with slope torques: for random x, applyTangent(x)
//      equals MatMult(J, x) to round-off of the products (relative 1e-13 of |J| |x|).
//  (2) A rigid translation t: J t = 0. applyTangent gives exactly 0; the assembled product has
//      round-off eps |J| |t| (printed), which is what the element-wise operator avoids.
//  (3) A clamped cable: same comparison as (1) (constrained columns take part in the element blocks).
//  (4) The rigid-motion-free product applyTangent(x, y, true) of the eigen solvers on the same
//      deformed, stressed cables: every element passes its check K_e R = F (spin of the internal
//      forces) and the product equals MatMult(J, x) to round-off.
#include <petscmat.h>
#include <petscsys.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "assembly/assembler.hpp"
#include "assembly/kernel_factory.hpp"
#include "mesh/distributed_mesh.hpp"
#include "mesh/fe_mesh.hpp"
#include "scene/scene_reader.hpp"

namespace {

int failures = 0;

void expect(bool ok, const char* what, double value) {
  PetscPrintf(PETSC_COMM_WORLD, "  %-62s %.3e  %s\n", what, value, ok ? "ok" : "FAILED");
  if (!ok) ++failures;
}

std::string cableScene(int n, bool clamped) {
  std::string s = R"({"nodes": [[0, 0], [1.5, 0]], "elements": [[1, 2]], "nprops": {)";
  s += clamped ? R"(1: {"fix_coords": [1, 1, 0, 1]}, )" : "";
  s += R"(2: {"moment": [0, 0, 40.0]}}, "eprops": [{"elems": [1], "type": "ancf_cable2d", "physicsMassPerLength": 1.0,
      "physicsBendingStiffness": 2.0, "physicsAxialStiffness": 5.0e6, "nbeams": )" +
       std::to_string(n) + R"(}], "opt": {"loadsteps": 1, "calcfreq": false}})";
  return s;
}

PetscErrorCode check(const std::string& scene, bool freeCable) {
  PetscFunctionBeginUser;
  const sinew::Model model = sinew::parseScene(scene, ".");
  const sinew::FeMesh fe = sinew::discretize(model);
  sinew::DistributedMesh mesh = sinew::distributeMesh(PETSC_COMM_WORLD, model, fe, sinew::makeKernelFactory(model, sinew::DynamicsSettings{}.beamMassInUse()));
  sinew::Assembler assembler(mesh, model.opt.gravity, sinew::StaticsSettings{}.assemblyCoo);
  Mat J;
  Vec U, x, y1, y2;
  PetscCall(assembler.createMatrix(&J));
  PetscCall(assembler.createVector(&U));
  PetscCall(VecDuplicate(U, &x));
  PetscCall(VecDuplicate(U, &y1));
  PetscCall(VecDuplicate(U, &y2));
  // a bent, stretched state: coordinate increments of a smooth field (all free unknowns)
  PetscInt lo, hi;
  PetscCall(VecGetOwnershipRange(U, &lo, &hi));
  for (PetscInt i = lo; i < hi; ++i) PetscCall(VecSetValue(U, i, 0.05 * std::sin(0.37 * static_cast<double>(i)), INSERT_VALUES));
  PetscCall(VecAssemblyBegin(U));
  PetscCall(VecAssemblyEnd(U));
  sinew::LoadState ls;
  ls.loadFactor = 1.0;
  assembler.keepTangentBlocks(true);
  assembler.keepRigidData(true);
  PetscCall(assembler.jacobian(U, ls, J));
  const long rigidFree = assembler.rigidFreeElements();
  long total = static_cast<long>(mesh.elements.size());
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_LONG, MPI_SUM, PETSC_COMM_WORLD);
  expect(rigidFree == total, "elements failing the rigid-motion check K_e R = F (0)", static_cast<double>(total - rigidFree));
  PetscReal jn;
  PetscCall(MatNorm(J, NORM_INFINITY, &jn));

  PetscRandom rnd;
  PetscCall(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
  PetscCall(PetscRandomSetSeed(rnd, 11));
  PetscCall(PetscRandomSeed(rnd));
  double worst = 0;
  for (int k = 0; k < 3; ++k) {
    PetscCall(VecSetRandom(x, rnd));
    PetscCall(MatMult(J, x, y1));
    PetscCall(assembler.applyTangent(x, y2));
    PetscCall(VecAXPY(y2, -1.0, y1));
    PetscReal d, xn;
    PetscCall(VecNorm(y2, NORM_INFINITY, &d));
    PetscCall(VecNorm(x, NORM_INFINITY, &xn));
    worst = std::max(worst, d / (jn * xn));
  }
  expect(worst < 1e-13, "random x: |applyTangent - MatMult| / (|J| |x|)", worst);
  worst = 0;
  for (int k = 0; k < 3; ++k) {
    PetscCall(VecSetRandom(x, rnd));
    PetscCall(MatMult(J, x, y1));
    PetscCall(assembler.applyTangent(x, y2, true));
    PetscCall(VecAXPY(y2, -1.0, y1));
    PetscReal d, xn;
    PetscCall(VecNorm(y2, NORM_INFINITY, &d));
    PetscCall(VecNorm(x, NORM_INFINITY, &xn));
    worst = std::max(worst, d / (jn * xn));
  }
  expect(worst < 1e-13, "random x: |applyTangent(rigid-motion free) - MatMult| / (|J| |x|)", worst);
  if (freeCable) {
    // rigid translation (1, -2) of every node: x, y coordinates; slopes unchanged
    PetscCall(VecSet(x, 0.0));
    for (const sinew::LocalNode& n : mesh.nodes) {
      if (n.dof[0] >= 0 && n.dof[0] < mesh.numOwnedUnknowns) PetscCall(VecSetValue(x, lo + n.dof[0], 1.0, INSERT_VALUES));
      if (n.dof[1] >= 0 && n.dof[1] < mesh.numOwnedUnknowns) PetscCall(VecSetValue(x, lo + n.dof[1], -2.0, INSERT_VALUES));
    }
    PetscCall(VecAssemblyBegin(x));
    PetscCall(VecAssemblyEnd(x));
    PetscCall(MatMult(J, x, y1));
    PetscCall(assembler.applyTangent(x, y2));
    PetscReal a, e;
    PetscCall(VecNorm(y1, NORM_INFINITY, &a));
    PetscCall(VecNorm(y2, NORM_INFINITY, &e));
    PetscPrintf(PETSC_COMM_WORLD, "  translation: assembled |J t| / |J| = %.3e (round-off), element-wise |J t| = %.3e\n",
                a / (2.0 * jn), e);
    expect(e == 0.0, "translation: element-wise |J t| (exactly 0)", e);
  }
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&U));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&y1));
  PetscCall(VecDestroy(&y2));
  PetscCall(MatDestroy(&J));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

int main(int argc, char** argv) {
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  PetscPrintf(PETSC_COMM_WORLD, "free cable, 200 elements, slope torque at node 2:\n");
  PetscCall(check(cableScene(200, false), true));
  PetscPrintf(PETSC_COMM_WORLD, "clamped cable, 64 elements:\n");
  PetscCall(check(cableScene(64, true), false));
  int all = failures;
  MPI_Allreduce(MPI_IN_PLACE, &all, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  PetscPrintf(PETSC_COMM_WORLD, "%s\n", all ? "FAILED" : "all checks passed");
  PetscCall(PetscFinalize());
  return all ? 1 : 0;
}
