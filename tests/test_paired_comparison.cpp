// harness/core/paired_comparison.hpp on synthetic per-frame values whose answers are known: the
// exact binomial tails by hand, the sign test's counts, the paired bootstrap where the pairing
// makes the interval exact, and a verdict on the bootstrap's interval (the rule itself:
// test_claim_verdict.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "harness/core/claim_verdict.hpp"
#include "harness/core/paired_comparison.hpp"

namespace vsgl {
namespace {

TEST(PairedComparison, BinomialTailsByHand) {
  // n = 10: C(10,0) + C(10,1) = 11 and + C(10,2) = 56 of the 1024 outcomes.
  EXPECT_NEAR(binomial_half_lower_tail(10, 0), 1.0 / 1024, 1e-15);
  EXPECT_NEAR(binomial_half_lower_tail(10, 1), 11.0 / 1024, 1e-15);
  EXPECT_NEAR(binomial_half_lower_tail(10, 2), 56.0 / 1024, 1e-15);
  EXPECT_NEAR(binomial_half_lower_tail(10, 5), 638.0 / 1024, 1e-15);
  EXPECT_DOUBLE_EQ(binomial_half_lower_tail(10, 10), 1.0);
  EXPECT_DOUBLE_EQ(binomial_half_lower_tail(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(binomial_half_lower_tail(1, 0), 0.5);
  // n = 32, k = 8: sum_{j<=8} C(32, j) / 2^32 = 0.0035001833457... (exact rational arithmetic).
  EXPECT_NEAR(binomial_half_lower_tail(32, 8), 0.0035001833457499743, 1e-15);
  // Past n = 1074, where 2^-n underflows: exact values 0.50891950557... and 0.01341207312...
  EXPECT_NEAR(binomial_half_lower_tail(2000, 1000), 0.5089195055729272, 1e-12);
  EXPECT_NEAR(binomial_half_lower_tail(2000, 950), 0.013412073120140347, 1e-12);
}

TEST(PairedComparison, SignTestCountsAndPValues) {
  // 9 frames A below B, 1 above, 3 ties: the ties are dropped, n = 10.
  const std::vector<double> a{1, 1, 1, 1, 1, 1, 1, 1, 1, 5, 2, 2, 2};
  const std::vector<double> b{2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2};
  const SignTest t = sign_test(a, b);
  EXPECT_EQ(t.frames, 13u);
  EXPECT_EQ(t.a_below, 9u);
  EXPECT_EQ(t.a_above, 1u);
  EXPECT_EQ(t.ties, 3u);
  EXPECT_NEAR(t.p_a_below, 11.0 / 1024, 1e-15);       // P(X >= 9)
  EXPECT_NEAR(t.p_a_above, 1.0 - 1.0 / 1024, 1e-15);  // P(X >= 1)
  EXPECT_NEAR(t.p_two_sided, 22.0 / 1024, 1e-15);
  // Swapping A and B swaps the one-sided values and keeps the two-sided one.
  const SignTest s = sign_test(b, a);
  EXPECT_EQ(s.a_below, 1u);
  EXPECT_EQ(s.a_above, 9u);
  EXPECT_DOUBLE_EQ(s.p_a_above, t.p_a_below);
  EXPECT_DOUBLE_EQ(s.p_two_sided, t.p_two_sided);
  // An even split is no evidence either way: the two-sided value is capped at 1.
  const SignTest even = sign_test(std::vector<double>{1, 3}, std::vector<double>{2, 2});
  EXPECT_DOUBLE_EQ(even.p_two_sided, 1.0);
  // All ties: nothing to test.
  const SignTest tied = sign_test(std::vector<double>{4, 4}, std::vector<double>{4, 4});
  EXPECT_EQ(tied.ties, 2u);
  EXPECT_DOUBLE_EQ(tied.p_two_sided, 1.0);
  EXPECT_DOUBLE_EQ(tied.p_a_below, 1.0);
}

TEST(PairedComparison, PairingCancelsWhatFramesShare) {
  // Frames of very different difficulty, A always exactly 1 above B, and A exactly 3 times B:
  // every replicate's difference is 1 and ratio 3 (sums of small integers are exact), so the
  // intervals collapse, where an unpaired comparison would be as wide as the frames' spread.
  std::vector<double> b, a, a3;
  for (int i = 0; i < 32; ++i) {
    const double f = static_cast<double>((i * 37) % 101 + 1);
    b.push_back(f);
    a.push_back(f + 1);
    a3.push_back(3 * f);
  }
  const PairedBootstrap d = paired_bootstrap(a, b);
  EXPECT_EQ(d.frames, 32u);
  EXPECT_DOUBLE_EQ(d.difference, 1.0);
  EXPECT_DOUBLE_EQ(d.difference_interval.low, 1.0);
  EXPECT_DOUBLE_EQ(d.difference_interval.high, 1.0);
  const PairedBootstrap r = paired_bootstrap(a3, b);
  ASSERT_TRUE(r.ratio.has_value());
  ASSERT_TRUE(r.ratio_interval.has_value());
  EXPECT_DOUBLE_EQ(*r.ratio, 3.0);
  EXPECT_DOUBLE_EQ(r.ratio_interval->low, 3.0);
  EXPECT_DOUBLE_EQ(r.ratio_interval->high, 3.0);
}

TEST(PairedComparison, BootstrapIntervalOfKnownSpread) {
  // Differences +1 and -1 alternating over 100 frames: the bootstrap distribution of their mean
  // has mean 0 and standard deviation sqrt(1 / 100) = 0.1 (plug-in variance 1), close to normal,
  // so the 95 % interval is about ±1.96 · 0.1.
  std::vector<double> a, b;
  for (int i = 0; i < 100; ++i) {
    b.push_back(10.0 + i);
    a.push_back(10.0 + i + (i % 2 == 0 ? 1.0 : -1.0));
  }
  const PairedBootstrap p = paired_bootstrap(a, b, {.resamples = 4000, .confidence = 0.95, .seed = 7});
  EXPECT_DOUBLE_EQ(p.difference, 0.0);
  EXPECT_NEAR(p.difference_interval.low, -0.196, 0.03);
  EXPECT_NEAR(p.difference_interval.high, 0.196, 0.03);
  // Two frames with differences 0 and 1: a replicate's mean is 0, 0.5 or 1 with probabilities
  // 1/4, 1/2, 1/4, so the 90 % interval's ends (5 % and 95 % quantiles) are 0 and 1.
  const PairedBootstrap two = paired_bootstrap(std::vector<double>{5, 6}, std::vector<double>{5, 5},
                                               {.resamples = 2000, .confidence = 0.9, .seed = 1});
  EXPECT_DOUBLE_EQ(two.difference_interval.low, 0.0);
  EXPECT_DOUBLE_EQ(two.difference_interval.high, 1.0);
}

TEST(PairedComparison, BootstrapIsSeededAndRecordsItsSettings) {
  std::vector<double> a, b;
  for (int i = 0; i < 20; ++i) {
    a.push_back(std::sin(i) + 2.0);
    b.push_back(std::cos(3.0 * i) + 2.0);
  }
  const PairedBootstrapOptions options{.resamples = 500, .confidence = 0.9, .seed = 42};
  const PairedBootstrap first = paired_bootstrap(a, b, options);
  const PairedBootstrap again = paired_bootstrap(a, b, options);
  EXPECT_EQ(first.difference_interval.low, again.difference_interval.low);
  EXPECT_EQ(first.difference_interval.high, again.difference_interval.high);
  EXPECT_EQ(first.ratio_interval->low, again.ratio_interval->low);
  EXPECT_EQ(first.resamples, 500u);
  EXPECT_EQ(first.confidence, 0.9);
  EXPECT_EQ(first.seed, 42u);
  const PairedBootstrap other = paired_bootstrap(a, b, {.resamples = 500, .confidence = 0.9, .seed = 43});
  EXPECT_NE(first.difference_interval.low, other.difference_interval.low);
  // The interval brackets the estimate.
  EXPECT_LE(first.difference_interval.low, first.difference);
  EXPECT_GE(first.difference_interval.high, first.difference);
}

TEST(PairedComparison, RatioNeedsPositiveB) {
  const PairedBootstrap p = paired_bootstrap(std::vector<double>{1, 2, 3}, std::vector<double>{0, 1, 2});
  EXPECT_FALSE(p.ratio.has_value());
  EXPECT_FALSE(p.ratio_interval.has_value());
  EXPECT_DOUBLE_EQ(p.difference, 1.0);
}

TEST(PairedComparison, WhatCannotBeComparedIsAnError) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(sign_test(std::vector<double>{1, 2}, std::vector<double>{1}), std::invalid_argument);
  EXPECT_THROW(sign_test(std::vector<double>{}, std::vector<double>{}), std::invalid_argument);
  EXPECT_THROW(sign_test(std::vector<double>{nan}, std::vector<double>{1}), std::invalid_argument);
  EXPECT_THROW(paired_bootstrap(std::vector<double>{1}, std::vector<double>{1}), std::invalid_argument);
  EXPECT_THROW(paired_bootstrap(std::vector<double>{1, 2}, std::vector<double>{1, nan}), std::invalid_argument);
  EXPECT_THROW(paired_bootstrap(std::vector<double>{1, 2}, std::vector<double>{1, 2}, {.resamples = 0}),
               std::invalid_argument);
  EXPECT_THROW(paired_bootstrap(std::vector<double>{1, 2}, std::vector<double>{1, 2}, {.confidence = 1.0}),
               std::invalid_argument);
}

TEST(PairedComparison, BootstrapVerdictEndToEnd) {
  // A is 20 % below B on every frame, give or take a few percent: the ratio's interval lies below
  // 0.9, so "A lower by more than 10 %" holds; and the sign test counts every frame a win.
  std::vector<double> a, b;
  for (int i = 0; i < 32; ++i) {
    const double f = 1.0 + 0.5 * std::sin(0.7 * i);
    b.push_back(f);
    a.push_back(f * (0.8 + 0.03 * std::cos(1.3 * i)));
  }
  const PairedBootstrap p = paired_bootstrap(a, b);
  ASSERT_TRUE(p.ratio_interval.has_value());
  const Interval ratio{p.ratio_interval->low, p.ratio_interval->high};
  EXPECT_EQ(judge_below(ratio, 0.9).outcome, Outcome::kHolds);
  EXPECT_EQ(judge_below(ratio, 0.7).outcome, Outcome::kDoesNotHold);
  const SignTest t = sign_test(a, b);
  EXPECT_EQ(t.a_below, 32u);
  EXPECT_NEAR(t.p_a_below, std::ldexp(1.0, -32), 1e-24);
}

}  // namespace
}  // namespace vsgl
