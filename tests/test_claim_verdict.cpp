// The one verdict type and its edge convention (harness/core/claim_verdict.hpp, DESIGN.md §9
// "Verdicts on intervals"): each interval rule at its bound, an interval touching the bound
// exactly from either side being inconclusive, and just past it decided.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "harness/core/claim_verdict.hpp"

namespace vsgl {
namespace {

Outcome below(double low, double high, double bound) { return judge_below({low, high}, bound).outcome; }
Outcome above(double low, double high, double bound) { return judge_above({low, high}, bound).outcome; }
Outcome within(double low, double high, double band_low, double band_high) {
  return judge_within({low, high}, band_low, band_high).outcome;
}

TEST(ClaimVerdict, BelowAtItsBound) {
  EXPECT_EQ(below(-0.5, -0.2, -0.1), Outcome::kHolds);
  EXPECT_EQ(below(-0.05, 0.3, -0.1), Outcome::kDoesNotHold);
  EXPECT_EQ(below(-0.3, 0.0, -0.1), Outcome::kInconclusive);  // straddles
  // Touching from the claimed side (high == bound) and from the other (low == bound): neither.
  EXPECT_EQ(below(-0.3, -0.1, -0.1), Outcome::kInconclusive);
  EXPECT_EQ(below(-0.1, 0.3, -0.1), Outcome::kInconclusive);
  // Just past the bound on either side: decided.
  EXPECT_EQ(below(-0.3, std::nextafter(-0.1, -1.0), -0.1), Outcome::kHolds);
  EXPECT_EQ(below(std::nextafter(-0.1, 1.0), 0.3, -0.1), Outcome::kDoesNotHold);
  // A point interval on the bound.
  EXPECT_EQ(below(1.0, 1.0, 1.0), Outcome::kInconclusive);
}

TEST(ClaimVerdict, AboveAtItsBound) {
  EXPECT_EQ(above(1.2, 1.5, 1.1), Outcome::kHolds);
  EXPECT_EQ(above(0.8, 1.0, 1.1), Outcome::kDoesNotHold);
  EXPECT_EQ(above(1.0, 1.2, 1.1), Outcome::kInconclusive);
  EXPECT_EQ(above(1.1, 1.5, 1.1), Outcome::kInconclusive);  // touching from the claimed side
  EXPECT_EQ(above(0.8, 1.1, 1.1), Outcome::kInconclusive);  // touching from the other side
  EXPECT_EQ(above(std::nextafter(1.1, 2.0), 1.5, 1.1), Outcome::kHolds);
  EXPECT_EQ(above(0.8, std::nextafter(1.1, 0.0), 1.1), Outcome::kDoesNotHold);
}

TEST(ClaimVerdict, WithinAtBothEndsOfItsBand) {
  EXPECT_EQ(within(0.97, 1.04, 0.95, 1.05), Outcome::kHolds);
  EXPECT_EQ(within(1.06, 1.2, 0.95, 1.05), Outcome::kDoesNotHold);
  EXPECT_EQ(within(0.8, 0.9, 0.95, 1.05), Outcome::kDoesNotHold);
  EXPECT_EQ(within(0.9, 1.0, 0.95, 1.05), Outcome::kInconclusive);
  EXPECT_EQ(within(0.9, 1.1, 0.95, 1.05), Outcome::kInconclusive);
  // Touching each end from inside: not inside.
  EXPECT_EQ(within(-10, 9, -10, 10), Outcome::kInconclusive);
  EXPECT_EQ(within(-9, 10, -10, 10), Outcome::kInconclusive);
  EXPECT_EQ(within(-10, 10, -10, 10), Outcome::kInconclusive);
  // Touching each end from outside: not outside.
  EXPECT_EQ(within(10, 40, -10, 10), Outcome::kInconclusive);
  EXPECT_EQ(within(-40, -10, -10, 10), Outcome::kInconclusive);
  // Just past each end: decided.
  EXPECT_EQ(within(std::nextafter(-10.0, 0.0), std::nextafter(10.0, 0.0), -10, 10), Outcome::kHolds);
  EXPECT_EQ(within(std::nextafter(10.0, 20.0), 40, -10, 10), Outcome::kDoesNotHold);
  EXPECT_EQ(within(-40, std::nextafter(-10.0, -20.0), -10, 10), Outcome::kDoesNotHold);
  // A band of width 0 is never held, only missed.
  EXPECT_EQ(within(2, 2, 2, 2), Outcome::kInconclusive);
  EXPECT_EQ(within(1.9, 2.1, 2, 2), Outcome::kInconclusive);
  EXPECT_EQ(within(2.01, 2.1, 2, 2), Outcome::kDoesNotHold);
}

TEST(ClaimVerdict, CarriesItsIntervalAndRule) {
  const ClaimVerdict v = judge_below({0.9, 0.95}, 0.99);
  EXPECT_TRUE(v.holds());
  ASSERT_TRUE(v.interval.has_value());
  EXPECT_EQ(v.interval->low, 0.9);
  EXPECT_EQ(v.interval->high, 0.95);
  EXPECT_EQ(v.rule, "interval below 0.99");
  EXPECT_TRUE(v.reason.empty());
  EXPECT_EQ(judge_above({1, 2}, 0.5).rule, "interval above 0.5");
  EXPECT_EQ(judge_within({-1, 1}, -10, 10).rule, "interval within (-10, 10)");
  EXPECT_TRUE(judge_within({20, 30}, -10, 10).fails());
  EXPECT_TRUE(judge_within({0, 30}, -10, 10).inconclusive());
}

TEST(ClaimVerdict, OutcomeInWords) {
  EXPECT_EQ(outcome_text(Outcome::kHolds), "holds");
  EXPECT_EQ(outcome_text(Outcome::kDoesNotHold), "does not hold");
  EXPECT_EQ(outcome_text(Outcome::kInconclusive), "inconclusive");
}

TEST(ClaimVerdict, RefusesAReversedIntervalOrBand) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(judge_below({1, 0}, 0.5), std::invalid_argument);
  EXPECT_THROW(judge_above({nan, 1}, 0.5), std::invalid_argument);
  EXPECT_THROW(judge_below({0, 1}, nan), std::invalid_argument);
  EXPECT_THROW(judge_within({0, 1}, 1, -1), std::invalid_argument);
}

}  // namespace
}  // namespace vsgl
