// opt.dynamics: generalized-alpha time integration (src/analysis/dynamic_analysis.hpp) from the
// (form-found) state at rest; writes t = 0 and every output_every-th step (and the last) as rows
// of /time, with sensors seeing velocities and accelerations. -dynamics_energy adds /energy
// [ns, 4] = kinetic, strain, gravity potential, total (ancf_cable2d scenes without user functions).
#include <array>
#include <cstdio>
#include <cmath>
#include <sstream>

#include "analysis/dynamic_analysis.hpp"
#include "analysis/sensor_analysis.hpp"
#include "app/restart.hpp"
#include "app/run_context.hpp"
#include "elements/ancf_cable2d.hpp"

namespace sinew {

namespace {

/// Gauss-Legendre and Lobatto rules on [-1, 1] used by the ANCF kernel.
void rule(int kind, std::vector<double>& xi, std::vector<double>& w) {
  switch (kind) {
    case 2: xi = {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)}; w = {1, 1}; break;
    case 3: xi = {-std::sqrt(0.6), 0, std::sqrt(0.6)}; w = {5.0 / 9, 8.0 / 9, 5.0 / 9}; break;
    case 4: {
      const double s = 2.0 / 7.0 * std::sqrt(6.0 / 5.0), a = std::sqrt(3.0 / 7.0 - s), b = std::sqrt(3.0 / 7.0 + s);
      const double wa = (18.0 + std::sqrt(30.0)) / 36.0, wb = (18.0 - std::sqrt(30.0)) / 36.0;
      xi = {-b, -a, a, b};
      w = {wb, wa, wa, wb};
      break;
    }
    case 5: {
      const double s = 2.0 * std::sqrt(10.0 / 7.0), a = std::sqrt(5.0 - s) / 3.0, b = std::sqrt(5.0 + s) / 3.0;
      const double wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0, wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
      xi = {-b, -a, 0, a, b};
      w = {wb, wa, 128.0 / 225.0, wa, wb};
      break;
    }
    default: xi = {-1, 0, 1}; w = {1.0 / 3, 4.0 / 3, 1.0 / 3}; break;  // Lobatto 3
  }
}

/// Strain energy int EA/2 (eps - eps_ref)^2 + EI/2 (K - K_ref)^2 dx with the kernel's own rules
/// (its internal force is the gradient of exactly this sum).
double strainEnergy(const AncfCable2D& k, const double* q) {
  const auto& p = k.parameters();
  const int r = p.useReducedOrderIntegration;
  std::vector<double> xi, w;
  double L = k.length(), E = 0;
  rule(r == 0 ? 5 : (r == 1 ? 4 : 1), xi, w);
  for (size_t i = 0; i < xi.size(); ++i) {
    const double x = 0.5 * L * (xi[i] + 1), d = k.axialStrain(q, x) - k.axialStrainRef(x);
    E += 0.25 * L * w[i] * p.physicsAxialStiffness * d * d;
  }
  rule(r == 0 ? 3 : 2, xi, w);
  for (size_t i = 0; i < xi.size(); ++i) {
    const double x = 0.5 * L * (xi[i] + 1), d = k.curvature(q, x) - k.curvatureRef(x);
    E += 0.25 * L * w[i] * p.physicsBendingStiffness * d * d;
  }
  return E;
}

/// Strain energy and gravity potential of the state U (global sums). False when some element
/// is not an ANCF cable with linear force laws.
PetscErrorCode potentialEnergy(Assembler& asm_, const std::optional<Vec3>& gravity, Vec U, const LoadState& ls,
                               double* strain, double* grav, bool* ok) {
  PetscFunctionBeginUser;
  const double* u = nullptr;
  PetscCall(asm_.beginLocal(U, ls, &u));
  std::array<double, 48> q{};
  std::array<int, 48> idx{};
  std::vector<double> fb;
  double e[3] = {0, 0, 0};  // strain, gravity, unsupported elements
  const Vec3 g = gravity.value_or(Vec3{});
  for (const LocalElement& el : asm_.mesh().elements) {
    asm_.gather(el, q.data(), idx.data());
    const auto* k = dynamic_cast<const AncfCable2D*>(el.kernel.get());
    if (!k || k->parameters().axialForceUserFunction || k->parameters().bendingMomentUserFunction) {
      e[2] += 1;
      continue;
    }
    e[0] += strainEnergy(*k, q.data());
    if (Vec3 a; asm_.bodyAcceleration(el, ls, &a)) {  // gravity + massProportionalLoad
      k->bodyForce(q.data(), a, fb);  // rhoA int S^T a dx: its product with q is int rhoA a.r dx
      for (int i = 0; i < 8; ++i) e[1] -= fb[i] * q[i];
    }
  }
  for (int i = 0; i < asm_.mesh().numOwnedNodes; ++i) {
    const LocalNode& n = asm_.mesh().nodes[i];
    if (n.mass <= 0) continue;
    const double* s = asm_.nodeState(i);
    e[1] -= n.mass * (g[0] * s[0] + g[1] * s[1] + g[2] * (n.kind == NodeKind::Ancf2D ? 0.0 : s[2]));
  }
  PetscCall(asm_.endLocal(&u));
  MPI_Allreduce(MPI_IN_PLACE, e, 3, MPI_DOUBLE, MPI_SUM, asm_.mesh().comm);
  *strain = e[0];
  *grav = e[1];
  *ok = e[2] == 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

PetscErrorCode runDynamics(RunContext& ctx) {
  PetscFunctionBeginUser;
  const DynamicsOptions& opts = *ctx.model.opt.dynamics;
  const double tStart = MPI_Wtime();
  const double outBefore = ctx.times.output, anaBefore = ctx.times.analyses;
  SensorAnalysis* sensors = nullptr;
  for (auto& a : ctx.stepAnalyses)
    if (auto* s = dynamic_cast<SensorAnalysis*>(a.get())) sensors = s;
  PetscBool energy = PETSC_FALSE;
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-dynamics_energy", &energy, nullptr));
  bool energyOk = true;
  double energy0 = 0, maxDrift = 0;

  DynamicAnalysis dyn(ctx.assembler, opts);
  dyn.setStopFlag(&ctx.stop);
  dyn.setResultFile(&ctx.file);
  if (ctx.restart && ctx.restart->phase() == CheckpointPhase::Dynamics)
    PetscCall(ctx.restart->resumeDynamics(ctx, dyn, &energy0, &maxDrift));
  // the checkpoint of a written time step (Arnold-Brüls only: PETSc TS keeps its state inside)
  Vec stepU = nullptr, stepV = nullptr, stepQdd = nullptr;  // the step being written
  if (!dyn.usesPetscTS())
    ctx.checkpointState = [&](CheckpointData& d) -> PetscErrorCode {
      const DynamicsProgress& p = dyn.progress();
      d.scalars[kCkPhase] = static_cast<double>(CheckpointPhase::Dynamics);
      d.scalars[kCkStep] = p.step;
      d.scalars[kCkStepValue] = p.time;
      d.scalars[kCkTime] = p.time;
      d.scalars[kCkSubstep] = p.h;
      d.scalars[kCkSuccesses] = p.successes;
      d.scalars[kCkDt] = opts.dt;
      d.scalars[kCkSpectralRadius] = opts.spectral_radius;
      d.scalars[kCkEnergy0] = energy0;
      d.scalars[kCkMaxDrift] = maxDrift;
      d.vectors = {{"U", stepU}, {"V", stepV}, {"A", dyn.auxiliaryAccelerations()}, {"Qdd", stepQdd}};
      return PETSC_SUCCESS;
    };
  const int nsteps = std::max(1, static_cast<int>(std::ceil(opts.tend / opts.dt - 1e-9)));
  ctx.progress.startPhase("time step", nsteps);
  auto writeEnergy = [&](int k, Vec U, Vec V, const LoadState& ls) -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (energy && energyOk) {
      double T = 0, S = 0, G = 0;
      bool ok = true;
      PetscCall(ctx.assembler.kineticEnergy(U, V, ls, &T));
      PetscCall(potentialEnergy(ctx.assembler, ctx.model.opt.gravity, U, ls, &S, &G, &ok));
      if (!ok) {
        energyOk = false;
        PetscCall(PetscPrintf(ctx.comm, "  -dynamics_energy: needs ancf_cable2d elements without user functions; not written\n"));
        PetscFunctionReturn(PETSC_SUCCESS);
      }
      const std::array<double, 4> row{T, S, G, T + S + G};
      if (k == 0) energy0 = row[3];
      maxDrift = std::max(maxDrift, std::abs(row[3] - energy0));
      ctx.file.writeStepRow("energy", row);
    }
    PetscFunctionReturn(PETSC_SUCCESS);
  };
  auto onStep = [&](int k, double t, Vec U, Vec V, Vec Qdd) -> PetscErrorCode {
    PetscFunctionBeginUser;
    const bool last = k == nsteps;
    if (k != 0 && !last && k % opts.output_every != 0) PetscFunctionReturn(PETSC_SUCCESS);
    LoadState ls;
    ls.loadFactor = 1.0;
    ls.time = t;
    ls.gravityRamped = false;
    if (sensors) sensors->setRates(V, Qdd);
    stepU = U;
    stepV = V;
    stepQdd = Qdd;
    char detail[64];
    std::snprintf(detail, sizeof detail, "t = %.6g", t);
    PetscCall(ctx.convergedStep({k, last, t, detail}, U, ls, [&]() { return writeEnergy(k, U, V, ls); }));
    if (sensors) sensors->setRates(nullptr, nullptr);
    PetscFunctionReturn(PETSC_SUCCESS);
  };
  bool ok = false;
  PetscCall(dyn.run(ctx.U, onStep, &ok));
  ctx.lastStepName = "time step";
  ctx.checkpointState = nullptr;
  if (!ok && !ctx.stop) PetscCall(ctx.writeSkippedLast(ctx.U));
  if (!ok && ctx.converged && !ctx.stop) {
    ctx.converged = false;
    ctx.failure = dyn.failureMessage();
  }
  const DynamicsReport& r = dyn.report();
  std::ostringstream s;
  s << "  dynamics: " << r.steps << " of " << nsteps << " steps of dt = " << opts.dt << " to t = " << r.time
    << ", generalized-alpha rho = " << opts.spectral_radius << " (alpha_m = " << dyn.alphaM()
    << ", alpha_f = " << dyn.alphaF() << "), " << r.newtonIterations << " Newton iterations on " << r.jacobians << " Jacobians, "
    << ctx.assembler.counters().dampingMatrices << " element damping matrices";
  if (r.guardedSteps > 0) s << ", " << r.guardedSteps << " steps retried from the last state";
  if (r.reducedSteps > 0) s << ", " << r.reducedSteps << " steps with halved sub-steps (" << r.substeps << " solves)";
  s << "\n";
  if (energy && energyOk) s << "  energy: initial " << energy0 << ", largest change " << maxDrift << "\n";
  ctx.summaryLines += s.str();
  ctx.times.dynamics += MPI_Wtime() - tStart - (ctx.times.output - outBefore) - (ctx.times.analyses - anaBefore);
  ctx.times.dynamicsIts = r.newtonIterations;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
