// The one Newton convergence test (solvers/newton_test.hpp): every rule decides where it should and
// only there, on synthetic iterates of a SNES (one process). Exit status 0 only when every check passed.
#include <petscsnes.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "solvers/newton_test.hpp"

namespace {

using sinew::NewtonIterate;
using sinew::NewtonRules;
using sinew::NewtonTest;

int failures = 0;

void expect(bool ok, const char* what) {
  std::printf("  %-74s %s\n", what, ok ? "ok" : "FAILED");
  if (!ok) ++failures;
}

struct Point {
  double fnorm, snorm, xnorm;
};

/// Runs the iterates 0, 1, ... through the test until it decides; returns the verdict and its iteration.
PetscErrorCode run(SNES snes, NewtonTest& test, const std::vector<Point>& pts, double scale, double floor,
                   SNESConvergedReason* reason, int* at) {
  PetscFunctionBeginUser;
  *reason = SNES_CONVERGED_ITERATING;
  *at = -1;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    NewtonIterate x;
    x.it = static_cast<PetscInt>(k);
    x.fnorm = pts[k].fnorm;
    x.snorm = pts[k].snorm;
    x.xnorm = pts[k].xnorm;
    x.scale = scale;
    x.floor = floor;
    x.coordMax = 1.0;
    PetscCall(test.judge(snes, x, reason));
    if (*reason != SNES_CONVERGED_ITERATING) {
      *at = static_cast<int>(k);
      break;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode checks(SNES snes) {
  PetscFunctionBeginUser;
  SNESConvergedReason why;
  int at;
  const double inf = std::numeric_limits<double>::infinity();

  expect(sinew::forceScale(2.0, 50.0, 10.0) == 10.0 && sinew::forceScale(2.0, 5.0) == 5.0 &&
             sinew::forceScale(7.0, 5.0) == 7.0,
         "force scale: max(f_ext, min(f_int, cap))");
  expect(std::abs(sinew::roundoffFloor(1e6, 2.0) - 16.0 * 2.220446049250313e-16 * 1e6) < 1e-24,
         "round-off floor 8 eps ||J|| max|X|");

  {  // force rule, from iteration 0 (statics) or 1 (dynamics)
    NewtonRules r;
    r.snes = NewtonRules::Snes::Own;
    r.forceRtol = 1e-10;
    NewtonTest t(r);
    PetscCall(run(snes, t, {{1e-11, 0, 1}}, 1.0, 0, &why, &at));
    expect(why == SNES_CONVERGED_FNORM_ABS && at == 0, "force rule: r <= force_rtol * scale at iteration 0");
    t.rules().forceFromIteration = 1;
    PetscCall(run(snes, t, {{1e-11, 0, 1}, {1e-11, 1e-3, 1}}, 1.0, 0, &why, &at));
    expect(why == SNES_CONVERGED_FNORM_ABS && at == 1, "force rule from iteration 1 waits for an update");
    t.rules().forceRtol = 1e-12;
    PetscCall(run(snes, t, {{1.0, 0, 1}, {1e-11, 1e-3, 1}, {1e-11, 1e-9, 1}}, 1.0, 0, &why, &at));
    expect(why == SNES_CONVERGED_ITERATING, "force rule: a residual above force_rtol * scale iterates");
  }
  {  // start rule: relative to the increment's start residual (before the predictor)
    NewtonRules r;
    r.snes = NewtonRules::Snes::Own;
    r.startRelative = true;
    NewtonTest t(r);
    t.setStartResidual(1.0);  // SNES rtol 1e-9 (set in main)
    // r_1 = 5e-7 is below 1e-9 r_0 (SNES's own relative test) but not below 1e-9 r_start
    PetscCall(run(snes, t, {{1e3, 0, 1}, {5e-7, 1, 1}, {5e-10, 1e-3, 1}}, 1.0, 0, &why, &at));
    expect(why == SNES_CONVERGED_FNORM_RELATIVE && at == 2, "start rule: r <= snes_rtol * r_start, not * r_0");
  }
  {  // start at the floor; stalled at the floor; statics' divergence
    NewtonRules r;
    r.snes = NewtonRules::Snes::Own;
    r.startFloorFactor = 1e-2;
    NewtonTest t(r);
    PetscCall(run(snes, t, {{0.5e-2, 0, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_FNORM_ABS && at == 0, "start-at-floor: r_0 <= 1e-2 floor is equilibrium");
    PetscCall(run(snes, t, {{2e-2, 0, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_ITERATING, "start-at-floor: r_0 above 1e-2 floor iterates");
    {  // a residual that is a load increment below the floor (a tiny load) is no equilibrium (issue 24 item 5)
      NewtonIterate x(0, 1, 0, 0.5e-2);
      x.scale = 0.5e-2;
      x.floor = 1.0;
      x.loadChange = 0.5e-2;
      NewtonTest tl(t.rules());
      PetscCall(tl.judge(snes, x, &why));
      expect(why == SNES_CONVERGED_ITERATING, "start-at-floor: r_0 that is the load increment iterates");
      x.loadChange = 0;
      PetscCall(tl.judge(snes, x, &why));
      expect(why == SNES_CONVERGED_FNORM_ABS, "start-at-floor: unchanged loads, r_0 at the floor is equilibrium");
    }

    t.rules().stalledAtFloor = true;
    // 1e4 -> 500 -> 0.9 (into the floor, 1/555 of the previous: neither stalled nor a 1000x drop, nor
    // from just above it) -> 0.5 (stalled: less than 10x, below 1e-3 r_0)
    PetscCall(run(snes, t, {{1e4, 0, 1}, {500, 1, 1}, {0.9, 1e-2, 1}, {0.5, 1e-3, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_FNORM_ABS && at == 3, "stalled: below the floor and 1e-3 r_0, no longer 10x per iteration");
    PetscCall(run(snes, t, {{1e4, 0, 1}, {500, 1, 1}, {0.9, 1e-2, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_ITERATING, "stalled: a first drop into the floor from far above iterates");
    t.rules().stalledAtFloor = false;
    PetscCall(run(snes, t, {{1e4, 0, 1}, {500, 1, 1}, {0.9, 1e-2, 1}, {0.5, 1e-3, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_ITERATING, "stalled rule off: the same iterates go on");

    t.rules().divergedIts = 3;
    PetscCall(run(snes, t, {{1.0, 0, 1}, {3.0, 1, 1}, {2.0, 1, 1}, {1.5, 1, 1}}, 1.0, 0, &why, &at));
    expect(why == SNES_DIVERGED_DTOL && at == 3, "diverged: above r_0 after divergedIts iterations is cut");
    PetscCall(run(snes, t, {{1.0, 0, 1}, {3.0, 1, 1}, {2.0, 1, 1}, {0.5, 1, 1}}, 1.0, 0, &why, &at));
    expect(why == SNES_CONVERGED_ITERATING, "diverged: below r_0 at divergedIts iterates");
  }
  {  // update rule, relative (statics with the element-wise operator; the coarse predictor)
    NewtonRules r;
    r.snes = NewtonRules::Snes::Own;
    r.update = NewtonRules::Update::Relative;
    r.updateTight = 1e-8;
    r.updateLoose = 1e-6;
    r.updateFloorFactor = 1.0;
    NewtonTest t(r);
    PetscCall(run(snes, t, {{10, 0, 1}, {0.5, 1e-2, 1}, {0.5, 5e-9, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_SNORM_RELATIVE && at == 2 && t.convergedOnUpdate(), "update: s/x <= 1e-8 at the floor");
    PetscCall(run(snes, t, {{10, 0, 1}, {0.5, 1e-5, 1}, {0.5, 5e-7, 1}, {0.5, 4e-7, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_SNORM_RELATIVE && at == 3, "update: below 1e-6 and no longer shrinking tenfold");
    PetscCall(run(snes, t, {{10, 0, 1}, {2.0, 1e-2, 1}, {2.0, 5e-9, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_ITERATING && !t.convergedOnUpdate(), "update: not while the residual is above the floor");
    t.rules().updateNeedsStartAtFloor = true;
    PetscCall(run(snes, t, {{10, 0, 1}, {0.5, 1e-2, 1}, {0.5, 5e-9, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_ITERATING, "update: only from a start at the floor when asked");
    t.rules().updateFloorFactor = 0;
    t.rules().updateNeedsStartAtFloor = false;
    PetscCall(run(snes, t, {{1e9, 0, 1}, {1e9, 1e-2, 1}, {1e9, 5e-9, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_SNORM_RELATIVE && at == 2, "update: at any residual (coarse predictor)");
    t.rules().update = NewtonRules::Update::None;
    PetscCall(run(snes, t, {{1e9, 0, 1}, {1e9, 1e-2, 1}, {1e9, 5e-9, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_ITERATING, "update rule off: the same iterates go on");
  }
  {  // dynamics: SNES's update verdict only at a small residual; contraction; at rest; midpoint; NaN
    NewtonRules r;
    r.snes = NewtonRules::Snes::KeepButUpdate;
    r.snesUpdateForceRtol = 1e-6;
    NewtonTest t(r);
    // SNES stol 1e-8 (main): an update of 1e-10 with a residual of 1e-3 of the forces proves nothing
    PetscCall(run(snes, t, {{1.0, 0, 1}, {1e-3, 1e-10, 1}}, 1.0, 0, &why, &at));
    expect(why == SNES_CONVERGED_ITERATING, "dynamics: SNES's update verdict overruled at r > 1e-6 scale");
    PetscCall(run(snes, t, {{1.0, 0, 1}, {1e-7, 1e-10, 1}}, 1.0, 0, &why, &at));
    expect(why == SNES_CONVERGED_SNORM_RELATIVE && at == 1, "dynamics: SNES's update verdict kept at r <= 1e-6 scale");

    t.rules().update = NewtonRules::Update::Contraction;
    t.rules().updateRtol = 1e-6;
    PetscCall(run(snes, t, {{1.0, 0, 1}, {0.5, 1e-3, 1}, {0.5, 1e-6, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_SNORM_RELATIVE && at == 2 && std::abs(t.contraction() - 1e-3) < 1e-15,
           "contraction: theta/(1-theta) |dU| <= 1e-6 |U|, theta = 1e-3");
    PetscCall(run(snes, t, {{1.0, 0, 1}, {0.5, 1e-3, 1}, {0.9, 1e-6, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_ITERATING, "contraction: not while the residual grows past 1.5x");
    PetscCall(run(snes, t, {{1.0, 0, 1}, {0.5, 1e-3, 1}, {0.5, 6e-4, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_ITERATING, "contraction: a slowly contracting update iterates");

    t.rules().update = NewtonRules::Update::None;
    t.rules().atRest = true;
    PetscCall(run(snes, t, {{0.5, 0, 1}, {0.5, 1e-14, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_SNORM_RELATIVE && at == 1, "at rest: residual and update at round-off");
    t.rules().atRest = false;
    t.rules().droppedBelowFloor = true;
    PetscCall(run(snes, t, {{100, 0, 1}, {0.05, 1e-2, 1}}, 1.0, 1.0, &why, &at));
    expect(why == SNES_CONVERGED_FNORM_ABS && at == 1, "dropped: below the floor and 1e-3 of r_0");

    t.rules().forceRtol = 1e-6;
    t.rules().forceFromIteration = 1;
    t.rules().finalUpdateRtol = 1e-14;
    PetscCall(run(snes, t, {{1.0, 0, 1}, {1e-8, 1e-3, 1}, {1e-9, 1e-15, 1}}, 1.0, 0, &why, &at));
    expect(why > 0 && at == 2, "midpoint: a verdict waits for an update at round-off");
    // energy-momentum with the consistent beam mass (the spin-up at 6 rad/s): the update of iteration 3
    // came from a residual at the floor (2e-6), so the step ends there instead of at the 1e-14 update
    const std::vector<Point> spin = {{19, 0, 10}, {0.15, 2.9e-3, 10}, {3e-8, 2.2e-7, 10}, {1e-8, 5.8e-12, 10}, {1e-8, 1e-15, 10}};
    PetscCall(run(snes, t, spin, 19.0, 2e-6, &why, &at));
    expect(why > 0 && at == 4, "midpoint: the spin-up's steps end at the 1e-14 update, iteration 4");
    t.rules().finalUpdateAtFloor = true;
    PetscCall(run(snes, t, spin, 19.0, 2e-6, &why, &at));
    expect(why > 0 && at == 3, "final update at floor: the update after a residual at the floor ends the step");
    PetscCall(run(snes, t, {{19, 0, 10}, {1e-7, 2.9e-3, 10}, {3e-8, 2.2e-7, 10}}, 19.0, 0, &why, &at));
    expect(why == SNES_CONVERGED_ITERATING, "final update at floor: not while the residuals are above the floor");
    t.rules().finalUpdateAtFloor = false;
    t.rules().finalUpdateRtol = 0;
    PetscCall(run(snes, t, {{1.0, 0, 1}, {1e-8, 1e-3, 1}}, 1.0, 0, &why, &at));
    expect(why == SNES_CONVERGED_FNORM_ABS && at == 1, "without the midpoint rule the force rule decides at once");

    PetscCall(run(snes, t, {{1.0, 0, 1}, {inf, 1e-3, 1}}, 1.0, 0, &why, &at));
    expect(why == SNES_DIVERGED_FNORM_NAN, "a non-finite residual diverges");
  }
  {  // a Newton loop written by hand (path following): tolerance or floor, from the first update on
    NewtonRules r;
    r.forceRtol = 1.0;
    r.forceFromIteration = 1;
    r.belowFloor = true;
    NewtonTest t(r);
    NewtonIterate x;
    x.fnorm = 1e-12;
    x.scale = 1e-9;
    expect(t.judge(x) == SNES_CONVERGED_ITERATING, "path: iteration 0 is never converged");
    x.it = 1;
    expect(t.judge(x) == SNES_CONVERGED_FNORM_ABS, "path: r <= tol after an update");
    x.fnorm = 1e-6;
    x.floor = 2e-6;
    expect(t.judge(x) == SNES_CONVERGED_FNORM_ABS, "path: r above tol but below the floor");
    x.floor = 0;
    expect(t.judge(x) == SNES_CONVERGED_ITERATING, "path: r above tol and floor iterates");
    t.rules().belowFloor = false;
    x.floor = 2e-6;
    expect(t.judge(x) == SNES_CONVERGED_ITERATING, "below-floor rule off: the same iterate goes on");
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

int main(int argc, char** argv) {
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  SNES snes;
  PetscCall(SNESCreate(PETSC_COMM_SELF, &snes));
  PetscCall(SNESSetTolerances(snes, 1e-50, 1e-9, 1e-8, 50, 10000));
  PetscCall(SNESSetDivergenceTolerance(snes, -1.0));
  PetscCall(checks(snes));
  PetscCall(SNESDestroy(&snes));
  std::printf("%s: %d failed\n", failures ? "FAILED" : "passed", failures);
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
