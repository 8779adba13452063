// The strain-rate (Kelvin-Voigt) damping switch of the kernels that damp their own strain rates with
// stiffness-proportional damping (docs/dynamics.md "Damping"): beams, 3D cables, membranes.
#pragma once
#include "sinew/element_kernel.hpp"

namespace sinew {

class StrainRateDampedKernel : public ElementKernel {
 public:
  /// beta (s) on the element's strain rates; 0 switches the damping off.
  bool setStrainRateDamping(double beta) override {
    beta_ = beta;
    return true;
  }
  bool strainRateDamped() const override { return beta_ > 0.0; }
  bool hasDamping() const override { return beta_ > 0.0; }

 protected:
  double beta_ = 0.0;  ///< strain-rate damping (s)
};

}  // namespace sinew
