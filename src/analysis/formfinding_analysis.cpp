#include "analysis/formfinding_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "parallel/collective_error.hpp"
#include "settings/read_settings.hpp"
#include "solvers/newton_test.hpp"
#include "solvers/step_controller.hpp"

namespace sinew {

namespace {
/// Above this many unknowns form finding solves iteratively by default (-ff_ksp_type/-ff_pc_type override).
constexpr long kIterativeAbove = 50000;
}  // namespace

namespace {

/// Homotopy factor and xURS of form-finding step k (1-based).
std::pair<double, bool> stepMode(const FormFinding& ff, int k) {
  const auto& hc = ff.homotopy_curve;
  const double lambda = hc.empty() ? 0.0 : hc[static_cast<size_t>(std::min<int>(k, static_cast<int>(hc.size())) - 1)];
  return {lambda, ff.x_urs && k >= ff.x_urs_step};
}

/// Switches the kernels of the form-found sets to form finding (on) or back to elastic.
void setFormFindingMode(DistributedMesh& m, const std::vector<int>& sets, bool on, double lambda, bool xurs) {
  for (const LocalElement& el : m.elements) {
    if (el.set < 0 || std::find(sets.begin(), sets.end(), el.set) == sets.end()) continue;
    FormFindingKernel* f = el.kernel->formFinding();
    if (!f) continue;
    if (on) f->enterFormFinding(lambda, xurs);
    else f->leaveFormFinding();
  }
}
}  // namespace

PetscErrorCode checkFormFindingConstraints(Assembler& assembler, const Model& model, const ModelCheckSettings& settings,
                                           int denseMaxUnknowns,
                                           ConstraintReport* report) {
  PetscFunctionBeginUser;
  DistributedMesh& m = assembler.mesh();
  const std::vector<int> sets = formFoundSets(*model.formfinding, model.eprops);
  const auto [lambda, xurs] = stepMode(*model.formfinding, 1);
  setFormFindingMode(m, sets, true, lambda, xurs);
  Vec U0;
  PetscCall(assembler.createVector(&U0));
  PetscCall(VecSet(U0, 0.0));
  PetscCall(checkConstraints(assembler, model, U0, LoadState{}, settings, denseMaxUnknowns, report));
  PetscCall(VecDestroy(&U0));
  setFormFindingMode(m, sets, false, 0.0, false);
  PetscFunctionReturn(PETSC_SUCCESS);
}

FormFindingAnalysis::FormFindingAnalysis(Assembler& assembler, const FormFinding& ff, const std::vector<ElementSet>& eprops,
                                         const FormFindingSettings& settings)
    : asm_(assembler), ff_(ff), eprops_(eprops) {
  newtonTest_.rules().forceRtol = ff_.equilibrium_accuracy;
  DistributedMesh& m = asm_.mesh();
  MPI_Comm comm = m.comm;
  ffSets_ = formFoundSets(ff_, eprops_);
  auto inList = [](const std::vector<int>& v, int s) { return std::find(v.begin(), v.end(), s) != v.end(); };
  // initial states (load factor 0): the reference of a NONE restart, initial areas, model size
  Vec U0;
  SinewCallThrow(comm, asm_.createVector(&U0));
  SinewCallThrow(comm, VecSet(U0, 0.0));
  const double* u;
  SinewCallThrow(comm, asm_.beginLocal(U0, ls_, &u));
  std::array<double, 48> q;
  std::array<int, 32> idx;
  double quality = 1.0;
  for (size_t e = 0; e < m.elements.size(); ++e) {
    const LocalElement& el = m.elements[e];
    if (el.set < 0 || !inList(ffSets_, el.set)) continue;
    FormFindingKernel* f = el.kernel->formFinding();
    if (!f) continue;
    asm_.gather(el, q.data(), idx.data());
    elems_.push_back(static_cast<int>(e));
    std::array<double, 12> s{};
    std::copy(q.begin(), q.begin() + 3 * el.numNodes, s.begin());
    initial_.push_back(s);
    size0_.push_back(f->size(q.data()));
    quality = std::min(quality, f->meshQuality(q.data()));
    const bool adapt = inList(ff_.stress_adaption, el.set);
    f->setAdaption(adapt ? ff_.lambda_max : 0.0, ff_.mue_relax, adapt ? ff_.distortion_max : 0.0);
  }
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (int i = 0; i < m.numOwnedNodes; ++i)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], asm_.nodeState(i)[k]);
      hi[k] = std::max(hi[k], asm_.nodeState(i)[k]);
    }
  SinewCallThrow(comm, asm_.endLocal(&u));
  SinewCallThrow(comm, VecDestroy(&U0));
  MPI_Allreduce(MPI_IN_PLACE, lo, 3, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(MPI_IN_PLACE, hi, 3, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(MPI_IN_PLACE, &quality, 1, MPI_DOUBLE, MPI_MIN, comm);
  quality0_ = quality;
  size_ = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
  if (!(size_ > 0.0)) size_ = 1.0;
  long n = static_cast<long>(elems_.size());
  MPI_Allreduce(&n, &nff_, 1, MPI_LONG, MPI_SUM, comm);

  SinewCallThrow(comm, asm_.createMatrix(&J_));
  SinewCallThrow(comm, asm_.createVector(&F_));
  SinewCallThrow(comm, asm_.createVector(&nrm_));
  SinewCallThrow(comm, asm_.createVector(&nrmOff_));
  SinewCallThrow(comm, asm_.createVector(&mdiag_));
  SinewCallThrow(comm, asm_.createVector(&moff_));
  SinewCallThrow(comm, SNESCreate(comm, &snes_));
  SinewCallThrow(comm, SNESSetOptionsPrefix(snes_, "ff_"));
  SinewCallThrow(comm, SNESSetType(snes_, SNESNEWTONLS));
  SinewCallThrow(comm, SNESSetFunction(snes_, F_, formFunction, this));
  SinewCallThrow(comm, SNESSetJacobian(snes_, J_, J_, formJacobian, this));
  SinewCallThrow(comm, SNESSetTolerances(snes_, 1e-50, 1e-50, 0.0, ff_.max_iter_equilibrium, 100000));
  SinewCallThrow(comm, SNESSetDivergenceTolerance(snes_, -1.0));
  SNESLineSearch ls;
  SinewCallThrow(comm, SNESGetLineSearch(snes_, &ls));
  SinewCallThrow(comm, SNESLineSearchSetType(ls, SNESLINESEARCHBASIC));
  SinewCallThrow(comm, SNESSetConvergenceTest(snes_, convergenceTest, this, nullptr));
  KSP ksp;
  PC pc;
  SinewCallThrow(comm, SNESGetKSP(snes_, &ksp));
  SinewCallThrow(comm, KSPGetPC(ksp, &pc));
  if (asm_.mesh().numGlobalUnknowns > kIterativeAbove) {
    // Large models: GMRES + BoomerAMG. The form-finding systems are well conditioned (geometric
    // stiffness of a prestressed surface); on the 185k-unknown sail this is 1.47 s per step on
    // 2 ranks against 1.60 s for MUMPS, and scales 2.3x from 1 to 2 ranks (MUMPS: 1.4x).
    SinewCallThrow(comm, KSPSetType(ksp, KSPGMRES));
    SinewCallThrow(comm, KSPSetTolerances(ksp, 1e-12, 1e-50, PETSC_DEFAULT, 2000));
    SinewCallThrow(comm, PCSetType(pc, PCHYPRE));
  } else {
    SinewCallThrow(comm, KSPSetType(ksp, KSPPREONLY));
    SinewCallThrow(comm, PCSetType(pc, PCLU));
    SinewCallThrow(comm, PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  }
  // MUMPS fill-reducing ordering: SCOTCH (ICNTL(7) = 3) unless the user chose one. Measured on the
  // sail (55k unknowns, docs/performance.md): the automatic choice factors 1.6-2.4x slower.
  SinewCallThrow(comm, applySolverOptionDefault("-ff_mat_mumps_icntl_7", settings.mumpsOrdering));
  SinewCallThrow(comm, SNESSetFromOptions(snes_));
}

FormFindingAnalysis::~FormFindingAnalysis() {
  SNESDestroy(&snes_);
  MatDestroy(&J_);
  VecDestroy(&F_);
  VecDestroy(&nrm_);
  VecDestroy(&nrmOff_);
  VecDestroy(&mdiag_);
  VecDestroy(&moff_);
}

PetscErrorCode FormFindingAnalysis::formFunction(SNES, Vec U, Vec F, void* ctx) {
  auto* self = static_cast<FormFindingAnalysis*>(ctx);
  return self->asm_.residual(U, self->ls_, F);
}

PetscErrorCode FormFindingAnalysis::formJacobian(SNES, Vec U, Mat, Mat P, void* ctx) {
  auto* self = static_cast<FormFindingAnalysis*>(ctx);
  return self->asm_.jacobian(U, self->ls_, P);
}

PetscErrorCode FormFindingAnalysis::convergenceTest(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm,
                                                    PetscReal fnorm, SNESConvergedReason* reason, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<FormFindingAnalysis*>(ctx);
  NewtonIterate x(it, xnorm, snorm, fnorm);
  x.scale = forceScale(self->asm_.externalForceNorm(), self->asm_.internalForceNorm());
  PetscCall(self->newtonTest_.judge(snes, x, reason));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void FormFindingAnalysis::setMode(double lambda, bool xurs) {
  for (int e : elems_) {
    asm_.mesh().elements[static_cast<size_t>(e)].kernel->formFinding()->enterFormFinding(lambda, xurs);
  }
}

PetscErrorCode FormFindingAnalysis::updateReferences(Vec U, long* badElement, double* quality) {
  PetscFunctionBeginUser;
  DistributedMesh& m = asm_.mesh();
  const double* u;
  PetscCall(asm_.beginLocal(U, ls_, &u));
  std::array<double, 48> q;
  std::array<int, 32> idx;
  long bad = 0;
  double qmin = 1.0;
  for (size_t i = 0; i < elems_.size(); ++i) {
    const LocalElement& el = m.elements[static_cast<size_t>(elems_[i])];
    asm_.gather(el, q.data(), idx.data());
    FormFindingKernel* f = el.kernel->formFinding();
    // a line of zero length, a surface below 1e-3 of its initial area
    if (f->collapsed(q.data(), size0_[i], size_)) {
      bad = std::max(bad, static_cast<long>(el.sceneElement) + 1);
      continue;
    }
    qmin = std::min(qmin, f->meshQuality(q.data()));
    try {
      f->updateReference(q.data());
    } catch (const std::invalid_argument&) {
      bad = std::max(bad, static_cast<long>(el.sceneElement) + 1);
    }
  }
  PetscCall(asm_.endLocal(&u));
  MPI_Allreduce(&bad, badElement, 1, MPI_LONG, MPI_MAX, m.comm);
  MPI_Allreduce(&qmin, quality, 1, MPI_DOUBLE, MPI_MIN, m.comm);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode FormFindingAnalysis::shapeChange(Vec U, Vec Uprev, double* change) {
  PetscFunctionBeginUser;
  DistributedMesh& m = asm_.mesh();
  const PetscScalar *a, *b;
  PetscCall(VecGetArrayRead(U, &a));
  PetscCall(VecGetArrayRead(Uprev, &b));
  double mx = 0.0;
  for (int i = 0; i < m.numOwnedNodes; ++i) {
    const LocalNode& n = m.nodes[i];
    double d2 = 0.0;
    for (int k = 0; k < 3 && k < n.ndof; ++k)
      if (n.dof[k] >= 0 && n.status[k] == DofStatus::Free) d2 += (a[n.dof[k]] - b[n.dof[k]]) * (a[n.dof[k]] - b[n.dof[k]]);
    mx = std::max(mx, std::sqrt(d2));
  }
  PetscCall(VecRestoreArrayRead(U, &a));
  PetscCall(VecRestoreArrayRead(Uprev, &b));
  MPI_Allreduce(MPI_IN_PLACE, &mx, 1, MPI_DOUBLE, MPI_MAX, m.comm);
  *change = mx / size_;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode FormFindingAnalysis::normalShapeChange(Vec U, Vec Uprev, double* change) {
  PetscFunctionBeginUser;
  DistributedMesh& m = asm_.mesh();
  // nodal sums over the form-found elements at the current shape (ghost contributions added):
  // nrm_/nrmOff_ = sum of A n n^T of the membranes (a a^T / |a|, a = area vector: the same for either
  // node order, so a mesh with flipped triangles gets the same normals, issue 10 item 15),
  // mdiag_/moff_ = sum of e e^T of cables (xx yy zz / xy yz zx)
  // (zeroed in the local forms: VecSet on a ghosted vector leaves the ghost entries, which would
  // carry the previous step's sums into this one at partition interfaces)
  Vec nl, dl, ol, nol;
  PetscCall(VecGhostGetLocalForm(nrm_, &nl));
  PetscCall(VecGhostGetLocalForm(nrmOff_, &nol));
  PetscCall(VecSet(nol, 0.0));
  PetscCall(VecGhostGetLocalForm(mdiag_, &dl));
  PetscCall(VecGhostGetLocalForm(moff_, &ol));
  PetscCall(VecSet(nl, 0.0));
  PetscCall(VecSet(dl, 0.0));
  PetscCall(VecSet(ol, 0.0));
  PetscScalar *na, *da, *oa, *noa;
  PetscCall(VecGetArray(nl, &na));
  PetscCall(VecGetArray(nol, &noa));
  PetscCall(VecGetArray(dl, &da));
  PetscCall(VecGetArray(ol, &oa));
  const double* u;
  PetscCall(asm_.beginLocal(U, ls_, &u));
  std::array<double, 48> q;
  std::array<int, 32> idx;
  auto freeXYZ = [](const LocalNode& n) {
    for (int k = 0; k < 3; ++k)
      if (k >= n.ndof || n.dof[k] < 0 || n.status[k] != DofStatus::Free) return false;
    return true;
  };
  for (int e : elems_) {
    const LocalElement& el = m.elements[static_cast<size_t>(e)];
    asm_.gather(el, q.data(), idx.data());
    const FormFindingKernel* f = el.kernel->formFinding();
    const bool cable = f->shapeType() == FormFindingKernel::Shape::Line;
    const Vec3 a = f->shapeAxis(q.data());  // line: unit direction; surface: a a^T = A n n^T
    for (int j = 0; j < el.numNodes; ++j) {
      const LocalNode& n = m.nodes[static_cast<size_t>(el.node[static_cast<size_t>(j)])];
      if (!freeXYZ(n)) continue;
      for (int k = 0; k < 3; ++k) {
        if (cable) {
          da[n.dof[k]] += a[k] * a[k];
          oa[n.dof[k]] += a[k] * a[(k + 1) % 3];
        } else {
          na[n.dof[k]] += a[k] * a[k];
          noa[n.dof[k]] += a[k] * a[(k + 1) % 3];
        }
      }
    }
  }
  PetscCall(asm_.endLocal(&u));
  PetscCall(VecRestoreArray(nl, &na));
  PetscCall(VecRestoreArray(nol, &noa));
  PetscCall(VecGhostRestoreLocalForm(nrmOff_, &nol));
  PetscCall(VecRestoreArray(dl, &da));
  PetscCall(VecRestoreArray(ol, &oa));
  PetscCall(VecGhostRestoreLocalForm(nrm_, &nl));
  PetscCall(VecGhostRestoreLocalForm(mdiag_, &dl));
  PetscCall(VecGhostRestoreLocalForm(moff_, &ol));
  for (Vec w : {nrm_, nrmOff_, mdiag_, moff_}) {
    PetscCall(VecGhostUpdateBegin(w, ADD_VALUES, SCATTER_REVERSE));
    PetscCall(VecGhostUpdateEnd(w, ADD_VALUES, SCATTER_REVERSE));
  }
  const PetscScalar *a, *b, *N, *NO, *D, *O;
  PetscCall(VecGetArrayRead(U, &a));
  PetscCall(VecGetArrayRead(Uprev, &b));
  PetscCall(VecGetArrayRead(nrm_, &N));
  PetscCall(VecGetArrayRead(nrmOff_, &NO));
  PetscCall(VecGetArrayRead(mdiag_, &D));
  PetscCall(VecGetArrayRead(moff_, &O));
  // dominant eigenvector and eigenvalue of the symmetric positive semidefinite tensor stored as
  // diagonal (xx yy zz) and off-diagonal (xy yz zx) parts at dof[0..2]
  auto dominant = [](const PetscScalar* Dg, const PetscScalar* Of, const int* dof, double* lam) {
    const double M[3][3] = {{Dg[dof[0]], Of[dof[0]], Of[dof[2]]},
                            {Of[dof[0]], Dg[dof[1]], Of[dof[1]]},
                            {Of[dof[2]], Of[dof[1]], Dg[dof[2]]}};
    int c = 0;
    for (int k = 1; k < 3; ++k)
      if (M[k][k] > M[c][c]) c = k;
    Vec3 t{M[0][c], M[1][c], M[2][c]};
    for (int it = 0; it < 30; ++it) {  // power iteration
      Vec3 s{};
      for (int r = 0; r < 3; ++r) s[r] = M[r][0] * t[0] + M[r][1] * t[1] + M[r][2] * t[2];
      const double ns = norm(s);
      if (!(ns > 0.0)) break;
      t = (1.0 / ns) * s;
    }
    *lam = 0.0;
    for (int r = 0; r < 3; ++r) *lam += t[r] * (M[r][0] * t[0] + M[r][1] * t[1] + M[r][2] * t[2]);
    return t;
  };
  double mx = 0.0;
  for (int i = 0; i < m.numOwnedNodes; ++i) {
    const LocalNode& n = m.nodes[i];
    if (!freeXYZ(n)) {  // partly constrained: every free component counts
      double d2 = 0.0;
      for (int k = 0; k < 3 && k < n.ndof; ++k)
        if (n.dof[k] >= 0 && n.status[k] == DofStatus::Free) d2 += (a[n.dof[k]] - b[n.dof[k]]) * (a[n.dof[k]] - b[n.dof[k]]);
      mx = std::max(mx, std::sqrt(d2));
      continue;
    }
    Vec3 d;
    for (int k = 0; k < 3; ++k) d[k] = a[n.dof[k]] - b[n.dof[k]];
    const double trace = D[n.dof[0]] + D[n.dof[1]] + D[n.dof[2]];
    const bool membrane = N[n.dof[0]] + N[n.dof[1]] + N[n.dof[2]] > 0.0;
    if (membrane && trace == 0.0) {
      double lamN;
      const Vec3 nn = dominant(N, NO, n.dof.data(), &lamN);  // area-weighted best-fit normal
      d = dot(d, nn) * nn;
    } else if (membrane) {
      // cable direction tensor M = sum e e^T; collinear cables: largest eigenvalue = trace
      double lam;
      const Vec3 t = dominant(D, O, n.dof.data(), &lam);
      if (lam >= 0.9 * trace) d = d - dot(d, t) * t;
    }
    mx = std::max(mx, norm(d));
  }
  PetscCall(VecRestoreArrayRead(U, &a));
  PetscCall(VecRestoreArrayRead(Uprev, &b));
  PetscCall(VecRestoreArrayRead(nrm_, &N));
  PetscCall(VecRestoreArrayRead(nrmOff_, &NO));
  PetscCall(VecRestoreArrayRead(mdiag_, &D));
  PetscCall(VecRestoreArrayRead(moff_, &O));
  MPI_Allreduce(MPI_IN_PLACE, &mx, 1, MPI_DOUBLE, MPI_MAX, m.comm);
  *change = mx / size_;
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::string FormFindingAnalysis::setNames() const {
  std::ostringstream s;
  for (size_t i = 0; i < ffSets_.size(); ++i) {
    const ElementSet& es = eprops_[static_cast<size_t>(ffSets_[i])];
    s << (i ? ", " : "") << epropsName(ffSets_[i]) << " (" << elementTypeName(es.type()) << " set)";
  }
  return s.str();
}

PetscErrorCode FormFindingAnalysis::run(Vec U, const StepCallback& onStep, bool* ok) {
  PetscFunctionBeginUser;
  MPI_Comm comm = asm_.mesh().comm;
  *ok = true;
  if (nff_ == 0) {
    *ok = false;
    failure_ = "formfinding: no cable or membrane element to form-find (formfinding_elements names the eprops sets)";
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  Vec Uprev;
  PetscCall(VecDuplicate(U, &Uprev));
  ls_ = LoadState{};  // load factor 0: initial loads only
  const int nsteps = ff_.formfinding_step;
  // stop on the normal change, from step 2 on and while the total change does not grow (an
  // in-plane collapse of a flat membrane has zero normal change but a growing total change)
  auto stops = [&]() {
    const size_t n = reports_.size();
    return n >= 2 && reports_[n - 1].step >= 2 && reports_[n - 1].shapeChangeNormal < ff_.formfinding_tolerance.value_or(0.0) &&
           reports_[n - 1].shapeChange <= reports_[n - 2].shapeChange;
  };
  // the shape found at the end: below formfinding_tolerance, or without one (CARAT++'s fixed step
  // count) below kShapeConverged in the last step
  const double judged = ff_.formfinding_tolerance.value_or(FormFinding::kShapeConverged);
  auto found = [&]() {
    return ff_.formfinding_tolerance ? stops() : (!reports_.empty() && reports_.back().shapeChangeNormal < judged);
  };
  // one URS step per report step, never cut (a failed step ends form finding); a resumed run
  // (resume()) continues after its last step, unless that step ended form finding
  StepRules rules;
  rules.maxCuts = 0;
  StepController control(rules, {"formfinding step", "URS step", "URS step"});
  control.resume(1.0);
  FormFindingStepReport rep;
  SteppedProcedure urs;
  urs.solve = [&](double, double, double, StepAttempt* a) -> PetscErrorCode {
    const int k = control.step();
    rep = FormFindingStepReport{};
    rep.step = k;
    std::tie(rep.lambda, rep.xurs) = stepMode(ff_, k);
    setMode(rep.lambda, rep.xurs);
    PetscCall(VecCopy(U, Uprev));
    NewtonOutcome out;
    PetscCall(solveNewton(snes_, U, &out));
    const SNESConvergedReason why = out.reason;
    rep.newtonIterations = out.iterations;
    rep.residualNorm = out.residualNorm;
    rep.equilibrium = why > 0;
    a->iterations = rep.newtonIterations;
    a->reason = SNESConvergedReasons[why];
    std::ostringstream msg;
    if (why < 0 && why != SNES_DIVERGED_MAX_IT) {
      msg << "formfinding step " << k << " of " << nsteps << ": no equilibrium (" << SNESConvergedReasons[why]
          << ", residual norm " << out.residualNorm << ") for the form-found sets " << setNames()
          << ". A singular tangent means a mechanism: a node held only by unstressed elements, a free membrane "
             "edge without an edge cable, or supports missing. Check prestress and supports; -ff_snes_monitor "
             "shows the iterations.";
      failure_ = msg.str();
      return PETSC_SUCCESS;
    }
    PetscCall(asm_.absorbRotations(U));
    PetscCall(shapeChange(U, Uprev, &rep.shapeChange));
    PetscCall(normalShapeChange(U, Uprev, &rep.shapeChangeNormal));
    if (!(rep.shapeChange <= ff_.max_shape_change)) {
      msg << "formfinding step " << k << " of " << nsteps << ": the shape changed by " << rep.shapeChange
          << " of the model size (max_shape_change " << ff_.max_shape_change << ") in the form-found sets "
          << setNames() << ": there is no equilibrium shape for this prestress"
          << (hint_.empty() ? "; the prestress is too low for the loads or the edge cables, or a membrane edge is "
                              "unsupported (add an edge cable or supports)."
                            : ": " + hint_);
      failure_ = msg.str();
      return PETSC_SUCCESS;
    }
    long bad = 0;
    PetscCall(updateReferences(U, &bad, &rep.meshQuality));
    if (bad > 0) {
      msg << "formfinding step " << k << " of " << nsteps << ": element " << bad
          << " collapsed (area below 1e-3 of its initial area, or zero length) in the form-found sets " << setNames()
          << ": the surface crumples instead of converging"
          << (hint_.empty() ? "; a membrane edge is unsupported or the prestress is too low against the edge cables or loads."
                            : ": " + hint_);
      failure_ = msg.str();
      return PETSC_SUCCESS;
    }
    a->converged = true;  // a step at max_iter_equilibrium counts: judged after the run
    return PETSC_SUCCESS;
  };
  StepSequence steps;
  steps.first = static_cast<int>(reports_.size()) + 1;
  steps.last = nsteps;
  steps.reached = [&](int&, StepStop* stop) -> PetscErrorCode {
    reports_.push_back(rep);
    if (onStep) PetscCall(onStep(rep, U));
    if (stop_ && *stop_) *stop = StepStop::Interrupted;
    else if (stops()) *stop = StepStop::StopCondition;
    return PETSC_SUCCESS;
  };
  StepStop stop = StepStop::StopCondition;
  double done = steps.first - 1;
  if (!(steps.first > 1 && stops())) PetscCall(control.run(urs, steps, &done, &stop));
  *ok = stop != StepStop::CutLimit;
  const bool interrupted = stop_ && *stop_;
  if (*ok && !reports_.empty() && !reports_.back().equilibrium) {
    std::ostringstream msg;
    msg << "formfinding step " << reports_.back().step << ": equilibrium_accuracy " << ff_.equilibrium_accuracy
        << " not reached in max_iter_equilibrium = " << ff_.max_iter_equilibrium << " iterations (residual norm "
        << reports_.back().residualNorm << "); raise max_iter_equilibrium or formfinding_step";
    failure_ = msg.str();
    *ok = false;
  } else if (*ok && !interrupted && judged > 0.0 && !found()) {
    // formfinding_step used up before the stop criterion (issue 10 item 14): the last shape is
    // written (and kept in the result file) but it is not the found shape
    const FormFindingStepReport& r = reports_.back();
    std::ostringstream msg;
    msg << "formfinding: the shape is not converged after formfinding_step = " << nsteps
        << " steps: normal shape change " << r.shapeChangeNormal << " of the model size in the last step ("
        << (ff_.formfinding_tolerance ? "formfinding_tolerance " : "a found shape changes by less than ") << judged << ")";
    if (reports_.size() >= 2 && r.shapeChange > reports_[reports_.size() - 2].shapeChange)
      msg << ", total change growing (" << reports_[reports_.size() - 2].shapeChange << " -> " << r.shapeChange << ")";
    msg << ", mesh quality " << r.meshQuality << " of the form-found sets " << setNames() << ". ";
    // drifting: the change per step decays by less than half over the last five steps
    const size_t n = reports_.size();
    const double c0 = n >= 6 ? reports_[n - 6].shapeChangeNormal : 0.0;
    if (c0 > 0.0 && r.shapeChangeNormal > 0.5 * c0) {
      const double rate = std::pow(r.shapeChangeNormal / c0, 0.2);
      msg << "The shape drifts: its change per step decays only by a factor " << rate << " per step";
      if (rate < 1.0)
        msg << " (about " << std::ceil(std::log(judged / r.shapeChangeNormal) / std::log(rate)) << " more steps to "
            << judged << ")";
      msg << ". ";
      bool cablesOnly = true;
      for (int set : ffSets_) cablesOnly = cablesOnly && eprops_[static_cast<size_t>(set)].type() == ElementType::Cable;
      if (cablesOnly)
        msg << "A cable net whose cables keep a constant force (prestress) has a unique shape only where those forces "
               "can hold on its boundary (nets along straight rulings); elsewhere its nodes slide step after step. "
               "Find the shape by the force density method in one step (formfinding_step: 1, formfinding_tolerance: 0: "
               "q = prestress / initial length, as runs/hypar_net.yaml), or give cables whose forces fit the boundary. ";
    }
    msg << "Raise formfinding_step, or formfinding_tolerance for a mesh that drifts in its surface "
           "(docs/formfinding.md); formfinding_tolerance: 0 runs exactly formfinding_step steps without a stop rule.";
    failure_ = msg.str();
    *ok = false;
  }
  PetscCall(VecDestroy(&Uprev));
  (void)comm;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode FormFindingAnalysis::restart(Vec U) {
  PetscFunctionBeginUser;
  DistributedMesh& m = asm_.mesh();
  const std::string& method = ff_.elastic_restart_method;
  for (size_t i = 0; i < elems_.size(); ++i) {
    FormFindingKernel* f = m.elements[static_cast<size_t>(elems_[i])].kernel->formFinding();
    f->leaveFormFinding();
    if (method == "FORCE") continue;
    f->clearPrestress();
    if (method == "NONE") f->setReference(initial_[i].data());
  }
  if (method == "NONE") {
    PetscCall(VecSet(U, 0.0));
  } else if (method == "FORCE") {
    // node reference positions := found positions (free translations), then U := 0 there
    const double* u;
    PetscCall(asm_.beginLocal(U, ls_, &u));
    for (LocalNode& n : m.nodes) {
      if (n.kind == NodeKind::Ancf2D) continue;
      for (int k = 0; k < 3; ++k)
        if (n.status[k] == DofStatus::Free) n.X0[k] += u[n.dof[k]];
    }
    PetscCall(asm_.endLocal(&u));
    PetscScalar* uo;
    PetscCall(VecGetArray(U, &uo));
    for (int i = 0; i < m.numOwnedNodes; ++i) {
      const LocalNode& n = m.nodes[i];
      if (n.kind == NodeKind::Ancf2D) continue;
      for (int k = 0; k < 3; ++k)
        if (n.status[k] == DofStatus::Free) uo[n.dof[k]] = 0.0;
    }
    PetscCall(VecRestoreArray(U, &uo));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
