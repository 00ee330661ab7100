// harness/core/equivalence_tost.hpp and holm_correction.hpp on hand-made replicates and p-values
// whose answers can be counted by hand.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <vector>

#include "harness/core/equivalence_tost.hpp"
#include "harness/core/holm_correction.hpp"

namespace vsgl {
namespace {

TEST(EquivalenceTest, PValuesCountedByHand) {
  // Replicates 0, 0.01, ..., 0.09 against ±0.05: 5 of 10 at or above 0.05, none at or below -0.05;
  // 6 at or below 0.05, all 10 at or above -0.05. (k + 1) / (B + 1) with B = 10.
  std::vector<double> r;
  for (int k = 0; k < 10; ++k) r.push_back(k / 100.0);
  const EquivalencePValues p = bootstrap_equivalence(r, 0.05);
  EXPECT_DOUBLE_EQ(p.equivalent, 6.0 / 11);
  EXPECT_DOUBLE_EQ(p.outside, 1.0);  // 2 * min(7/11, 11/11), capped at 1
  // Everything well inside: the smallest p-value B replicates can give.
  const EquivalencePValues inside = bootstrap_equivalence(std::vector<double>(1999, 0.01), 0.1);
  EXPECT_DOUBLE_EQ(inside.equivalent, 1.0 / 2000);
  EXPECT_DOUBLE_EQ(inside.outside, 1.0);
  // Everything above the band: equivalence is out of the question, "outside" as sure as B allows.
  const EquivalencePValues above = bootstrap_equivalence(std::vector<double>(1999, 0.2), 0.1);
  EXPECT_DOUBLE_EQ(above.equivalent, 1.0);
  EXPECT_DOUBLE_EQ(above.outside, 2.0 / 2000);
  // Below the band, the mirror.
  const EquivalencePValues below = bootstrap_equivalence(std::vector<double>(1999, -0.2), 0.1);
  EXPECT_DOUBLE_EQ(below.equivalent, 1.0);
  EXPECT_DOUBLE_EQ(below.outside, 2.0 / 2000);
}

TEST(EquivalenceTest, AgreesWithTheIntervalInsideTheBand) {
  // 100 replicates spread evenly over [-0.099, 0.099]: inside ±0.1 entirely, so equivalence p is
  // 1/101; against ±0.05, 25 of them lie at or beyond each end: p = 26/101.
  std::vector<double> r;
  for (int k = -49; k <= 50; ++k) r.push_back(0.099 * (k - 0.5) / 49.5);
  EXPECT_DOUBLE_EQ(bootstrap_equivalence(r, 0.1).equivalent, 1.0 / 101);
  EXPECT_DOUBLE_EQ(bootstrap_equivalence(r, 0.05).equivalent, 26.0 / 101);
}

TEST(EquivalenceTest, RefusesWhatItCannotTest) {
  EXPECT_THROW(bootstrap_equivalence(std::vector<double>{}, 0.1), std::invalid_argument);
  EXPECT_THROW(bootstrap_equivalence(std::vector<double>{0.0}, 0.0), std::invalid_argument);
  EXPECT_THROW(bootstrap_equivalence(std::vector<double>{std::numeric_limits<double>::quiet_NaN()}, 0.1),
               std::invalid_argument);
}

TEST(HolmCorrection, StepsDownAndStops) {
  // Sorted: 0.005 (rank 1, level 0.05/4), 0.01 (rank 2, 0.05/3), 0.03 (rank 3, 0.05/2: not below),
  // 0.04 (rank 4, level 0.05: below it, but Holm has stopped).
  const std::vector<double> p{0.01, 0.04, 0.03, 0.005};
  const std::vector<HolmDecision> d = holm_correction(p, 0.05);
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(d[3].rank, 1u);
  EXPECT_DOUBLE_EQ(d[3].level, 0.0125);
  EXPECT_TRUE(d[3].rejected);
  EXPECT_EQ(d[0].rank, 2u);
  EXPECT_DOUBLE_EQ(d[0].level, 0.05 / 3);
  EXPECT_TRUE(d[0].rejected);
  EXPECT_EQ(d[2].rank, 3u);
  EXPECT_FALSE(d[2].rejected);
  EXPECT_EQ(d[1].rank, 4u);
  EXPECT_DOUBLE_EQ(d[1].level, 0.05);
  EXPECT_FALSE(d[1].rejected);
  // Four p-values of 0.02: each alone passes 0.05, but none passes 0.05 / 4 first.
  for (const HolmDecision& h : holm_correction(std::vector<double>(4, 0.02), 0.05)) EXPECT_FALSE(h.rejected);
  EXPECT_TRUE(holm_correction(std::vector<double>{0.02}, 0.05)[0].rejected);
  // Ties keep the input order.
  const std::vector<HolmDecision> tied = holm_correction(std::vector<double>{0.001, 0.001}, 0.05);
  EXPECT_EQ(tied[0].rank, 1u);
  EXPECT_EQ(tied[1].rank, 2u);
}

TEST(HolmCorrection, RefusesWhatItCannotCorrect) {
  EXPECT_THROW(holm_correction(std::vector<double>{}, 0.05), std::invalid_argument);
  EXPECT_THROW(holm_correction(std::vector<double>{1.5}, 0.05), std::invalid_argument);
  EXPECT_THROW(holm_correction(std::vector<double>{0.5}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace vsgl
