#include "analysis/constraint_check.hpp"
#include "analysis/stiffness_spread.hpp"
#include "solvers/solver_defaults.hpp"

#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace sinew {
namespace {

const char* kDofNames[6] = {"translation x", "translation y", "translation z", "rotation x", "rotation y", "rotation z"};

/// Rigid deformation modes (1-based) of a beam element, in multiplier order (as BeamCorotational).
std::vector<int> rigidModes(const Model& model, const LocalElement& el) {
  std::vector<int> modes;
  if (el.set >= 0 && model.eprops[el.set].type() != ElementType::Beam) return modes;
  std::set<int> released;
  if (auto it = model.opt.rls.find(el.sceneElement); it != model.opt.rls.end()) released.insert(it->second.begin(), it->second.end());
  for (int i = 1; i <= 6; ++i)
    if (!released.count(i) && (el.set < 0 || !model.eprops[el.set].get<BeamProperties>().flex[i - 1])) modes.push_back(i);
  return modes;
}

std::string joinInts(const std::vector<int>& v) {
  std::ostringstream s;
  for (size_t i = 0; i < v.size(); ++i) s << (i ? ", " : "") << v[i];
  return s.str();
}

/// Gathers every rank's lines on rank 0 (in rank order).
std::string gatherText(MPI_Comm comm, const std::string& mine) {
  int rank, size;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  int n = static_cast<int>(mine.size());
  std::vector<int> counts(size), displs(size, 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  int total = 0;
  for (int r = 0; r < size; ++r) {
    displs[r] = total;
    total += counts[r];
  }
  std::string all(rank == 0 ? total : 0, '\0');
  MPI_Gatherv(mine.data(), n, MPI_CHAR, all.data(), counts.data(), displs.data(), MPI_CHAR, 0, comm);
  return all;
}

/// "weight<TAB>text" lines -> texts sorted by decreasing weight (at most maxItems, then "...").
std::string ranked(const std::string& lines, size_t maxItems) {
  std::map<std::string, double> best;  // the same item may come from several null vectors
  std::istringstream in(lines);
  std::string line;
  while (std::getline(in, line)) {
    const auto tab = line.find('\t');
    if (tab == std::string::npos) continue;
    double& w = best[line.substr(tab + 1)];
    w = std::max(w, std::stod(line.substr(0, tab)));
  }
  std::vector<std::pair<double, std::string>> items;
  for (const auto& [text, w] : best) items.emplace_back(w, text);
  std::stable_sort(items.begin(), items.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::ostringstream s;
  for (size_t i = 0; i < items.size() && i < maxItems; ++i) s << (i ? "; " : "") << items[i].second;
  if (items.size() > maxItems) s << "; ... (" << items.size() - maxItems << " more)";
  return s.str();
}

/// "weight<TAB>element<TAB>mode" lines -> "element 3: modes 1, 2; ..." (elements by decreasing weight).
std::string groupedModes(const std::string& lines, size_t maxItems) {
  std::map<int, std::pair<double, std::set<int>>> byElement;
  std::istringstream in(lines);
  double w;
  int e, mode;
  while (in >> w >> e >> mode) {
    auto& entry = byElement[e];
    entry.first = std::max(entry.first, w);
    entry.second.insert(mode);
  }
  std::ostringstream s;
  for (const auto& [el, entry] : byElement) {
    const std::vector<int> modes(entry.second.begin(), entry.second.end());
    s << entry.first << "\telement " << el << ": mode" << (modes.size() > 1 ? "s " : " ") << joinInts(modes) << '\n';
  }
  return ranked(s.str(), maxItems);
}

/// Guard vectors iterated beside the -constraint_check_vectors asked for: the subspace then holds the
/// null space and the next directions converged, so its Ritz values (below) do not depend on the
/// random start, i.e. on the rank count.
constexpr PetscInt kGuardVectors = 2;

/// A mechanism in a model whose element stiffnesses span more than this / tol is blamed on the spread:
/// a direction resisted only by elements 1/ratio as stiff as the diagonal of its rows looks null
/// (||J v|| <= tol ||D v||) once 1/ratio nears tol.
constexpr double kUnresolvedSpread = 0.1;

/// Eigenvalues (ascending, *w) and eigenvectors (columns of the row-major n x n *V) of the symmetric
/// row-major n x n matrix A, by cyclic Jacobi rotations (n is a handful: the constraint check's block).
void symmetricEigen(int n, std::vector<double> A, std::vector<double>* w, std::vector<double>* V) {
  const auto at = [n](std::vector<double>& M, int i, int j) -> double& { return M[static_cast<size_t>(i * n + j)]; };
  V->assign(static_cast<size_t>(n * n), 0.0);
  for (int i = 0; i < n; ++i) at(*V, i, i) = 1.0;
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0.0, diag = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) (i == j ? diag : off) += at(A, i, j) * at(A, i, j);
    if (off <= 1e-32 * diag || off == 0.0) break;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) {
        if (at(A, p, q) == 0.0) continue;
        // rotation (c, s) that zeroes A_pq: t = tan, theta = (A_qq - A_pp) / (2 A_pq)
        const double theta = (at(A, q, q) - at(A, p, p)) / (2.0 * at(A, p, q));
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < n; ++k) {  // A <- A G (columns p, q)
          const double akp = at(A, k, p), akq = at(A, k, q);
          at(A, k, p) = c * akp - s * akq;
          at(A, k, q) = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) {  // A <- G^T A (rows p, q)
          const double apk = at(A, p, k), aqk = at(A, q, k);
          at(A, p, k) = c * apk - s * aqk;
          at(A, q, k) = s * apk + c * aqk;
        }
        for (int k = 0; k < n; ++k) {  // V <- V G
          const double vkp = at(*V, k, p), vkq = at(*V, k, q);
          at(*V, k, p) = c * vkp - s * vkq;
          at(*V, k, q) = s * vkp + c * vkq;
        }
      }
  }
  std::vector<int> order(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) order[static_cast<size_t>(i)] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return at(A, a, a) < at(A, b, b); });
  std::vector<double> sortedV(V->size());
  w->resize(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const int o = order[static_cast<size_t>(i)];
    (*w)[static_cast<size_t>(i)] = at(A, o, o);
    for (int k = 0; k < n; ++k) at(sortedV, k, i) = at(*V, k, o);
  }
  *V = std::move(sortedV);
}

/// The null directions of span X: the v = D^-1 q, q in span(D X), that minimise ||J v|| / ||D v||
/// (Rayleigh-Ritz for the singular values of J D^-1 on span(D X): Q orthonormal basis of D X,
/// C = (J D^-1 Q)^T (J D^-1 Q), C c = mu c); null where mu <= tol^2. A property of the subspace,
/// not of its basis: the same directions and count whatever vectors the iteration ended with.
/// Returns them (new vectors, unit length) in *dirs, most null first.
PetscErrorCode nullDirections(Mat J, Vec D, const std::vector<Vec>& X, PetscReal tol, std::vector<Vec>* dirs) {
  PetscFunctionBeginUser;
  std::vector<Vec> Q;
  for (Vec x : X) {  // Q = orth(D X), Gram-Schmidt twice; a dependent column is dropped
    Vec q;
    PetscCall(VecDuplicate(x, &q));
    PetscCall(VecPointwiseMult(q, D, x));
    PetscReal n0, n;
    PetscCall(VecNorm(q, NORM_2, &n0));
    for (int pass = 0; pass < 2; ++pass)
      for (Vec qi : Q) {
        PetscScalar c;
        PetscCall(VecDot(q, qi, &c));
        PetscCall(VecAXPY(q, -c, qi));
      }
    PetscCall(VecNormalize(q, &n));
    if (n > 1e-10 * n0) Q.push_back(q);
    else PetscCall(VecDestroy(&q));
  }
  const PetscInt b = static_cast<PetscInt>(Q.size());
  std::vector<Vec> Z(Q.size());
  for (PetscInt j = 0; j < b; ++j) {  // Z = J D^-1 Q
    Vec w;
    PetscCall(VecDuplicate(Q[j], &w));
    PetscCall(VecDuplicate(Q[j], &Z[j]));
    PetscCall(VecPointwiseDivide(w, Q[j], D));
    PetscCall(MatMult(J, w, Z[j]));
    PetscCall(VecDestroy(&w));
  }
  std::vector<double> C(static_cast<size_t>(b * b)), mu;
  for (PetscInt j = 0; j < b; ++j) PetscCall(VecMDot(Z[j], b, Z.data(), &C[static_cast<size_t>(j * b)]));
  std::vector<double> V;
  symmetricEigen(static_cast<int>(b), C, &mu, &V);  // every rank computes the same
  for (PetscInt i = 0; i < b; ++i) {
    if (!(mu[static_cast<size_t>(i)] <= tol * tol)) break;
    Vec v;  // v = D^-1 Q c_i (column i of V holds c_i)
    PetscCall(VecDuplicate(Q[0], &v));
    PetscCall(VecSet(v, 0.0));
    for (PetscInt j = 0; j < b; ++j) PetscCall(VecAXPY(v, V[static_cast<size_t>(j * b + i)], Q[static_cast<size_t>(j)]));
    PetscCall(VecPointwiseDivide(v, v, D));
    PetscReal n;
    PetscCall(VecNormalize(v, &n));
    dirs->push_back(v);
  }
  for (auto& z : Z) PetscCall(VecDestroy(&z));
  for (auto& q : Q) PetscCall(VecDestroy(&q));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

PetscErrorCode checkConstraints(
Assembler& assembler, const Model& model, Vec U, const LoadState& ls,
                                const ModelCheckSettings& settings, int denseMaxUnknowns, ConstraintReport* report,
                                Mat tangent) {
  PetscFunctionBeginUser;
  *report = ConstraintReport{};
  DistributedMesh& m = assembler.mesh();
  MPI_Comm comm = m.comm;
  if (m.numGlobalUnknowns == 0) PetscFunctionReturn(PETSC_SUCCESS);
  const PetscReal tol = settings.tol;
  const PetscInt nvec = std::clamp<PetscInt>(settings.vectors, 1, static_cast<PetscInt>(m.numGlobalUnknowns));

  Mat J = tangent, As;
  if (!tangent) {
    PetscCall(assembler.createMatrix(&J));
    PetscCall(assembler.jacobian(U, ls, J));
  }
  // Which owned rows are node DOFs (the rest are multipliers).
  const int nloc = m.numOwnedUnknowns;
  std::vector<char> isNode(nloc, 0);
  for (int i = 0; i < m.numOwnedNodes; ++i)
    for (int k = 0; k < m.nodes[i].ndof; ++k)
      if (m.nodes[i].dof[k] >= 0) isNode[m.nodes[i].dof[k]] = 1;
  // D: |J_ii| on node rows (the mean where 0), -||G_i||^2 / mean on multiplier rows.
  Vec D, Dg;
  PetscCall(assembler.createVector(&Dg));
  PetscCall(VecDuplicate(Dg, &D));
  PetscCall(MatGetDiagonal(J, D));
  PetscInt rStart;
  PetscCall(MatGetOwnershipRange(J, &rStart, nullptr));
  {
    PetscScalar* d;
    PetscCall(VecGetArray(D, &d));
    double sum[2] = {0, 0};
    for (int i = 0; i < nloc; ++i)
      if (isNode[i] && std::abs(d[i]) > 0) {
        sum[0] += std::abs(d[i]);
        sum[1] += 1;
      }
    MPI_Allreduce(MPI_IN_PLACE, sum, 2, MPI_DOUBLE, MPI_SUM, comm);
    const double mean = sum[1] > 0 ? sum[0] / sum[1] : 1.0;
    for (int i = 0; i < nloc; ++i) {
      if (isNode[i]) {
        // a diagonal at round-off level (below 1e-13 of the mean: an unstressed flat membrane's normal
        // stiffness is E t eps) is scaled like a zero one; else that row's D is noise and whether its
        // null direction is found depends on the partition
        d[i] = std::abs(d[i]) > 1e-13 * mean ? std::abs(d[i]) : mean;
      } else {
        PetscInt ncols;
        const PetscScalar* vals;
        PetscCall(MatGetRow(J, rStart + i, &ncols, nullptr, &vals));
        double g2 = 0;
        for (PetscInt c = 0; c < ncols; ++c) g2 += vals[c] * vals[c];
        PetscCall(MatRestoreRow(J, rStart + i, &ncols, nullptr, &vals));
        d[i] = -(g2 > 0 ? g2 / mean : mean);
      }
    }
    PetscCall(VecRestoreArray(D, &d));
  }
  // (J + sigma D) factored once (MUMPS, or dense LU for a small one-process model); sigma is relative since D carries the scale.
  const double sigma = 1e-8;
  PetscCall(MatDuplicate(J, MAT_COPY_VALUES, &As));
  {
    Vec sD;
    PetscCall(VecDuplicate(D, &sD));
    PetscCall(VecCopy(D, sD));
    PetscCall(VecScale(sD, sigma));
    PetscCall(MatDiagonalSet(As, sD, ADD_VALUES));
    PetscCall(VecDestroy(&sD));
  }
  KSP ksp;
  PC pc;
  PetscCall(KSPCreate(comm, &ksp));
  PetscCall(KSPSetOptionsPrefix(ksp, "constraint_check_"));
  PetscCall(KSPSetOperators(ksp, As, As));
  PetscCall(useDirectSolver(ksp, m, denseMaxUnknowns));
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(KSPSetUp(ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PCFailedReason why = PC_NOERROR;
  PetscCall(PCGetFailedReason(pc, &why));
  int failed = why != PC_NOERROR;
  MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_LOR, comm);
  std::ostringstream msg;
  if (failed) {
    report->singular = true;
    msg << "error: the tangent stiffness cannot be factored even after a diagonal shift; the model is singular "
           "(check supports, rigid modes and releases)\n";
    report->message = msg.str();
  }

  // Subspace inverse iteration: X <- (J + sigma D)^{-1} D X, orthonormalized, with guard vectors
  // beyond the nvec directions asked for; then the null directions of the converged subspace.
  const PetscInt block = std::min<PetscInt>(nvec + kGuardVectors, static_cast<PetscInt>(m.numGlobalUnknowns));
  std::vector<Vec> X(block), nullDirs;
  Vec t, r;
  PetscCall(VecDuplicate(D, &t));
  PetscCall(VecDuplicate(D, &r));
  if (!failed) {
    PetscRandom rnd;
    PetscCall(PetscRandomCreate(comm, &rnd));
    PetscCall(PetscRandomSetSeed(rnd, 7));
    PetscCall(PetscRandomSeed(rnd));
    for (auto& x : X) {
      PetscCall(VecDuplicate(D, &x));
      PetscCall(VecSetRandom(x, rnd));
    }
    PetscCall(PetscRandomDestroy(&rnd));
    for (int it = 0; it < 4; ++it) {
      for (PetscInt j = 0; j < block; ++j) {
        PetscCall(VecPointwiseMult(t, D, X[j]));
        PetscCall(KSPSolve(ksp, t, X[j]));
        for (PetscInt i = 0; i < j; ++i) {  // modified Gram-Schmidt
          PetscScalar c;
          PetscCall(VecDot(X[j], X[i], &c));
          PetscCall(VecAXPY(X[j], -c, X[i]));
        }
        PetscReal nrm;
        PetscCall(VecNormalize(X[j], &nrm));
      }
    }
    PetscCall(nullDirections(J, D, X, tol, &nullDirs));
  }

  // Null directions: min ||J v|| / ||D v|| <= tol over span X. Name their DOFs/multipliers.
  std::ostringstream nodeLines, multLines, rlsLines;
  std::set<int> rlsNamed;
  int mech = 0, redund = 0;
  for (Vec vj : nullDirs) {
    // weighted components sqrt|D_i| |v_i|; split into node and multiplier parts
    const PetscScalar *v, *d;
    PetscCall(VecGetArrayRead(vj, &v));
    PetscCall(VecGetArrayRead(D, &d));
    double part[2] = {0, 0}, mx[2] = {0, 0};
    for (int i = 0; i < nloc; ++i) {
      const double w = std::sqrt(std::abs(d[i])) * std::abs(v[i]);
      part[isNode[i] ? 0 : 1] += w * w;
      mx[isNode[i] ? 0 : 1] = std::max(mx[isNode[i] ? 0 : 1], w);
    }
    MPI_Allreduce(MPI_IN_PLACE, part, 2, MPI_DOUBLE, MPI_SUM, comm);
    MPI_Allreduce(MPI_IN_PLACE, mx, 2, MPI_DOUBLE, MPI_MAX, comm);
    const bool isMech = part[0] >= 1e-6 * (part[0] + part[1]);
    const bool isRedund = part[1] >= 1e-6 * (part[0] + part[1]);
    mech += isMech;
    redund += isRedund;
    std::ostringstream mine;
    if (isMech) {
      for (int i = 0; i < m.numOwnedNodes; ++i) {
        const LocalNode& n = m.nodes[i];
        for (int k = 0; k < n.ndof; ++k) {
          if (n.dof[k] < 0) continue;
          const double w = std::sqrt(std::abs(d[n.dof[k]])) * std::abs(v[n.dof[k]]);
          if (w < 0.2 * mx[0]) continue;
          mine << w / mx[0] << '\t';
          if (n.sceneNode >= 0) mine << "node " << n.sceneNode + 1 << ' ' << kDofNames[k] << '\n';
          else mine << "FE node " << n.gid + 1 << " (inside a split element) " << kDofNames[k] << '\n';
        }
      }
    }
    if (isRedund) {
      for (const LocalElement& el : m.elements) {
        if (el.firstMultiplier < 0) continue;
        const auto modes = rigidModes(model, el);
        for (size_t c = 0; c < modes.size(); ++c) {
          const int i = el.firstMultiplier + static_cast<int>(c);
          const double w = std::sqrt(std::abs(d[i])) * std::abs(v[i]);
          if (w >= 0.05 * mx[1]) multLines << w / mx[1] << '\t' << el.sceneElement + 1 << '\t' << modes[c] << '\n';
        }
      }
    }
    PetscCall(VecRestoreArrayRead(D, &d));
    PetscCall(VecRestoreArrayRead(vj, &v));
    nodeLines << mine.str();
    if (isMech) {
      // releases of the elements touching the moving nodes (ghost values needed)
      PetscCall(VecCopy(vj, Dg));
      PetscCall(VecGhostUpdateBegin(Dg, INSERT_VALUES, SCATTER_FORWARD));
      PetscCall(VecGhostUpdateEnd(Dg, INSERT_VALUES, SCATTER_FORWARD));
      Vec gl;
      const PetscScalar* g;
      PetscCall(VecGhostGetLocalForm(Dg, &gl));
      PetscCall(VecGetArrayRead(gl, &g));
      double gmax = 0;
      for (int i = 0; i < nloc; ++i)
        if (isNode[i]) gmax = std::max(gmax, std::abs(g[i]));
      MPI_Allreduce(MPI_IN_PLACE, &gmax, 1, MPI_DOUBLE, MPI_MAX, comm);
      for (const LocalElement& el : m.elements) {
        const auto it = model.opt.rls.find(el.sceneElement);
        if (it == model.opt.rls.end() || rlsNamed.count(el.sceneElement)) continue;
        bool moves = false;
        for (int a = 0; a < el.numNodes; ++a) {
          const LocalNode& n = m.nodes[el.node[a]];
          for (int k = 0; k < n.ndof; ++k) moves |= n.dof[k] >= 0 && std::abs(g[n.dof[k]]) >= 0.05 * gmax;
        }
        if (!moves) continue;
        rlsNamed.insert(el.sceneElement);
        rlsLines << 1.0 << "\telement " << el.sceneElement + 1 << " (released modes " << joinInts(it->second) << ")\n";
      }
      PetscCall(VecRestoreArrayRead(gl, &g));
      PetscCall(VecGhostRestoreLocalForm(Dg, &gl));
    }
  }
  const std::string nodesAll = gatherText(comm, nodeLines.str());
  const std::string multAll = gatherText(comm, multLines.str());
  std::string rlsAll = gatherText(comm, rlsLines.str());
  if (m.rank == 0 && !rlsAll.empty()) {  // the same element may be named by several ranks' ghosts
    std::istringstream in(rlsAll);
    std::set<std::string> seen;
    std::string line, uniq;
    while (std::getline(in, line))
      if (seen.insert(line).second) uniq += line + "\n";
    rlsAll = uniq;
  }
  StiffnessSpread spread;
  if (mech) PetscCall(stiffnessSpread(assembler, U, ls, &spread));
  if (mech || redund) {
    report->singular = true;
    report->mechanisms = mech;
    report->redundant = redund;
    if (mech) {
      msg << "error: the model is a mechanism (under-constrained): " << mech << (mech == block ? " or more" : "") << " free motion" << (mech > 1 ? "s" : "")
          << " with zero stiffness\n  moving: " << ranked(nodesAll, 12) << "\n";
      if (!rlsAll.empty()) msg << "  released modes nearby: " << ranked(rlsAll, 8) << "\n";
      const bool spreadCause = spread.ratio() * tol >= kUnresolvedSpread;
      if (spreadCause) {
        std::ostringstream ratio;
        ratio << std::setprecision(2) << spread.ratio() << " times stiffer than element " << spread.softest + 1
              << " (largest vs smallest translational diagonal of the element tangents, EA/L, 12 EI/L^3), near or beyond the 1/tol = " << 1.0 / tol;
        msg << "  likely cause: the element stiffnesses, not the supports: element " << spread.stiffest + 1 << " is "
            << ratio.str() << " within which the check (-constraint_check_tol) tells the softer elements' stiffness "
            << "from the stiffest one's round-off (double precision keeps 16 digits)\n"
            << "  fix: make element " << spread.stiffest + 1 << " rigid (an element in no eprops set, or flex: []) instead "
            << "of giving it a huge stiffness, or bring the ratio below " << kUnresolvedSpread / tol << "\n";
      }
      msg << (spreadCause ? "  if the model does move freely: " : "  fix: ")
          << "add a support (nprops fix / fix_pos / fix_orien / fix_x..z), make a deformation mode flexible "
             "(eprops flex), or release fewer modes (opt.rls)\n";
    }
    if (redund) {
      msg << "error: the model is over-constrained: " << redund << (redund == block ? " or more" : "")
          << " redundant rigid-mode constraint" << (redund > 1 ? "s" : "")
          << " (dependent rows of the constraint Jacobian)\n  redundant among: " << groupedModes(multAll, 12)
          << " (over-constrained)\n"
          << "  fix: release one of these modes (opt.rls: {element: [modes]}) or make it flexible (eprops flex)\n";
    }
    report->message = msg.str();
  }
  for (auto& x : X) PetscCall(VecDestroy(&x));
  for (auto& x : nullDirs) PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&t));
  PetscCall(VecDestroy(&r));
  PetscCall(VecDestroy(&D));
  PetscCall(VecDestroy(&Dg));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(MatDestroy(&As));
  if (!tangent) PetscCall(MatDestroy(&J));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
