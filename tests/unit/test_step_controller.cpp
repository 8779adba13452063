// Unit tests of the one step loop (src/solvers/step_controller.hpp), driven by synthetic solves:
// each rule (cut, cut limit, smallest step, same-size retry, growth by iterations and by converged
// steps in a row, the largest step, landing on the target, size strategies) acts where it should,
// and each switched off no longer acts, so a rule the controller ignored would fail here.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "solvers/step_controller.hpp"

using sinew::IterationTarget;
using sinew::Landing;
using sinew::FirstSize;
using sinew::StepAttempt;
using sinew::StepController;
using sinew::StepNames;
using sinew::StepRules;
using sinew::StepSequence;
using sinew::SteppedProcedure;
using sinew::StepStop;

namespace {

struct Step {
  double x, to, h;
  bool converged;
};

/// A synthetic procedure: a step converges when its size is at most `hardest` (iterations `its`);
/// records every attempt, accepted step and message.
struct Synthetic {
  double hardest = 1e300;
  int its = 1;
  std::vector<Step> attempts;
  std::vector<double> accepted;  // positions reached
  std::vector<std::string> messages;
  SteppedProcedure procedure() {
    SteppedProcedure p;
    p.solve = [this](double x, double to, double h, StepAttempt* a) {
      a->converged = h <= hardest;
      a->iterations = its;
      a->reason = "DIVERGED_MAX_IT";
      attempts.push_back({x, to, h, a->converged});
      return 0;
    };
    p.accept = [this](double, double to, double, const StepAttempt&) {
      accepted.push_back(to);
      return 0;
    };
    p.print = [this](const std::string& m) { messages.push_back(m); };
    return p;
  }
};

const StepNames kNames{"load step", "load factor", "increment"};

/// Report steps 1..n with targets k / n.
StepSequence ramp(int n) {
  StepSequence s;
  s.first = 1;
  s.last = n;
  s.target = [n](int k) { return static_cast<double>(k) / n; };
  return s;
}

StepStop runOnce(StepController& c, Synthetic& syn, const StepSequence& s, double* x) {
  StepStop stop = StepStop::None;
  EXPECT_EQ(c.run(syn.procedure(), s, x, &stop), 0);
  return stop;
}

}  // namespace

TEST(StepController, CutOnFailureThenConverges) {
  StepRules r;
  r.maxCuts = 5;
  StepController c(r, kNames);
  c.resume(1.0);
  Synthetic syn;
  syn.hardest = 0.3;
  double x = 0;
  EXPECT_EQ(runOnce(c, syn, ramp(1), &x), StepStop::EndReached);
  // 1 and 0.5 fail, 0.25 converges, then the rest in steps of 0.25 (no growth rule)
  ASSERT_GE(syn.attempts.size(), 3u);
  EXPECT_DOUBLE_EQ(syn.attempts[0].h, 1.0);
  EXPECT_DOUBLE_EQ(syn.attempts[1].h, 0.5);
  EXPECT_DOUBLE_EQ(syn.attempts[2].h, 0.25);
  EXPECT_EQ(syn.accepted.size(), 4u);
  EXPECT_EQ(x, 1.0);
  EXPECT_EQ(c.cuts(), 2);
  ASSERT_EQ(syn.messages.size(), 2u);
  EXPECT_EQ(syn.messages[0], "  load step 1: Newton failed at load factor 1 (DIVERGED_MAX_IT); retrying with increment 0.5\n");
}

TEST(StepController, CutFactor) {
  StepRules r;
  r.cutFactor = 0.25;
  StepController c(r, kNames);
  c.resume(1.0);
  Synthetic syn;
  syn.hardest = 0.3;
  double x = 0;
  runOnce(c, syn, ramp(1), &x);
  EXPECT_DOUBLE_EQ(syn.attempts[1].h, 0.25);
}

TEST(StepController, CutLimit) {
  for (int maxCuts : {0, 3}) {
    StepRules r;
    r.maxCuts = maxCuts;
    StepController c(r, kNames);
    c.resume(1.0);
    Synthetic syn;
    syn.hardest = 1e-6;  // needs 20 halvings
    double x = 0;
    EXPECT_EQ(runOnce(c, syn, ramp(1), &x), StepStop::CutLimit);
    EXPECT_EQ(syn.attempts.size(), static_cast<size_t>(maxCuts + 1));
    EXPECT_EQ(syn.messages.size(), static_cast<size_t>(maxCuts));
    EXPECT_EQ(x, 0.0);
    EXPECT_TRUE(syn.accepted.empty());
  }
  // switched off (no limit): the halvings go on until the step converges
  StepRules r;
  r.maxCuts = -1;
  StepController c(r, kNames);
  c.resume(1.0);
  Synthetic syn;
  syn.hardest = 1e-6;
  double x = 0;
  syn.attempts.reserve(1 << 21);
  EXPECT_EQ(runOnce(c, syn, ramp(1), &x), StepStop::EndReached);
  EXPECT_EQ(c.cuts(), 20);
}

TEST(StepController, CutsCountPerReportStep) {
  StepRules r;
  r.maxCuts = 1;
  r.firstSize = FirstSize::Rest;
  StepController c(r, kNames);
  Synthetic syn;
  syn.hardest = 0.15;  // every load step of 0.25 needs one halving
  double x = 0;
  EXPECT_EQ(runOnce(c, syn, ramp(4), &x), StepStop::EndReached);
  EXPECT_EQ(syn.messages.size(), 4u);
}

TEST(StepController, SmallestStep) {
  StepRules r;
  r.maxCuts = -1;
  r.minStep = 0.1;
  StepController c(r, kNames);
  c.resume(1.0);
  Synthetic syn;
  syn.hardest = 0.01;
  double x = 0;
  EXPECT_EQ(runOnce(c, syn, ramp(1), &x), StepStop::BelowMinimum);
  // 1, 0.5, 0.25, 0.125, then max(0.0625, 0.1) = 0.1 fails: stop
  ASSERT_EQ(syn.attempts.size(), 5u);
  EXPECT_DOUBLE_EQ(syn.attempts.back().h, 0.1);
  // switched off: the cuts go below 0.1 and the step converges
  r.minStep = 0;
  StepController off(r, kNames);
  off.resume(1.0);
  Synthetic syn2;
  syn2.hardest = 0.01;
  x = 0;
  EXPECT_EQ(runOnce(off, syn2, ramp(1), &x), StepStop::EndReached);
}

TEST(StepController, SameSizeRetryBeforeCutting) {
  StepRules r;
  StepController c(r, kNames);
  c.resume(1.0);
  Synthetic syn;
  bool other = false;  // the other way converges
  SteppedProcedure p = syn.procedure();
  p.solve = [&](double x, double to, double h, StepAttempt* a) {
    a->converged = other;
    a->reason = "DIVERGED_DTOL";
    syn.attempts.push_back({x, to, h, a->converged});
    return 0;
  };
  p.retry = [&](const StepAttempt&, bool* retry, std::string* how) {
    *retry = !other;
    other = true;
    *how = "full Newton from the last state";
    return 0;
  };
  double x = 0;
  StepStop stop;
  ASSERT_EQ(c.run(p, ramp(1), &x, &stop), 0);
  EXPECT_EQ(stop, StepStop::EndReached);
  ASSERT_EQ(syn.attempts.size(), 2u);
  EXPECT_DOUBLE_EQ(syn.attempts[1].h, 1.0);  // same size
  EXPECT_EQ(c.cuts(), 0);
  ASSERT_EQ(syn.messages.size(), 1u);
  EXPECT_EQ(syn.messages[0],
            "  load step 1: Newton failed at load factor 1 (DIVERGED_DTOL); retrying with full Newton from the last state\n");
}

TEST(StepController, GrowAfterFewIterations) {
  StepRules r;
  r.growIts = 3;
  r.maxStep = 0.5;
  StepController c(r, kNames);
  c.resume(0.125);
  Synthetic syn;
  syn.its = 3;
  double x = 0;
  EXPECT_EQ(runOnce(c, syn, ramp(1), &x), StepStop::EndReached);
  // 0.125, 0.25, 0.5 (never beyond maxStep), then the rest 0.125
  std::vector<double> h;
  for (const Step& s : syn.attempts) h.push_back(s.h);
  EXPECT_EQ(h, (std::vector<double>{0.125, 0.25, 0.5, 0.125}));
  EXPECT_EQ(x, 1.0);
  // more iterations than growIts: no growth
  Synthetic hard;
  hard.its = 4;
  StepController c2(r, kNames);
  c2.resume(0.125);
  x = 0;
  runOnce(c2, hard, ramp(1), &x);
  EXPECT_EQ(hard.attempts.size(), 8u);
  // switched off
  r.growIts = -1;
  StepController off(r, kNames);
  off.resume(0.125);
  Synthetic syn3;
  x = 0;
  runOnce(off, syn3, ramp(1), &x);
  EXPECT_EQ(syn3.attempts.size(), 8u);
}

TEST(StepController, GrowAfterConvergedStepsInARow) {
  StepRules r;
  r.growAfter = 2;
  r.maxStep = 0.5;
  r.firstSize = FirstSize::Carried;
  r.landing = Landing::Relative;
  r.landingSlack = 1e-6;
  StepController c(r, kNames);
  c.resume(0.125);
  Synthetic syn;
  double x = 0;
  runOnce(c, syn, ramp(1), &x);
  std::vector<double> h;
  for (const Step& s : syn.attempts) h.push_back(s.h);
  // two steps of 0.125 then 0.25 (twice, reaching 0.75) then 0.25 (the rest; the rule would allow 0.5)
  EXPECT_EQ(h, (std::vector<double>{0.125, 0.125, 0.25, 0.25, 0.25}));
  EXPECT_EQ(c.carried(), 0.5);
  // switched off
  r.growAfter = 0;
  StepController off(r, kNames);
  off.resume(0.125);
  Synthetic syn2;
  x = 0;
  runOnce(off, syn2, ramp(1), &x);
  EXPECT_EQ(syn2.attempts.size(), 8u);
}

TEST(StepController, MaxStepBoundsGrowth) {
  StepRules r;
  r.growIts = 10;
  r.maxStep = 0.3;
  StepController c(r, kNames);
  c.resume(0.2);
  Synthetic syn;
  double x = 0;
  runOnce(c, syn, ramp(1), &x);
  for (const Step& s : syn.attempts) EXPECT_LE(s.h, 0.3 + 1e-15);  // h = to - x: round-off
  // without the bound the steps grow beyond it
  r.maxStep = 1e300;
  StepController off(r, kNames);
  off.resume(0.2);
  Synthetic syn2;
  x = 0;
  runOnce(off, syn2, ramp(1), &x);
  EXPECT_GT(syn2.attempts[1].h, 0.3);
}

TEST(StepController, LandsExactlyOnTheTarget) {
  for (Landing l : {Landing::Absolute, Landing::Relative, Landing::EqualSplit, Landing::Clamp}) {
    StepRules r;
    r.landing = l;
    StepController c(r, kNames);
    c.resume(0.3);
    Synthetic syn;
    double x = 0;
    StepSequence s = ramp(1);
    s.target = [](int) { return 0.7; };
    EXPECT_EQ(runOnce(c, syn, s, &x), StepStop::EndReached);
    EXPECT_EQ(x, 0.7);  // exactly, never beyond
    EXPECT_EQ(syn.attempts.back().to, 0.7);
    for (const Step& st : syn.attempts) EXPECT_LE(st.to, 0.7);
    if (l == Landing::EqualSplit) {
      for (const Step& st : syn.attempts) EXPECT_NEAR(st.h, 0.7 / 3, 1e-15);
    }
  }
}

TEST(StepController, NoSliverStepNearTheTarget) {
  // 0.7 - 3 x 0.2333.. leaves a sliver of round-off size: with the slack the last step ends on 0.7
  for (double slack : {1e-9, 0.0}) {
    StepRules r;
    r.landing = Landing::Absolute;
    r.landingSlack = slack;
    StepController c(r, kNames);
    c.resume(0.7 / 3 - 1e-13);
    Synthetic syn;
    double x = 0;
    StepSequence s = ramp(1);
    s.target = [](int) { return 0.7; };
    runOnce(c, syn, s, &x);
    EXPECT_EQ(x, 0.7);
    EXPECT_EQ(syn.attempts.size(), slack > 0 ? 3u : 4u);
  }
}

TEST(StepController, FirstSizeOfATarget) {
  // a target's first step from 0.5 to 0.75 with the carried size 0.2 and maxStep 0.125: the carried
  // size, the rest (statics' fixed increments), maxStep (-dt_grow_after 0)
  struct Case {
    FirstSize rule;
    double first;
  };
  for (Case k : {Case{FirstSize::CarriedWithinRest, 0.2}, Case{FirstSize::Carried, 0.2}, Case{FirstSize::Rest, 0.25},
                 Case{FirstSize::Max, 0.125}}) {
    StepRules r;
    r.firstSize = k.rule;
    r.maxStep = 0.125;
    StepController c(r, kNames);
    c.resume(0.2);
    Synthetic syn;
    double x = 0.5;
    StepSequence s = ramp(1);
    s.target = [](int) { return 0.75; };
    runOnce(c, syn, s, &x);
    EXPECT_DOUBLE_EQ(syn.attempts[0].h, k.first);
  }
  // a carried size above the rest: within the rest, the size that grows is the rest (statics);
  // carried, the step lands on the target but the size that grows is the carried one
  for (FirstSize rule : {FirstSize::CarriedWithinRest, FirstSize::Carried}) {
    StepRules r;
    r.firstSize = rule;
    r.growIts = 100;
    StepController c(r, kNames);
    c.resume(0.4);
    Synthetic syn;
    double x = 0.5;
    StepSequence s = ramp(1);
    s.target = [](int) { return 0.75; };
    runOnce(c, syn, s, &x);
    EXPECT_DOUBLE_EQ(syn.attempts[0].h, 0.25);
    EXPECT_DOUBLE_EQ(c.carried(), rule == FirstSize::Carried ? 0.8 : 0.5);
  }
}

TEST(StepController, ZeroStepAtTarget) {
  StepRules r;
  r.firstSize = FirstSize::CarriedWithinRest;
  StepController c(r, kNames);
  c.resume(0.5);
  Synthetic syn;
  StepSequence s;
  s.first = 1;
  s.last = 3;
  s.target = [](int k) { return (k - 1) / 2.0; };  // SPACAR Light's steps: step 1 at load factor 0
  s.solveAtTarget = [](int k) { return k == 1; };
  double x = 0;
  EXPECT_EQ(runOnce(c, syn, s, &x), StepStop::EndReached);
  ASSERT_EQ(syn.attempts.size(), 3u);
  EXPECT_EQ(syn.attempts[0].h, 0.0);
  EXPECT_EQ(c.carried(), 0.5);  // a step of size 0 adapts nothing
  // a failed step of size 0 cannot be cut
  Synthetic fails;
  fails.hardest = -1;
  StepController c2(r, kNames);
  c2.resume(0.5);
  x = 0;
  EXPECT_EQ(runOnce(c2, fails, s, &x), StepStop::CutLimit);
  EXPECT_EQ(fails.attempts.size(), 1u);
  EXPECT_TRUE(fails.messages.empty());
}

TEST(StepController, StopReasons) {
  StepRules r;
  Synthetic syn;
  double x = 0;
  {  // report steps without a target: one step each, then MaxSteps
    StepController c(r, kNames);
    c.resume(0.1);
    StepSequence s;
    s.first = 1;
    s.last = 5;
    EXPECT_EQ(runOnce(c, syn, s, &x), StepStop::MaxSteps);
    EXPECT_EQ(syn.attempts.size(), 5u);
    EXPECT_NEAR(x, 0.5, 1e-15);
  }
  for (StepStop want : {StepStop::StopCondition, StepStop::Interrupted}) {
    StepController c(r, kNames);
    c.resume(1.0);
    StepSequence s = ramp(4);
    s.reached = [want](int& k, StepStop* stop) {
      if (k == 2) *stop = want;
      return 0;
    };
    x = 0;
    EXPECT_EQ(runOnce(c, syn, s, &x), want);
    EXPECT_EQ(x, 0.5);
  }
  {  // a procedure that made report steps of its own advances k
    StepController c(r, kNames);
    c.resume(1.0);
    StepSequence s;
    s.first = 1;
    s.last = 6;
    std::vector<int> seen;
    s.reached = [&seen](int& k, StepStop*) {
      seen.push_back(k);
      if (k == 2) ++k;
      return 0;
    };
    x = 0;
    runOnce(c, syn, s, &x);
    EXPECT_EQ(seen, (std::vector<int>{1, 2, 4, 5, 6}));
  }
  {  // an error code of a callback is passed on at once
    StepController c(r, kNames);
    SteppedProcedure p = syn.procedure();
    p.solve = [](double, double, double, StepAttempt*) { return 73; };
    StepStop stop;
    x = 0;
    EXPECT_EQ(c.run(p, ramp(2), &x, &stop), 73);
  }
}

TEST(StepController, SizeStrategies) {
  {  // a rejected converged step is repeated with the strategy's size and not accepted
    StepRules r;
    r.strategy = [](double h, double proposal, const StepAttempt&, double* next, bool* reject) {
      *reject = h > 0.2;  // steps above 0.2 are refused and repeated at half the size
      *next = *reject ? 0.5 * h : proposal;
      return 0;
    };
    r.growIts = 100;  // replaced by the strategy
    StepController c(r, kNames);
    c.resume(0.5);
    Synthetic syn;
    double x = 0;
    EXPECT_EQ(runOnce(c, syn, ramp(1), &x), StepStop::EndReached);
    EXPECT_EQ(syn.accepted.size(), 8u);
    EXPECT_EQ(c.cuts(), 0);
  }
  {  // iteration target: arc length scaled by sqrt(desired / its) within [0.5, 2] and |ds| <= max
    IterationTarget t(4, 0.5, 2.0, 0.3);
    EXPECT_DOUBLE_EQ(t.grown(0.1, 1), 0.2);
    EXPECT_DOUBLE_EQ(t.grown(0.1, 16), 0.05);
    EXPECT_DOUBLE_EQ(t.grown(0.2, 1), 0.3);
    EXPECT_DOUBLE_EQ(t.grown(-0.2, 1), -0.3);
    EXPECT_DOUBLE_EQ(t.grown(0.1, 100), 0.05);
    IterationTarget unbounded(4, 0.5, 2.0, 0.0);
    EXPECT_DOUBLE_EQ(unbounded.grown(0.2, 1), 0.4);
    StepRules r;
    r.strategy = t;
    StepController c(r, kNames);
    c.resume(0.1);
    Synthetic syn;
    syn.its = 1;
    StepSequence s;
    s.first = 1;
    s.last = 3;
    double x = 0;
    runOnce(c, syn, s, &x);
    EXPECT_DOUBLE_EQ(syn.attempts[1].h, 0.2);
    EXPECT_DOUBLE_EQ(syn.attempts[2].h, 0.3);
  }
}
