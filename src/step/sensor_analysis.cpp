#include "step/sensor_analysis.hpp"

#include <algorithm>
#include <array>
#include <cmath>

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
      const ElementKernel* k = el.kernel.get();
      if (!k->hasSensors()) continue;
      // the scene element is split into numSub equal FE elements: t along it in FE element lengths ->
      // FE element sub = floor(t), s = t - sub along it
      const double t = k->sensorPosition(s.x, s.xi, el.numSub);
      const int sub = std::clamp(static_cast<int>(std::floor(t)), 0, el.numSub - 1);
      if (sub != el.subIndex) continue;
      p.element = static_cast<int>(e);
      p.xLocal = std::clamp(t - sub, 0.0, 1.0);
      p.kernel = k;
    }
    probes_.push_back(p);
  }
  // values per row (ANCF ForceLocal etc. are scalars, every beam variable is a vector): the owning
  // rank's kernel knows, the others learn it here
  std::vector<int> counts(probes_.size(), 0);
  for (size_t i = 0; i < probes_.size(); ++i) {
    const Probe& p = probes_[i];
    if (p.node >= 0) counts[i] = 3;
    else if (p.kernel) counts[i] = p.kernel->sensorValueCount(p.sensor.variable);
  }
  MPI_Allreduce(MPI_IN_PLACE, counts.data(), static_cast<int>(counts.size()), MPI_INT, MPI_MAX, asm_.mesh().comm);
  for (size_t i = 0; i < probes_.size(); ++i)
    probes_[i].count = probes_[i].sensor.node >= 0 ? 3 : std::max(counts[i], 1);
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
  std::array<double, kMaxElementRows> qd{}, qdd{};
  std::array<double, 12> disp{};
  for (const Probe& p : probes_) {
    std::vector<double> out(p.count, 0.0);
    if (p.node >= 0) nodeValues(p, asm_.mesh().nodes[p.node], asm_.nodeState(p.node), v, a, out.data());
    if (p.element >= 0) {
      const LocalElement& el = asm_.mesh().elements[p.element];
      asm_.gather(el, q.data(), idx.data());
      const int ndofs = el.kernel->numDofs();
      gatherDofs(v, idx.data(), ndofs, qd.data());
      gatherDofs(a, idx.data(), ndofs, qdd.data());
      // x - X0 of the position nodes, as the node sensors' Displacement
      const std::span<const NodeKind> kinds = el.kernel->nodeKinds();
      for (size_t i = 0, off = 0; i < kinds.size(); off += stateSize(kinds[i]), ++i)
        for (int c = 0; c < 3; ++c)
          disp[3 * i + c] = kinds[i] == NodeKind::Ancf2D ? 0.0 : q[off + c] - asm_.mesh().nodes[el.node[i]].X0[c];
      SensorInput in;
      in.q = q.data();
      in.disp = disp.data();
      in.qdot = v ? qd.data() : nullptr;
      in.qddot = a ? qdd.data() : nullptr;
      in.lambda = el.firstMultiplier >= 0 ? u + el.firstMultiplier : nullptr;
      in.t = ls.time;
      out = p.kernel->sensorValue(p.sensor.variable, p.xLocal, in);
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
    file.writeStepRow("sensors/" + p.sensor.name, std::span<const double>(values.data() + off, p.count));
    off += p.count;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
