#pragma once
// Summary statistics of a set of values (DESIGN.md §9): timing samples, a per-frame series
// (§11a.1), the kernels' PDF mass (§11a). One summary for all: median (the timing headline), min,
// max, quartiles, the 95th and 99th percentiles, mean and sample standard deviation. Quantiles use
// linear interpolation between order statistics, Hyndman & Fan type 7 (R's default, NumPy's
// "linear"): with the n values sorted as x[0] <= ... <= x[n-1], Q(p) = x[j] + (h - j) (x[j+1] -
// x[j]) where h = (n - 1) p, j = floor(h). A statistic that cannot be computed is an error, never
// a NaN in a table (DESIGN.md §12).
#include <cstddef>
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
  double p95 = 0;  // a per-frame series' tail (DESIGN.md §11a.1)
  double p99 = 0;  // the kernels' PDF mass's tail (DESIGN.md §11a)
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
// Element-wise difference a[i] - b[i] of paired series (the same round of two cases, DESIGN.md §9).
// Throws std::invalid_argument when the lengths differ.
std::vector<double> subtract_samples(std::span<const double> a, std::span<const double> b);

// ---- Paired differences: the Hodges-Lehmann estimate and its distribution-free interval ----
// For differences d_1..d_n (one per round), the Walsh averages are (d_i + d_j) / 2 for all
// i <= j, M = n (n + 1) / 2 of them. The Hodges-Lehmann estimate of the shift is their median;
// sorted W_(1) <= ... <= W_(M), the interval [W_(C), W_(M + 1 - C)] covers the true median of a
// symmetric difference distribution with probability 1 - 2 P(T+ <= C - 1), T+ the Wilcoxon
// signed-rank statistic under H0 (Hollander & Wolfe, Nonparametric Statistical Methods, §3.2).
// C is the largest c >= 1 with P(T+ <= c - 1) <= alpha / 2: from the exact null distribution
// of T+ for n <= kSignedRankExactMax, from its normal approximation with continuity correction
// (mean n(n+1)/4, variance n(n+1)(2n+1)/24) above. When even C = 1 (the whole range of the
// differences) cannot reach the asked confidence (n <= 5 for 95 %), the interval is that range
// and `confidence` says what it reaches: a caller must not read it as a 95 % interval.

inline constexpr std::size_t kSignedRankExactMax = 200;

struct PairedInterval {
  std::size_t count = 0;       // n, the pairs
  double median = 0;           // median of the differences (type 7)
  double hodges_lehmann = 0;   // median of the Walsh averages
  double low = 0, high = 0;    // [W_(C), W_(M + 1 - C)]
  double confidence = 0;       // coverage reached: 1 - 2 P(T+ <= C - 1) (the normal value for large n)
  double nominal = 0;          // coverage asked for
  std::size_t rank = 0;        // C
  bool exact = true;           // C from the exact null distribution (else the normal approximation)

  bool reaches_nominal() const { return confidence >= nominal; }
};

// P(T+ <= t) under H0 for n pairs, from the exact distribution (each rank in T+ with probability
// 1/2, independently). Throws std::invalid_argument for n = 0 or n > kSignedRankExactMax.
double signed_rank_lower_tail(std::size_t n, long long t);
// C for n pairs and two-sided level alpha (0 < alpha < 1), exact or normal as above; at least 1.
// `exact` says which was used.
std::size_t signed_rank_rank(std::size_t n, double alpha, bool* exact = nullptr);
// The same C from the normal approximation, whatever n (exposed so tests can compare the two).
std::size_t signed_rank_rank_normal(std::size_t n, double alpha);
// The standard normal quantile (inverse CDF) for 0 < p < 1.
double normal_quantile(double p);

// Walsh averages of the differences, sorted.
std::vector<double> walsh_averages(std::span<const double> differences);

// Throws std::invalid_argument for no differences, a non-finite one, or a confidence outside (0, 1).
PairedInterval paired_interval(std::span<const double> differences, double confidence = 0.95);

}  // namespace vsgl
