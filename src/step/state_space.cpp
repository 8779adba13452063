#include "step/state_space.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

namespace sinew {
namespace {
const char* kInNames[6] = {"force_x", "force_y", "force_z", "moment_x", "moment_y", "moment_z"};
const char* kOutNames[6] = {"displ_x", "displ_y", "displ_z", "veloc_x", "veloc_y", "veloc_z"};

int codeOf(const std::string& name, const char* const* names) {
  for (int c = 0; c < 6; ++c)
    if (name == names[c]) return c;
  return -1;
}
}  // namespace

StateSpaceAnalysis::StateSpaceAnalysis(Assembler& assembler, const ModalAnalysis& modal, const Model& model, double zeta)
    : asm_(assembler), modal_(modal), zeta_(zeta) {
  for (const auto& [node, np] : model.nprops) {  // ascending node, then as listed
    for (const auto& s : np.transfer_in) in_.push_back({node, codeOf(s, kInNames)});
    for (const auto& s : np.transfer_out) out_.push_back({node, codeOf(s, kOutNames)});
  }
}

PetscErrorCode StateSpaceAnalysis::atStep(Vec /*U*/, const LoadState& ls, ResultFile& file, bool* ok) {
  PetscFunctionBeginUser;
  if (written_ || ls.loadFactor < 1.0 - 1e-12) PetscFunctionReturn(PETSC_SUCCESS);
  written_ = true;
  const DistributedMesh& m = asm_.mesh();
  const std::vector<double>& hz = modal_.frequencies();
  const std::vector<Vec>& modes = modal_.modes();
  const int k = static_cast<int>(hz.size());
  const int nin = static_cast<int>(in_.size()), nout = static_cast<int>(out_.size());
  // Phi rows of every channel: the owner of the node's DOF fills them, the sum gathers them
  std::vector<TransferChannel> all(in_);
  all.insert(all.end(), out_.begin(), out_.end());
  const int nc = static_cast<int>(all.size());
  std::vector<double> phi(static_cast<size_t>(nc) * k + nc, 0.0);  // [nc x k], then 1 per channel found
  for (int c = 0; c < nc; ++c) {
    const int dir = c < nin ? all[c].code : all[c].code % 3;
    for (int i = 0; i < m.numOwnedNodes; ++i) {
      const LocalNode& n = m.nodes[i];
      if (n.sceneNode != all[c].node || dir >= n.ndof || (dir >= 3 && n.kind != NodeKind::Frame6)) continue;
      if (n.status[dir] != DofStatus::Free || n.dof[dir] < 0 || n.dof[dir] >= m.numOwnedUnknowns) continue;
      for (int j = 0; j < k; ++j) {
        const PetscScalar* a;
        PetscCall(VecGetArrayRead(modes[j], &a));
        phi[static_cast<size_t>(c) * k + j] = a[n.dof[dir]];
        PetscCall(VecRestoreArrayRead(modes[j], &a));
      }
      phi[static_cast<size_t>(nc) * k + c] = 1.0;
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, phi.data(), static_cast<int>(phi.size()), MPI_DOUBLE, MPI_SUM, m.comm);
  for (int c = 0; c < nc; ++c)
    if (phi[static_cast<size_t>(nc) * k + c] == 0.0 && failure_.empty()) {
      std::ostringstream msg;
      msg << "state-space: " << (c < nin ? "transfer_in " : "transfer_out ")
          << (c < nin ? kInNames[all[c].code] : kOutNames[all[c].code]) << " of node " << all[c].node + 1
          << " is not a free unknown of the model (a rotation on a node without rotations, or a held direction)";
      failure_ = msg.str();
    }
  for (double f : hz)
    if (!std::isfinite(f) && failure_.empty()) failure_ = "state-space: not every natural frequency converged";
  if (!failure_.empty()) {
    *ok = false;
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  const int n = 2 * k;
  states_ = n;
  std::vector<double> A(static_cast<size_t>(n) * n, 0.0), B(static_cast<size_t>(n) * nin, 0.0),
      C(static_cast<size_t>(nout) * n, 0.0), D(static_cast<size_t>(nout) * nin, 0.0);
  const double twoPi = 2.0 * std::numbers::pi;
  for (int j = 0; j < k; ++j) {
    const double w = twoPi * std::abs(hz[j]);
    const double w2 = hz[j] < 0 ? -w * w : w * w;  // negative: unstable state, kept as computed
    A[static_cast<size_t>(j) * n + k + j] = 1.0;
    A[static_cast<size_t>(k + j) * n + j] = -w2;
    A[static_cast<size_t>(k + j) * n + k + j] = -2.0 * zeta_ * w;
    for (int c = 0; c < nin; ++c) B[static_cast<size_t>(k + j) * nin + c] = phi[static_cast<size_t>(c) * k + j];
    for (int o = 0; o < nout; ++o) {
      const double p = phi[static_cast<size_t>(nin + o) * k + j];
      C[static_cast<size_t>(o) * n + (out_[o].code < 3 ? j : k + j)] = p;
    }
  }
  std::vector<double> ins, outs;
  for (const auto& c : in_) ins.insert(ins.end(), {static_cast<double>(c.node + 1), static_cast<double>(c.code + 1)});
  for (const auto& c : out_) outs.insert(outs.end(), {static_cast<double>(c.node + 1), static_cast<double>(c.code + 1)});
  file.writeArray("statespace/A", A, {n, n});
  file.writeArray("statespace/B", B, {n, nin});
  file.writeArray("statespace/C", C, {nout, n});
  file.writeArray("statespace/D", D, {nout, nin});
  file.writeArray("statespace/inputs", ins, {nin, 2});
  file.writeArray("statespace/outputs", outs, {nout, 2});
  file.writeArray("statespace/freq", hz, {k});
  file.writeArray("statespace/zeta", std::vector<double>{zeta_}, {1});
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::string StateSpaceAnalysis::summary() const {
  if (!written_ || states_ == 0) return {};
  char buf[200];
  std::snprintf(buf, sizeof buf, "\n state-space model (load factor 1): %d states (%d modes), %zu inputs, %zu outputs, zeta = %g\n",
                states_, states_ / 2, in_.size(), out_.size(), zeta_);
  return buf;
}

}  // namespace sinew
