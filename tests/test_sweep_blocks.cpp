// Repeated blocks of a sweep (harness/sweep/sweep_blocks.hpp) without a device: the visit order
// drawn from a seed, each point's visits pooled, and the order and rounds per visit kept by the
// sweep document (harness/formats/sweep_model.hpp) and its schema.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "harness/core/json_schema_subset.hpp"
#include "harness/formats/sweep_model.hpp"
#include "harness/sweep/sweep_blocks.hpp"
#include "harness/sweep/sweep_markdown.hpp"
#include "input_error.hpp"
#include "synthetic_sweep.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

TEST(SweepBlocks, OneBlockIsAxisOrderAndMoreAreSeededPermutations) {
  const SweepOrder one = sweep_visit_order(5, 1, 7);
  ASSERT_EQ(one.visits.size(), 1u);
  EXPECT_EQ(one.visits[0], (std::vector<std::size_t>{0, 1, 2, 3, 4}));

  const SweepOrder a = sweep_visit_order(5, 8, kSweepOrderSeed);
  EXPECT_EQ(a.blocks, 8u);
  EXPECT_EQ(a.seed, kSweepOrderSeed);
  ASSERT_EQ(a.visits.size(), 8u);
  std::set<std::vector<std::size_t>> distinct;
  std::vector<std::size_t> first_visited(5, 0);
  for (const std::vector<std::size_t>& block : a.visits) {
    std::vector<std::size_t> sorted = block;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, (std::vector<std::size_t>{0, 1, 2, 3, 4})) << "each block visits every point once";
    distinct.insert(block);
    ++first_visited[block.front()];
  }
  // Drawn, not fixed: 8 permutations of 5 points drawn uniformly are all equal with probability
  // 120^-7, and this seed's are not; and more than one point opens a block.
  EXPECT_GT(distinct.size(), 1u);
  EXPECT_GT(std::count_if(first_visited.begin(), first_visited.end(), [](std::size_t n) { return n > 0; }), 1);
  // The same seed draws the same order; another seed another one.
  EXPECT_EQ(sweep_visit_order(5, 8, kSweepOrderSeed).visits, a.visits);
  EXPECT_NE(sweep_visit_order(5, 8, kSweepOrderSeed + 1).visits, a.visits);
  EXPECT_THROW(sweep_visit_order(0, 2, 1), std::invalid_argument);
  EXPECT_THROW(sweep_visit_order(3, 0, 1), std::invalid_argument);
}

// One visit of a point of the synthetic sweep, its totals scaled by `scale` and its stop reason set.
SweepPointOutcome visit(const MeasuredSweep& s, std::size_t point, double scale, const std::string& stop) {
  SweepPointOutcome o;
  o.timed = s.points[point];
  for (CaseTiming& c : o.timed->timing.cases) {
    for (double& v : c.total_ms) v *= scale;
    for (auto& phase : c.phase_ms)
      for (double& v : phase) v *= scale;
  }
  o.timed->timing.stop_reason = stop;
  o.scene = s.scene;
  return o;
}

TEST(SweepBlocks, VisitsArePooledPerPointInAxisOrder) {
  const MeasuredSweep s = test::synthetic_sweep({parse_axis_spec("pdf-sharpness=0,1,2")}, {"fis_modified"});
  MeasuredSweep empty = s;
  empty.points.clear();
  PooledSweep pooled(empty, 3, true);
  // Block 1 visits 2, 0, 1; block 2 visits 1, 2, 0. The partial sweep is in axis order throughout.
  pooled.add(2, visit(s, 2, 1.0, "noise_target"));
  ASSERT_EQ(pooled.sweep().points.size(), 1u);
  pooled.add(0, visit(s, 0, 1.0, "noise_target"));
  pooled.add(1, visit(s, 1, 1.0, "noise_target"));
  ASSERT_EQ(pooled.sweep().points.size(), 3u);
  EXPECT_EQ(pooled.sweep().points[0].value_index, (std::vector<std::size_t>{0}));
  pooled.add(1, visit(s, 1, 2.0, "time_cap"));
  pooled.add(2, visit(s, 2, 1.0, "max_repetitions"));
  pooled.add(0, visit(s, 0, 1.0, "noise_target"));
  const MeasuredSweep m = pooled.take();
  ASSERT_EQ(m.points.size(), 3u);
  const SweepPointResult& p = m.points[1];
  EXPECT_EQ(p.block_rounds, (std::vector<uint32_t>{5, 5}));
  EXPECT_EQ(p.timing.repetitions, 10u);
  EXPECT_DOUBLE_EQ(p.timing.timed_seconds, 0.2);
  EXPECT_DOUBLE_EQ(p.time_cap_s, 4.0);          // 2 s per visit
  EXPECT_EQ(p.timing.stop_reason, "time_cap");  // the strongest of its visits
  EXPECT_EQ(m.points[2].timing.stop_reason, "max_repetitions");
  EXPECT_EQ(m.points[0].timing.stop_reason, "noise_target");
  const CaseTiming& c = p.timing.cases[0];
  ASSERT_EQ(c.total_ms.size(), 10u);
  EXPECT_DOUBLE_EQ(c.total_ms[5], 2.0 * c.total_ms[0]);  // the second visit's rounds follow the first's
  ASSERT_EQ(c.phase_ms[2].size(), 10u);
  // The pooled noise is the rounds' own: two visits a factor 2 apart spread the totals widely.
  EXPECT_GT(p.timing.worst_noise, 0.3);
}

TEST(SweepBlocks, WhatIsBeyondTheDeviceIsKeptOnceAndTheSceneFromTheFirstCapture) {
  const MeasuredSweep s = test::synthetic_sweep({parse_axis_spec("pdf-sharpness=0,1")}, {"fis_modified"});
  MeasuredSweep empty = s;
  empty.points.clear();
  empty.scene = SceneIdentity{};
  PooledSweep pooled(empty, 2, true);
  SweepPointOutcome whole;
  whole.beyond_device.push_back(BeyondDevicePoint{{0}, "", "", "simulated"});
  pooled.add(0, whole);
  EXPECT_TRUE(pooled.beyond_device(0));
  SweepPointOutcome part = visit(s, 1, 1.0, "noise_target");
  part.beyond_device.push_back(BeyondDevicePoint{{1}, "kmeans_2d", "camera_view", "simulated"});
  pooled.add(1, part);
  pooled.add(1, part);  // the second visit meets the same limit: not recorded twice
  EXPECT_FALSE(pooled.beyond_device(1));
  EXPECT_EQ(pooled.sweep().beyond_device.size(), 2u);
  EXPECT_EQ(pooled.sweep().scene.name, "tiny");
  // A later visit that times other cases is a bug, not a measurement.
  SweepPointOutcome other = visit(s, 1, 1.0, "noise_target");
  other.timed->timing.cases.pop_back();
  EXPECT_THROW(pooled.add(1, other), std::logic_error);
}

TEST(SweepBlocks, TheDocumentKeepsTheOrderAndTheRoundsPerVisit) {
  MeasuredSweep s = test::synthetic_sweep({parse_axis_spec("pdf-sharpness=0,1,2")}, {"fis_modified"});
  s.order = sweep_visit_order(3, 2, 99);
  for (SweepPointResult& p : s.points) p.block_rounds = {2, 3};
  const ojson doc = test::synthetic_sweep_json(s);
  ASSERT_TRUE(doc.contains("order"));
  EXPECT_EQ(doc["order"]["blocks"], 2);
  EXPECT_EQ(doc["order"]["seed"], 99);
  EXPECT_EQ(doc["points"][0]["timing"]["block_rounds"], ojson::parse("[2, 3]"));
  EXPECT_NE(doc["time_budget_rule"].get<std::string>().find("blocks"), std::string::npos);
  const SweepModel m = read_sweep_model(doc, "mem");
  ASSERT_TRUE(m.order.has_value());
  EXPECT_EQ(m.order->visits, s.order->visits);
  EXPECT_EQ(m.points[2].timing.block_rounds, (std::vector<uint32_t>{2, 3}));
  EXPECT_EQ(to_json(m), doc);
  EXPECT_NE(sweep_markdown(m).find("Timed in 2 repeated blocks"), std::string::npos);
  const auto problems = validate_against_schema(
      doc, test::read_json(std::filesystem::path(VSGL_SOURCE_DIR) / "results/schema/sweep.schema.json"));
  EXPECT_TRUE(problems.empty()) << problems.front();
  // One pass in axis order writes neither key, as before repeated blocks.
  const ojson plain = test::synthetic_sweep_json(test::synthetic_sweep({parse_axis_spec("pdf-sharpness=0,1")}));
  EXPECT_FALSE(plain.contains("order"));
  EXPECT_FALSE(plain["points"][0]["timing"].contains("block_rounds"));

  const auto message = [](const ojson& d) { return test::input_error([&] { read_sweep_model(d, "s.json"); }); };
  ojson bad = doc;
  bad["points"][0]["timing"]["block_rounds"] = ojson::parse("[2, 2]");
  EXPECT_NE(message(bad).find("/points/0/timing/block_rounds: sums to 4, not the 5 repetitions"), std::string::npos)
      << message(bad);
  bad = doc;
  bad["order"]["visits"][1] = ojson::parse("[0, 0, 2]");
  EXPECT_NE(message(bad).find("/order/visits/1: is not an order of the 3 points"), std::string::npos) << message(bad);
  bad = doc;
  bad["order"]["blocks"] = 3;
  EXPECT_NE(message(bad).find("/order/visits: has 2 blocks, not 3"), std::string::npos) << message(bad);
}

}  // namespace
}  // namespace vsgl
