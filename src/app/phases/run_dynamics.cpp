// opt.dynamics: generalized-alpha time integration (src/dynamics/dynamic_analysis.hpp) from the
// (form-found) state at rest; writes t = 0 and every output_every-th step (and the last) as rows
// of /time, with sensors seeing velocities and accelerations. -dynamics_energy adds
// /energy/{kinetic, strain, external_work, total} [ns] (total = T + S - W) and /momentum/{linear,
// angular} [ns, 3] (src/dynamics/energy_momentum.hpp; the external work integrates the loads'
// power over every time step, written or not).
#include <array>
#include <memory>
#include <cstdio>
#include <cmath>
#include <sstream>

#include "app/phases/restart.hpp"
#include "app/phases/run_context.hpp"
#include "dynamics/dynamic_analysis.hpp"
#include "dynamics/energy_momentum.hpp"
#include "step/sensor_analysis.hpp"

namespace sinew {

namespace {
/// Whether a beam set has a density (the beams' mass, -beam_mass, matters).
bool beamsWithMass(const Model& model) {
  for (const auto& set : model.eprops)
    if (const auto* b = set.as<BeamProperties>(); b && b->dens > 0) return true;
  return false;
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
  const bool energy = ctx.settings.dynamics.energy;
  bool energyOk = true;
  double energy0 = 0, maxDrift = 0, work = 0, power = 0, tPrev = 0;
  std::unique_ptr<EnergyMomentum> em;
  if (energy) em = std::make_unique<EnergyMomentum>(ctx.assembler);

  DynamicAnalysis dyn(ctx.assembler, opts, ctx.settings);
  dyn.setStopFlag(ctx.status.stopFlag());
  dyn.setResultFile(&ctx.file);
  if (ctx.restart && ctx.restart->phase() == CheckpointPhase::Dynamics) {
    PetscCall(ctx.restart->resumeDynamics(ctx, dyn, &energy0, &maxDrift, &work, &power));
    tPrev = dyn.progress().time;
  } else {
    dyn.setLevelHandover(ctx.settings.accuracy.handover.get());  // a -target_error level in time
  }
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
      d.scalars[kCkExternalWork] = work;
      d.scalars[kCkExternalPower] = power;
      d.scalars[kCkAdaptScale] = p.scale;
      d.vectors = {{"U", stepU}, {"V", stepV}, {"A", dyn.auxiliaryAccelerations()}, {"Qdd", stepQdd}};
      return PETSC_SUCCESS;
    };
  const int nsteps = std::max(1, static_cast<int>(std::ceil(opts.tend / opts.dt - 1e-9)));
  ctx.startPhase(StepPhase::Dynamics, "time step", nsteps);
  // external work: trapezoidal rule on the loads' power f_ext . qd at every time step
  auto addWork = [&](int k, double t, Vec U, Vec V, const LoadState& ls) -> PetscErrorCode {
    PetscFunctionBeginUser;
    double p = 0;
    PetscCall(em->externalPower(U, V, ls, &p));
    if (k > 0) work += 0.5 * (t - tPrev) * (power + p);
    power = p;
    tPrev = t;
    PetscFunctionReturn(PETSC_SUCCESS);
  };
  auto writeEnergy = [&](int k, Vec U, Vec V, const LoadState& ls) -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (energy && energyOk) {
      EnergyMomentumRow r;
      bool ok = true;
      std::string missing;
      PetscCall(em->evaluate(U, V, ls, &r, &ok, &missing));
      if (!ok) {
        energyOk = false;
        PetscCall(PetscPrintf(ctx.comm, "  -dynamics_energy: no strain energy for %s elements; /energy and /momentum not written\n",
                              missing.c_str()));
        PetscFunctionReturn(PETSC_SUCCESS);
      }
      const double total = r.kinetic + r.strain - work;
      if (k == 0) energy0 = total;
      maxDrift = std::max(maxDrift, std::abs(total - energy0));
      ctx.file.writeStepRow("energy/kinetic", std::array<double, 1>{r.kinetic});
      ctx.file.writeStepRow("energy/strain", std::array<double, 1>{r.strain});
      ctx.file.writeStepRow("energy/external_work", std::array<double, 1>{work});
      ctx.file.writeStepRow("energy/total", std::array<double, 1>{total});
      ctx.file.writeStepRow("momentum/linear", r.linear);
      ctx.file.writeStepRow("momentum/angular", r.angular);
    }
    PetscFunctionReturn(PETSC_SUCCESS);
  };
  auto onStep = [&](int k, double t, Vec U, Vec V, Vec Qdd) -> PetscErrorCode {
    PetscFunctionBeginUser;
    const bool last = k == nsteps;
    const LoadState ls = DynamicAnalysis::loadsAt(t);
    if (energy && energyOk && (k == 0 || !dyn.adaptive())) PetscCall(addWork(k, t, U, V, ls));  // adaptive: onSubstep
    if (k != 0 && !last && k % opts.output_every != 0) PetscFunctionReturn(PETSC_SUCCESS);
    stepU = U;
    stepV = V;
    stepQdd = Qdd;
    if (k == 0 && dyn.damped() && !dyn.usesPetscTS()) {  // the damping's start state, for a -restart
      PetscErrorCode ierr = PETSC_SUCCESS;
      stepU = dyn.dampingState();  // U as the damping saw it (multipliers before lambda0)
      ctx.guardedWrite([&] { ierr = ctx.writeCheckpoint(kDynamicsStartGroup); });
      PetscCall(ierr);
      stepU = U;
    }
    if (sensors) sensors->setRates(V, Qdd);
    ctx.assembler.setReactionRates(V, Qdd);  // dynamic reactions: f_int - f_ext + M qdd
    char detail[64];
    std::snprintf(detail, sizeof detail, "t = %.6g", t);
    PetscCall(ctx.convergedStep({k, last, t, detail}, U, ls, [&]() -> PetscErrorCode {
      PetscFunctionBeginUser;
      if (dyn.adaptive()) {  // the step size that reached this row and the steps taken since t = 0
        ctx.file.writeStepRow("dynamics/dt", std::array<double, 1>{k == 0 ? 0.0 : dyn.lastStep()});
        ctx.file.writeStepRow("dynamics/steps", std::array<double, 1>{static_cast<double>(dyn.report().acceptedSteps)});
      }
      PetscCall(writeEnergy(k, U, V, ls));
      PetscFunctionReturn(PETSC_SUCCESS);
    }));
    if (sensors) sensors->setRates(nullptr, nullptr);
    ctx.assembler.setReactionRates(nullptr, nullptr);
    PetscFunctionReturn(PETSC_SUCCESS);
  };
  if (dyn.adaptive() && energy)  // the external work integrates over every accepted step
    dyn.setSubstepCallback([&](double t, Vec U, Vec V) -> PetscErrorCode {
      PetscFunctionBeginUser;
      if (energyOk) PetscCall(addWork(1, t, U, V, DynamicAnalysis::loadsAt(t)));
      PetscFunctionReturn(PETSC_SUCCESS);
    });
  bool ok = false;
  PetscCall(dyn.run(ctx.U, onStep, &ok));
  ctx.checkpointState = nullptr;
  if (!ok && !ctx.status.stopping()) PetscCall(ctx.writeSkippedLast(ctx.U));
  if (ok) PetscCall(ctx.finishStepAnalyses(ctx.U));
  if (!ok && !ctx.status.stopping()) ctx.status.fail(dyn.failureMessage());
  const DynamicsReport& r = dyn.report();
  std::ostringstream s;
  s << "  dynamics: " << r.steps << " of " << nsteps << " steps of dt = " << opts.dt << " to t = " << r.time;
  if (dyn.midpoint()) s << ", implicit midpoint rule";
  else if (dyn.energyMomentum()) {
    s << ", energy-momentum scheme" << (dyn.energyDecay() > 0 ? " with energy decay" : "");
    if (ctx.settings.dynamics.linearMassByScheme() && beamsWithMass(ctx.model))
      s << " (beams: the linear mass, energy-exact; -beam_mass)";
  }
  else s << ", generalized-alpha rho = " << opts.spectral_radius << " (alpha_m = " << dyn.alphaM() << ", alpha_f = " << dyn.alphaF() << ")";
  s << ", " << r.newtonIterations << " Newton iterations on " << r.jacobians << " Jacobians";
  if (r.corotatedJacobians > 0) s << " (" << r.corotatedJacobians << " rebuilt from rotated element blocks)";
  if (r.refinedSolves > 0)
    s << ", " << r.refinedSolves << " refinements of step solves with the element-wise Newton matrix (" << r.refinements
      << " per solve at the end)";
  s << ", " << ctx.assembler.counters().dampingMatrices << " element damping matrices";
  if (r.coarseStarts > 0) s << ", " << r.coarseStarts << " steps started from the coarser level";
  if (r.guardedSteps > 0) s << ", " << r.guardedSteps << " steps retried from the last state";
  if (r.reducedSteps > 0) s << ", " << r.reducedSteps << " steps with halved sub-steps (" << r.substeps << " solves)";
  s << "\n";
  if (dyn.adaptive())
    s << "  adaptive steps: " << r.acceptedSteps << " accepted steps of h = " << r.hMin << " .. " << r.hMax << ", "
      << r.rejectedSteps << " rejected by the error estimate\n";
  if (energy && energyOk) s << "  energy: T + S - W initially " << energy0 << ", largest change " << maxDrift << "\n";
  ctx.summaryLines += s.str();
  ctx.times.dynamics += MPI_Wtime() - tStart - (ctx.times.output - outBefore) - (ctx.times.analyses - anaBefore);
  ctx.times.dynamicsIts = r.newtonIterations;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
