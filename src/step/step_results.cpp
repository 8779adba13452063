#include "step/step_results.hpp"

#include <algorithm>
#include <limits>

#include <cmath>

#include "parallel/collective_error.hpp"
#include "sinew/rotation.hpp"

namespace sinew {

namespace {

constexpr const char* kCellKinds[3] = {"lines", "triangles", "quads"};
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

int cellKindOf(const LocalElement& el) { return el.numNodes == 2 ? 0 : (el.numNodes == 3 ? 1 : 2); }

}  // namespace

StepResults::StepResults(Assembler& assembler, const StepResultOptions& opts) : asm_(assembler), opts_(opts) {
  DistributedMesh& m = asm_.mesh();
  SinewCallThrow(m.comm, asm_.createFullVector(&full_));
  // scene element rows: contiguous ranges
  PetscLayout layout;
  SinewCallThrow(m.comm, PetscLayoutCreate(m.comm, &layout));
  SinewCallThrow(m.comm, PetscLayoutSetSize(layout, static_cast<PetscInt>(m.numSceneElements)));
  SinewCallThrow(m.comm, PetscLayoutSetUp(layout));
  SinewCallThrow(m.comm, PetscLayoutGetRange(layout, &elemLo_, &elemHi_));
  if (opts_.stress) {
    std::vector<PetscInt> remote(m.elements.size());
    for (size_t e = 0; e < m.elements.size(); ++e) remote[e] = m.elements[e].sceneElement;
    SinewCallThrow(m.comm, PetscSFCreate(m.comm, &stressSF_));
    SinewCallThrow(m.comm, PetscSFSetGraphLayout(stressSF_, layout, static_cast<PetscInt>(remote.size()), nullptr,
                                                 PETSC_COPY_VALUES, remote.data()));
    SinewCallThrow(m.comm, PetscSFSetUp(stressSF_));
  }
  SinewCallThrow(m.comm, PetscLayoutDestroy(&layout));
  for (const LocalElement& el : m.elements) ++cellCounts_[cellKindOf(el)];
  for (int i = 0; i < m.numOwnedNodes; ++i) {
    const LocalNode& n = m.nodes[i];
    reference_.push_back({n.X0[0], n.X0[1], n.kind == NodeKind::Ancf2D ? 0.0 : n.X0[2]});
  }
  MPI_Allreduce(MPI_IN_PLACE, cellCounts_, 3, MPI_LONG, MPI_SUM, m.comm);
}

StepResults::~StepResults() {
  VecDestroy(&full_);
  PetscSFDestroy(&stressSF_);
}

void StepResults::fillLayout(ResultLayout& layout) const {
  const DistributedMesh& m = asm_.mesh();
  layout.numNodes = m.numSceneNodes;
  layout.numElements = m.numSceneElements;
  layout.numMeshNodes = m.numFeNodes;
  layout.dimension = m.dimension;
  for (int i = 0; i < m.numOwnedNodes; ++i) {
    const LocalNode& n = m.nodes[i];
    if (n.sceneNode >= 0) layout.ownedNodes.push_back(n.sceneNode);
    layout.ownedMeshNodes.push_back(n.gid);
    layout.meshReference.insert(layout.meshReference.end(), reference_[i].begin(), reference_[i].end());
  }
  for (PetscInt e = elemLo_; e < elemHi_; ++e) layout.ownedElements.push_back(e);
  for (const LocalElement& el : m.elements) {
    auto& cells = el.numNodes == 2 ? layout.lines : (el.numNodes == 3 ? layout.triangles : layout.quads);
    auto& owner = el.numNodes == 2 ? layout.lineElement : (el.numNodes == 3 ? layout.triangleElement : layout.quadElement);
    for (int i = 0; i < el.numNodes; ++i) cells.push_back(m.nodes[el.node[i]].gid);
    owner.push_back(el.sceneElement + 1);
  }
}

PetscErrorCode StepResults::write(ResultFile& file, Vec U, const LoadState& ls) {
  PetscFunctionBeginUser;
  DistributedMesh& m = asm_.mesh();
  PetscCall(PetscLogEventBegin(SinewEvents::get().output, 0, 0, 0, 0));
  PetscCall(asm_.fullResidual(U, ls, full_));  // also evaluates the node states
  Vec fl;
  const PetscScalar* fr;
  PetscCall(VecGhostGetLocalForm(full_, &fl));
  PetscCall(VecGetArrayRead(fl, &fr));
  std::vector<double> p, quat, axang, eul, slope, Freac, Mreac, meshP, meshU;
  rows_.clear();
  maxMove_ = MaxMove{};
  anyMove_ = MaxMove{};
  for (int i = 0; i < m.numOwnedNodes; ++i) {
    const LocalNode& n = m.nodes[i];
    const double* s = asm_.nodeState(i);
    Vec3 x{s[0], s[1], n.kind == NodeKind::Ancf2D ? 0.0 : s[2]};
    meshP.insert(meshP.end(), x.begin(), x.end());
    for (int k = 0; k < 3; ++k) meshU.push_back(x[k] - reference_[i][k]);
    if (n.sceneNode < 0) continue;
    Mat3 R = identity3();
    if (n.kind == NodeKind::Frame6) std::copy(s + 3, s + 12, R.begin());
    if (n.kind == NodeKind::Ancf2D)  // the slope's turn from its reference direction, about z
      R = expSO3({0.0, 0.0, std::remainder(std::atan2(s[3], s[2]) - std::atan2(n.slope0[1], n.slope0[0]), 2 * M_PI)});
    const auto q = quaternionOf(R);
    const auto aa = axisAngleOf(R);
    const Vec3 e = eulerZYXOf(R);
    Vec3 F{}, M{};
    const int nt = n.kind == NodeKind::Ancf2D ? 2 : 3;
    for (int k = 0; k < nt; ++k)
      if (n.status[k] != DofStatus::Free) F[k] = fr[n.fullDof[k]];
    if (n.kind == NodeKind::Frame6)
      for (int k = 0; k < 3; ++k)
        if (n.status[3 + k] != DofStatus::Free) M[k] = fr[n.fullDof[3 + k]];
    if (n.kind == NodeKind::Ancf2D) {
      // generalized reactions Q on the constrained slope coordinates; a rotation dphi moves the slope
      // by dphi ez x s, so their moment about z is s_x Q_y - s_y Q_x
      double Q[2] = {0, 0};
      for (int k = 0; k < 2; ++k)
        if (n.status[2 + k] != DofStatus::Free) Q[k] = fr[n.fullDof[2 + k]];
      M[2] = s[2] * Q[1] - s[3] * Q[0];
    }
    p.insert(p.end(), x.begin(), x.end());
    quat.insert(quat.end(), q.begin(), q.end());
    axang.insert(axang.end(), aa.begin(), aa.end());
    eul.insert(eul.end(), e.begin(), e.end());
    Freac.insert(Freac.end(), F.begin(), F.end());
    Mreac.insert(Mreac.end(), M.begin(), M.end());
    if (m.anyAncf) {
      slope.push_back(n.kind == NodeKind::Ancf2D ? s[2] : 0.0);
      slope.push_back(n.kind == NodeKind::Ancf2D ? s[3] : 0.0);
    }
    bool report = false, held = false;
    for (int k = 0; k < 6; ++k) {
      report |= n.load[k] != 0.0 || n.loadInitial[k] != 0.0 || n.status[k] != DofStatus::Free;
      held |= n.status[k] != DofStatus::Free;
    }
    const double umag = norm(x - n.X0);
    const bool movesMost = !held && umag > anyMove_.u;  // among the free nodes (a support may be moved on purpose)
    if (report || umag > maxMove_.u || movesMost) {
      NodeSummaryRow row;
      row.node = n.sceneNode + 1;
      const Vec3 rv = logSO3(R);
      for (int k = 0; k < 3; ++k) {
        row.v[k] = x[k] - n.X0[k];
        row.v[3 + k] = rv[k];
        row.v[6 + k] = F[k];
        row.v[9 + k] = M[k];
      }
      if (report) rows_.push_back(row);
      else if (umag > maxMove_.u) maxMove_ = MaxMove{umag, row};
      if (movesMost) anyMove_ = MaxMove{umag, row};
    }
  }
  PetscCall(VecRestoreArrayRead(fl, &fr));
  PetscCall(VecGhostRestoreLocalForm(full_, &fl));
  file.writeNodeField("node/p", p, {3});
  file.writeNodeField("node/r_quat", quat, {4});
  file.writeNodeField("node/r_axang", axang, {4});
  file.writeNodeField("node/r_eulzyx", eul, {3});
  file.writeNodeField("node/Freac", Freac, {3});
  file.writeNodeField("node/Mreac", Mreac, {3});
  if (m.anyAncf) file.writeNodeField("node/slope", slope, {2});
  file.writeMeshField("mesh/p", meshP, {3});
  file.writeMeshField("mesh/u", meshU, {3});

  std::vector<double> local;  // Von Mises stress per local FE element
  if (opts_.stress) {
    PetscCall(asm_.elementStress(U, ls, local));
    std::vector<double> rows(static_cast<size_t>(elemHi_ - elemLo_), 0.0);
    PetscCall(PetscSFReduceBegin(stressSF_, MPIU_REAL, local.data(), rows.data(), MPI_MAX));
    PetscCall(PetscSFReduceEnd(stressSF_, MPIU_REAL, local.data(), rows.data(), MPI_MAX));
    struct {
      double v;
      int e;
    } best{0.0, -1}, global{};
    for (size_t i = 0; i < rows.size(); ++i)
      if (rows[i] > best.v || best.e < 0) best = {rows[i], static_cast<int>(elemLo_ + i)};
    if (best.e < 0) best.v = -1.0;
    MPI_Allreduce(&best, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, m.comm);
    stressMax_ = std::max(global.v, 0.0);
    stressElement_ = global.e;
    file.writeStepRow("stressmax", std::span<const double>(&stressMax_, 1));
    if (opts_.stressPerElement) file.writeElementField("element/stressmax", rows, {});
  }
  PetscCall(writeCellFields(file, U, ls, local));
  PetscCall(PetscLogEventEnd(SinewEvents::get().output, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Cell fields of the visualization mesh, one value per FE element in the order of the /mesh cell
// lists: Von Mises stress (when computed), the axial force of cables and ANCF cables (NaN on beams),
// the membrane stress resultants n11 n22 n12 in the element's current prestress frame.
PetscErrorCode StepResults::writeCellFields(ResultFile& file, Vec U, const LoadState& ls,
                                            const std::vector<double>& stress) {
  PetscFunctionBeginUser;
  DistributedMesh& m = asm_.mesh();
  std::vector<double> vm[3], axial, n[3][3];  // n[kind][component]: triangles and quads
  int has[2] = {0, 0};                        // any axial force, any membrane resultant (local)
  const double* u = nullptr;
  PetscCall(asm_.beginLocal(U, ls, &u));
  std::array<double, 48> q;
  std::array<int, kMaxElementRows> idx;
  std::vector<double> out;
  tensile_ = TensileSummary{};
  for (size_t e = 0; e < m.elements.size(); ++e) {
    const LocalElement& el = m.elements[e];
    const int k = cellKindOf(el);
    if (!stress.empty()) vm[k].push_back(stress[e]);
    asm_.gather(el, q.data(), idx.data());
    el.kernel->elementForce(q.data(), out);
    if (k == 0) {
      // cable: the axial force; ANCF cable: axial forces at x = 0, L/2, L (the middle one)
      axial.push_back(out.size() == 1 ? out[0] : out.size() == 3 ? out[1] : kNaN);
      has[0] |= !out.empty();
      if (el.kernel->tensionOnly() && out.size() == 1) addCable(q.data(), *el.kernel, out[0], el.sceneElement);
    } else {
      for (int c = 0; c < 3; ++c) n[k][c].push_back(out.size() == 3 ? out[c] : kNaN);
      has[1] |= out.size() == 3;
      if (out.size() == 3) addMembrane(out, el.sceneElement);
    }
  }
  PetscCall(asm_.endLocal(&u));
  MPI_Allreduce(MPI_IN_PLACE, has, 2, MPI_INT, MPI_LOR, m.comm);
  for (int k = 0; k < 3; ++k) {
    if (cellCounts_[k] == 0) continue;
    if (opts_.stress) file.writeCellField(kCellKinds[k], "stress", vm[k], {});
    if (k == 0 && has[0]) file.writeCellField("lines", "axial_force", axial, {});
    if (k > 0 && has[1]) {
      file.writeCellField(kCellKinds[k], "membrane_n11", n[k][0], {});
      file.writeCellField(kCellKinds[k], "membrane_n22", n[k][1], {});
      file.writeCellField(kCellKinds[k], "membrane_n12", n[k][2], {});
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

void StepResults::addCable(const double* q, const ElementKernel& kernel, double force, int element) {
  TensileSummary& t = tensile_;
  double stiffness = 0;
  t.slack += kernel.slack(q, &stiffness) ? 1 : 0;
  // ties: the lowest element, so that the summary does not depend on the partition
  if (t.cables == 0 || force > t.forceMax || (force == t.forceMax && element < t.forceMaxElement))
    t.forceMax = force, t.forceMaxElement = element;
  if (t.cables == 0 || force < t.forceMin || (force == t.forceMin && element < t.forceMinElement))
    t.forceMin = force, t.forceMinElement = element;
  ++t.cables;
}

void StepResults::addMembrane(const std::vector<double>& n, int element) {
  TensileSummary& t = tensile_;
  // principal resultants of [n11 n12; n12 n22]
  const double c = 0.5 * (n[0] + n[1]), r = std::hypot(0.5 * (n[0] - n[1]), n[2]);
  const double n1 = c + r, n2 = c - r;
  t.wrinkled += n2 <= 0.0 ? 1 : 0;
  if (t.membranes == 0 || n1 > t.n1Max || (n1 == t.n1Max && element < t.n1MaxElement)) t.n1Max = n1, t.n1MaxElement = element;
  if (t.membranes == 0 || n2 < t.n2Min || (n2 == t.n2Min && element < t.n2MinElement)) t.n2Min = n2, t.n2MinElement = element;
  ++t.membranes;
}

TensileSummary StepResults::tensileSummary() const {
  const MPI_Comm comm = asm_.mesh().comm;
  TensileSummary all = tensile_;
  long counts[4] = {tensile_.cables, tensile_.slack, tensile_.membranes, tensile_.wrinkled};
  MPI_Allreduce(MPI_IN_PLACE, counts, 4, MPI_LONG, MPI_SUM, comm);
  all.cables = counts[0], all.slack = counts[1], all.membranes = counts[2], all.wrinkled = counts[3];
  // extremes with their element: MAXLOC picks the lowest element among equal values
  struct Loc {
    double v;
    int e;
  };
  auto extreme = [&](bool any, double v, int e, bool largest, double* out, int* elem) {
    Loc mine{any ? (largest ? v : -v) : -std::numeric_limits<double>::infinity(), any ? e : std::numeric_limits<int>::max()},
        best{};
    MPI_Allreduce(&mine, &best, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm);
    *out = largest ? best.v : -best.v;
    *elem = best.e;
  };
  const bool c = tensile_.cables > 0, mb = tensile_.membranes > 0;
  extreme(c, tensile_.forceMax, tensile_.forceMaxElement, true, &all.forceMax, &all.forceMaxElement);
  extreme(c, tensile_.forceMin, tensile_.forceMinElement, false, &all.forceMin, &all.forceMinElement);
  extreme(mb, tensile_.n1Max, tensile_.n1MaxElement, true, &all.n1Max, &all.n1MaxElement);
  extreme(mb, tensile_.n2Min, tensile_.n2MinElement, false, &all.n2Min, &all.n2MinElement);
  return all;
}

NodeSummaryRow StepResults::mostMovingNode() const {
  const DistributedMesh& m = asm_.mesh();
  // the largest displacement; among equal ones the lowest node (MAXLOC)
  struct {
    double u;
    int node;
  } mine{anyMove_.u, anyMove_.row.node}, best{};
  if (anyMove_.u < 0) mine.node = std::numeric_limits<int>::max();
  MPI_Allreduce(&mine, &best, 1, MPI_DOUBLE_INT, MPI_MAXLOC, m.comm);
  int owner = anyMove_.u >= 0 && mine.node == best.node && anyMove_.u == best.u ? m.rank : m.size;
  MPI_Allreduce(MPI_IN_PLACE, &owner, 1, MPI_INT, MPI_MIN, m.comm);
  NodeSummaryRow row = anyMove_.row;
  if (owner < m.size && owner != 0) {
    if (m.rank == owner) MPI_Send(&row, sizeof(NodeSummaryRow), MPI_BYTE, 0, 8, m.comm);
    if (m.rank == 0) MPI_Recv(&row, sizeof(NodeSummaryRow), MPI_BYTE, owner, 8, m.comm, MPI_STATUS_IGNORE);
  }
  return owner < m.size ? row : NodeSummaryRow{};
}

std::vector<NodeSummaryRow> StepResults::summaryRows() const {
  const DistributedMesh& m = asm_.mesh();
  const int n = static_cast<int>(rows_.size());
  std::vector<int> counts(m.size), displs(m.size, 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, m.comm);
  std::vector<int> bytes(m.size);
  int total = 0;
  for (int r = 0; r < m.size; ++r) {
    bytes[r] = counts[r] * static_cast<int>(sizeof(NodeSummaryRow));
    displs[r] = total;
    total += bytes[r];
  }
  std::vector<NodeSummaryRow> all(m.rank == 0 ? total / sizeof(NodeSummaryRow) : 0);
  MPI_Gatherv(rows_.data(), n * static_cast<int>(sizeof(NodeSummaryRow)), MPI_BYTE, all.data(), bytes.data(),
              displs.data(), MPI_BYTE, 0, m.comm);
  // the node that moves most, when no load or support names it already
  struct {
    double u;
    int rank;
  } mine{maxMove_.u, m.rank}, best{};
  MPI_Allreduce(&mine, &best, 1, MPI_DOUBLE_INT, MPI_MAXLOC, m.comm);
  if (best.u > 0 && best.rank != 0 && m.rank == best.rank)
    MPI_Send(&maxMove_.row, sizeof(NodeSummaryRow), MPI_BYTE, 0, 7, m.comm);
  if (best.u > 0 && m.rank == 0) {
    NodeSummaryRow row = maxMove_.row;
    if (best.rank != 0) MPI_Recv(&row, sizeof(NodeSummaryRow), MPI_BYTE, best.rank, 7, m.comm, MPI_STATUS_IGNORE);
    bool present = false;
    for (const auto& r : all) present |= r.node == row.node;
    if (!present) all.push_back(row);
  }
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.node < b.node; });
  return all;
}

}  // namespace sinew
