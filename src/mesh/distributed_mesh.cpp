#include "mesh/distributed_mesh.hpp"

#include <metis.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "parallel/collective_error.hpp"

namespace sinew {
namespace {

std::string nodeField(int sceneNode, const char* field) {
  return npropsPath(sceneNode, field);
}

/// METIS k-way partition of the element dual graph, computed on rank 0 and broadcast.
std::vector<int> partitionElements(MPI_Comm comm, const FeMesh& fe, int nparts) {
  const int ne = static_cast<int>(fe.elements.size());
  std::vector<int> epart(ne, 0);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (nparts > 1 && rank == 0) {
    if (ne < nparts) {
      for (int e = 0; e < ne; ++e) epart[e] = e;
    } else {
      std::vector<idx_t> eptr(ne + 1, 0), eind;
      eind.reserve(2 * static_cast<size_t>(ne));
      for (int e = 0; e < ne; ++e) {
        for (int i = 0; i < fe.elements[e].numNodes; ++i) eind.push_back(fe.elements[e].nodes[i]);
        eptr[e + 1] = static_cast<idx_t>(eind.size());
      }
      idx_t nel = ne, nnod = static_cast<idx_t>(fe.X.size()), ncommon = 1, np = nparts, objval = 0;
      idx_t options[METIS_NOPTIONS];
      METIS_SetDefaultOptions(options);
      options[METIS_OPTION_SEED] = 1;  // deterministic partitions
      std::vector<idx_t> ep(ne), nptmp(nnod);
      const int status = METIS_PartMeshDual(&nel, &nnod, eptr.data(), eind.data(), nullptr, nullptr, &ncommon,
                                            &np, nullptr, options, &objval, ep.data(), nptmp.data());
      if (status != METIS_OK) throw std::runtime_error("METIS_PartMeshDual failed with status " + std::to_string(status));
      for (int e = 0; e < ne; ++e) epart[e] = static_cast<int>(ep[e]);
    }
  }
  if (nparts > 1) MPI_Bcast(epart.data(), ne, MPI_INT, 0, comm);
  return epart;
}

/// The functions of time among a node's nprops (null when it has none).
std::shared_ptr<const NodeTimeFunctions> nodeTimeFunctions(const NodeProps& p, int s, bool ancf) {
  if (!p.hasTimeFunctions()) return nullptr;
  auto f = std::make_shared<NodeTimeFunctions>();
  const std::string node = npropsPath(s, "");
  auto compile = [&](std::optional<Expression>& slot, const std::string& text, const std::string& field) {
    if (!text.empty()) slot = Expression::compile(text, node + field);
  };
  for (int k = 0; k < (ancf ? 2 : 3); ++k) {
    compile(f->load[k], p.force_t[k], indexedPath("force", static_cast<std::size_t>(k)));
    compile(f->prescribed[k], p.displ_t[k], std::string("displ_") + "xyz"[k]);
    if (!ancf) compile(f->load[3 + k], p.moment_t[k], indexedPath("moment", static_cast<std::size_t>(k)));
  }
  if (ancf) compile(f->load[4], p.moment_t[2], "moment");  // the torque about z acts on the slope
  compile(f->rotAngle, p.rot_t, "rot(1)");
  f->rotAxis = p.rot_axis;
  return f;
}

/// Supports, prescriptions, loads and inertia of one FE node from the scene's nprops.
void applyNodeProps(const Model& model, LocalNode& n) {
  n.ndof = dofSize(n.kind);
  n.status.fill(DofStatus::Free);
  if (n.sceneNode < 0) return;
  const auto it = model.nprops.find(n.sceneNode);
  if (it == model.nprops.end()) return;
  const NodeProps& p = it->second;
  const int s = n.sceneNode;
  auto fixDof = [&](int k) { n.status[k] = DofStatus::Fixed; };
  if (n.kind == NodeKind::Ancf2D) {
    if (p.fix) for (int k = 0; k < 4; ++k) fixDof(k);
    if (p.fix_pos) { fixDof(0); fixDof(1); }
    if (p.fix_x) fixDof(0);
    if (p.fix_y) fixDof(1);
    if (p.fix_z) throw SceneError(nodeField(s, "fix_z"), "a 2D ANCF node has no z coordinate");
    if (p.fix_coords)
      for (int k = 0; k < 4; ++k)
        if ((*p.fix_coords)[k]) fixDof(k);
    if (p.fix_orien) {
      // slope direction fixed, stretch free: one slope component for an axis-aligned slope
      if (std::abs(n.slope0[1]) < 1e-12) fixDof(3);
      else if (std::abs(n.slope0[0]) < 1e-12) fixDof(2);
      else throw SceneError(nodeField(s, "fix_orien"),
                            "node " + std::to_string(s + 1) + " has an oblique reference slope; use fix_coords");
    }
    for (int k = 0; k < 2; ++k) {
      if (p.displ[k] || p.displ_initial[k]) {
        n.status[k] = DofStatus::Prescribed;
        n.prescribed[k] = p.displ[k].value_or(0.0);
        n.prescribedInitial[k] = p.displ_initial[k].value_or(0.0);
      }
    }
    if (p.displ[2] || p.displ_initial[2]) throw SceneError(nodeField(s, "displ_z"), "a 2D ANCF node has no z coordinate");
    if (p.rot || p.rot_initial) throw SceneError(nodeField(s, "rot"), "prescribed rotations need a beam node");
    n.load = {p.force[0], p.force[1], 0, 0, 0, 0};
    n.loadInitial = {p.force_initial[0], p.force_initial[1], 0, 0, 0, 0};
    n.load[4] = p.moment[2];  // torque about z, acts on the slope (handled by the assembler)
    n.loadInitial[4] = p.moment_initial[2];
    n.mass = p.mass;
    n.timeFn = nodeTimeFunctions(p, s, true);
    return;
  }
  const bool frame = n.kind == NodeKind::Frame6;
  if (p.fix) for (int k = 0; k < n.ndof; ++k) fixDof(k);
  if (p.fix_pos) for (int k = 0; k < 3; ++k) fixDof(k);
  if (p.fix_x) fixDof(0);
  if (p.fix_y) fixDof(1);
  if (p.fix_z) fixDof(2);
  for (int k = 0; k < 3; ++k) {
    if (p.displ[k] || p.displ_initial[k]) {
      n.status[k] = DofStatus::Prescribed;
      n.prescribed[k] = p.displ[k].value_or(0.0);
      n.prescribedInitial[k] = p.displ_initial[k].value_or(0.0);
    }
  }
  const bool anyMoment =
      norm(p.moment) > 0 || norm(p.moment_initial) > 0 || !p.moment_t[0].empty() || !p.moment_t[1].empty() || !p.moment_t[2].empty();
  if (!frame) {
    if (p.fix_orien || p.rot || p.rot_initial || anyMoment || p.mominertia != std::array<double, 6>{})
      throw SceneError(nodeField(s, p.fix_orien ? "fix_orien" : (anyMoment ? "moment" : "rot")),
                       "node " + std::to_string(s + 1) + " has no rotations (only cables/membranes meet there)");
  } else {
    if (p.fix_orien) for (int k = 3; k < 6; ++k) fixDof(k);
    if (p.rot || p.rot_initial) {
      n.rotationPrescribed = true;
      n.rot = p.rot.value_or(Vec3{});
      n.rotInitial = p.rot_initial.value_or(Vec3{});
      for (int k = 3; k < 6; ++k) n.status[k] = DofStatus::Prescribed;
    } else if (n.status[3] == DofStatus::Fixed) {
      n.rotationPrescribed = true;  // fixed orientation: R = I
    }
    if (n.status[3] != n.status[4] || n.status[3] != n.status[5])
      throw SceneError(nodeField(s, "fix_orien"), "rotations are fixed all together");
  }
  for (int k = 0; k < 3; ++k) {
    n.load[k] = p.force[k];
    n.loadInitial[k] = p.force_initial[k];
    if (frame) {
      n.load[3 + k] = p.moment[k];
      n.loadInitial[3 + k] = p.moment_initial[k];
    }
  }
  n.mass = p.mass;
  n.mominertia = p.mominertia;
  n.timeFn = nodeTimeFunctions(p, s, false);
}

/// Records the first kernel that could not be built on this rank (scene errors and invalid element
/// data: a SceneError, exit 2; anything else is rethrown as std::runtime_error, exit 1 like any
/// other set-up error).
void kernelFailure(const std::exception& ex, const FeMesh& fe, int e, RunFailure* failure, long* failedElement) {
  if (*failure) return;
  const bool sceneError = dynamic_cast<const SceneError*>(&ex) || dynamic_cast<const std::invalid_argument*>(&ex);
  failure->exitCode = sceneError ? 2 : kExitSolverError;
  failure->message = std::string(ex.what()) + " (element " + std::to_string(fe.elements[e].sceneElement + 1) + ")";
  *failedElement = e;
}

}  // namespace

int rigidModeCount(const Model& model, int e) {
  if (elementTypeOf(model, e) != ElementType::Beam) return 0;
  const int set = model.elementSet[e];
  std::array<bool, 6> released{};
  if (auto it = model.opt.rls.find(e); it != model.opt.rls.end())
    for (int m : it->second) released[m - 1] = true;
  int count = 0;
  for (int i = 0; i < 6; ++i)
    if (!released[i] && (set < 0 || !model.eprops[set].get<BeamProperties>().flex[i])) ++count;
  return count;
}

DistributedMesh distributeMesh(MPI_Comm comm, const Model& model, const FeMesh& fe, const ElementKernels& kernels) {
  DistributedMesh dm;
  dm.comm = comm;
  dm.setLoads = kernels.setLoads;
  MPI_Comm_rank(comm, &dm.rank);
  MPI_Comm_size(comm, &dm.size);
  const int ne = static_cast<int>(fe.elements.size());
  const int nn = static_cast<int>(fe.X.size());
  dm.numSceneNodes = fe.numSceneNodes;
  dm.numSceneElements = static_cast<long>(model.elements.size());
  dm.numFeNodes = nn;
  dm.dimension = model.dimension;

  const std::vector<int> epart = partitionElements(comm, fe, dm.size);
  // Owner of a node: one of the ranks whose elements meet there. Interface nodes alternate between
  // the lowest and the highest such rank (by node id), so both sides of an interface own about
  // half of it and receive about half of the off-process matrix entries.
  std::vector<int> owner(nn, dm.size), highest(nn, -1);
  for (int e = 0; e < ne; ++e)
    for (int i = 0; i < fe.elements[e].numNodes; ++i) {
      const int n = fe.elements[e].nodes[i];
      owner[n] = std::min(owner[n], epart[e]);
      highest[n] = std::max(highest[n], epart[e]);
    }
  for (int n = 0; n < nn; ++n)
    if (highest[n] >= 0 && (n & 1)) owner[n] = highest[n];
  // a trailing node no element connects (SPACAR Light allows them): rank 0 owns it, held fixed below
  for (int n = 0; n < nn; ++n)
    if (highest[n] < 0) owner[n] = 0;

  // Constraint status of every node (set-up only), then a global numbering: per rank, its owned
  // nodes' free DOFs in ascending node order, then its elements' multipliers.
  std::vector<LocalNode> all(nn);
  for (int n = 0; n < nn; ++n) {
    LocalNode& ln = all[n];
    ln.gid = n;
    ln.sceneNode = n < fe.numSceneNodes ? n : -1;
    ln.kind = fe.kind[n];
    ln.X0 = fe.X[n];
    ln.slope0 = fe.slope[n];
    if (n < static_cast<int>(fe.connected.size()) && !fe.connected[n]) {
      ln.ndof = dofSize(ln.kind);  // unconnected: no stiffness, so no unknowns (its supports, if any, change nothing)
      ln.status.fill(DofStatus::Fixed);
    } else {
      applyNodeProps(model, ln);
    }
  }
  std::vector<long> freeCount(dm.size, 0), fullCount(dm.size, 0), multCount(dm.size, 0);
  for (int n = 0; n < nn; ++n) {
    for (int k = 0; k < all[n].ndof; ++k)
      if (all[n].status[k] == DofStatus::Free) ++freeCount[owner[n]];
    fullCount[owner[n]] += all[n].ndof;
  }
  std::vector<int> elemMult(ne);
  for (int e = 0; e < ne; ++e) {
    elemMult[e] = rigidModeCount(model, fe.elements[e].sceneElement);
    multCount[epart[e]] += elemMult[e];
  }
  std::vector<long> unkOffset(dm.size + 1, 0), fullOffset(dm.size + 1, 0);
  for (int r = 0; r < dm.size; ++r) {
    unkOffset[r + 1] = unkOffset[r] + freeCount[r] + multCount[r];
    fullOffset[r + 1] = fullOffset[r] + fullCount[r];
  }
  dm.numGlobalUnknowns = unkOffset[dm.size];
  dm.numGlobalFull = fullOffset[dm.size];
  dm.firstOwnedUnknown = unkOffset[dm.rank];
  dm.numOwnedUnknowns = static_cast<int>(unkOffset[dm.rank + 1] - unkOffset[dm.rank]);
  dm.firstOwnedFull = fullOffset[dm.rank];
  dm.numOwnedFull = static_cast<int>(fullCount[dm.rank]);

  std::vector<long> nodeUnk(static_cast<size_t>(nn) * 6, -1), nodeFull(static_cast<size_t>(nn) * 6, -1);
  std::vector<long> nextUnk(unkOffset.begin(), unkOffset.end() - 1), nextFull(fullOffset.begin(), fullOffset.end() - 1);
  for (int n = 0; n < nn; ++n) {
    const int r = owner[n];
    for (int k = 0; k < all[n].ndof; ++k) {
      nodeFull[6 * n + k] = nextFull[r]++;
      if (all[n].status[k] == DofStatus::Free) nodeUnk[6 * n + k] = nextUnk[r]++;
    }
  }
  std::vector<long> elemMultGlobal(ne, -1);
  for (int e = 0; e < ne; ++e)
    if (elemMult[e] > 0) {
      elemMultGlobal[e] = nextUnk[epart[e]];
      nextUnk[epart[e]] += elemMult[e];
    }

  // Local nodes: owned (ascending), then ghosts (ascending).
  std::vector<int> localOf(nn, -1);
  std::vector<char> touched(nn, 0);
  for (int e = 0; e < ne; ++e)
    if (epart[e] == dm.rank)
      for (int i = 0; i < fe.elements[e].numNodes; ++i) touched[fe.elements[e].nodes[i]] = 1;
  for (int pass = 0; pass < 2; ++pass)
    for (int n = 0; n < nn; ++n) {
      const bool mine = owner[n] == dm.rank;
      if ((pass == 0 && mine) || (pass == 1 && !mine && touched[n])) {
        localOf[n] = static_cast<int>(dm.nodes.size());
        dm.nodes.push_back(all[n]);
      }
    }
  dm.numOwnedNodes = 0;
  for (int n = 0; n < nn; ++n) dm.numOwnedNodes += owner[n] == dm.rank;

  // Local forms: owned unknowns map to [0, numOwnedUnknowns); ghosts follow in node order.
  for (LocalNode& ln : dm.nodes) {
    const bool mine = owner[ln.gid] == dm.rank;
    for (int k = 0; k < 6; ++k) {
      ln.dof[k] = -1;
      ln.fullDof[k] = -1;
    }
    for (int k = 0; k < ln.ndof; ++k) {
      const long gu = nodeUnk[6 * ln.gid + k], gf = nodeFull[6 * ln.gid + k];
      if (mine) {
        if (gu >= 0) ln.dof[k] = static_cast<int>(gu - dm.firstOwnedUnknown);
        ln.fullDof[k] = static_cast<int>(gf - dm.firstOwnedFull);
      } else {
        if (gu >= 0) {
          ln.dof[k] = dm.numOwnedUnknowns + static_cast<int>(dm.ghostUnknowns.size());
          dm.ghostUnknowns.push_back(gu);
        }
        ln.fullDof[k] = dm.numOwnedFull + static_cast<int>(dm.ghostFull.size());
        dm.ghostFull.push_back(gf);
      }
    }
    if (ln.kind == NodeKind::Frame6) dm.anyRotations = true;
    if (ln.kind == NodeKind::Ancf2D) dm.anyAncf = true;
  }
  RunFailure failure;
  long failedElement = -1;
  for (int e = 0; e < ne; ++e) {
    if (epart[e] != dm.rank) continue;
    LocalElement le;
    le.feIndex = e;
    le.sceneElement = fe.elements[e].sceneElement;
    le.subIndex = e - fe.sceneElementFirst[le.sceneElement];
    le.numSub = fe.sceneElementCount[le.sceneElement];
    le.set = fe.elements[e].set;
    le.numNodes = fe.elements[e].numNodes;
    for (int i = 0; i < le.numNodes; ++i) le.node[i] = localOf[fe.elements[e].nodes[i]];
    if (elemMult[e] > 0) le.firstMultiplier = static_cast<int>(elemMultGlobal[e] - dm.firstOwnedUnknown);
    try {
      le.kernel = kernels.kernelOf(model, fe, e);
    } catch (const std::exception& ex) {
      kernelFailure(ex, fe, e, &failure, &failedElement);
      continue;
    }
    if (le.kernel->numConstraints() != elemMult[e])
      throw std::logic_error("kernel constraint count differs from the DOF numbering");
    dm.elements.push_back(std::move(le));
  }
  // A kernel that cannot be built on one rank ends the set-up on every rank, with the message of the
  // lowest failing element (the same on any number of ranks; it was a SEGV on 2 ranks, issue 13 item 1).
  if (const RunFailure f = agreeOnFailure(comm, failure, failedElement)) {
    if (f.exitCode == 2) throw SceneError("", f.message);
    throw std::runtime_error(f.message);
  }
  int flags[2] = {dm.anyRotations, dm.anyAncf};
  MPI_Allreduce(MPI_IN_PLACE, flags, 2, MPI_INT, MPI_LOR, comm);
  dm.anyRotations = flags[0];
  dm.anyAncf = flags[1];
  return dm;
}

}  // namespace sinew
