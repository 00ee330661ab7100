#include "harness/core/claim_verdict.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "harness/core/text_format.hpp"

namespace vsgl {
namespace {

void check(const Interval& interval, double bound) {
  if (!(interval.low <= interval.high))
    throw std::invalid_argument("a verdict's interval needs low <= high (got [" + number_text(interval.low) + ", " +
                                number_text(interval.high) + "])");
  if (!std::isfinite(bound)) throw std::invalid_argument("a verdict's bound must be finite");
}

ClaimVerdict decided(const Interval& interval, std::string rule, bool holds, bool fails) {
  ClaimVerdict v;
  v.outcome = holds ? Outcome::kHolds : fails ? Outcome::kDoesNotHold : Outcome::kInconclusive;
  v.rule = std::move(rule);
  v.interval = interval;
  return v;
}

}  // namespace

std::string_view outcome_text(Outcome outcome) {
  switch (outcome) {
    case Outcome::kHolds: return "holds";
    case Outcome::kDoesNotHold: return "does not hold";
    case Outcome::kInconclusive: return "inconclusive";
  }
  return "inconclusive";
}

ClaimVerdict judge_below(const Interval& interval, double bound) {
  check(interval, bound);
  return decided(interval, "interval below " + number_text(bound, 6), interval.high<bound, interval.low> bound);
}

ClaimVerdict judge_above(const Interval& interval, double bound) {
  check(interval, bound);
  return decided(interval, "interval above " + number_text(bound, 6), interval.low > bound, interval.high < bound);
}

ClaimVerdict judge_within(const Interval& interval, double low, double high) {
  check(interval, low);
  check(interval, high);
  if (!(low <= high)) throw std::invalid_argument("a verdict's band needs low <= high");
  return decided(interval, "interval within (" + number_text(low, 6) + ", " + number_text(high, 6) + ")",
                 low < interval.low && interval.high < high, interval.high < low || interval.low > high);
}

}  // namespace vsgl
