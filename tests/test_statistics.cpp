// harness/core/statistics.hpp against hand-computed cases (type-7 quartiles, sample stdev) and the
// errors that keep a NaN out of every table.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "harness/core/statistics.hpp"

namespace vsgl {
namespace {

TEST(Statistics, FourSamplesByHand) {
  // Sorted 1 2 3 4: h(q1) = 3 * 0.25 = 0.75 -> 1 + 0.75 * 1 = 1.75; h(q3) = 2.25 -> 3.25;
  // median h = 1.5 -> 2.5; mean 2.5; squared deviations 2.25 + 0.25 + 0.25 + 2.25 = 5 -> sqrt(5/3).
  const std::vector<double> s{4.0, 1.0, 3.0, 2.0};
  const SampleStats st = summarize(s);
  EXPECT_EQ(st.count, 4u);
  EXPECT_DOUBLE_EQ(st.min, 1.0);
  EXPECT_DOUBLE_EQ(st.max, 4.0);
  EXPECT_DOUBLE_EQ(st.median, 2.5);
  EXPECT_DOUBLE_EQ(st.q1, 1.75);
  EXPECT_DOUBLE_EQ(st.q3, 3.25);
  // h(p95) = 2.85 -> 3 + 0.85 = 3.85; h(p99) = 2.97 -> 3.97.
  EXPECT_DOUBLE_EQ(st.p95, 3.85);
  EXPECT_DOUBLE_EQ(st.p99, 3.97);
  EXPECT_DOUBLE_EQ(st.mean, 2.5);
  EXPECT_DOUBLE_EQ(st.stdev, std::sqrt(5.0 / 3.0));
  EXPECT_DOUBLE_EQ(relative_iqr(st), 1.5 / 2.5);
}

TEST(Statistics, OddCountAndOutlier) {
  // Sorted 1 3 5 100 7 -> 1 3 5 7 100: median 5, q1 = x[1] = 3, q3 = x[3] = 7 (h exact integers),
  // mean 23.2; the median and quartiles ignore the outlier, the mean does not.
  const std::vector<double> s{1.0, 3.0, 5.0, 100.0, 7.0};
  const SampleStats st = summarize(s);
  EXPECT_DOUBLE_EQ(st.median, 5.0);
  EXPECT_DOUBLE_EQ(st.q1, 3.0);
  EXPECT_DOUBLE_EQ(st.q3, 7.0);
  EXPECT_DOUBLE_EQ(st.mean, 23.2);
  // deviations -22.2 -20.2 -18.2 -16.2 76.8: squares 492.84 + 408.04 + 331.24 + 262.44 + 5898.24
  // = 7392.8, / (n - 1) = 1848.2
  EXPECT_NEAR(st.stdev, std::sqrt(1848.2), 1e-9);
}

TEST(Statistics, TwoSamplesAndQuantileEnds) {
  const std::vector<double> s{2.0, 6.0};
  const SampleStats st = summarize(s);
  EXPECT_DOUBLE_EQ(st.q1, 3.0);  // 2 + 0.25 * 4
  EXPECT_DOUBLE_EQ(st.q3, 5.0);
  EXPECT_DOUBLE_EQ(st.stdev, std::sqrt(8.0));
  const std::vector<double> sorted{1.0, 2.0, 4.0};
  EXPECT_DOUBLE_EQ(quantile_sorted(sorted, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile_sorted(sorted, 1.0), 4.0);
  EXPECT_DOUBLE_EQ(quantile_sorted(sorted, 0.75), 3.0);  // h = 1.5
}

TEST(Statistics, WhatCannotBeComputedIsAnError) {
  EXPECT_THROW(summarize(std::vector<double>{}), std::invalid_argument);
  EXPECT_THROW(summarize(std::vector<double>{1.0}), std::invalid_argument);  // no stdev from one sample
  EXPECT_THROW(summarize(std::vector<double>{1.0, std::numeric_limits<double>::quiet_NaN()}), std::invalid_argument);
  EXPECT_THROW(summarize(std::vector<double>{1.0, std::numeric_limits<double>::infinity()}), std::invalid_argument);
  EXPECT_THROW(relative_iqr(summarize(std::vector<double>{-1.0, 0.0, 1.0})), std::invalid_argument);  // median 0
  EXPECT_THROW(quantile_sorted(std::vector<double>{1.0}, 1.5), std::invalid_argument);
  EXPECT_THROW(add_samples(std::vector<double>{1.0}, std::vector<double>{1.0, 2.0}), std::invalid_argument);
  EXPECT_EQ(add_samples(std::vector<double>{1.0, 2.0}, std::vector<double>{0.5, 0.25}), (std::vector<double>{1.5, 2.25}));
}

// ---- Paired differences (Hodges-Lehmann + Wilcoxon signed-rank interval), on synthetic samples ----

TEST(PairedStatistics, SignedRankNullDistributionByHand) {
  // n = 3: the 8 subsets of {1, 2, 3} have sums 0 1 2 3 3 4 5 6.
  EXPECT_DOUBLE_EQ(signed_rank_lower_tail(3, -1), 0.0);
  EXPECT_DOUBLE_EQ(signed_rank_lower_tail(3, 0), 1.0 / 8);
  EXPECT_DOUBLE_EQ(signed_rank_lower_tail(3, 3), 5.0 / 8);
  EXPECT_DOUBLE_EQ(signed_rank_lower_tail(3, 6), 1.0);
  // n = 10: 25 of the 1024 subsets of {1..10} sum to <= 8, 33 to <= 9 (tabulated).
  EXPECT_NEAR(signed_rank_lower_tail(10, 8), 25.0 / 1024, 1e-15);
  EXPECT_NEAR(signed_rank_lower_tail(10, 9), 33.0 / 1024, 1e-15);
  // Symmetry about n(n+1)/4: P(T <= t) = P(T >= M - t) = 1 - P(T <= M - t - 1).
  EXPECT_NEAR(signed_rank_lower_tail(40, 300), 1.0 - signed_rank_lower_tail(40, 820 - 300 - 1), 1e-12);
  EXPECT_THROW(signed_rank_lower_tail(0, 0), std::invalid_argument);
  EXPECT_THROW(signed_rank_lower_tail(kSignedRankExactMax + 1, 0), std::invalid_argument);
}

TEST(PairedStatistics, CriticalValuesMatchTheTables) {
  // Two-sided alpha = 0.05 critical values of T (reject when T <= value), from the published
  // tables: n 6 -> 0, 10 -> 8, 15 -> 25, 20 -> 52, 25 -> 89, 30 -> 137; C = value + 1.
  const std::pair<std::size_t, std::size_t> table[] = {{6, 0}, {10, 8}, {15, 25}, {20, 52}, {25, 89}, {30, 137}};
  for (const auto& [n, critical] : table) {
    bool exact = false;
    EXPECT_EQ(signed_rank_rank(n, 0.05, &exact), critical + 1) << "n = " << n;
    EXPECT_TRUE(exact);
  }
  // n = 5 cannot reach 95 %: C = 1, the whole range.
  EXPECT_EQ(signed_rank_rank(5, 0.05), 1u);
  // Above the exact range the normal approximation takes over; near the boundary it agrees with
  // the exact value to within one rank.
  bool exact = true;
  signed_rank_rank(kSignedRankExactMax + 1, 0.05, &exact);
  EXPECT_FALSE(exact);
  for (std::size_t n : {50u, 120u, 200u}) {
    const auto e = static_cast<long long>(signed_rank_rank(n, 0.05));
    const auto a = static_cast<long long>(signed_rank_rank_normal(n, 0.05));
    EXPECT_LE(std::abs(e - a), 1) << "n = " << n;
  }
  EXPECT_NEAR(normal_quantile(0.975), 1.959963984540054, 1e-12);
  EXPECT_NEAR(normal_quantile(0.001), -3.090232306167814, 1e-12);
  EXPECT_THROW(normal_quantile(0.0), std::invalid_argument);
}

TEST(PairedStatistics, HodgesLehmannIntervalByHand) {
  // d = 1..10 (shuffled): Walsh averages (i + j) / 2, i <= j. Sums 2, 3 occur once, 4, 5 twice,
  // 6 three times: the 9th smallest average (C = 9 for n = 10) is 6 / 2 = 3, and by symmetry
  // the 47th (M + 1 - C, M = 55) is 16 / 2 = 8. The estimate is the centre, 5.5.
  const std::vector<double> d{7, 2, 9, 1, 10, 4, 3, 6, 8, 5};
  const PairedInterval r = paired_interval(d);
  EXPECT_EQ(r.count, 10u);
  EXPECT_EQ(r.rank, 9u);
  EXPECT_TRUE(r.exact);
  EXPECT_DOUBLE_EQ(r.median, 5.5);
  EXPECT_DOUBLE_EQ(r.hodges_lehmann, 5.5);
  EXPECT_DOUBLE_EQ(r.low, 3.0);
  EXPECT_DOUBLE_EQ(r.high, 8.0);
  EXPECT_NEAR(r.confidence, 1.0 - 2.0 * 25.0 / 1024, 1e-15);
  EXPECT_TRUE(r.reaches_nominal());
  // Equivariant: shifting every difference shifts estimate and interval alike.
  std::vector<double> shifted = d;
  for (double& x : shifted) x -= 100.0;
  const PairedInterval s = paired_interval(shifted);
  EXPECT_DOUBLE_EQ(s.low, -97.0);
  EXPECT_DOUBLE_EQ(s.high, -92.0);
  // Three differences: averages 1, 1.5, 2, 2, 2.5, 3 -> estimate 2; an outlier moves the mean, not it.
  EXPECT_DOUBLE_EQ(paired_interval(std::vector<double>{1, 2, 3}).hodges_lehmann, 2.0);
  EXPECT_DOUBLE_EQ(paired_interval(std::vector<double>{1, 2, 3, 2, 1000}).hodges_lehmann, 2.5);
  EXPECT_EQ(walsh_averages(std::vector<double>{1, 2, 3}), (std::vector<double>{1, 1.5, 2, 2, 2.5, 3}));
}

TEST(PairedStatistics, TooFewPairsSayWhatTheyReach) {
  // n = 3: the widest interval (the range) covers with 1 - 2 / 8 = 75 %, short of 95 %.
  const PairedInterval r = paired_interval(std::vector<double>{0.5, -0.25, 1.0});
  EXPECT_DOUBLE_EQ(r.low, -0.25);
  EXPECT_DOUBLE_EQ(r.high, 1.0);
  EXPECT_DOUBLE_EQ(r.confidence, 0.75);
  EXPECT_FALSE(r.reaches_nominal());
  // n = 6 reaches it with the range: 1 - 2 / 64.
  const PairedInterval six = paired_interval(std::vector<double>{1, 2, 3, 4, 5, 6});
  EXPECT_DOUBLE_EQ(six.confidence, 1.0 - 2.0 / 64);
  EXPECT_TRUE(six.reaches_nominal());
  const PairedInterval one = paired_interval(std::vector<double>{4.0});
  EXPECT_DOUBLE_EQ(one.low, 4.0);
  EXPECT_DOUBLE_EQ(one.high, 4.0);
  EXPECT_DOUBLE_EQ(one.confidence, 0.0);
}

TEST(PairedStatistics, PairingCancelsSharedNoise) {
  // Two series share a large round-to-round drift (+-90) and differ by 1 + a jitter of +-0.06:
  // the interval of the per-round differences brackets 1 and is as narrow as the jitter.
  std::vector<double> a, b;
  for (int i = 0; i < 40; ++i) {
    const double drift = 50.0 * std::sin(1.3 * i) + ((i * 37) % 11) * 4.0;
    const double jitter = 0.01 * (((i * 7919) % 13) - 6);
    b.push_back(1000.0 + drift);
    a.push_back(1000.0 + drift + 1.0 + jitter);
  }
  const PairedInterval r = paired_interval(subtract_samples(a, b));
  EXPECT_EQ(r.count, 40u);
  EXPECT_LE(r.low, 1.0);
  EXPECT_GE(r.high, 1.0);
  EXPECT_LT(r.high - r.low, 0.2);
  EXPECT_GE(r.confidence, 0.95);
}

TEST(PairedStatistics, LargeSamplesUseTheNormalApproximation) {
  std::vector<double> d;
  for (int i = 0; i < 301; ++i) d.push_back(static_cast<double>((i * 83) % 301) - 150.0);  // -150..150, shuffled
  const PairedInterval r = paired_interval(d);
  EXPECT_FALSE(r.exact);
  EXPECT_DOUBLE_EQ(r.hodges_lehmann, 0.0);
  EXPECT_DOUBLE_EQ(r.low, -r.high);  // symmetric data, symmetric interval
  EXPECT_LT(r.low, 0.0);
  EXPECT_NEAR(r.confidence, 0.95, 0.002);
  EXPECT_GE(r.confidence, 0.95);
}

TEST(PairedStatistics, WhatCannotBeComputedIsAnError) {
  EXPECT_THROW(paired_interval(std::vector<double>{}), std::invalid_argument);
  EXPECT_THROW(paired_interval(std::vector<double>{1.0, std::numeric_limits<double>::quiet_NaN()}), std::invalid_argument);
  EXPECT_THROW(paired_interval(std::vector<double>{1.0, 2.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(subtract_samples(std::vector<double>{1.0}, std::vector<double>{1.0, 2.0}), std::invalid_argument);
  EXPECT_EQ(subtract_samples(std::vector<double>{1.0, 2.0}, std::vector<double>{0.5, 0.25}), (std::vector<double>{0.5, 1.75}));
}

}  // namespace
}  // namespace vsgl
