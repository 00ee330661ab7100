#include "harness/core/paired_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace vsgl {

namespace {

void check_paired(std::span<const double> a, std::span<const double> b, std::size_t least) {
  if (a.size() != b.size())
    throw std::invalid_argument("paired series of different lengths (" + std::to_string(a.size()) + " and " +
                                std::to_string(b.size()) + " frames)");
  if (a.size() < least)
    throw std::invalid_argument("a paired comparison needs at least " + std::to_string(least) + " frames (got " +
                                std::to_string(a.size()) + ")");
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!std::isfinite(a[i]) || !std::isfinite(b[i]))
      throw std::invalid_argument("frame " + std::to_string(i) + "'s value is not finite");
}

double mean_of(std::span<const double> x) {
  double sum = 0;
  for (double v : x) sum += v;
  return sum / static_cast<double>(x.size());
}

}  // namespace

double binomial_half_lower_tail(std::size_t n, std::size_t k) {
  if (k >= n) return 1.0;
  // The terms C(n, j) relative to the central one, by the ratio C(n, j+1) / C(n, j) = (n - j) /
  // (j + 1) outward from j = n/2: no 2^-n (which underflows past n = 1074) and only * and /, so
  // every platform rounds alike. Terms far in the tails underflow to 0, below double precision of
  // the total anyway.
  const std::size_t mid = n / 2;
  std::vector<double> term(n + 1, 0.0);
  term[mid] = 1.0;
  for (std::size_t j = mid; j < n; ++j) term[j + 1] = term[j] * static_cast<double>(n - j) / static_cast<double>(j + 1);
  for (std::size_t j = mid; j > 0; --j) term[j - 1] = term[j] * static_cast<double>(j) / static_cast<double>(n - j + 1);
  // Sum smallest first, from both ends, so the small tail terms are not lost.
  double total = 0;
  for (std::size_t j = 0; j < mid; ++j) total += term[j];
  for (std::size_t j = n; j > mid; --j) total += term[j];
  total += term[mid];
  double tail = 0;
  for (std::size_t j = 0; j <= k; ++j) tail += term[j];
  return std::min(1.0, tail / total);
}

SignTest sign_test(std::span<const double> a, std::span<const double> b) {
  check_paired(a, b, 1);
  SignTest t;
  t.frames = a.size();
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] < b[i]) ++t.a_below;
    else if (a[i] > b[i]) ++t.a_above;
    else ++t.ties;
  }
  const std::size_t n = t.a_below + t.a_above;
  if (n == 0) return t;
  // P(X >= k) = P(X <= n - k) by the symmetry of Binomial(n, 1/2).
  t.p_a_below = binomial_half_lower_tail(n, n - t.a_below);
  t.p_a_above = binomial_half_lower_tail(n, n - t.a_above);
  t.p_two_sided = std::min(1.0, 2.0 * binomial_half_lower_tail(n, std::min(t.a_below, t.a_above)));
  return t;
}

PairedBootstrap paired_bootstrap(std::span<const double> a, std::span<const double> b,
                                 const PairedBootstrapOptions& options) {
  check_paired(a, b, 2);
  if (options.resamples == 0) throw std::invalid_argument("a bootstrap needs at least one resample");
  if (!(options.confidence > 0.0 && options.confidence < 1.0))
    throw std::invalid_argument("a confidence must lie in (0, 1)");
  PairedBootstrap out;
  out.frames = a.size();
  out.resamples = options.resamples;
  out.confidence = options.confidence;
  out.seed = options.seed;
  out.mean_a = mean_of(a);
  out.mean_b = mean_of(b);
  out.difference = out.mean_a - out.mean_b;
  const bool ratio = std::all_of(b.begin(), b.end(), [](double v) { return v > 0.0; });
  if (ratio) out.ratio = out.mean_a / out.mean_b;

  // One draw of frame indices serves both generators: the pairing is what cancels the frames'
  // shared difficulty (the replicates of the difference vary with a_i - b_i, not with a_i and b_i).
  BootstrapSampler sampler(options.seed);
  std::vector<double> differences(options.resamples), ratios;
  if (ratio) ratios.resize(options.resamples);
  const std::size_t n = a.size();
  for (std::size_t r = 0; r < options.resamples; ++r) {
    double sum_a = 0, sum_b = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = sampler.index(n);
      sum_a += a[j];
      sum_b += b[j];
    }
    differences[r] = (sum_a - sum_b) / static_cast<double>(n);
    if (ratio) ratios[r] = sum_a / sum_b;
  }
  out.difference_interval = percentile_interval(differences, options.confidence);
  if (ratio) out.ratio_interval = percentile_interval(ratios, options.confidence);
  return out;
}

}  // namespace vsgl
