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
    if (!std::isfinite(s)) throw std::invalid_argument("a timing sample is not finite");
  std::vector<double> sorted(samples.begin(), samples.end());
  std::sort(sorted.begin(), sorted.end());
  SampleStats st;
  st.count = sorted.size();
  st.min = sorted.front();
  st.max = sorted.back();
  st.median = quantile_sorted(sorted, 0.5);
  st.q1 = quantile_sorted(sorted, 0.25);
  st.q3 = quantile_sorted(sorted, 0.75);
  // Two passes (mean, then squared deviations): no cancellation for tightly clustered samples.
  double sum = 0;
  for (double s : sorted) sum += s;
  st.mean = sum / static_cast<double>(st.count);
  double squares = 0;
  for (double s : sorted) squares += (s - st.mean) * (s - st.mean);
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

}  // namespace vsgl
