// Path following's end report (src/analysis/path_report.hpp): the stop reason and whether it ends
// short of the scene's stop criterion; a path that runs back along itself (issue 24 item 4).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/path_report.hpp"

using sinew::ContinuationOptions;

TEST(PathReport, StopReason) {
  ContinuationOptions c;
  c.max_steps = 200;
  c.node = 2;
  auto end = sinew::pathEnd(c, 200, 0.58069, -0.012, false, false);
  EXPECT_EQ(end.reason, "max_steps 200 reached");
  EXPECT_FALSE(end.endedShort);  // no other end asked for
  c.stop_displacement = -0.02;
  end = sinew::pathEnd(c, 200, 0.58069, -0.012, false, false);
  EXPECT_TRUE(end.endedShort);
  EXPECT_EQ(end.reason, "max_steps 200 reached before stop_displacement -0.02 (load factor 0.58069, control displacement -0.012)");
  end = sinew::pathEnd(c, 150, 0.7, -0.021, false, false);
  EXPECT_FALSE(end.endedShort);
  EXPECT_EQ(end.reason, "stop_displacement -0.02 reached (control displacement -0.021)");
  c.stop_load_factor = 0.5;
  end = sinew::pathEnd(c, 20, 0.51, -0.001, false, false);
  EXPECT_EQ(end.reason, "stop_load_factor 0.5 reached (load factor 0.51)");
  EXPECT_FALSE(sinew::pathEnd(c, 20, 0.4, -0.001, true, false).endedShort);  // a failure is reported as such
  EXPECT_EQ(sinew::pathEnd(c, 20, 0.4, -0.001, false, true).reason, "interrupted after path point 20");
}

TEST(PathReport, Retrace) {
  std::vector<double> lambda, u;
  // up a curve to a turning point, then back down the same curve (the predictor reversed)
  for (int i = 0; i <= 10; ++i) {
    lambda.push_back(std::sin(0.1 * i));
    u.push_back(-0.01 * i);
  }
  for (int i = 9; i >= 5; --i) {
    lambda.push_back(std::sin(0.1 * i) + 1e-4);
    u.push_back(-0.01 * i);
  }
  const auto r = sinew::pathRetrace(lambda, u);
  EXPECT_EQ(r.point, 11);
  EXPECT_EQ(r.earlier, 9);
  // a limit point passed (load factor back down while the displacement grows) and a snap-back loop
  // (the displacement turns back, the path crosses itself at an angle): no retrace
  std::vector<double> l2, u2;
  for (int i = 0; i <= 60; ++i) {
    const double t = 0.1 * i;
    l2.push_back(std::sin(t) + 0.3 * std::sin(2 * t));
    u2.push_back(-(t - 1.5 * std::sin(t)));  // u reverses twice: a loop in the (lambda, u) plane
  }
  EXPECT_EQ(sinew::pathRetrace(l2, u2).point, -1);
  // no control displacement: nothing to judge
  EXPECT_EQ(sinew::pathRetrace(lambda, std::vector<double>(lambda.size(), 0.0)).point, -1);
}

TEST(PathReport, TurnBack) {
  // a path that turns back after its limit point and runs back down the way it came (load factors
  // within 1e-3 of those there): limit at u = -0.0053, on to u = -0.0170, back to u = -0.0057
  const std::vector<double> lambda = {0, 0.02, 0.0415, 0.03, 0.01, -0.01, 0.0101, 0.0301, 0.0405, 0.03};
  const std::vector<double> u = {0, -0.0011, -0.0053, -0.0089, -0.0130, -0.0170, -0.0130, -0.0089, -0.0057, -0.0100};
  const auto r = sinew::pathTurnBack(lambda, u);
  EXPECT_EQ(r.limit, 2);
  EXPECT_EQ(r.turn, 5);
  EXPECT_EQ(r.back, 8);
  EXPECT_NEAR(r.fraction, (0.0170 - 0.0057) / 0.0170, 1e-12);
  // the shallow arch of issue 24 as shallow-arch theory and Sinew follow it: limit at u = -0.0052, on
  // to u = -0.0171, back to u = -0.0057 at other load factors (a loop of the symmetric path), on to
  // the inverted state: another branch, no turn-back
  const std::vector<double> la = {0, 0.2, 0.415, 0.2, -0.3, -0.618, -0.45, -0.2, 0.3, 0.553, 0.49, 0.2, -0.45, 0, 0.3};
  const std::vector<double> ua = {0, -0.0011, -0.0052, -0.0089, -0.0130, -0.0155, -0.0171, -0.0150, -0.0090, -0.0061,
                                  -0.0057, -0.0090, -0.0165, -0.0202, -0.0215};
  EXPECT_EQ(sinew::pathTurnBack(la, ua).turn, -1);
  // a snap-back (Lee's frame): the displacement turns back over a small part of its way, then on
  const std::vector<double> l2 = {0, 10, 18.5, 10, 0, -9, -5, 5, 20};
  const std::vector<double> u2 = {0, -20, -40, -55, -70, -80, -65, -75, -100};
  EXPECT_EQ(sinew::pathTurnBack(l2, u2).turn, -1);
  // past the limit point the displacement goes on (the von Mises truss): nothing
  EXPECT_EQ(sinew::pathTurnBack({0, 3, 3.8, 3, 0, -3.8, -2, 0}, {0, -0.01, -0.04, -0.08, -0.1, -0.16, -0.2, -0.22}).turn, -1);
}
