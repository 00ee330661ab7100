#include "harness/core/growth_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>
#include <tuple>
#include <utility>

#include "harness/core/bootstrap.hpp"
#include "harness/core/error.hpp"
#include "harness/core/statistics.hpp"
#include "harness/core/text_format.hpp"

namespace vsgl {
namespace {

double median_of(std::vector<double>& values) {
  std::sort(values.begin(), values.end());
  return quantile_sorted(values, 0.5);
}

// Least-squares slope and intercept of v against u (u not all equal, checked by the caller).
std::pair<double, double> line_fit(const std::vector<double>& u, const std::vector<double>& v) {
  const double n = static_cast<double>(u.size());
  double mu = 0, mv = 0;
  for (std::size_t i = 0; i < u.size(); ++i) mu += u[i], mv += v[i];
  mu /= n;
  mv /= n;
  double suv = 0, suu = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    suv += (u[i] - mu) * (v[i] - mv);
    suu += (u[i] - mu) * (u[i] - mu);
  }
  const double slope = suv / suu;
  return {slope, mv - slope * mu};
}

// Two decimals, never "-0.00".
std::string fixed2(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  if (s == "-0.00") s = "0.00";
  return s;
}

}  // namespace

double GrowthFit::predicted_ms(double x) const { return std::exp(intercept + slope * std::log(x)); }

GrowthFit fit_growth(const std::vector<GrowthPoint>& points, const GrowthFitOptions& options) {
  const std::string& what = options.subject;
  if (options.resamples < 1 || options.resamples > kMaxResamples)
    throw InputError(what + ": the bootstrap takes 1 to " + std::to_string(kMaxResamples) + " resamples (got " +
                     std::to_string(options.resamples) + ")");
  if (!(options.confidence > 0 && options.confidence < 1))
    throw InputError(what + ": the confidence must lie strictly between 0 and 1 (got " +
                     number_text(options.confidence) + ")");
  std::set<double> distinct;
  std::size_t min_rounds = SIZE_MAX;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const GrowthPoint& p = points[i];
    const std::string at = what + ": point " + std::to_string(i + 1) + " (x = " + number_text(p.x) + ")";
    if (!std::isfinite(p.x) || !(p.x > 0))
      throw InputError(at + ": the parameter must be a finite positive number for a log-log fit");
    if (p.samples_ms.size() < 2)
      throw InputError(at + ": needs at least 2 rounds (got " + std::to_string(p.samples_ms.size()) + ")");
    for (std::size_t r = 0; r < p.samples_ms.size(); ++r) {
      const double s = p.samples_ms[r];
      if (!std::isfinite(s) || !(s > 0))
        throw InputError(at + ": round " + std::to_string(r + 1) + " is not a positive time (" + number_text(s) +
                         " ms)");
    }
    distinct.insert(p.x);
    min_rounds = std::min(min_rounds, p.samples_ms.size());
  }
  if (distinct.size() < 2)
    throw InputError(what + ": a slope needs at least 2 distinct parameter values (got " +
                     std::to_string(distinct.size()) + ")");

  std::vector<double> log_x(points.size()), log_median(points.size());
  GrowthFit fit;
  fit.medians_ms.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::vector<double> copy = points[i].samples_ms;
    fit.medians_ms[i] = median_of(copy);
    log_x[i] = std::log(points[i].x);
    log_median[i] = std::log(fit.medians_ms[i]);
  }
  std::tie(fit.slope, fit.intercept) = line_fit(log_x, log_median);

  // Bootstrap: every replicate draws each point's rounds anew, in point order, so the sequence
  // of draws (and the interval) depends only on the input and the seed.
  BootstrapSampler sampler(options.seed);
  std::vector<double> slopes(options.resamples), log_boot(points.size());
  for (std::size_t b = 0; b < options.resamples; ++b) {
    for (std::size_t i = 0; i < points.size(); ++i)
      log_boot[i] = std::log(sampler.resampled_median(points[i].samples_ms));
    slopes[b] = line_fit(log_x, log_boot).first;
  }
  const PercentileInterval interval = percentile_interval(slopes, options.confidence);
  fit.low = interval.low;
  fit.high = interval.high;
  fit.confidence = options.confidence;
  fit.points = points.size();
  fit.distinct_x = distinct.size();
  fit.resamples = options.resamples;
  fit.min_rounds = min_rounds;
  fit.seed = options.seed;
  return fit;
}

std::string growth_text(const GrowthFit& fit, const std::string& axis_symbol) {
  return "cost \u221d " + axis_symbol + "^" + fixed2(fit.slope) + " [" + fixed2(fit.low) + ", " + fixed2(fit.high) +
         "]";
}

const char* growth_verdict_name(const ClaimVerdict& verdict, double expected_slope) {
  if (!verdict.fails()) return "consistent";
  return verdict.interval && verdict.interval->low > expected_slope ? "faster" : "slower";
}

ClaimVerdict growth_verdict(double low, double high, double expected_slope, double tolerance) {
  return judge_within({low, high}, expected_slope - tolerance, expected_slope + tolerance);
}

GrowthJudgement judge_growth(const GrowthFit& fit, const GrowthExpectation& expected, const std::string& axis_symbol) {
  if (!std::isfinite(expected.slope) || !std::isfinite(expected.tolerance) || expected.tolerance < 0)
    throw InputError("expected growth: the slope must be finite and the tolerance finite and non-negative (got " +
                     number_text(expected.slope) + " \u00b1 " + number_text(expected.tolerance) + ")");
  GrowthJudgement j;
  j.verdict = growth_verdict(fit.low, fit.high, expected.slope, expected.tolerance);
  std::string expectation = axis_symbol + "^" + fixed2(expected.slope);
  if (expected.tolerance > 0) expectation += " \u00b1 " + fixed2(expected.tolerance);
  if (!expected.why.empty()) expectation += " (" + expected.why + ")";
  const std::string fitted = growth_text(fit, axis_symbol);
  const std::string name = growth_verdict_name(j.verdict, expected.slope);
  if (name == "consistent") j.text = fitted + " is consistent with the expected " + expectation;
  else j.text = fitted + " grows " + name + " than the expected " + expectation + ": the interval excludes it";
  return j;
}

}  // namespace vsgl
