#pragma once
// How a phase's cost grows over a numeric parameter (DESIGN.md §9.1): the least-squares slope of
// log(median ms) against log(x), so cost ∝ x^slope, with a percentile bootstrap interval over
// the rounds, and a check of that slope against what the algorithm predicts.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "harness/core/claim_verdict.hpp"

namespace vsgl {

// One value of the parameter and the per-round samples (ms) of one phase measured at it.
struct GrowthPoint {
  double x = 0;                    // > 0
  std::vector<double> samples_ms;  // finite, > 0, at least 2
};

inline constexpr std::size_t kMaxResamples = 1000000;

struct GrowthFitOptions {
  std::size_t resamples = 2000;            // bootstrap replicates, 1 ... kMaxResamples
  double confidence = 0.95;                // of the percentile interval, in (0, 1)
  std::uint64_t seed = 0x67726f777468ULL;  // same seed and input -> same interval, on any platform
  std::string subject = "cost growth";     // starts every error message (e.g. the phase's name)
};

struct GrowthFit {
  double slope = 0;          // from the medians of all samples
  double low = 0, high = 0;  // percentile bootstrap interval of the slope
  double intercept = 0;      // ln(median ms) at x = 1 of the fitted line
  double confidence = 0;
  std::size_t points = 0;
  std::size_t distinct_x = 0;
  std::size_t resamples = 0;
  std::size_t min_rounds = 0;  // fewest samples at any point
  std::uint64_t seed = 0;
  std::vector<double> medians_ms;  // per point, in input order

  // The fitted cost (ms) at x.
  double predicted_ms(double x) const;
};

// Throws InputError for fewer than 2 distinct x, an x that is not a finite positive number, a
// point with fewer than 2 samples, a sample that is not a finite positive time, or options
// outside their ranges. Each bootstrap replicate resamples every point's samples with
// replacement independently of the other points (DESIGN.md §9.1 says why), takes the medians
// and refits the slope.
GrowthFit fit_growth(const std::vector<GrowthPoint>& points, const GrowthFitOptions& options = {});

// "cost ∝ N^0.98 [0.95, 1.01]", two decimals.
std::string growth_text(const GrowthFit& fit, const std::string& axis_symbol);

// What the algorithm predicts: slope ± tolerance, and the sentence that says why.
struct GrowthExpectation {
  double slope = 1;
  double tolerance = 0;  // >= 0; the accepted band is [slope - tolerance, slope + tolerance]
  std::string why;       // e.g. "filtered sampling is linear in N"
};

// The verdict on "the slope lies within the accepted band" (core/claim_verdict.hpp's
// judge_within): holds when the interval lies inside the band, does not hold when it lies wholly
// outside (the phase does not grow as its algorithm says), inconclusive when it touches or
// crosses an end of the band.
struct GrowthJudgement {
  ClaimVerdict verdict;
  std::string text;

  // The interval excludes the expectation.
  bool flagged() const { return verdict.fails(); }
};

// The verdict alone: judge_within of the slope's interval [low, high] over the band
// [expected_slope - tolerance, expected_slope + tolerance]. Throws std::invalid_argument for
// low > high, or a slope or tolerance that is not finite.
ClaimVerdict growth_verdict(double low, double high, double expected_slope, double tolerance);

// The verdict as the sweep document words it: "consistent" (the interval meets the band: holds or
// inconclusive), "faster" or "slower" (it does not hold, the interval lying above or below the
// band, hence above or below `expected_slope`).
const char* growth_verdict_name(const ClaimVerdict& verdict, double expected_slope);

// Throws InputError for an expectation whose slope or tolerance is not finite or whose
// tolerance is negative.
GrowthJudgement judge_growth(const GrowthFit& fit, const GrowthExpectation& expected, const std::string& axis_symbol);

}  // namespace vsgl
