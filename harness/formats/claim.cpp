#include "harness/formats/claim.hpp"

#include <stdexcept>
#include <utility>

#include "harness/core/json_reader.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

constexpr const char* kHolds = "holds";
constexpr const char* kDoesNotHold = "does not hold";
constexpr const char* kNotMeasuredPrefix = "not measured";

bool starts_with(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

// Every layout: a verdict, or a note that says why there is none; never both.
void check_verdict_or_note(const Claim& c) {
  if (c.verdict ? !c.note.empty() : c.note.empty())
    throw std::invalid_argument("claim " + c.text + ": a verdict or a note that says why there is none, never both");
}

// The interval a verdict read, where the claim's measured numbers hold one: the quality
// document's "interval" [low, high], the table's "ci_low_us" and "ci_high_us".
std::optional<Interval> measured_interval(const ojson& measured) {
  const auto number = [&](const char* key) { return measured.contains(key) && measured[key].is_number(); };
  if (measured.contains("interval")) {
    const ojson& i = measured["interval"];
    if (i.is_array() && i.size() == 2 && i[0].is_number() && i[1].is_number())
      return Interval{i[0].get<double>(), i[1].get<double>()};
  }
  if (number("ci_low_us") && number("ci_high_us"))
    return Interval{measured["ci_low_us"].get<double>(), measured["ci_high_us"].get<double>()};
  return std::nullopt;
}

}  // namespace

ojson claim_holds_json(const Claim& c) {
  check_verdict_or_note(c);
  if (!c.verdict) return nullptr;
  if (c.verdict->inconclusive() && !starts_with(c.verdict->reason, kInconclusivePrefix))
    throw std::invalid_argument("claim " + c.text + ": an inconclusive reason must start with \"" +
                                std::string(kInconclusivePrefix) + "\"");
  return c.verdict->inconclusive() ? ojson(nullptr) : ojson(c.verdict->holds());
}

void set_verdict(Claim& claim, std::optional<bool> holds, const std::string& note) {
  if (holds || starts_with(note, kInconclusivePrefix)) {
    ClaimVerdict v;
    v.outcome = !holds ? Outcome::kInconclusive : *holds ? Outcome::kHolds : Outcome::kDoesNotHold;
    v.rule = claim.criterion;
    v.interval = measured_interval(claim.measured);
    v.reason = note;
    claim.verdict = std::move(v);
    claim.note.clear();
  } else {
    claim.verdict.reset();
    claim.note = note;
  }
}

namespace {

ojson table_json(const Claim& c) {
  return ojson{{"id", c.id},
               {"claim", c.text},
               {"criterion", c.criterion},
               {"measured", c.measured},
               {"holds", claim_holds_json(c)},
               {"note", claim_note(c)},
               {"informative_only", c.informative}};
}

Claim read_table(const JsonReader& r, const ojson& c, const std::string& p) {
  if (!c.is_object()) r.wrong_type(c, p, "an object");
  Claim claim;
  claim.id = r.string(c, p, "id");
  claim.text = r.string(c, p, "claim");
  claim.criterion = r.string(c, p, "criterion");
  claim.measured = r.object(c, p, "measured");
  const std::optional<bool> holds =
      r.member(c, p, "holds").is_null() ? std::nullopt : std::optional<bool>(r.boolean(c, p, "holds"));
  set_verdict(claim, holds, r.string(c, p, "note"));
  claim.informative = r.boolean(c, p, "informative_only");
  return claim;
}

// The quality document's own keys; every other member of a claim is one of its measured numbers.
constexpr const char* kQualityKeys[] = {"claim", "source", "measure", "verdict"};

bool is_quality_key(const std::string& key) {
  for (const char* k : kQualityKeys)
    if (key == k) return true;
  return false;
}

ojson quality_json(const Claim& c) {
  if (!c.id.empty() || c.informative) throw std::invalid_argument("a quality claim has no id and no informative flag");
  if (!c.measured.is_object()) throw std::invalid_argument("a quality claim's measured numbers are an object");
  check_verdict_or_note(c);
  if (c.verdict && !c.verdict->inconclusive() && !c.verdict->reason.empty())
    throw std::invalid_argument("a held or refuted quality claim states no reason");
  if (c.verdict && c.verdict->inconclusive() &&
      (c.verdict->reason.empty() || c.verdict->reason == kHolds || c.verdict->reason == kDoesNotHold ||
       starts_with(c.verdict->reason, kNotMeasuredPrefix)))
    throw std::invalid_argument("a quality claim's inconclusive reason reads as another verdict: " + c.verdict->reason);
  if (!c.verdict && !starts_with(c.note, kNotMeasuredPrefix))
    throw std::invalid_argument("a quality claim without a verdict says \"" + std::string(kNotMeasuredPrefix) +
                                "...\": " + c.note);
  ojson o{{"claim", c.text}, {"source", c.source}, {"measure", c.criterion}, {"verdict", stated_verdict(c)}};
  for (const auto& [key, value] : c.measured.items()) {
    if (is_quality_key(key)) throw std::invalid_argument("a quality claim's measured number is named " + key);
    o[key] = value;
  }
  return o;
}

Claim read_quality(const JsonReader& r, const ojson& c, const std::string& p) {
  if (!c.is_object()) r.wrong_type(c, p, "an object");
  Claim claim;
  claim.text = r.string(c, p, "claim");
  claim.source = r.string(c, p, "source");
  claim.criterion = r.string(c, p, "measure");
  for (const auto& [key, value] : c.items())
    if (!is_quality_key(key)) claim.measured[key] = value;
  const std::string verdict = r.string(c, p, "verdict");
  if (verdict.empty()) r.fail(r.child(p, "verdict"), "is empty");
  if (starts_with(verdict, kNotMeasuredPrefix)) {
    claim.note = verdict;
  } else {
    ClaimVerdict v;
    v.outcome = verdict == kHolds         ? Outcome::kHolds
                : verdict == kDoesNotHold ? Outcome::kDoesNotHold
                                          : Outcome::kInconclusive;
    v.rule = claim.criterion;
    v.interval = measured_interval(claim.measured);
    if (v.inconclusive()) v.reason = verdict;
    claim.verdict = std::move(v);
  }
  return claim;
}

}  // namespace

std::string claim_verdict(const Claim& c) {
  return c.verdict ? std::string(outcome_text(c.verdict->outcome)) : std::string(kNotMeasuredPrefix);
}

std::string stated_verdict(const Claim& c) {
  if (!c.verdict) return c.note;
  return c.verdict->inconclusive() ? c.verdict->reason : std::string(outcome_text(c.verdict->outcome));
}

const std::string& claim_note(const Claim& c) { return c.verdict ? c.verdict->reason : c.note; }

nlohmann::ordered_json to_json(const Claim& claim, ClaimLayout layout) {
  return layout == ClaimLayout::kTable ? table_json(claim) : quality_json(claim);
}

Claim claim_from_json(const JsonReader& reader, const nlohmann::ordered_json& value, const std::string& path,
                      ClaimLayout layout) {
  return layout == ClaimLayout::kTable ? read_table(reader, value, path) : read_quality(reader, value, path);
}

}  // namespace vsgl
