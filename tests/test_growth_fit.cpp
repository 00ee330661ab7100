// harness/core/growth_fit.hpp on synthetic samples c·x^k with seeded multiplicative noise: the
// fit recovers k, its interval covers k, collapses without noise, and the refusals and verdicts.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "harness/core/growth_fit.hpp"
#include "input_error.hpp"

namespace vsgl {
namespace {

using test::input_error;

// Points at x = 1e3, ~2.2e3, ..., 1e6 (7 per three decades) with `rounds` samples each of
// c·x^k·exp(sigma·z), z standard normal from a seeded engine.
std::vector<GrowthPoint> power_law(double c, double k, double sigma, std::size_t rounds, std::uint64_t seed,
                                   std::size_t count = 7) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> z(0.0, 1.0);
  std::vector<GrowthPoint> points;
  for (std::size_t i = 0; i < count; ++i) {
    GrowthPoint p;
    p.x = 1e3 * std::pow(10.0, 3.0 * static_cast<double>(i) / static_cast<double>(count - 1));
    for (std::size_t r = 0; r < rounds; ++r) p.samples_ms.push_back(c * std::pow(p.x, k) * std::exp(sigma * z(rng)));
    points.push_back(std::move(p));
  }
  return points;
}

GrowthFit fit_with(double low, double high, double slope) {
  GrowthFit f;
  f.slope = slope;
  f.low = low;
  f.high = high;
  return f;
}

TEST(GrowthFit, RecoversAKnownSlopeUnderNoise) {
  const GrowthFit fit = fit_growth(power_law(2e-6, 1.5, 0.05, 30, 17));
  EXPECT_GE(fit.slope, 1.45);
  EXPECT_LE(fit.slope, 1.55);
  EXPECT_LE(fit.low, 1.5);
  EXPECT_GE(fit.high, 1.5);
  EXPECT_LT(fit.low, fit.slope);
  EXPECT_GT(fit.high, fit.slope);
  EXPECT_LT(fit.high - fit.low, 0.05);  // 5 % noise over three decades pins the slope closely
  EXPECT_EQ(fit.points, 7u);
  EXPECT_EQ(fit.distinct_x, 7u);
  EXPECT_EQ(fit.resamples, 2000u);
  EXPECT_EQ(fit.min_rounds, 30u);
  EXPECT_DOUBLE_EQ(fit.confidence, 0.95);
  ASSERT_EQ(fit.medians_ms.size(), 7u);
  // The fitted line passes near the data: within 5 % of c·x^1.5 at both ends.
  EXPECT_NEAR(fit.predicted_ms(1e3) / (2e-6 * std::pow(1e3, 1.5)), 1.0, 0.05);
  EXPECT_NEAR(fit.predicted_ms(1e6) / (2e-6 * std::pow(1e6, 1.5)), 1.0, 0.05);
}

TEST(GrowthFit, ZeroNoiseCollapsesTheIntervalOnTheExactSlope) {
  const GrowthFit fit = fit_growth(power_law(3e-4, 1.5, 0.0, 5, 1));
  EXPECT_NEAR(fit.slope, 1.5, 1e-12);
  EXPECT_NEAR(fit.low, 1.5, 1e-12);
  EXPECT_NEAR(fit.high, 1.5, 1e-12);
  EXPECT_NEAR(fit.intercept, std::log(3e-4), 1e-9);
  // A flat cost is slope 0, a quadratic one 2.
  EXPECT_NEAR(fit_growth(power_law(1.0, 0.0, 0.0, 3, 1)).slope, 0.0, 1e-12);
  EXPECT_NEAR(fit_growth(power_law(1e-9, 2.0, 0.0, 3, 1)).high, 2.0, 1e-12);
}

TEST(GrowthFit, IntervalCoversTheTrueSlopeMostOfTheTime) {
  // 40 independent data sets: a 95 % interval should miss about twice; an interval that is far
  // too narrow (e.g. one ignoring the rounds' spread) would miss most of them.
  int covered = 0;
  GrowthFitOptions options;
  options.resamples = 400;
  for (std::uint64_t seed = 100; seed < 140; ++seed) {
    const GrowthFit fit = fit_growth(power_law(1e-3, 0.75, 0.1, 15, seed, 4), options);
    if (fit.low <= 0.75 && 0.75 <= fit.high) ++covered;
  }
  EXPECT_GE(covered, 32);
}

TEST(GrowthFit, NoisierRoundsWidenTheInterval) {
  const GrowthFit quiet = fit_growth(power_law(1e-3, 1.0, 0.02, 20, 5));
  const GrowthFit noisy = fit_growth(power_law(1e-3, 1.0, 0.2, 20, 5));
  EXPECT_GT(noisy.high - noisy.low, 4 * (quiet.high - quiet.low));
}

TEST(GrowthFit, SameSeedSameIntervalOtherSeedOtherInterval) {
  const auto points = power_law(1e-3, 1.0, 0.1, 12, 9);
  const GrowthFit a = fit_growth(points), b = fit_growth(points);
  EXPECT_EQ(a.low, b.low);
  EXPECT_EQ(a.high, b.high);
  GrowthFitOptions other;
  other.seed = 12345;
  const GrowthFit c = fit_growth(points, other);
  EXPECT_EQ(c.slope, a.slope);  // the estimate does not depend on the resampling
  EXPECT_NE(c.low, a.low);
  EXPECT_EQ(c.seed, 12345u);
}

TEST(GrowthFit, RoundCountsMayDifferAndRepeatedXIsAllowed) {
  std::vector<GrowthPoint> points{
      {10, {1.0, 1.1, 0.9, 1.0, 1.05}}, {10, {1.0, 1.02}}, {100, {10, 11, 9, 10, 10, 10.5, 9.5}}};
  const GrowthFit fit = fit_growth(points);
  EXPECT_EQ(fit.points, 3u);
  EXPECT_EQ(fit.distinct_x, 2u);
  EXPECT_EQ(fit.min_rounds, 2u);
  EXPECT_NEAR(fit.slope, 1.0, 0.02);
  EXPECT_DOUBLE_EQ(fit.medians_ms[0], 1.0);
  EXPECT_DOUBLE_EQ(fit.medians_ms[1], 1.01);
  EXPECT_DOUBLE_EQ(fit.medians_ms[2], 10.0);
}

TEST(GrowthFit, RefusesWhatCannotBeFitted) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const auto fit = [](std::vector<GrowthPoint> p, GrowthFitOptions o = {}) { return fit_growth(p, o); };
  EXPECT_NE(input_error([&] { fit({}); }).find("at least 2 distinct parameter values (got 0)"), std::string::npos);
  EXPECT_NE(input_error([&] {
              fit({{4, {1, 2}}, {4, {1, 2}}});
            }).find("2 distinct parameter values (got 1)"),
            std::string::npos);
  EXPECT_NE(input_error([&] {
              fit({{1, {1, 2}}, {0, {1, 2}}});
            }).find("point 2 (x = 0): the parameter must be a finite positive"),
            std::string::npos);
  EXPECT_NE(input_error([&] { fit({{-3, {1, 2}}, {1, {1, 2}}}); }).find("x = -3"), std::string::npos);
  EXPECT_NE(input_error([&] { fit({{nan, {1, 2}}, {1, {1, 2}}}); }).find("finite positive"), std::string::npos);
  EXPECT_NE(input_error([&] {
              fit({{1, {1, 2}}, {2, {1, 0}}});
            }).find("point 2 (x = 2): round 2 is not a positive time (0 ms)"),
            std::string::npos);
  EXPECT_NE(input_error([&] {
              fit({{1, {-1, 2}}, {2, {1, 1}}});
            }).find("round 1 is not a positive time"),
            std::string::npos);
  EXPECT_NE(input_error([&] {
              fit({{1, {inf, 2}}, {2, {1, 1}}});
            }).find("not a positive time (inf ms)"),
            std::string::npos);
  EXPECT_NE(input_error([&] { fit({{1, {nan, 2}}, {2, {1, 1}}}); }).find("not a positive time"), std::string::npos);
  EXPECT_NE(input_error([&] {
              fit({{1, {1}}, {2, {1, 1}}});
            }).find("point 1 (x = 1): needs at least 2 rounds (got 1)"),
            std::string::npos);
  GrowthFitOptions none;
  none.resamples = 0;
  EXPECT_NE(input_error([&] {
              fit({{1, {1, 2}}, {2, {1, 2}}}, none);
            }).find("1 to 1000000 resamples (got 0)"),
            std::string::npos);
  none.resamples = kMaxResamples + 1;
  EXPECT_NE(input_error([&] { fit({{1, {1, 2}}, {2, {1, 2}}}, none); }).find("(got 1000001)"), std::string::npos);
  GrowthFitOptions certain;
  certain.confidence = 1;
  EXPECT_NE(input_error([&] { fit({{1, {1, 2}}, {2, {1, 2}}}, certain); }).find("confidence"), std::string::npos);
  GrowthFitOptions named;
  named.subject = "filtered_sampling over N";
  EXPECT_EQ(input_error([&] { fit({{1, {1, 2}}}, named); }).rfind("filtered_sampling over N: ", 0), 0u);
}

TEST(GrowthFit, TextHasTwoDecimals) {
  EXPECT_EQ(growth_text(fit_with(0.951, 1.006, 0.98), "N"), "cost \u221d N^0.98 [0.95, 1.01]");
  EXPECT_EQ(growth_text(fit_with(-0.2, 0.004, -0.001), "M"), "cost \u221d M^0.00 [-0.20, 0.00]");
  EXPECT_EQ(growth_text(fit_with(1.994, 2.126, 2.0), "W\u00b7H"), "cost \u221d W\u00b7H^2.00 [1.99, 2.13]");
}

TEST(GrowthJudge, VerdictsAgainstTheExpectedBand) {
  const GrowthExpectation linear{1.0, 0.05, "filtered sampling is linear in N"};
  const GrowthJudgement ok = judge_growth(fit_with(0.95, 1.01, 0.98), linear, "N");
  EXPECT_EQ(ok.verdict.outcome, Outcome::kInconclusive);  // touches the band's low end
  EXPECT_STREQ(growth_verdict_name(ok.verdict, linear.slope), "consistent");
  EXPECT_FALSE(ok.flagged());
  EXPECT_EQ(ok.text,
            "cost \u221d N^0.98 [0.95, 1.01] is consistent with the expected N^1.00 \u00b1 0.05 (filtered sampling is "
            "linear in N)");

  const GrowthJudgement fast = judge_growth(fit_with(1.2, 1.35, 1.28), linear, "N");
  EXPECT_EQ(fast.verdict.outcome, Outcome::kDoesNotHold);
  EXPECT_TRUE(fast.flagged());
  EXPECT_NE(fast.text.find("grows faster than the expected N^1.00"), std::string::npos);
  EXPECT_NE(fast.text.find("the interval excludes it"), std::string::npos);
  EXPECT_STREQ(growth_verdict_name(fast.verdict, linear.slope), "faster");
  EXPECT_EQ(fast.verdict.rule, "interval within (0.95, 1.05)");

  const GrowthJudgement slow = judge_growth(fit_with(0.5, 0.7, 0.6), linear, "N");
  EXPECT_EQ(slow.verdict.outcome, Outcome::kDoesNotHold);
  EXPECT_TRUE(slow.flagged());
  EXPECT_STREQ(growth_verdict_name(slow.verdict, linear.slope), "slower");
  const GrowthJudgement inside = judge_growth(fit_with(0.97, 1.03, 1.0), linear, "N");
  EXPECT_EQ(inside.verdict.outcome, Outcome::kHolds);
  EXPECT_FALSE(inside.flagged());
  EXPECT_STREQ(growth_verdict_name(inside.verdict, linear.slope), "consistent");

  // The edge convention at both ends of the band (core/claim_verdict.hpp): touching an end from
  // either side is inconclusive (consistent, not flagged); just past it is decided.
  const auto outcome = [&](double low, double high, const GrowthExpectation& e) {
    return judge_growth(fit_with(low, high, (low + high) / 2), e, "N").verdict.outcome;
  };
  EXPECT_EQ(outcome(1.05, 1.2, linear), Outcome::kInconclusive);   // touches the high end from outside
  EXPECT_EQ(outcome(0.8, 0.95, linear), Outcome::kInconclusive);   // the low end from outside
  EXPECT_EQ(outcome(0.97, 1.05, linear), Outcome::kInconclusive);  // the high end from inside
  EXPECT_EQ(outcome(0.95, 1.03, linear), Outcome::kInconclusive);  // the low end from inside
  EXPECT_EQ(outcome(1.0501, 1.2, linear), Outcome::kDoesNotHold);
  EXPECT_EQ(outcome(0.8, 0.9499, linear), Outcome::kDoesNotHold);
  EXPECT_EQ(outcome(0.9501, 1.0499, linear), Outcome::kHolds);
  EXPECT_FALSE(judge_growth(fit_with(1.05, 1.2, 1.1), linear, "N").flagged());
  EXPECT_TRUE(judge_growth(fit_with(1.0501, 1.2, 1.1), linear, "N").flagged());

  // No tolerance: the interval must contain the expected slope itself, and never "holds".
  const GrowthExpectation exact{2.0, 0.0, ""};
  EXPECT_EQ(outcome(1.9, 2.1, exact), Outcome::kInconclusive);
  EXPECT_EQ(outcome(2.01, 2.1, exact), Outcome::kDoesNotHold);
  EXPECT_EQ(judge_growth(fit_with(1.9, 2.1, 2.0), exact, "N").text,
            "cost \u221d N^2.00 [1.90, 2.10] is consistent with the expected N^2.00");
}

TEST(GrowthJudge, AFittedQuadraticIsFlaggedAgainstALinearExpectation) {
  const GrowthFit fit = fit_growth(power_law(1e-6, 2.0, 0.1, 20, 3));
  EXPECT_TRUE(judge_growth(fit, {1.0, 0.1, "linear"}, "N").flagged());
  EXPECT_FALSE(judge_growth(fit, {2.0, 0.05, "quadratic"}, "N").flagged());
}

TEST(GrowthJudge, RefusesABadExpectation) {
  const GrowthFit fit = fit_with(0.9, 1.1, 1.0);
  EXPECT_NE(input_error([&] { judge_growth(fit, {1.0, -0.1, ""}, "N"); }).find("tolerance"), std::string::npos);
  EXPECT_NE(input_error([&] {
              judge_growth(fit, {std::numeric_limits<double>::infinity(), 0.1, ""}, "N");
            }).find("expected growth"),
            std::string::npos);
}

}  // namespace
}  // namespace vsgl
