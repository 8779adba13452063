#include "sinew/element_kernel.hpp"

namespace sinew {

// A kernel without inertia has zero mass and feels no body force.
void ElementKernel::mass(const double* /*q*/, std::vector<double>& M) const {
  const size_t n = static_cast<size_t>(numDofs());
  M.assign(n * n, 0.0);
}

void ElementKernel::bodyForce(const double* /*q*/, const Vec3& /*a*/, std::vector<double>& f) const {
  f.assign(static_cast<size_t>(numDofs()), 0.0);
}

}  // namespace sinew
