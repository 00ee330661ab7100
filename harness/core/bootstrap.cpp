#include "harness/core/bootstrap.hpp"

#include <algorithm>

#include "harness/core/statistics.hpp"

namespace vsgl {

std::size_t BootstrapSampler::index(std::size_t n) {
  const std::uint64_t bound = n;
  const std::uint64_t threshold = (0 - bound) % bound;  // 2^64 mod n
  for (;;) {
    const std::uint64_t r = rng_();
    if (r >= threshold) return static_cast<std::size_t>(r % bound);
  }
}

double BootstrapSampler::resampled_median(std::span<const double> samples) {
  draw_.resize(samples.size());
  for (double& d : draw_) d = samples[index(samples.size())];
  std::sort(draw_.begin(), draw_.end());
  return quantile_sorted(draw_, 0.5);
}

PercentileInterval percentile_interval(std::vector<double>& replicates, double confidence) {
  std::sort(replicates.begin(), replicates.end());
  const double tail = (1 - confidence) / 2;
  return {quantile_sorted(replicates, tail), quantile_sorted(replicates, 1 - tail)};
}

}  // namespace vsgl
