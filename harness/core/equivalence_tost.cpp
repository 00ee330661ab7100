#include "harness/core/equivalence_tost.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace vsgl {

EquivalencePValues bootstrap_equivalence(std::span<const double> replicates, double delta) {
  if (replicates.empty()) throw std::invalid_argument("an equivalence test needs bootstrap replicates");
  if (!(delta > 0.0) || !std::isfinite(delta)) throw std::invalid_argument("an equivalence band must be positive");
  std::size_t at_or_above_high = 0, at_or_below_low = 0, at_or_below_high = 0, at_or_above_low = 0;
  for (double r : replicates) {
    if (!std::isfinite(r)) throw std::invalid_argument("a bootstrap replicate is not finite");
    if (r >= delta) ++at_or_above_high;
    if (r <= -delta) ++at_or_below_low;
    if (r <= delta) ++at_or_below_high;
    if (r >= -delta) ++at_or_above_low;
  }
  const double b = static_cast<double>(replicates.size()) + 1.0;
  const auto share = [b](std::size_t k) { return (static_cast<double>(k) + 1.0) / b; };
  EquivalencePValues p;
  p.equivalent = std::max(share(at_or_above_high), share(at_or_below_low));
  p.outside = std::min(1.0, 2.0 * std::min(share(at_or_below_high), share(at_or_above_low)));
  return p;
}

}  // namespace vsgl
