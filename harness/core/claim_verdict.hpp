#pragma once
// The verdict on a claim: holds, does not hold, or inconclusive, with the interval it read and the
// rule that decided. Every verdict the table, sweep and quality documents carry is one, and so is
// every judgement inside them (a growth expectation, a TOST per case, a bootstrap comparison).
//
// The edge convention (DESIGN.md §9 "Verdicts on intervals"), implemented once below: an interval
// [low, high] is closed, so a bound it touches lies in it. Hence "below b" is high < b, "above b"
// is low > b, "inside [lo, hi]" is lo < low and high < hi, and "outside" is high < lo or low > hi;
// an interval that touches a bound is on neither side of it, and its claim is inconclusive.
#include <optional>
#include <string>
#include <string_view>

namespace vsgl {

enum class Outcome { kHolds, kDoesNotHold, kInconclusive };

// "holds", "does not hold", "inconclusive".
std::string_view outcome_text(Outcome outcome);

// A closed interval of a measured quantity (a confidence or bootstrap interval); low <= high.
struct Interval {
  double low = 0, high = 0;
};

struct ClaimVerdict {
  Outcome outcome = Outcome::kInconclusive;
  // The rule that decided, in words ("interval below 0.99", "every ratio >= 7"). Read back from a
  // document, whose keys carry no rule of their own: the claim's criterion.
  std::string rule;
  std::optional<Interval> interval;  // the interval the rule read; none for a rule on point values
  // Why it does not hold or is inconclusive, as the document words it; "" where the outcome and
  // the rule say it all.
  std::string reason;

  bool holds() const { return outcome == Outcome::kHolds; }
  bool fails() const { return outcome == Outcome::kDoesNotHold; }
  bool inconclusive() const { return outcome == Outcome::kInconclusive; }
};

// The three interval rules of the edge convention above. They set outcome, rule and interval and
// leave the reason to the caller, who words it as its document does. Throw std::invalid_argument
// for an interval with low > high or a bound that is not finite (and for within, low > high).
// "The quantity lies below `bound`": holds when interval.high < bound, does not hold when
// interval.low > bound.
ClaimVerdict judge_below(const Interval& interval, double bound);
// "... above `bound`": holds when interval.low > bound, does not hold when interval.high < bound.
ClaimVerdict judge_above(const Interval& interval, double bound);
// "... within [low, high]": holds when low < interval.low and interval.high < high, does not hold
// when interval.high < low or interval.low > high.
ClaimVerdict judge_within(const Interval& interval, double low, double high);

}  // namespace vsgl
