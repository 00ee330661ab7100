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

}  // namespace
}  // namespace vsgl
