#include "analysis/sensor_analysis.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "elements/ancf_cable2d.hpp"
#include "sinew/rotation.hpp"

namespace sinew {

namespace {
/// Element DOF values of a ghosted vector's local form (0 at constrained DOFs).
void gatherDofs(const double* x, const int* idx, int n, double* out) {
  for (int k = 0; k < n; ++k) out[k] = (x && idx[k] >= 0) ? x[idx[k]] : 0.0;
}

PetscErrorCode localRead(Vec X, Vec* xl, const PetscScalar** x) {
  PetscFunctionBeginUser;
  *x = nullptr;
  if (!X) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecGhostUpdateBegin(X, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGhostUpdateEnd(X, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGhostGetLocalForm(X, xl));
  PetscCall(VecGetArrayRead(*xl, x));
  PetscFunctionReturn(PETSC_SUCCESS);
}
PetscErrorCode localRestore(Vec X, Vec* xl, const PetscScalar** x) {
  PetscFunctionBeginUser;
  if (!X) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecRestoreArrayRead(*xl, x));
  PetscCall(VecGhostRestoreLocalForm(X, xl));
  PetscFunctionReturn(PETSC_SUCCESS);
}
}  // namespace

int SensorAnalysis::valueCount(const std::string& v) {
  static const std::array<const char*, 8> vectors = {"Position", "Displacement", "Velocity", "VelocityLocal",
                                                     "Acceleration", "Director1", "AngularVelocity", "AngularAcceleration"};
  return std::any_of(vectors.begin(), vectors.end(), [&](const char* s) { return v == s; }) ? 3 : 1;
}

SensorAnalysis::SensorAnalysis(Assembler& assembler, const std::vector<Sensor>& sensors) : asm_(assembler) {
  const auto& elements = asm_.mesh().elements;
  for (const Sensor& s : sensors) {
    Probe p;
    p.sensor = s;
    if (s.node >= 0) {
      for (int i = 0; i < asm_.mesh().numOwnedNodes; ++i)
        if (asm_.mesh().nodes[i].sceneNode == s.node) p.node = i;
      probes_.push_back(p);
      continue;
    }
    for (size_t e = 0; e < elements.size(); ++e) {
      const LocalElement& el = elements[e];
      if (el.sceneElement != s.element) continue;
      const auto* k = dynamic_cast<const AncfCable2D*>(el.kernel.get());
      if (!k) continue;
      // the scene element is split into numSub equal FE elements of length L_fe
      const double Lfe = k->length(), xi = s.x / (Lfe * el.numSub) * el.numSub;
      const int sub = std::clamp(static_cast<int>(std::floor(xi)), 0, el.numSub - 1);
      if (sub != el.subIndex) continue;
      p.element = static_cast<int>(e);
      p.xLocal = std::clamp((xi - sub) * Lfe, 0.0, Lfe);
      p.kernel = k;
    }
    probes_.push_back(p);
  }
}

void SensorAnalysis::nodeValues(const Probe& p, const LocalNode& n, const double* s, const double* v, const double* a,
                                double* out) {
  const std::string& var = p.sensor.variable;
  auto rate = [&](const double* x, int first) {
    for (int k = 0; k < 3; ++k) out[k] = (x && n.dof[first + k] >= 0) ? x[n.dof[first + k]] : 0.0;
  };
  if (var == "Position") {
    for (int k = 0; k < 3; ++k) out[k] = s[k];
  } else if (var == "Displacement") {
    for (int k = 0; k < 3; ++k) out[k] = s[k] - n.X0[k];
  } else if (var == "Rotation") {
    const Mat3 R{s[3], s[4], s[5], s[6], s[7], s[8], s[9], s[10], s[11]};
    const Vec3 w = logSO3(R);
    for (int k = 0; k < 3; ++k) out[k] = w[k];
  } else if (var == "Velocity") {
    rate(v, 0);
  } else if (var == "Acceleration") {
    rate(a, 0);
  } else if (var == "AngularVelocity") {
    rate(v, 3);
  } else if (var == "AngularAcceleration") {
    rate(a, 3);
  }
}

PetscErrorCode SensorAnalysis::atStep(Vec U, const LoadState& ls, ResultFile& file, bool* ok) {
  PetscFunctionBeginUser;
  *ok = true;
  Vec vl = nullptr, al = nullptr;
  const PetscScalar *v = nullptr, *a = nullptr;
  PetscCall(localRead(V_, &vl, &v));
  PetscCall(localRead(A_, &al, &a));
  const double* u = nullptr;
  PetscCall(asm_.beginLocal(U, ls, &u));
  std::vector<double> values;
  std::array<double, 48> q{};
  std::array<int, 48> idx{};
  std::array<double, 8> qd{}, qdd{};
  for (const Probe& p : probes_) {
    const int k = p.sensor.node >= 0 ? 3 : valueCount(p.sensor.variable);
    std::vector<double> out(k, 0.0);
    if (p.node >= 0) nodeValues(p, asm_.mesh().nodes[p.node], asm_.nodeState(p.node), v, a, out.data());
    if (p.element >= 0) {
      const LocalElement& el = asm_.mesh().elements[p.element];
      asm_.gather(el, q.data(), idx.data());
      gatherDofs(v, idx.data(), 8, qd.data());
      gatherDofs(a, idx.data(), 8, qdd.data());
      out = p.kernel->output(p.sensor.variable, p.xLocal, q.data(), v ? qd.data() : nullptr, a ? qdd.data() : nullptr,
                             ls.time);
    }
    values.insert(values.end(), out.begin(), out.end());
  }
  PetscCall(asm_.endLocal(&u));
  PetscCall(localRestore(A_, &al, &a));
  PetscCall(localRestore(V_, &vl, &v));
  // exactly one rank owns each sensor's element: a sum brings its values to every rank
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, asm_.mesh().comm);
  size_t off = 0;
  for (const Probe& p : probes_) {
    const int k = p.sensor.node >= 0 ? 3 : valueCount(p.sensor.variable);
    file.writeStepRow("sensors/" + p.sensor.name, std::span<const double>(values.data() + off, k));
    off += k;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
