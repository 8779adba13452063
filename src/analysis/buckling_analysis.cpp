#include "analysis/solver_defaults.hpp"
#include "analysis/buckling_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "analysis/modal_analysis.hpp"
#include "mesh/collective_error.hpp"

namespace sinew {

BucklingAnalysis::BucklingAnalysis(Assembler& assembler, int nbuck) : asm_(assembler), nbuck_(nbuck) {
  MPI_Comm comm = asm_.mesh().comm;
  SinewCallThrow(comm, asm_.createMatrix(&Km_));
  SinewCallThrow(comm, asm_.createMatrix(&Kg_));
  SinewCallThrow(comm, EPSCreate(comm, &eps_));
  SinewCallThrow(comm, EPSSetOptionsPrefix(eps_, "buck_"));
  SinewCallThrow(comm, EPSSetProblemType(eps_, EPS_GNHEP));
  SinewCallThrow(comm, EPSSetDimensions(eps_, 2 * nbuck + 2, PETSC_DEFAULT, PETSC_DEFAULT));
  SinewCallThrow(comm, EPSSetWhichEigenpairs(eps_, EPS_TARGET_MAGNITUDE));
  SinewCallThrow(comm, EPSSetTarget(eps_, 0.0));
  ST st;
  KSP ksp;
  SinewCallThrow(comm, EPSGetST(eps_, &st));
  SinewCallThrow(comm, STSetType(st, STSINVERT));
  SinewCallThrow(comm, STSetMatStructure(st, SUBSET_NONZERO_PATTERN));
  SinewCallThrow(comm, STGetKSP(st, &ksp));
  SinewCallThrow(comm, useDirectSolver(ksp));
  SinewCallThrow(comm, EPSSetFromOptions(eps_));
  PetscBool set = PETSC_FALSE;
  SinewCallThrow(comm, PetscOptionsHasName(nullptr, "buck_", "-eps_nev", &set));
  userNev_ = set;
}

BucklingAnalysis::~BucklingAnalysis() {
  EPSDestroy(&eps_);
  MatDestroy(&Km_);
  MatDestroy(&Kg_);
}

PetscErrorCode BucklingAnalysis::solve(int nev, int* nconv) {
  PetscFunctionBeginUser;
  if (!userNev_) PetscCall(EPSSetDimensions(eps_, nev, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(EPSSetOperators(eps_, Km_, Kg_));
  PetscCall(PetscLogEventBegin(SinewEvents::get().eigen, 0, 0, 0, 0));
  PetscCall(EPSSolve(eps_));
  PetscCall(PetscLogEventEnd(SinewEvents::get().eigen, 0, 0, 0, 0));
  PetscInt n;
  PetscCall(EPSGetConverged(eps_, &n));
  *nconv = static_cast<int>(n);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode BucklingAnalysis::atStep(Vec U, const LoadState& ls, ResultFile& file, bool* ok) {
  PetscFunctionBeginUser;
  ++step_;
  const DistributedMesh& mesh = asm_.mesh();
  const double inf = std::numeric_limits<double>::infinity();
  PetscCall(asm_.splitTangent(U, ls, Km_, Kg_));
  PetscReal nm, ng;
  PetscCall(MatNorm(Km_, NORM_FROBENIUS, &nm));
  PetscCall(MatNorm(Kg_, NORM_FROBENIUS, &ng));
  mu_.assign(nbuck_, inf);
  std::vector<Vec> shapes;
  if (ng > 1e-13 * nm) {  // a stress-free state has no buckling load: every multiplier +inf
    PetscCall(MatScale(Kg_, -1.0));  // K_m phi = mu (-K_g) phi
    PetscInt N;
    PetscCall(MatGetSize(Km_, &N, nullptr));
    struct Pair {
      double mu;
      Vec x;
    };
    std::vector<Pair> positive;
    int nev = 2 * nbuck_ + 2, nconv = 0;
    EPSConvergedReason reason = EPS_CONVERGED_ITERATING;
    for (int attempt = 0; attempt < 3; ++attempt) {
      for (auto& p : positive) PetscCall(VecDestroy(&p.x));
      positive.clear();
      PetscCall(solve(std::min<int>(nev, static_cast<int>(N)), &nconv));
      PetscCall(EPSGetConvergedReason(eps_, &reason));
      for (int i = 0; i < nconv; ++i) {
        PetscScalar kr, ki;
        Vec x;
        PetscCall(MatCreateVecs(Km_, &x, nullptr));
        PetscCall(EPSGetEigenpair(eps_, i, &kr, &ki, x, nullptr));
        // mu ||K_g|| > 1e4 ||K_m||: a null direction of K_g (infinite multiplier) computed at round-off level;
        // a real buckling load has mu ||K_g|| / ||K_m|| of the order of (thickness / length)^2
        const bool finite = std::isfinite(kr) && kr * ng < 1e4 * nm;
        if (finite && kr > 0 && std::abs(ki) <= 1e-6 * std::abs(kr)) positive.push_back({kr, x});
        else PetscCall(VecDestroy(&x));
      }
      // enough positive multipliers, or the nearest ones are all negative and the spectrum is exhausted
      if (static_cast<int>(positive.size()) >= nbuck_ || userNev_ || nev >= N) break;
      nev *= 4;
    }
    std::sort(positive.begin(), positive.end(), [](const Pair& a, const Pair& b) { return a.mu < b.mu; });
    for (int j = 0; j < nbuck_ && j < static_cast<int>(positive.size()); ++j) {
      mu_[j] = positive[j].mu;
      shapes.push_back(positive[j].x);
      positive[j].x = nullptr;
    }
    for (auto& p : positive) PetscCall(VecDestroy(&p.x));
    PetscCall(PetscInfo(nullptr, "buckling step %d: %d converged (%s), %zu positive multipliers kept\n", step_, nconv,
                        EPSConvergedReasons[reason], shapes.size()));
    if (reason < 0 && shapes.empty()) {
      *ok = false;
      std::ostringstream msg;
      msg << "buckling at step " << step_ << ": SLEPc did not converge (" << EPSConvergedReasons[reason]
          << "); try -buck_eps_max_it, -buck_eps_ncv or -buck_eps_tol";
      failure_ = msg.str();
    }
  }
  file.writeStepRow("buck", mu_);
  std::vector<double> rows, rot;
  std::vector<double>* withRot = mesh.anyRotations ? &rot : nullptr;
  for (int j = 0; j < nbuck_; ++j) {
    if (j < static_cast<int>(shapes.size())) {
      PetscCall(modeShapeRows(mesh, shapes[j], rows, withRot));
    } else {
      rows.assign(3 * static_cast<size_t>(mesh.numOwnedNodes), 0.0);
      rot = rows;
    }
    file.writeMeshField("mesh/mode_buck_" + std::to_string(j + 1), rows, {3});
    if (withRot) file.writeMeshField("mesh/mode_buck_" + std::to_string(j + 1) + "_rot", rot, {3});
  }
  for (Vec& x : shapes) PetscCall(VecDestroy(&x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::string BucklingAnalysis::summary() const {
  if (mu_.empty()) return {};
  std::ostringstream s;
  char buf[64];
  s << "\n buckling load multipliers (last step):";
  bool anyInf = false;
  for (double m : mu_) {
    std::snprintf(buf, sizeof buf, " %.6g", m);
    s << buf;
    anyInf |= std::isinf(m);
  }
  s << "\n";
  if (anyInf) s << "   inf: no (further) positive multiplier: no compressive stress state that the current load can buckle\n";
  return s.str();
}

}  // namespace sinew
