// The Mann-Whitney U test against values computed independently (brute-force enumeration of all
// rank arrangements; textbook examples), and the verdicts on synthetic runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "harness/compare/mann_whitney.hpp"
#include "harness/compare/regression_verdict.hpp"

namespace vsgl {
namespace {

// Two-sided exact p by enumerating every way to split ranks 1..n1+n2 (no ties).
double brute_force_p(std::size_t n1, std::size_t n2, double u1) {
  const std::size_t n = n1 + n2;
  std::vector<int> pick(n, 0);
  std::fill(pick.end() - static_cast<std::ptrdiff_t>(n1), pick.end(), 1);
  double total = 0, extreme = 0;
  const double mean = static_cast<double>(n1 * n2) / 2.0;
  do {
    double rank_sum = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (pick[i]) rank_sum += static_cast<double>(i + 1);
    const double u = rank_sum - static_cast<double>(n1 * (n1 + 1)) / 2.0;
    total += 1;
    if (std::abs(u - mean) >= std::abs(u1 - mean) - 1e-9) extreme += 1;
  } while (std::next_permutation(pick.begin(), pick.end()));
  return extreme / total;
}

TEST(MannWhitney, UStatisticCountsPairs) {
  const auto r = mann_whitney_u({1, 2, 3}, {4, 5, 6, 7});
  EXPECT_DOUBLE_EQ(r.u1, 0.0);  // no value of the first sample beats one of the second
  EXPECT_DOUBLE_EQ(r.u2, 12.0);
  const auto t = mann_whitney_u({1, 5}, {5, 2});  // a tie counts one half
  EXPECT_DOUBLE_EQ(t.u1, 1.5);
}

TEST(MannWhitney, ExactPMatchesEnumeration) {
  std::mt19937 rng(7);
  for (std::size_t n1 : {3u, 5u, 7u})
    for (std::size_t n2 : {4u, 6u}) {
      std::vector<double> pooled(n1 + n2);
      for (std::size_t i = 0; i < pooled.size(); ++i) pooled[i] = static_cast<double>(i) + 0.5;
      for (int trial = 0; trial < 5; ++trial) {
        std::shuffle(pooled.begin(), pooled.end(), rng);
        const std::vector<double> a(pooled.begin(), pooled.begin() + static_cast<std::ptrdiff_t>(n1));
        const std::vector<double> b(pooled.begin() + static_cast<std::ptrdiff_t>(n1), pooled.end());
        const auto r = mann_whitney_u(a, b);
        ASSERT_TRUE(r.exact);
        EXPECT_NEAR(r.p_value, std::min(1.0, brute_force_p(n1, n2, r.u1)), 1e-12) << n1 << "x" << n2;
      }
    }
}

TEST(MannWhitney, TextbookValues) {
  // Completely separated samples of 5 and 5: p = 2 / C(10, 5) = 2 / 252.
  EXPECT_NEAR(mann_whitney_u({1, 2, 3, 4, 5}, {6, 7, 8, 9, 10}).p_value, 2.0 / 252.0, 1e-12);
  // Large samples use the normal approximation: identical distributions give a large p, a clear
  // shift a tiny one.
  std::vector<double> a, b, c;
  for (int i = 0; i < 100; ++i) {
    a.push_back(100 + (i * 37) % 100 * 0.1);
    b.push_back(100 + (i * 53) % 100 * 0.1);
    c.push_back(110 + (i * 53) % 100 * 0.1);
  }
  const auto same = mann_whitney_u(a, b);
  EXPECT_FALSE(same.exact);
  EXPECT_GT(same.p_value, 0.9);
  EXPECT_LT(mann_whitney_u(a, c).p_value, 1e-10);
}

TEST(MannWhitney, AllEqualValuesShowNoDifference) {
  EXPECT_DOUBLE_EQ(mann_whitney_u({2, 2, 2}, {2, 2, 2, 2}).p_value, 1.0);
}

TEST(MannWhitney, RejectsEmptyAndNonFiniteSamples) {
  EXPECT_THROW(mann_whitney_u({}, {1.0}), std::invalid_argument);
  EXPECT_THROW(mann_whitney_u({1.0, std::nan("")}, {1.0}), std::invalid_argument);
}

std::vector<double> noisy_samples(double centre, double spread, std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> d(centre, spread);
  std::vector<double> v(n);
  for (auto& x : v) x = d(rng);
  return v;
}

TEST(RegressionVerdict, SyntheticRuns) {
  const auto base = noisy_samples(1.0, 0.01, 30, 1);
  EXPECT_EQ(compare_samples(base, base).verdict, Verdict::kSame);
  EXPECT_EQ(compare_samples(base, noisy_samples(1.0, 0.01, 30, 2)).verdict, Verdict::kSame);
  EXPECT_EQ(compare_samples(base, noisy_samples(1.10, 0.01, 30, 3)).verdict, Verdict::kSlower);
  EXPECT_EQ(compare_samples(base, noisy_samples(0.90, 0.01, 30, 4)).verdict, Verdict::kFaster);
  // Medians 5 % apart but noise of 50 %: the samples cannot decide.
  EXPECT_EQ(compare_samples(noisy_samples(1.0, 0.5, 12, 5), noisy_samples(1.05, 0.5, 12, 6)).verdict,
            Verdict::kAmbiguous);
  // Too few samples.
  EXPECT_EQ(compare_samples({1.0, 1.0}, {2.0, 2.0}).verdict, Verdict::kAmbiguous);
  // A significant but irrelevant change is SAME.
  EXPECT_EQ(compare_samples(noisy_samples(1.0, 0.0001, 30, 7), noisy_samples(1.005, 0.0001, 30, 8)).verdict,
            Verdict::kSame);
}

}  // namespace
}  // namespace vsgl
