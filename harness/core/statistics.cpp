#include "harness/core/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vsgl {

double quantile_sorted(std::span<const double> sorted, double p) {
  if (sorted.empty()) throw std::invalid_argument("quantile of no samples");
  if (!(p >= 0.0 && p <= 1.0)) throw std::invalid_argument("quantile probability outside [0, 1]");
  const double h = static_cast<double>(sorted.size() - 1) * p;
  const auto j = static_cast<std::size_t>(std::floor(h));
  if (j + 1 >= sorted.size()) return sorted.back();
  return sorted[j] + (h - static_cast<double>(j)) * (sorted[j + 1] - sorted[j]);
}

SampleStats summarize(std::span<const double> samples) {
  if (samples.size() < 2)
    throw std::invalid_argument("statistics need at least 2 samples (got " + std::to_string(samples.size()) + ")");
  for (double s : samples)
    if (!std::isfinite(s)) throw std::invalid_argument("a sample is not finite");
  std::vector<double> sorted(samples.begin(), samples.end());
  std::sort(sorted.begin(), sorted.end());
  SampleStats st;
  st.count = sorted.size();
  st.min = sorted.front();
  st.max = sorted.back();
  st.median = quantile_sorted(sorted, 0.5);
  st.q1 = quantile_sorted(sorted, 0.25);
  st.q3 = quantile_sorted(sorted, 0.75);
  st.p95 = quantile_sorted(sorted, 0.95);
  st.p99 = quantile_sorted(sorted, 0.99);
  // Two passes (mean, then squared deviations): no cancellation for tightly clustered samples. In
  // the input's order, as the per-frame series' means in committed quality documents were summed.
  double sum = 0;
  for (double s : samples) sum += s;
  st.mean = sum / static_cast<double>(st.count);
  double squares = 0;
  for (double s : samples) squares += (s - st.mean) * (s - st.mean);
  st.stdev = std::sqrt(squares / static_cast<double>(st.count - 1));
  return st;
}

double relative_iqr(const SampleStats& stats) {
  if (!(stats.median > 0.0)) throw std::invalid_argument("relative noise needs a positive median");
  return stats.iqr() / stats.median;
}

std::vector<double> add_samples(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size()) throw std::invalid_argument("sample series of different lengths cannot be added");
  std::vector<double> out(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = a[i] + b[i];
  return out;
}

std::vector<double> subtract_samples(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size()) throw std::invalid_argument("paired sample series of different lengths cannot be subtracted");
  std::vector<double> out(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = a[i] - b[i];
  return out;
}

namespace {

void check_alpha(double alpha) {
  if (!(alpha > 0.0 && alpha < 1.0)) throw std::invalid_argument("a two-sided level must lie in (0, 1)");
}

// P(T+ = s), s = 0 .. n(n+1)/2, under H0, adding the ranks one at a time: rank k is in T+ with
// probability 1/2. Probabilities, not counts, so that 2^n cannot overflow.
std::vector<double> signed_rank_pmf(std::size_t n) {
  std::vector<double> p(n * (n + 1) / 2 + 1, 0.0);
  p[0] = 1.0;
  std::size_t reach = 0;
  for (std::size_t k = 1; k <= n; ++k) {
    reach += k;
    for (std::size_t s = reach; s >= k; --s) p[s] = 0.5 * (p[s] + p[s - k]);
    for (std::size_t s = 0; s < k; ++s) p[s] *= 0.5;
  }
  return p;
}

// Standard normal CDF.
double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

}  // namespace

double normal_quantile(double p) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("a normal quantile needs 0 < p < 1");
  // P. J. Acklam's rational approximation (relative error < 1.2e-9), then one Halley step on
  // the exact CDF, which brings it to double precision.
  static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                                 1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                                 6.680131188771972e+01,  -1.328068155288572e+01};
  static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                                 -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                                 3.754408661907416e+00};
  constexpr double p_low = 0.02425;
  double x;
  if (p < p_low) {
    const double q = std::sqrt(-2.0 * std::log(p));
    x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  } else if (p <= 1.0 - p_low) {
    const double q = p - 0.5, r = q * q;
    x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
  } else {
    const double q = std::sqrt(-2.0 * std::log(1.0 - p));
    x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  }
  const double e = normal_cdf(x) - p;
  const double u = e * std::sqrt(2.0 * 3.14159265358979323846) * std::exp(0.5 * x * x);
  return x - u / (1.0 + 0.5 * x * u);
}

double signed_rank_lower_tail(std::size_t n, long long t) {
  if (n == 0 || n > kSignedRankExactMax)
    throw std::invalid_argument("the exact signed-rank distribution is computed for 1 to " +
                                std::to_string(kSignedRankExactMax) + " pairs");
  const std::size_t max_sum = n * (n + 1) / 2;
  if (t < 0) return 0.0;
  if (static_cast<std::size_t>(t) >= max_sum) return 1.0;
  const std::vector<double> p = signed_rank_pmf(n);
  double tail = 0;
  for (long long s = 0; s <= t; ++s) tail += p[static_cast<std::size_t>(s)];
  return std::min(tail, 1.0);
}

std::size_t signed_rank_rank_normal(std::size_t n, double alpha) {
  check_alpha(alpha);
  if (n == 0) throw std::invalid_argument("no pairs");
  const double nn = static_cast<double>(n);
  const double mean = nn * (nn + 1.0) / 4.0;
  const double sd = std::sqrt(nn * (nn + 1.0) * (2.0 * nn + 1.0) / 24.0);
  // P(T+ <= C - 1) ~ Phi((C - 1 + 0.5 - mean) / sd) <= alpha / 2 (continuity-corrected).
  const double c = std::floor(mean + 0.5 + normal_quantile(alpha / 2.0) * sd);
  return c < 1.0 ? 1 : static_cast<std::size_t>(c);
}

std::size_t signed_rank_rank(std::size_t n, double alpha, bool* exact) {
  check_alpha(alpha);
  if (n == 0) throw std::invalid_argument("no pairs");
  if (exact) *exact = n <= kSignedRankExactMax;
  if (n > kSignedRankExactMax) return signed_rank_rank_normal(n, alpha);
  // The cumulative distribution once, then the largest c with P(T+ <= c - 1) <= alpha / 2.
  const std::size_t max_sum = n * (n + 1) / 2;
  const std::vector<double> p = signed_rank_pmf(n);
  std::size_t c = 1;
  double tail = p[0];  // P(T+ <= c - 1) for c = 1
  while (c < max_sum && tail + p[c] <= alpha / 2.0) tail += p[c++];
  return tail <= alpha / 2.0 ? c : 1;
}

std::vector<double> walsh_averages(std::span<const double> d) {
  std::vector<double> w;
  w.reserve(d.size() * (d.size() + 1) / 2);
  for (std::size_t i = 0; i < d.size(); ++i)
    for (std::size_t j = i; j < d.size(); ++j) w.push_back(0.5 * (d[i] + d[j]));
  std::sort(w.begin(), w.end());
  return w;
}

PairedInterval paired_interval(std::span<const double> differences, double confidence) {
  if (differences.empty()) throw std::invalid_argument("a paired interval needs at least one difference");
  if (!(confidence > 0.0 && confidence < 1.0)) throw std::invalid_argument("a confidence level must lie in (0, 1)");
  for (double d : differences)
    if (!std::isfinite(d)) throw std::invalid_argument("a paired difference is not finite");
  PairedInterval r;
  r.count = differences.size();
  r.nominal = confidence;
  std::vector<double> sorted(differences.begin(), differences.end());
  std::sort(sorted.begin(), sorted.end());
  r.median = quantile_sorted(sorted, 0.5);
  const std::vector<double> w = walsh_averages(differences);
  r.hodges_lehmann = quantile_sorted(w, 0.5);
  const double alpha = 1.0 - confidence;
  const std::size_t m = w.size();
  std::size_t c = signed_rank_rank(r.count, alpha, &r.exact);
  c = std::min(c, (m + 1) / 2);  // never an empty interval
  r.rank = c;
  r.low = w[c - 1];
  r.high = w[m - c];
  if (r.exact) {
    r.confidence = 1.0 - 2.0 * signed_rank_lower_tail(r.count, static_cast<long long>(c) - 1);
  } else {
    const double nn = static_cast<double>(r.count);
    const double mean = nn * (nn + 1.0) / 4.0;
    const double sd = std::sqrt(nn * (nn + 1.0) * (2.0 * nn + 1.0) / 24.0);
    r.confidence = 1.0 - 2.0 * normal_cdf((static_cast<double>(c) - 0.5 - mean) / sd);
  }
  return r;
}

}  // namespace vsgl
