#include "harness/compare/mann_whitney.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace vsgl {
namespace {

// Largest n1 * n2 for which the exact distribution is tabulated (a few kB of doubles).
constexpr std::size_t kExactLimit = 2500;

// P(U <= u) for samples of n1 and n2 with no ties: the number of arrangements with U = k follows
// the recurrence f(n1, n2, k) = f(n1 - 1, n2, k - n2) + f(n1, n2 - 1, k), normalized by C(n1+n2, n1).
double exact_cdf(std::size_t n1, std::size_t n2, double u) {
  const std::size_t max_u = n1 * n2;
  // counts[j][k]: arrangements of i first-sample and j second-sample values with U = k.
  std::vector<std::vector<double>> counts(n2 + 1, std::vector<double>(max_u + 1, 0.0));
  for (std::size_t j = 0; j <= n2; ++j) counts[j][0] = 1.0;  // i = 0
  for (std::size_t i = 1; i <= n1; ++i) {
    std::vector<std::vector<double>> next(n2 + 1, std::vector<double>(max_u + 1, 0.0));
    next[0][0] = 1.0;
    for (std::size_t j = 1; j <= n2; ++j)
      for (std::size_t k = 0; k <= i * j; ++k) {
        // The largest of the i + j values is from the first sample (it beats all j) or the second.
        const double first = k >= j ? counts[j][k - j] : 0.0;
        next[j][k] = first + next[j - 1][k];
      }
    counts.swap(next);
  }
  const auto& dist = counts[n2];
  const double total = std::accumulate(dist.begin(), dist.end(), 0.0);
  double below = 0;
  for (std::size_t k = 0; k <= max_u && static_cast<double>(k) <= u + 1e-9; ++k) below += dist[k];
  return below / total;
}

}  // namespace

MannWhitneyResult mann_whitney_u(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.empty() || b.empty()) throw std::invalid_argument("Mann-Whitney U needs two non-empty samples");
  for (const auto* s : {&a, &b})
    for (double v : *s)
      if (!std::isfinite(v)) throw std::invalid_argument("Mann-Whitney U: a sample holds a non-finite value");
  const std::size_t n1 = a.size(), n2 = b.size(), n = n1 + n2;

  // Average ranks over the pooled sample.
  std::vector<std::pair<double, int>> pooled;
  pooled.reserve(n);
  for (double v : a) pooled.emplace_back(v, 0);
  for (double v : b) pooled.emplace_back(v, 1);
  std::sort(pooled.begin(), pooled.end());
  double rank_sum_a = 0, tie_term = 0;
  bool ties = false;
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j + 1 < n && pooled[j + 1].first == pooled[i].first) ++j;
    const double t = static_cast<double>(j - i + 1);
    const double average_rank = 0.5 * static_cast<double>(i + j) + 1.0;
    for (std::size_t k = i; k <= j; ++k)
      if (pooled[k].second == 0) rank_sum_a += average_rank;
    if (t > 1) {
      ties = true;
      tie_term += t * t * t - t;
    }
    i = j + 1;
  }
  MannWhitneyResult r;
  const double n1d = static_cast<double>(n1), n2d = static_cast<double>(n2), nd = static_cast<double>(n);
  r.u1 = rank_sum_a - n1d * (n1d + 1.0) / 2.0;
  r.u2 = n1d * n2d - r.u1;
  const double u_min = std::min(r.u1, r.u2);

  if (!ties && n1 * n2 <= kExactLimit) {
    r.exact = true;
    r.p_value = std::min(1.0, 2.0 * exact_cdf(n1, n2, u_min));
    return r;
  }
  const double mean = n1d * n2d / 2.0;
  const double variance = n1d * n2d / 12.0 * ((nd + 1.0) - tie_term / (nd * (nd - 1.0)));
  if (variance <= 0) {  // every value equal: no evidence of any difference
    r.p_value = 1.0;
    return r;
  }
  const double z = std::max(0.0, std::abs(r.u1 - mean) - 0.5) / std::sqrt(variance);
  r.p_value = std::min(1.0, std::erfc(z / std::sqrt(2.0)));
  return r;
}

}  // namespace vsgl
