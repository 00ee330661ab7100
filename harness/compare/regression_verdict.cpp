#include "harness/compare/regression_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "harness/compare/mann_whitney.hpp"

namespace vsgl {
namespace {
// Quantile by linear interpolation between order statistics (type 7, as harness/statistics).
double quantile(const std::vector<double>& sorted, double q) {
  const double h = (static_cast<double>(sorted.size()) - 1.0) * q;
  const std::size_t lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return quantile(v, 0.5);
}
double relative_iqr(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const double m = quantile(v, 0.5);
  return m > 0 ? (quantile(v, 0.75) - quantile(v, 0.25)) / m : 0.0;
}
}  // namespace

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::kFaster: return "FASTER";
    case Verdict::kSlower: return "SLOWER";
    case Verdict::kSame: return "SAME";
    case Verdict::kAmbiguous: return "AMBIGUOUS";
  }
  return "?";
}

Comparison compare_samples(const std::vector<double>& base, const std::vector<double>& fresh,
                           const VerdictConfig& config) {
  if (base.empty() || fresh.empty()) throw std::invalid_argument("a comparison needs samples on both sides");
  Comparison c;
  c.base_median = median(base);
  c.new_median = median(fresh);
  if (!(c.base_median > 0)) throw std::invalid_argument("the base median is not a positive time");
  c.change = c.new_median / c.base_median - 1.0;
  c.p_value = mann_whitney_u(base, fresh).p_value;
  c.threshold = std::max(config.min_change,
                         config.noise_factor * std::max(relative_iqr(base), relative_iqr(fresh)));
  std::ostringstream why;
  if (base.size() < config.min_samples || fresh.size() < config.min_samples) {
    c.verdict = Verdict::kAmbiguous;
    why << "too few samples (" << base.size() << " vs " << fresh.size() << ", need " << config.min_samples << ")";
  } else if (std::abs(c.change) < config.min_change) {
    c.verdict = Verdict::kSame;
    why << "median moved less than " << config.min_change * 100 << " %";
  } else if (std::abs(c.change) < c.threshold) {
    c.verdict = Verdict::kAmbiguous;
    why << "median moved less than the runs' own spread (relative IQR " << c.threshold * 100 << " %)";
  } else if (c.p_value < config.alpha) {
    c.verdict = c.change < 0 ? Verdict::kFaster : Verdict::kSlower;
    why << "p = " << c.p_value << " < " << config.alpha;
  } else {
    c.verdict = Verdict::kAmbiguous;
    why << "median moved but the samples overlap (p = " << c.p_value << ")";
  }
  c.reason = why.str();
  return c;
}

}  // namespace vsgl
