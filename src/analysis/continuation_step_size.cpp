// Path following's step size: the model's size in the arc-length metric (the default ds_max) and the
// turn of the path from step to step (continuation_analysis.hpp, run()).
#include <algorithm>
#include <cmath>

#include "analysis/continuation_analysis.hpp"

namespace sinew {

double ContinuationAnalysis::modelPathSize() const {
  const DistributedMesh& m = asm_.mesh();
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  long counts[2] = {0, 0};  // free translations, free rotations and slopes
  for (int i = 0; i < m.numOwnedNodes; ++i) {
    const LocalNode& n = m.nodes[i];
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], n.X0[k]);
      hi[k] = std::max(hi[k], n.X0[k]);
    }
    const int translations = n.kind == NodeKind::Ancf2D ? 2 : 3;
    for (int k = 0; k < n.ndof; ++k)
      if (n.dof[k] >= 0) ++counts[k < translations ? 0 : 1];
  }
  MPI_Comm comm = m.comm;
  MPI_Allreduce(MPI_IN_PLACE, lo, 3, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(MPI_IN_PLACE, hi, 3, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPI_LONG, MPI_SUM, comm);
  double D2 = 0;
  for (int k = 0; k < 3; ++k) D2 += hi[k] > lo[k] ? (hi[k] - lo[k]) * (hi[k] - lo[k]) : 0.0;
  if (!(D2 > 0)) D2 = 1.0;
  return std::sqrt(static_cast<double>(counts[0]) * D2 + static_cast<double>(counts[1]));
}

PetscErrorCode ContinuationAnalysis::turnAngle(Vec U, Vec Uprev, double dl, Vec dUprev, double dlPrev, double* angle) {
  PetscFunctionBeginUser;
  // the load factor's weight: the spherical constraint's psi^2 |q|^2; with the cylindrical one, that of
  // the first path step, (ds_1 / lambda_1)^2, so that the path's first tangent is at 45 degrees (a
  // limit point turns it by about as much; kept in the checkpoint with the points)
  double w = opt_.constraint == "spherical" ? opt_.psi * opt_.psi * lastQnorm_ * lastQnorm_ : 0.0;
  if (opt_.constraint != "spherical" && !points_.empty() && points_.front().loadFactor != 0.0) {
    const double r = points_.front().arcLength / points_.front().loadFactor;
    w = r * r;
  }
  PetscCall(VecWAXPY(work_, -1.0, Uprev, U));
  PetscReal dd, pp, dp;
  PetscCall(VecDot(work_, work_, &dd));
  PetscCall(VecDot(dUprev, dUprev, &pp));
  PetscCall(VecDot(work_, dUprev, &dp));
  const double na = dd + w * dl * dl, nb = pp + w * dlPrev * dlPrev;
  *angle = na > 0 && nb > 0 ? std::acos(std::clamp((dp + w * dl * dlPrev) / std::sqrt(na * nb), -1.0, 1.0)) : 0.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
