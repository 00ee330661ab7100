// The parts the documents share (harness/formats/timing_statistics.hpp, claim.hpp): one type each,
// written in each document's layout with that document's keys, and read back to the same value.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "harness/core/json_reader.hpp"
#include "harness/formats/claim.hpp"
#include "harness/formats/timing_statistics.hpp"
#include "input_error.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;
using test::input_error;

const JsonReader kReader("doc.json", JsonPathStyle::kPointer);

std::vector<std::string> keys(const ojson& o) {
  std::vector<std::string> out;
  for (const auto& [k, v] : o.items()) out.push_back(k);
  return out;
}

TEST(TimingStatistics, TableLayoutKeysCarryTheUnit) {
  const TimingStatistics s = timing_statistics(std::vector<double>{1, 2, 3, 4}, 2.5);
  EXPECT_EQ(s.median_ms, 2.5);
  EXPECT_EQ(s.count, 4u);
  const ojson j = to_json(s, StatisticsLayout::kTable);
  EXPECT_EQ(keys(j), (std::vector<std::string>{"median_ms", "paper_ms", "min_ms", "max_ms", "q1_ms", "q3_ms", "mean_ms",
                                               "stdev_ms", "relative_iqr", "count", "samples_ms"}));
  EXPECT_EQ(j["paper_ms"], 2.5);
  const TimingStatistics back = timing_statistics_from_json(kReader, j, "/t", StatisticsLayout::kTable);
  EXPECT_EQ(to_json(back, StatisticsLayout::kTable).dump(), j.dump());
  // The optional ones are written only when set; the paper's number is null when there is none.
  TimingStatistics bare;
  bare.samples_ms = {1.0};
  bare.median_ms = bare.q1_ms = bare.q3_ms = 1.0;
  EXPECT_EQ(to_json(bare, StatisticsLayout::kTable).dump(),
            R"({"median_ms":1.0,"paper_ms":null,"q1_ms":1.0,"q3_ms":1.0,"samples_ms":[1.0]})");
}

TEST(TimingStatistics, SweepLayoutKeysHaveNoUnitAndTheSamplesBeside) {
  const TimingStatistics s = timing_statistics(std::vector<double>{1, 2, 3});
  const ojson j = to_json(s, StatisticsLayout::kSweep);
  EXPECT_EQ(keys(j), (std::vector<std::string>{"stats", "samples_ms"}));
  EXPECT_EQ(keys(j["stats"]), (std::vector<std::string>{"count", "median", "q1", "q3", "min", "max", "mean", "stdev"}));
  const TimingStatistics back = timing_statistics_from_json(kReader, j, "/s", StatisticsLayout::kSweep);
  EXPECT_EQ(to_json(back, StatisticsLayout::kSweep).dump(), j.dump());
  EXPECT_FALSE(back.paper_ms);
  TimingStatistics partial = s;
  partial.mean_ms.reset();
  EXPECT_THROW(to_json(partial, StatisticsLayout::kSweep), std::invalid_argument);
}

TEST(TimingStatistics, BadValuesAreNamedByPointer) {
  ojson j = to_json(timing_statistics(std::vector<double>{1, 2, 3}), StatisticsLayout::kTable);
  j["q1_ms"] = 2.5;  // above the median
  EXPECT_NE(input_error([&] {
              timing_statistics_from_json(kReader, j, "/t", StatisticsLayout::kTable);
            }).find("doc.json: /t: has quartiles that do not enclose the median"),
            std::string::npos);
  j["samples_ms"][1] = -1;
  EXPECT_NE(input_error([&] {
              timing_statistics_from_json(kReader, j, "/t", StatisticsLayout::kTable);
            }).find("/t/samples_ms/1: is not a positive time (-1)"),
            std::string::npos);
  ojson sweep = to_json(timing_statistics(std::vector<double>{1, 2, 3}), StatisticsLayout::kSweep);
  sweep["stats"].erase("stdev");
  EXPECT_NE(input_error([&] {
              timing_statistics_from_json(kReader, sweep, "/s", StatisticsLayout::kSweep);
            }).find("/s/stats/stdev: missing field"),
            std::string::npos);
}

ClaimVerdict verdict_of(Outcome outcome, const std::string& reason = "") {
  ClaimVerdict v;
  v.outcome = outcome;
  v.rule = "the interval within 5 µs";
  v.interval = Interval{1.0, 4.0};
  v.reason = reason;
  return v;
}

Claim measured_claim() {
  Claim c;
  c.id = "overhead_5us";
  c.text = "Modified FIS costs about 5 microseconds more.";
  c.criterion = "the interval within 5 µs";
  c.measured = ojson{{"ci_low_us", 1.0}, {"ci_high_us", 4.0}};
  c.verdict = verdict_of(Outcome::kHolds);
  c.informative = true;
  return c;
}

TEST(Claim, TableLayoutWritesAndReadsEachOutcomeAndNone) {
  Claim c = measured_claim();
  const ojson j = to_json(c, ClaimLayout::kTable);
  EXPECT_EQ(keys(j),
            (std::vector<std::string>{"id", "claim", "criterion", "measured", "holds", "note", "informative_only"}));
  EXPECT_EQ(to_json(claim_from_json(kReader, j, "/claims/0", ClaimLayout::kTable), ClaimLayout::kTable).dump(),
            j.dump());
  struct Case {
    std::optional<ClaimVerdict> verdict;
    std::string note;
    ojson holds;
    std::string words;
  };
  const std::vector<Case> cases{
      {verdict_of(Outcome::kHolds), "", true, "holds"},
      {verdict_of(Outcome::kDoesNotHold, "k-means moves less"), "", false, "does not hold"},
      {verdict_of(Outcome::kInconclusive, kInconclusiveNote), "", nullptr, "inconclusive"},
      {std::nullopt, "needs fis_tok15 in this run", nullptr, "not measured"},
  };
  for (const Case& k : cases) {
    c.verdict = k.verdict;
    c.note = k.note;
    SCOPED_TRACE(k.words);
    const ojson w = to_json(c, ClaimLayout::kTable);
    EXPECT_EQ(w["holds"], k.holds);
    EXPECT_EQ(w["note"], k.verdict ? k.verdict->reason : k.note);
    EXPECT_EQ(claim_verdict(c), k.words);
    const Claim back = claim_from_json(kReader, w, "/claims/0", ClaimLayout::kTable);
    EXPECT_EQ(claim_verdict(back), k.words);
    ASSERT_EQ(back.verdict.has_value(), k.verdict.has_value());
    if (back.verdict) {
      EXPECT_EQ(back.verdict->outcome, k.verdict->outcome);
      EXPECT_EQ(back.verdict->reason, k.verdict->reason);
      EXPECT_EQ(back.verdict->rule, c.criterion);  // the document's words for the rule
      ASSERT_TRUE(back.verdict->interval.has_value());
      EXPECT_EQ(back.verdict->interval->low, 1.0);
      EXPECT_EQ(back.verdict->interval->high, 4.0);
    }
    EXPECT_EQ(to_json(back, ClaimLayout::kTable).dump(), w.dump());
  }
  // What the layout would read back as something else is refused, never written.
  c.verdict = verdict_of(Outcome::kInconclusive, "the intervals overlap");
  EXPECT_THROW(to_json(c, ClaimLayout::kTable), std::invalid_argument);
  c.verdict = verdict_of(Outcome::kHolds);
  c.note = "a note beside a verdict";
  EXPECT_THROW(to_json(c, ClaimLayout::kTable), std::invalid_argument);
  c.verdict.reset();
  c.note.clear();
  EXPECT_THROW(to_json(c, ClaimLayout::kTable), std::invalid_argument);
}

TEST(Claim, QualityLayoutWritesTheVerdictInWordsAndTheNumbersBeside) {
  Claim c;
  c.text = "Flickering is reduced.";
  c.source = "paper §1";
  c.criterion = "weighted CV";
  c.measured = ojson{{"fis_tok15", 0.2}, {"fis_modified", 0.1}, {"interval", {1.5, 2.5}}};
  c.verdict = verdict_of(Outcome::kDoesNotHold);
  const ojson j = to_json(c, ClaimLayout::kQuality);
  EXPECT_EQ(j["verdict"], "does not hold");
  EXPECT_EQ(j["fis_modified"], 0.1);
  EXPECT_FALSE(j.contains("measured"));
  const Claim back = claim_from_json(kReader, j, "/claims/3", ClaimLayout::kQuality);
  ASSERT_TRUE(back.verdict.has_value());
  EXPECT_EQ(back.verdict->outcome, Outcome::kDoesNotHold);
  ASSERT_TRUE(back.verdict->interval.has_value());
  EXPECT_EQ(back.verdict->interval->low, 1.5);
  EXPECT_EQ(back.verdict->interval->high, 2.5);
  EXPECT_EQ(back.measured.dump(), c.measured.dump());
  // Each outcome and none: the verdict in words, the inconclusive reason, or the note.
  struct Case {
    std::optional<ClaimVerdict> verdict;
    std::string note;
    std::string stated, words;
  };
  const std::vector<Case> cases{
      {verdict_of(Outcome::kHolds), "", "holds", "holds"},
      {verdict_of(Outcome::kDoesNotHold), "", "does not hold", "does not hold"},
      {verdict_of(Outcome::kInconclusive, "reference not converged at some step"), "",
       "reference not converged at some step", "inconclusive"},
      {verdict_of(Outcome::kInconclusive, "no clear difference (within 1%)"), "", "no clear difference (within 1%)",
       "inconclusive"},
      {std::nullopt, "not measured here", "not measured here", "not measured"},
  };
  for (const Case& k : cases) {
    c.verdict = k.verdict;
    c.note = k.note;
    SCOPED_TRACE(k.stated);
    const ojson w = to_json(c, ClaimLayout::kQuality);
    EXPECT_EQ(w["verdict"], k.stated);
    EXPECT_EQ(stated_verdict(c), k.stated);
    const Claim read = claim_from_json(kReader, w, "/claims/3", ClaimLayout::kQuality);
    EXPECT_EQ(claim_verdict(read), k.words);
    EXPECT_EQ(stated_verdict(read), k.stated);
    EXPECT_EQ(to_json(read, ClaimLayout::kQuality).dump(), w.dump());
  }
  // What the quality document cannot hold is refused, never dropped.
  c.verdict.reset();
  c.note = "not measured here";
  Claim with_id = c;
  with_id.id = "x";
  EXPECT_THROW(to_json(with_id, ClaimLayout::kQuality), std::invalid_argument);
  Claim clash = c;
  clash.measured["verdict"] = 1;
  EXPECT_THROW(to_json(clash, ClaimLayout::kQuality), std::invalid_argument);
  Claim reasoned = c;
  reasoned.note.clear();
  reasoned.verdict = verdict_of(Outcome::kHolds, "a reason the layout has no place for");
  EXPECT_THROW(to_json(reasoned, ClaimLayout::kQuality), std::invalid_argument);
  Claim ambiguous = reasoned;
  ambiguous.verdict = verdict_of(Outcome::kInconclusive, "not measured, as it reads");
  EXPECT_THROW(to_json(ambiguous, ClaimLayout::kQuality), std::invalid_argument);
  Claim unnamed = c;
  unnamed.note = "a note that does not say it was not measured";
  EXPECT_THROW(to_json(unnamed, ClaimLayout::kQuality), std::invalid_argument);
  ojson missing = to_json(c, ClaimLayout::kQuality);
  missing.erase("source");
  EXPECT_NE(input_error([&] {
              claim_from_json(kReader, missing, "/claims/3", ClaimLayout::kQuality);
            }).find("/claims/3/source: missing field"),
            std::string::npos);
}

}  // namespace
}  // namespace vsgl
