// CorotatedNewtonMatrix (solvers/ancf/corotated_newton_matrix.hpp: the Newton matrix of fine ANCF cables rebuilt from kept element
// blocks turned with their elements) on the ranks it is started with (ctest: 1 and 2). Exit status 0
// only when every check passed.
//  (1) A free, bent and stretched ANCF cable (nodal mass and a slope torque included) turned rigidly
//      by 0.7 rad about the origin: the rebuilt matrix from the blocks kept at the first state equals
//      dynamicJacobian at the turned state to round-off (objectivity: B(Q q) = Q B(q) Q^T, the mass
//      term is isotropic), while the kept matrix itself differs from it at O(1).
//  (2) The same with a deformation added to the turn: the rebuilt matrix is no longer exact (printed),
//      but closer to the fresh one than the kept matrix is.
//  (1b) The kept matrix turned with the nodes, R J0 R^T (R: each node's position and slope turned by
//      the node's turn since J0 was built; useNodeRotatedPC), applied to a vector: exact for the
//      rigid turn, closer to the fresh matrix than the kept one with the deformation.
// Measured (2026-11-26, 1 and 2 ranks): (1) 6.9e-15 against 0.48 for the kept matrix; (2) 1.3e-2
// against 0.48; (1b) 7.9e-16, 7.6e-16, 2.8e-15 on 1, 2, 3 ranks against 0.11 for the kept matrix, and
// 1.9e-3 with the deformation.
#include <petscmat.h>
#include <petscsys.h>

#include <cmath>
#include <string>

#include "assembly/assembler.hpp"
#include "assembly/kernel_factory.hpp"
#include "mesh/distributed_mesh.hpp"
#include "mesh/fe_mesh.hpp"
#include "scene/scene_reader.hpp"
#include "solvers/ancf/corotated_newton_matrix.hpp"
#include "solvers/cut_corrected_lu.hpp"

namespace {

int failures = 0;

void expect(bool ok, const char* what, double value) {
  PetscPrintf(PETSC_COMM_WORLD, "  %-66s %.3e  %s\n", what, value, ok ? "ok" : "FAILED");
  if (!ok) ++failures;
}

const char* kScene = R"({"nodes": [[0, 0], [1.5, 0]], "elements": [[1, 2]],
  "nprops": {2: {"moment": [0, 0, 40.0], "mass": 0.3}},
  "eprops": [{"elems": [1], "type": "ancf_cable2d", "physicsMassPerLength": 1.0, "physicsBendingStiffness": 2.0,
              "physicsAxialStiffness": 5.0e6, "nbeams": 200}],
  "opt": {"loadsteps": 1, "calcfreq": false}})";

/// ||A - B||_inf / ||B||_inf
PetscErrorCode relDiff(Mat A, Mat B, double* d) {
  PetscFunctionBeginUser;
  Mat D;
  PetscCall(MatDuplicate(A, MAT_COPY_VALUES, &D));
  PetscCall(MatAXPY(D, -1.0, B, SAME_NONZERO_PATTERN));
  PetscReal nd, nb;
  PetscCall(MatNorm(D, NORM_INFINITY, &nd));
  PetscCall(MatNorm(B, NORM_INFINITY, &nb));
  PetscCall(MatDestroy(&D));
  *d = nd / nb;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// U1 = the state of U0 turned by alpha about the origin (positions and slopes), plus `extra` times a
/// smooth field on every unknown.
PetscErrorCode turned(sinew::Assembler& a, const sinew::DistributedMesh& mesh, Vec U0, double alpha, double extra,
                      Vec U1) {
  PetscFunctionBeginUser;
  sinew::LoadState ls;
  ls.loadFactor = 1.0;
  PetscCall(a.updateStates(U0, ls));
  PetscScalar* u;
  PetscCall(VecGetArray(U1, &u));
  const double c = std::cos(alpha), s = std::sin(alpha);
  for (int i = 0; i < mesh.numOwnedNodes; ++i) {
    const sinew::LocalNode& n = mesh.nodes[i];
    const double* st = a.nodeState(i);
    const double ref[4] = {n.X0[0], n.X0[1], n.slope0[0], n.slope0[1]};
    const double rot[4] = {c * st[0] - s * st[1], s * st[0] + c * st[1], c * st[2] - s * st[3], s * st[2] + c * st[3]};
    for (int k = 0; k < 4; ++k)
      if (n.dof[k] >= 0) u[n.dof[k]] = rot[k] - ref[k] + extra * std::sin(1.3 * n.dof[k]);
  }
  PetscCall(VecRestoreArray(U1, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode check() {
  PetscFunctionBeginUser;
  const sinew::Model model = sinew::parseScene(kScene, ".");
  const sinew::FeMesh fe = sinew::discretize(model);
  sinew::DistributedMesh mesh = sinew::distributeMesh(PETSC_COMM_WORLD, model, fe, sinew::makeKernelFactory(model, sinew::DynamicsSettings{}.beamMassInUse()));
  sinew::Assembler a(mesh, model.opt.gravity, sinew::StaticsSettings{}.assemblyCoo);
  Mat J0, Jc, J1;
  Vec U0, U1, V;
  PetscCall(a.createMatrix(&J0));
  PetscCall(a.createMatrix(&Jc));
  PetscCall(a.createMatrix(&J1));
  PetscCall(a.createVector(&U0));
  PetscCall(VecDuplicate(U0, &U1));
  PetscCall(VecDuplicate(U0, &V));
  PetscCall(VecSet(V, 0.0));
  PetscInt lo, hi;
  PetscCall(VecGetOwnershipRange(U0, &lo, &hi));
  for (PetscInt i = lo; i < hi; ++i) PetscCall(VecSetValue(U0, i, 0.05 * std::sin(0.37 * static_cast<double>(i)), INSERT_VALUES));
  PetscCall(VecAssemblyBegin(U0));
  PetscCall(VecAssemblyEnd(U0));
  sinew::LoadState ls;
  ls.loadFactor = 1.0;
  const double shiftV = 7.0, shiftA = 3.0e4;
  auto relVec = [](Vec a, Vec ref, double* d) -> PetscErrorCode {
    PetscFunctionBeginUser;
    Vec t;
    PetscCall(VecDuplicate(a, &t));
    PetscCall(VecWAXPY(t, -1.0, ref, a));
    PetscReal nt, nr;
    PetscCall(VecNorm(t, NORM_2, &nt));
    PetscCall(VecNorm(ref, NORM_2, &nr));
    PetscCall(VecDestroy(&t));
    *d = nt / nr;
    PetscFunctionReturn(PETSC_SUCCESS);
  };
  sinew::CorotatedNewtonMatrix cm(a);
  Vec xr, wr, yr, y0, y1r;  // node rotation: R J0 R^T xr against J1 xr
  PetscCall(VecDuplicate(U0, &xr));
  for (Vec* v : {&wr, &yr, &y0, &y1r}) PetscCall(VecDuplicate(U0, v));
  for (PetscInt i = lo; i < hi; ++i) PetscCall(VecSetValue(xr, i, std::cos(0.53 * static_cast<double>(i)), INSERT_VALUES));
  PetscCall(VecAssemblyBegin(xr));
  PetscCall(VecAssemblyEnd(xr));
  for (double extra : {0.0, 1e-4}) {
    PetscCall(a.dynamicJacobian(U0, V, nullptr, ls, shiftV, shiftA, J0));
    expect(cm.valid(), "blocks kept for every element (1 = yes)", cm.valid() ? 1.0 : 0.0);
    PetscCall(turned(a, mesh, U0, 0.7, extra, U1));
    // (1b) the kept matrix turned with the nodes (useNodeRotatedPC): R J0 R^T, R from the node turns
    // since J0 was built; exact for a rigid turn as the rebuilt one
    PetscCall(cm.turnToIterate(U1, ls));
    {
      const PetscScalar* xa;
      PetscScalar* wa;
      PetscCall(VecGetArrayRead(xr, &xa));
      PetscCall(VecGetArray(wr, &wa));
      cm.rotateNodes(xa, wa, true);
      PetscCall(VecRestoreArray(wr, &wa));
      PetscCall(VecRestoreArrayRead(xr, &xa));
      PetscCall(MatMult(J0, wr, yr));
      PetscCall(VecGetArray(yr, &wa));
      cm.rotateNodes(wa, wa, false);
      PetscCall(VecRestoreArray(yr, &wa));
      PetscCall(MatMult(J0, xr, y0));
    }
    PetscCall(cm.assemble(U1, ls, Jc));
    PetscCall(a.dynamicJacobian(U1, V, nullptr, ls, shiftV, shiftA, J1));
    double dc = 0, d0 = 0, dn = 0, dk = 0;
    PetscCall(relDiff(Jc, J1, &dc));
    PetscCall(relDiff(J0, J1, &d0));
    PetscCall(MatMult(J1, xr, y1r));
    PetscCall(relVec(yr, y1r, &dn));
    PetscCall(relVec(y0, y1r, &dk));
    if (extra == 0.0) {
      expect(dc < 1e-13, "rigid turn 0.7 rad: |rebuilt - fresh| / |fresh| (< 1e-13)", dc);
      expect(d0 > 1e-2, "rigid turn 0.7 rad: |kept - fresh| / |fresh| (> 1e-2)", d0);
      expect(dn < 1e-13, "rigid turn 0.7 rad: |R kept R^T x - fresh x| / |fresh x| (< 1e-13)", dn);
      expect(dk > 1e-2, "rigid turn 0.7 rad: |kept x - fresh x| / |fresh x| (> 1e-2)", dk);
    } else {
      expect(dc < d0, "turn + deformation 1e-4: |rebuilt - fresh| / |fresh| (< kept's)", dc);
      expect(d0 > 1e-2, "turn + deformation 1e-4: |kept - fresh| / |fresh|", d0);
      expect(dn < dk, "turn + deformation 1e-4: |R kept R^T x - fresh x| / |fresh x| (< kept's)", dn);
    }
  }
  for (Vec* v : {&xr, &wr, &yr, &y0, &y1r}) PetscCall(VecDestroy(v));
  // (3) applyCorotated applies the assembled Newton matrix element by element: after the rebuild (Jc)
  Vec x, y1, y2, b;
  PetscCall(VecDuplicate(U0, &x));
  PetscCall(VecDuplicate(U0, &y1));
  PetscCall(VecDuplicate(U0, &y2));
  PetscCall(VecDuplicate(U0, &b));
  for (PetscInt i = lo; i < hi; ++i) PetscCall(VecSetValue(x, i, std::cos(0.91 * static_cast<double>(i)), INSERT_VALUES));
  PetscCall(VecAssemblyBegin(x));
  PetscCall(VecAssemblyEnd(x));
  double dop = 0;
  PetscCall(cm.assemble(U1, ls, Jc));
  PetscCall(MatMult(Jc, x, y1));
  PetscCall(cm.apply(x, y2));
  PetscCall(relVec(y2, y1, &dop));
  expect(dop < 1e-13, "rebuilt matrix: |element-wise product - assembled| / |assembled|", dop);
  PetscCall(a.dynamicJacobian(U1, V, nullptr, ls, shiftV, shiftA, J1));
  PetscCall(MatMult(J1, x, y1));
  PetscCall(cm.apply(x, y2));
  PetscCall(relVec(y2, y1, &dop));
  expect(dop < 1e-13, "fresh matrix: |element-wise product - assembled| / |assembled|", dop);
  // (4) the cut-corrected LU solves J1 exactly (relative residual), block Jacobi alone does not
  PetscCall(MatMult(J1, x, b));
  for (bool correct : {true, false}) {
    KSP ksp;
    PetscCall(KSPCreate(PETSC_COMM_WORLD, &ksp));
    PetscCall(KSPSetOperators(ksp, J1, J1));
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    if (correct) {
      PetscCall(sinew::useCutCorrectedLU(ksp));
    } else {
      PC pc;
      PetscCall(KSPGetPC(ksp, &pc));
      PetscCall(PCSetType(pc, PCBJACOBI));
      PetscCall(KSPSetUp(ksp));
      KSP* sub;
      PetscInt nsub;
      PetscCall(PCBJacobiGetSubKSP(pc, &nsub, nullptr, &sub));
      PC spc;
      PetscCall(KSPGetPC(sub[0], &spc));
      PetscCall(PCSetType(spc, PCLU));
    }
    PetscCall(KSPSolve(ksp, b, y1));
    PetscCall(MatMult(J1, y1, y2));
    double res = 0, err = 0;
    PetscCall(relVec(y2, b, &res));
    PetscCall(relVec(y1, x, &err));
    int size = 1;
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    if (correct) {
      expect(res < 1e-12, "cut-corrected LU: |J y - b| / |b|", res);
      expect(err < 1e-8, "cut-corrected LU: |y - x| / |x|", err);
    } else if (size > 1) {
      expect(err > 1e-3, "block Jacobi alone (no correction): |y - x| / |x|", err);
    }
    PetscCall(KSPDestroy(&ksp));
  }
  for (Vec* v : {&x, &y1, &y2, &b}) PetscCall(VecDestroy(v));
  for (Mat* m : {&J0, &Jc, &J1}) PetscCall(MatDestroy(m));
  for (Vec* v : {&U0, &U1, &V}) PetscCall(VecDestroy(v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

int main(int argc, char** argv) {
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  PetscPrintf(PETSC_COMM_WORLD, "free cable, 200 elements, nodal mass and slope torque at node 2:\n");
  PetscCall(check());
  int all = failures;
  MPI_Allreduce(MPI_IN_PLACE, &all, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  PetscPrintf(PETSC_COMM_WORLD, "%s\n", all ? "FAILED" : "all checks passed");
  PetscCall(PetscFinalize());
  return all ? 1 : 0;
}
