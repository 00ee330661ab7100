// The parts the documents share (harness/formats/timing_statistics.hpp, claim.hpp): one type each,
// written in each document's layout with that document's keys, and read back to the same value.
#include <gtest/gtest.h>

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

Claim measured_claim() {
  Claim c;
  c.id = "overhead_5us";
  c.text = "Modified FIS costs about 5 microseconds more.";
  c.criterion = "the interval within 5 µs";
  c.measured = ojson{{"low_us", 1.0}, {"high_us", 4.0}};
  c.holds = true;
  c.informative = true;
  return c;
}

TEST(Claim, TableLayout) {
  const Claim c = measured_claim();
  const ojson j = to_json(c, ClaimLayout::kTable);
  EXPECT_EQ(keys(j),
            (std::vector<std::string>{"id", "claim", "criterion", "measured", "holds", "note", "informative_only"}));
  EXPECT_EQ(to_json(claim_from_json(kReader, j, "/claims/0", ClaimLayout::kTable), ClaimLayout::kTable).dump(),
            j.dump());
  Claim open = c;
  open.holds.reset();
  open.note = kInconclusiveNote;
  const ojson oj = to_json(open, ClaimLayout::kTable);
  EXPECT_TRUE(oj["holds"].is_null());
  EXPECT_FALSE(claim_from_json(kReader, oj, "/claims/0", ClaimLayout::kTable).holds);
  EXPECT_EQ(claim_verdict(open), "inconclusive");
  open.note = "needs fis_tok15 in this run";
  EXPECT_EQ(claim_verdict(open), "not measured");
  EXPECT_EQ(claim_verdict(c), "holds");
}

TEST(Claim, QualityLayoutWritesTheVerdictInWordsAndTheNumbersBeside) {
  Claim c;
  c.text = "Flickering is reduced.";
  c.source = "paper §1";
  c.criterion = "weighted CV";
  c.measured = ojson{{"fis_tok15", 0.2}, {"fis_modified", 0.1}};
  c.holds = false;
  const ojson j = to_json(c, ClaimLayout::kQuality);
  EXPECT_EQ(j["verdict"], "does not hold");
  EXPECT_EQ(j["fis_modified"], 0.1);
  EXPECT_FALSE(j.contains("measured"));
  const Claim back = claim_from_json(kReader, j, "/claims/3", ClaimLayout::kQuality);
  EXPECT_EQ(back.holds, false);
  EXPECT_EQ(back.measured.dump(), c.measured.dump());
  // No verdict either way: the verdict in words is the note.
  c.holds.reset();
  c.note = "no clear difference (within 1%)";
  const ojson open = to_json(c, ClaimLayout::kQuality);
  EXPECT_EQ(open["verdict"], "no clear difference (within 1%)");
  EXPECT_EQ(claim_from_json(kReader, open, "/claims/3", ClaimLayout::kQuality).note, c.note);
  // What the quality document cannot hold is refused, never dropped.
  Claim with_id = c;
  with_id.id = "x";
  EXPECT_THROW(to_json(with_id, ClaimLayout::kQuality), std::invalid_argument);
  Claim clash = c;
  clash.measured["verdict"] = 1;
  EXPECT_THROW(to_json(clash, ClaimLayout::kQuality), std::invalid_argument);
  ojson missing = open;
  missing.erase("source");
  EXPECT_NE(input_error([&] {
              claim_from_json(kReader, missing, "/claims/3", ClaimLayout::kQuality);
            }).find("/claims/3/source: missing field"),
            std::string::npos);
}

}  // namespace
}  // namespace vsgl
