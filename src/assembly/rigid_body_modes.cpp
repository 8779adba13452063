// Rigid-body motions of the model in the unknowns' layout: the near-null space that algebraic
// multigrid preconditioners (-pc_type gamg) need for structures.
#include "assembly/assembler.hpp"

namespace sinew {

PetscErrorCode Assembler::rigidBodyModes(MatNullSpace* nsp) const {
  PetscFunctionBeginUser;
  const bool planar = mesh_.anyAncf;
  const int nmodes = planar ? 3 : 6;
  // centroid of the owned nodes (all ranks): rotations about it keep the vectors well scaled
  double c[4] = {0, 0, 0, 0};
  for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
    for (int k = 0; k < 3; ++k) c[k] += mesh_.nodes[i].X0[k];
    c[3] += 1;
  }
  MPI_Allreduce(MPI_IN_PLACE, c, 4, MPI_DOUBLE, MPI_SUM, mesh_.comm);
  const Vec3 center = c[3] > 0 ? Vec3{c[0] / c[3], c[1] / c[3], c[2] / c[3]} : Vec3{};
  std::vector<Vec> modes(nmodes);
  for (int m = 0; m < nmodes; ++m) {
    PetscCall(VecCreateMPI(mesh_.comm, mesh_.numOwnedUnknowns, PETSC_DETERMINE, &modes[m]));
    PetscCall(VecSet(modes[m], 0.0));
    PetscScalar* v;
    PetscCall(VecGetArray(modes[m], &v));
    for (int i = 0; i < mesh_.numOwnedNodes; ++i) {
      const LocalNode& n = mesh_.nodes[i];
      const Vec3 r = n.X0 - center;
      std::array<double, 6> d{};
      if (planar) {  // x, y translations; rotation about z (positions and slopes turn)
        if (m < 2) d[m] = 1.0;
        else d = {-r[1], r[0], -n.slope0[1], n.slope0[0], 0, 0};
      } else if (m < 3) {
        d[m] = 1.0;
      } else {  // rotation about axis a: u = a x r, theta = a
        Vec3 a{};
        a[m - 3] = 1.0;
        const Vec3 u = cross(a, r);
        d = {u[0], u[1], u[2], a[0], a[1], a[2]};
      }
      for (int k = 0; k < n.ndof; ++k)
        if (n.dof[k] >= 0) v[n.dof[k]] = d[k];
    }
    PetscCall(VecRestoreArray(modes[m], &v));
  }
  // orthonormalize (modified Gram-Schmidt), dropping modes the supports remove completely
  std::vector<Vec> basis;
  for (Vec x : modes) {
    for (Vec b : basis) {
      PetscScalar dot;
      PetscCall(VecDot(x, b, &dot));
      PetscCall(VecAXPY(x, -dot, b));
    }
    PetscReal nrm;
    PetscCall(VecNorm(x, NORM_2, &nrm));
    if (nrm > 1e-12) {
      PetscCall(VecScale(x, 1.0 / nrm));
      basis.push_back(x);
    } else {
      PetscCall(VecDestroy(&x));
    }
  }
  PetscCall(MatNullSpaceCreate(mesh_.comm, PETSC_FALSE, static_cast<PetscInt>(basis.size()), basis.data(), nsp));
  for (Vec& b : basis) PetscCall(VecDestroy(&b));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
