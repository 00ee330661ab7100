#pragma once
// Two generators compared frame by frame (DESIGN.md §11a "Verdicts from many frames"): per-frame
// values a_i and b_i of generators A and B on the same frame i (the same lattice offset, the same
// animation frame), so that what the frames share (the scene's hard regions, a lucky offset) drops
// out of the comparison. Three parts:
// - the sign test: how many frames A is below B, above, tied, and the exact binomial p-value of
//   that split under "A below and above B equally likely" (ties dropped, the usual convention);
// - the paired percentile bootstrap: frames drawn with replacement, the same draw for A and B, of
//   mean(a) - mean(b) and mean(a) / mean(b), seeded (core/bootstrap.hpp), so one input gives the
//   same interval on every platform;
// - the verdict of an interval against a bound fixed before the run is core/claim_verdict.hpp's:
//   "holds" when the whole interval lies on the claimed side, "does not hold" when it lies wholly
//   on the other, and "inconclusive" when it touches or straddles the bound.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "harness/core/bootstrap.hpp"

namespace vsgl {

struct SignTest {
  std::size_t frames = 0;
  std::size_t a_below = 0;  // frames with a_i < b_i ("A wins" where lower is better: error, flicker)
  std::size_t a_above = 0;  // frames with a_i > b_i
  std::size_t ties = 0;     // a_i == b_i, left out of the test
  // Under H0 (each untied frame A below with probability 1/2, independently), with n = a_below +
  // a_above: P(X >= a_below), P(X >= a_above), X ~ Binomial(n, 1/2), and the two-sided p-value
  // min(1, 2 P(X <= min(a_below, a_above))). All 1 when every frame ties.
  double p_a_below = 1;
  double p_a_above = 1;
  double p_two_sided = 1;
};

// P(X <= k) for X ~ Binomial(n, 1/2), exact up to double rounding (log-space terms, so no
// underflow for large n). Returns 1 for k >= n.
double binomial_half_lower_tail(std::size_t n, std::size_t k);

// Throws std::invalid_argument for series of different lengths, no frames, or a value that is not
// finite.
SignTest sign_test(std::span<const double> a, std::span<const double> b);

struct PairedBootstrapOptions {
  std::size_t resamples = 2000;
  double confidence = 0.95;
  std::uint64_t seed = 0x7061697265ULL;  // "paire": any fixed value; recorded beside the interval
};

struct PairedBootstrap {
  std::size_t frames = 0;
  double mean_a = 0, mean_b = 0;
  double difference = 0;                             // mean_a - mean_b
  PercentileInterval difference_interval;            // of the replicates' mean(a*) - mean(b*)
  std::optional<double> ratio;                       // mean_a / mean_b, when every b_i > 0
  std::optional<PercentileInterval> ratio_interval;  // of mean(a*) / mean(b*), likewise
  std::size_t resamples = 0;
  double confidence = 0;
  std::uint64_t seed = 0;
};

// The paired bootstrap of the mean difference and of the ratio of means. The ratio is left out
// (none) unless every b_i is positive: only then is every replicate's mean(b*) positive. Throws
// std::invalid_argument for series of different lengths, fewer than 2 frames, a value that is not
// finite, no resamples, or a confidence outside (0, 1).
PairedBootstrap paired_bootstrap(std::span<const double> a, std::span<const double> b,
                                 const PairedBootstrapOptions& options = {});

}  // namespace vsgl
