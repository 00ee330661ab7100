#pragma once
// The percentile bootstrap over timing rounds (DESIGN.md §9.1), shared by the growth fits and the
// PDF-independence judgement: draws that are the same bytes on every platform for one seed, the
// median of a resample, and the percentile interval of the replicates.
#include <cstddef>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

namespace vsgl {

class BootstrapSampler {
 public:
  explicit BootstrapSampler(std::uint64_t seed) : rng_(seed) {}

  // A uniform index below n (n > 0) by rejection, no modulo bias. Not
  // std::uniform_int_distribution: its algorithm differs between standard libraries, while
  // std::mt19937_64's sequence is fixed by the standard.
  std::size_t index(std::size_t n);

  // The median of |samples| draws with replacement from `samples` (not empty).
  double resampled_median(std::span<const double> samples);

 private:
  std::mt19937_64 rng_;
  std::vector<double> draw_;
};

struct PercentileInterval {
  double low = 0, high = 0;
};

// The central `confidence` interval of the replicates (not empty; confidence in (0, 1)), type-7
// quantiles (statistics.hpp). Sorts the replicates.
PercentileInterval percentile_interval(std::vector<double>& replicates, double confidence);

}  // namespace vsgl
