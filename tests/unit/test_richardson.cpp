// The Richardson estimate of -target_error (src/accuracy/richardson.hpp) on sequences with a known
// error: q(h) = q* + C h^p.
#include <gtest/gtest.h>

#include <cmath>

#include "accuracy/richardson.hpp"

using sinew::accuracy::EstimateStatus;
using sinew::accuracy::richardson;

namespace {

std::vector<double> level(double exact, double c, double p, int l) { return {exact + c * std::pow(0.5, p * l)}; }

}  // namespace

TEST(Richardson, AsymptoticSequenceGivesTheTrueErrorAndTheLimit) {
  // q = 2 + 0.1 h^4, h = 1, 1/2, 1/4: the estimate of the finest is its true error, q* the limit
  const auto q0 = level(2, 0.1, 4, 0), q1 = level(2, 0.1, 4, 1), q2 = level(2, 0.1, 4, 2);
  const auto e = richardson(q0, q1, q2, 2.0, 4.0, 1e-3);
  EXPECT_EQ(e.status, EstimateStatus::Converging);
  EXPECT_NEAR(e.order, 4.0, 1e-12);
  EXPECT_NEAR(e.error, (q2[0] - 2) / 2, 1e-15);
  ASSERT_EQ(e.extrapolated.size(), 1u);
  EXPECT_NEAR(e.extrapolated[0], 2.0, 1e-14);
}

TEST(Richardson, OrderFarFromTheElementsIsErratic) {
  // h^2 convergence where the element promises h^4 (below 4 - 0.6), and a change that grows
  auto e = richardson(level(1, 1, 2, 0), level(1, 1, 2, 1), level(1, 1, 2, 2), 1.0, 4.0, 1e-3);
  EXPECT_EQ(e.status, EstimateStatus::Erratic);
  EXPECT_NEAR(e.order, 2.0, 1e-12);
  EXPECT_TRUE(e.extrapolated.empty());
  e = richardson({1.0}, {1.1}, {1.5}, 1.0, 2.0, 1e-3);
  EXPECT_EQ(e.status, EstimateStatus::Erratic);
  EXPECT_NEAR(e.error, 0.4, 1e-14);
}

TEST(Richardson, UpperOrderWidensTheBand) {
  // a bifurcation load: h^4 on a straight path, h^2 where it bends; p_th = 2 alone calls h^4 erratic
  const auto q0 = level(1, 0.1, 4, 0), q1 = level(1, 0.1, 4, 1), q2 = level(1, 0.1, 4, 2);
  EXPECT_EQ(richardson(q0, q1, q2, 1.0, 2.0, 1e-3).status, EstimateStatus::Erratic);
  const auto e = richardson(q0, q1, q2, 1.0, 2.0, 1e-3, 0, 4.0);
  EXPECT_EQ(e.status, EstimateStatus::Converging);
  EXPECT_NEAR(e.error, q2[0] - 1, 1e-15);
  EXPECT_EQ(richardson(level(1, 1, 2, 0), level(1, 1, 2, 1), level(1, 1, 2, 2), 1.0, 2.0, 1e-3, 0, 4.0).status,
            EstimateStatus::Converging);
}

TEST(Richardson, ChangesFarBelowTheTargetAreResolved) {
  // round-off changes of a mesh-independent quantity: no order, resolved, estimate the larger change
  const auto e = richardson({1.0, 0.0}, {1.0 + 3e-12, 0.0}, {1.0 - 1e-12, 0.0}, 1.0, 2.0, 1e-5);
  EXPECT_EQ(e.status, EstimateStatus::Resolved);
  EXPECT_NEAR(e.error, 4e-12, 1e-15);  // 1 + 3e-12 is not exact in binary
  const auto same = richardson({3.0}, {3.0}, {3.0}, 3.0, 2.0, 1e-5);
  EXPECT_EQ(same.status, EstimateStatus::Resolved);
  EXPECT_EQ(same.error, 0.0);
}

TEST(Richardson, TimeHistoryTakesTheWorstRow) {
  // two rows of 3 components: row 1 converges as dt^2 (changes 0.4, 0.1), row 0 hardly changes and
  // with another order; the norm is the worst row's, so the order is 2 and the error 0.1 / 3
  const std::vector<double> q0{1, 0, 0, 2.0, 0, 0}, q1{1 + 1e-9, 0, 0, 2.4, 0, 0}, q2{1 + 1.5e-9, 0, 0, 2.5, 0, 0};
  const auto e = richardson(q0, q1, q2, 1.0, 2.0, 1e-3, 3);
  EXPECT_EQ(e.status, EstimateStatus::Converging);
  EXPECT_NEAR(e.order, 2.0, 1e-12);
  EXPECT_NEAR(e.error, 0.1 / 3, 1e-12);
  EXPECT_NEAR(e.extrapolated[3], 2.5 + 0.1 / 3, 1e-12);
  // the same values as one vector: the Euclidean norm over both rows
  const auto whole = richardson(q0, q1, q2, 1.0, 2.0, 1e-3);
  EXPECT_NEAR(whole.order, std::log2(std::hypot(0.4, 1e-9) / std::hypot(0.1, 5e-10)), 1e-12);
}
