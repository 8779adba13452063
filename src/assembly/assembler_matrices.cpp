// Assembler matrix structures: the preallocation of the Jacobian (nonzeros per owned row from the
// element and multiplier couplings), the matrix with every element block and the diagonal inserted
// as zeros, and the COO pattern of the element blocks for COO assembly (Assembler::jacobian).
#include <algorithm>
#include <array>

#include "assembly/aij_pattern.hpp"
#include "assembly/assembler.hpp"

namespace sinew {

// Nonzeros per owned row, once per assembler: through the local elements, every local node couples
// with its neighbour nodes (all their free DOFs) and the multipliers of its elements; multiplier
// rows with their element's DOFs and multipliers. Counts of ghost rows are added to their owners,
// so rows on partition interfaces may be counted a little high (never low).
PetscErrorCode Assembler::preallocationCounts() const {
  PetscFunctionBeginUser;
  if (countsReady_) PetscFunctionReturn(PETSC_SUCCESS);
  const int nl = mesh_.numLocalUnknowns(), nown = mesh_.numOwnedUnknowns;
  std::vector<long> first(static_cast<size_t>(mesh_.size) + 1, 0);
  MPI_Allgather(&mesh_.firstOwnedUnknown, 1, MPI_LONG, first.data(), 1, MPI_LONG, mesh_.comm);
  first[static_cast<size_t>(mesh_.size)] = mesh_.numGlobalUnknowns;
  const size_t nn = mesh_.nodes.size();
  std::vector<std::vector<int>> nbr(nn), mult(nn);
  for (size_t a = 0; a < nn; ++a) nbr[a].push_back(static_cast<int>(a));
  for (const LocalElement& el : mesh_.elements) {
    const int nc = el.kernel->numConstraints();
    for (int i = 0; i < el.numNodes; ++i) {
      for (int j = 0; j < el.numNodes; ++j) nbr[el.node[i]].push_back(el.node[j]);
      for (int c = 0; c < nc; ++c) mult[el.node[i]].push_back(el.firstMultiplier + c);
    }
  }
  std::vector<double> dc(nl, 0.0), oc(nl, 0.0);
  auto count = [&](int row, const std::vector<int>& cols) {
    const long g = mesh_.localToGlobalUnknown(row);
    const size_t o = static_cast<size_t>(std::upper_bound(first.begin(), first.end(), g) - first.begin()) - 1;
    for (int c : cols) {
      const long gc = mesh_.localToGlobalUnknown(c);
      (gc >= first[o] && gc < first[o + 1] ? dc : oc)[row] += 1.0;
    }
  };
  std::vector<int> cols;
  for (size_t a = 0; a < nn; ++a) {
    auto& nb = nbr[a];
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
    cols.clear();
    for (int b : nb)
      for (int k = 0; k < mesh_.nodes[b].ndof; ++k)
        if (mesh_.nodes[b].dof[k] >= 0) cols.push_back(mesh_.nodes[b].dof[k]);
    std::sort(mult[a].begin(), mult[a].end());
    mult[a].erase(std::unique(mult[a].begin(), mult[a].end()), mult[a].end());
    cols.insert(cols.end(), mult[a].begin(), mult[a].end());
    const LocalNode& n = mesh_.nodes[a];
    for (int k = 0; k < n.ndof; ++k)
      if (n.dof[k] >= 0) count(n.dof[k], cols);
  }
  for (const LocalElement& el : mesh_.elements) {
    const int nc = el.kernel->numConstraints();
    if (nc == 0) continue;
    cols.clear();
    for (int i = 0; i < el.numNodes; ++i) {
      const LocalNode& n = mesh_.nodes[el.node[i]];
      for (int k = 0; k < n.ndof; ++k)
        if (n.dof[k] >= 0) cols.push_back(n.dof[k]);
    }
    for (int c = 0; c < nc; ++c) cols.push_back(el.firstMultiplier + c);
    for (int c = 0; c < nc; ++c) count(el.firstMultiplier + c, cols);
  }
  Vec D, O;
  PetscCall(createVector(&D));
  PetscCall(VecDuplicate(D, &O));
  for (auto [v, src] : {std::pair<Vec, std::vector<double>*>{D, &dc}, {O, &oc}}) {
    Vec loc;
    PetscScalar* x;
    PetscCall(VecGhostGetLocalForm(v, &loc));
    PetscCall(VecGetArray(loc, &x));
    std::copy(src->begin(), src->end(), x);
    PetscCall(VecRestoreArray(loc, &x));
    PetscCall(VecGhostRestoreLocalForm(v, &loc));
    PetscCall(ghostUpdate(v, ADD_VALUES, SCATTER_REVERSE));
  }
  const PetscScalar *d, *o;
  PetscCall(VecGetArrayRead(D, &d));
  PetscCall(VecGetArrayRead(O, &o));
  dnnz_.resize(nown);
  onnz_.resize(nown);
  const long offMax = mesh_.numGlobalUnknowns - nown;
  for (int i = 0; i < nown; ++i) {
    dnnz_[i] = static_cast<PetscInt>(std::min<double>(std::max(d[i], 1.0), nown));
    onnz_[i] = static_cast<PetscInt>(std::min<double>(o[i], static_cast<double>(offMax)));
  }
  PetscCall(VecRestoreArrayRead(D, &d));
  PetscCall(VecRestoreArrayRead(O, &o));
  PetscCall(VecDestroy(&D));
  PetscCall(VecDestroy(&O));
  countsReady_ = true;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The structure is every element block plus the diagonal of every unknown, inserted as zeros and
// assembled, so that later assemblies, shifts and diagonal updates never allocate. Built once per
// assembler; every further matrix is a copy of that structure (an analysis makes up to eight).
PetscErrorCode Assembler::createMatrix(Mat* A) const {
  PetscFunctionBeginUser;
  if (!structure_) PetscCall(buildStructure(&structure_));
  PetscCall(MatDuplicate(structure_, MAT_DO_NOT_COPY_VALUES, A));
  PetscCall(MatSetOption(*A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  PetscCall(MatSetOption(*A, MAT_SUBSET_OFF_PROC_ENTRIES, PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Assembler::buildStructure(Mat* A) const {
  PetscFunctionBeginUser;
  const PetscInt nloc = mesh_.numOwnedUnknowns, N = static_cast<PetscInt>(mesh_.numGlobalUnknowns);
  PetscCall(preallocationCounts());
  PetscCall(MatCreate(mesh_.comm, A));
  PetscCall(MatSetSizes(*A, nloc, nloc, N, N));
  PetscCall(MatSetType(*A, MATAIJ));
  PetscCall(MatXAIJSetPreallocation(*A, 1, dnnz_.data(), onnz_.data(), nullptr, nullptr));
  PetscCall(MatSetLocalToGlobalMapping(*A, l2g_, l2g_));
  PetscCall(MatSetOption(*A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  std::array<PetscInt, kMaxElementRows> idx;
  std::array<PetscScalar, kMaxElementRows * kMaxElementRows> zeros{};
  for (const LocalElement& el : mesh_.elements) {
    int n = 0;
    const auto kinds = el.kernel->nodeKinds();
    for (size_t i = 0; i < kinds.size(); ++i)
      for (int k = 0; k < dofSize(kinds[i]); ++k) idx[n++] = mesh_.nodes[el.node[i]].dof[k];
    for (int j = 0; j < el.kernel->numConstraints(); ++j) idx[n++] = el.firstMultiplier + j;
    PetscCall(MatSetValuesLocal(*A, n, idx.data(), n, idx.data(), zeros.data(), INSERT_VALUES));
  }
  // node-level blocks (nodal inertia) lie inside element blocks; the diagonal of every unknown too
  for (PetscInt i = 0; i < nloc; ++i) PetscCall(MatSetValuesLocal(*A, 1, &i, 1, &i, zeros.data(), INSERT_VALUES));
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  // every assembly sends the same off-process entries: PETSc reuses the communication pattern
  PetscCall(MatSetOption(*A, MAT_SUBSET_OFF_PROC_ENTRIES, PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// COO assembly needs the tangent to be exactly the element blocks: no node-level or load tangents.
bool Assembler::cooApplies() const { return cooAssembly_; }

PetscErrorCode Assembler::prepareCOO(Mat J, bool* sums) {
  PetscFunctionBeginUser;
  // a marker composed with the matrix: it dies with the matrix (a later matrix may reuse the address)
  PetscObject marker = nullptr;
  PetscCall(PetscObjectQuery(reinterpret_cast<PetscObject>(J), "SinewCOOSums", &marker));
  *sums = marker != nullptr;
  if (!marker) PetscCall(PetscObjectQuery(reinterpret_cast<PetscObject>(J), "SinewCOO", &marker));
  if (marker) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(SinewEvents::get().cooSetup, 0, 0, 0, 0));
  PetscBool seq = PETSC_FALSE;
  if (mesh_.size == 1) PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(J), MATSEQAIJ, &seq));
  std::vector<PetscInt> ci, cj;
  if (seq && !cooSums_.built) {
    cooIndices(&ci, &cj);
    PetscCall(buildCooSums(ci, cj));
  }
  if (seq && cooSums_.usable) PetscCall(matchesCooSums(J, sums));
  if (*sums) {
    cooValues_.assign(static_cast<size_t>(cooSums_.entries), 0.0);
  } else {
    if (ci.empty()) cooIndices(&ci, &cj);
    cooValues_.assign(ci.size(), 0.0);
    PetscCall(MatSetPreallocationCOO(J, static_cast<PetscCount>(ci.size()), ci.data(), cj.data()));
  }
  PetscContainer tag;
  PetscCall(PetscContainerCreate(mesh_.comm, &tag));
  PetscCall(PetscObjectCompose(reinterpret_cast<PetscObject>(J), *sums ? "SinewCOOSums" : "SinewCOO",
                               reinterpret_cast<PetscObject>(tag)));
  PetscCall(PetscContainerDestroy(&tag));
  PetscCall(PetscLogEventEnd(SinewEvents::get().cooSetup, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Global (row, column) of every entry of every element block, in element order (-1: a fixed DOF).
void Assembler::cooIndices(std::vector<PetscInt>* ci, std::vector<PetscInt>* cj) const {
  std::array<int, kMaxElementRows> idx;
  std::array<double, 48> q;
  for (const LocalElement& el : mesh_.elements) {
    gatherElement(el, q.data(), nullptr, idx.data(), nullptr);
    const int n = el.kernel->numDofs() + el.kernel->numConstraints();
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        ci->push_back(idx[r] >= 0 ? static_cast<PetscInt>(mesh_.localToGlobalUnknown(idx[r])) : -1);
        cj->push_back(idx[c] >= 0 ? static_cast<PetscInt>(mesh_.localToGlobalUnknown(idx[c])) : -1);
      }
  }
}

// The pattern and sums of MatSetPreallocationCOO_SeqAIJ (PETSc 3.18), made by the same steps: entries
// with a negative index dropped, sorted by row (PetscSortIntWithIntCountArrayPair), each row by column
// (PetscSortIntWithCountArray), repeated (row, column) pairs summed in the order the sorts leave them.
PetscErrorCode Assembler::buildCooSums(const std::vector<PetscInt>& ci, const std::vector<PetscInt>& cj) {
  PetscFunctionBeginUser;
  CooSums& s = cooSums_;
  s = CooSums{};
  s.built = true;
  const PetscCount n = static_cast<PetscCount>(ci.size());
  s.entries = n;
  const PetscInt M = static_cast<PetscInt>(mesh_.numGlobalUnknowns);
  std::vector<PetscInt> i(ci), j(cj);
  std::vector<PetscCount> perm(static_cast<size_t>(n));
  for (PetscCount k = 0; k < n; ++k) {
    if (j[k] < 0) i[k] = -1;
    perm[k] = k;
  }
  PetscCall(PetscSortIntWithIntCountArrayPair(n, i.data(), j.data(), perm.data()));
  PetscCount k = 0;
  while (k < n && i[k] < 0) ++k;
  const PetscCount nneg = k;
  s.row.assign(static_cast<size_t>(M) + 1, 0);
  std::vector<PetscCount> repeats;
  while (k < n) {
    const PetscInt r = i[k];
    if (r >= M) PetscFunctionReturn(PETSC_SUCCESS);  // not this matrix's rows: PETSc's path
    const PetscCount start = k;
    while (k < n && i[k] == r) ++k;
    PetscCall(PetscSortIntWithCountArray(k - start, j.data() + start, perm.data() + start));
    for (PetscCount p = start; p < k; ++p) {
      if (p == start || j[p] != j[p - 1]) {
        s.col.push_back(j[p]);
        repeats.push_back(0);
        ++s.row[static_cast<size_t>(r) + 1];
      }
      ++repeats.back();
    }
  }
  for (PetscInt r = 0; r < M; ++r) s.row[static_cast<size_t>(r) + 1] += s.row[static_cast<size_t>(r)];
  s.jmap.assign(repeats.size() + 1, 0);
  for (size_t p = 0; p < repeats.size(); ++p) s.jmap[p + 1] = s.jmap[p] + repeats[p];
  s.perm.assign(perm.begin() + nneg, perm.end());
  s.usable = true;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// J's nonzero pattern (CSR) is the COO pattern of the sums.
PetscErrorCode Assembler::matchesCooSums(Mat J, bool* match) const {
  PetscFunctionBeginUser;
  *match = false;
  PetscInt m;
  const PetscInt *ia, *ja;
  PetscBool done;
  PetscCall(MatGetRowIJ(J, 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
  if (!done) PetscFunctionReturn(PETSC_SUCCESS);
  const CooSums& s = cooSums_;
  *match = samePattern(m, ia, ja, s.row, s.col);
  PetscCall(MatRestoreRowIJ(J, 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// J = the element blocks in cooValues_, as MatSetValuesCOO(J, cooValues_, INSERT_VALUES) sums them.
PetscErrorCode Assembler::setValuesFromCooSums(Mat J) const {
  PetscFunctionBeginUser;
  const CooSums& s = cooSums_;
  const PetscScalar* v = cooValues_.data();
  PetscScalar* a;
  PetscCall(MatSeqAIJGetArray(J, &a));
  const size_t nnz = s.col.size();
  const PetscCount *jmap = s.jmap.data(), *perm = s.perm.data();
  for (size_t p = 0; p < nnz; ++p) {
    PetscScalar sum = 0.0;
    const PetscCount end = jmap[p + 1];
    for (PetscCount q = jmap[p]; q < end; ++q) sum += v[perm[q]];
    a[p] = 0.0 + sum;
  }
  PetscCall(MatSeqAIJRestoreArray(J, &a));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
