#include "harness/regression_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "harness/mann_whitney.hpp"

namespace vsgl {
namespace {
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
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
  std::ostringstream why;
  if (base.size() < config.min_samples || fresh.size() < config.min_samples) {
    c.verdict = Verdict::kAmbiguous;
    why << "too few samples (" << base.size() << " vs " << fresh.size() << ", need " << config.min_samples << ")";
  } else if (std::abs(c.change) < config.min_change) {
    c.verdict = Verdict::kSame;
    why << "median moved less than " << config.min_change * 100 << " %";
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
