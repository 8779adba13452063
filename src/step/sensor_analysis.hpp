// Sensors (scene block `sensors`): Exudyn output variables of ancf_cable2d elements sampled at an
// axial position x of a scene element at every written step. The FE element that holds x is
// found from the nbeams split (LocalElement::subIndex/numSub, ElementKernel::sensorPosition); the
// value is computed by the rank that owns that element with its kernel's sensor methods
// (ElementKernel::sensorValue; ancf_cable2d: AncfCable2D::output(q, qdot, qddot)) and reduced to rank 0,
// which writes /sensors/<name> [ns, k]. Node sensors (`node`, Exudyn's SensorNode) sample a beam
// (Frame6) node: Position, Displacement (x - X0), Rotation (rotation vector of R, angle times axis,
// as /node/r_axang), Velocity, Acceleration, AngularVelocity, AngularAcceleration (spatial: global
// frame), 3 values each, from the owning rank. Beam element sensors (`element` with `xi` or `x` on a
// beam or rigid element, Exudyn's SensorBody) sample the FE element of the nbeams split that holds
// xi with the same methods (BeamCorotational::sensorValue, 3 values, docs/dynamics.md "Sensors
// along beam elements").
#pragma once
#include <string>
#include <vector>

#include "sinew/model.hpp"
#include "step/step_analysis.hpp"

namespace sinew {

class SensorAnalysis : public StepAnalysis {
 public:
  SensorAnalysis(Assembler& assembler, const std::vector<Sensor>& sensors);
  const char* name() const override { return "sensors"; }
  bool everyRow() const override { return true; }
  /// Velocities and accelerations (unknowns layout) of the next atStep; nullptr = at rest (statics).
  void setRates(Vec V, Vec A) {
    V_ = V;
    A_ = A;
  }
  PetscErrorCode atStep(Vec U, const LoadState& ls, ResultFile& file, bool* ok) override;

 private:
  struct Probe {
    Sensor sensor;
    int element = -1;  ///< local element index on the owning rank, -1 elsewhere
    double xLocal = 0;                  ///< position s in [0, 1] along that FE element
    const ElementKernel* kernel = nullptr;  ///< its kernel (hasSensors())
    int count = 1;                         ///< values per row (agreed over the ranks)
    int node = -1;  ///< node sensor: local owned node index on the owning rank, -1 elsewhere
  };
  /// A node sensor's 3 values from the node state (s: x, R) and the rates (local forms or null).
  static void nodeValues(const Probe& p, const LocalNode& n, const double* s, const double* v, const double* a, double* out);
  Assembler& asm_;
  std::vector<Probe> probes_;
  Vec V_ = nullptr, A_ = nullptr;
};

}  // namespace sinew
