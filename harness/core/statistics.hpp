#pragma once
// Summary statistics of timing samples (SPEC §9): median (the headline), min, max, quartiles,
// mean and sample standard deviation. Quartiles use linear interpolation between order
// statistics, Hyndman & Fan type 7 (R's default, NumPy's "linear"): with the n samples sorted
// as x[0] <= ... <= x[n-1], Q(p) = x[j] + (h - j) (x[j+1] - x[j]) where h = (n - 1) p, j = floor(h).
// A statistic that cannot be computed is an error, never a NaN in a table (SPEC §12).
#include <span>
#include <vector>

namespace vsgl {

struct SampleStats {
  std::size_t count = 0;
  double median = 0;
  double min = 0;
  double max = 0;
  double q1 = 0;
  double q3 = 0;
  double mean = 0;
  double stdev = 0;  // sample standard deviation (divisor n - 1)

  double iqr() const { return q3 - q1; }
};

// Type-7 quantile of already sorted samples; p in [0, 1]. Throws std::invalid_argument for an
// empty input or p outside [0, 1].
double quantile_sorted(std::span<const double> sorted, double p);

// Throws std::invalid_argument for fewer than 2 samples (no standard deviation) or a sample
// that is not finite.
SampleStats summarize(std::span<const double> samples);

// The stop rule's noise measure: IQR / median. Throws std::invalid_argument when the median
// is not positive (timings are positive by construction; see TimestampPool::interval_ns).
double relative_iqr(const SampleStats& stats);

// Element-wise sum of equally long sample series (e.g. camera view + light view per repetition).
// Throws std::invalid_argument when the lengths differ.
std::vector<double> add_samples(std::span<const double> a, std::span<const double> b);

}  // namespace vsgl
