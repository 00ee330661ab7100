#include "harness/core/holm_correction.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace vsgl {

std::vector<HolmDecision> holm_correction(std::span<const double> p, double alpha) {
  if (p.empty()) throw std::invalid_argument("Holm's correction needs at least one p-value");
  if (!(alpha > 0.0 && alpha < 1.0)) throw std::invalid_argument("a family-wise level must lie in (0, 1)");
  for (double v : p)
    if (!(v >= 0.0 && v <= 1.0)) throw std::invalid_argument("a p-value must lie in [0, 1]");
  const std::size_t m = p.size();
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
  std::vector<HolmDecision> out(m);
  bool stopped = false;
  for (std::size_t i = 0; i < m; ++i) {
    HolmDecision& d = out[order[i]];
    d.rank = i + 1;
    d.level = alpha / static_cast<double>(m - i);
    if (!stopped && p[order[i]] <= d.level) d.rejected = true;
    else stopped = true;
  }
  return out;
}

}  // namespace vsgl
