// `compare` flags exactly the generator that `tables --debug-slow` slowed (the test build's
// workload, tests/hooks/debug_slowdown.hpp), in two parts so that noise cannot fail it:
//
// - The verdict logic on synthetic samples (no device, no clock): base and new runs with the
//   same noise, one generator's last phase slowed; exactly its rows (that phase, its view totals,
//   its total) are SLOWER and every other row is SAME. This is where "and only it" is proven.
// - End to end on the test device (lavapipe): two real `tables` runs on tiny captures, the second
//   slowed. Checked only what noise cannot flip: the run says it was slowed; the slowed
//   generator's recording holds exactly one more dispatch per view and no other generator's
//   changed (counted while recording); and the slowed rows are SLOWER, with extra work about
//   two orders of magnitude above the rows' own time (DebugSlowWork x 16: about 100x in a run on a busy 2-core machine,
//   where noise moved unslowed rows by up to 7x), so that noise, which only ever adds time, would have to add tens of
//   milliseconds to most base samples to hide it. Whether an unslowed row stays SAME is not asserted here: on a shared,
//   busy CPU a 0.05 ms phase can double from preemption alone, which is a property of the machine, not of `compare`.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <random>
#include <set>

#include "gpu_test.hpp"
#include "harness/compare/regression_compare.hpp"
#include "harness/report/tables_run.hpp"
#include "hooks/debug_slowdown.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

// The rows that contain fis_modified's last phase, in both tables.
std::set<std::string> slowed_rows() {
  std::set<std::string> expected;
  for (const std::string t : {"table1", "table2"}) {
    for (const std::string v : {"camera_view", "light_view"}) {
      expected.insert(t + "/fis_modified/" + v + "/filtered_sampling");
      expected.insert(t + "/fis_modified/" + v + "/total");
    }
    expected.insert(t + "/fis_modified/total");
  }
  return expected;
}

std::set<std::string> rows_with(const RunComparison& c, Verdict v) {
  std::set<std::string> names;
  for (const auto& r : c.rows)
    if (r.result.verdict == v) names.insert(r.name);
  return names;
}

// A run of three generators on both tables, each phase's samples lognormal noise (0.2 %) around a
// fixed median; `slow_ms` is added to every sample of fis_modified's filtered_sampling.
BenchRun synthetic_run(uint32_t seed, double slow_ms) {
  std::mt19937 rng(seed);
  std::lognormal_distribution<double> noise(0.0, 0.002);
  constexpr int kSamples = 12;
  BenchRun run;
  run.path = "synthetic-" + std::to_string(seed);
  run.format = "table";
  run.device = "Test GPU";
  const std::vector<std::pair<std::string, std::vector<std::string>>> generators = {
      {"fis_tok15", {"additional", "mipmapping", "filtered_sampling"}},
      {"fis_modified", {"additional", "mipmapping", "filtered_sampling"}},
      {"kmeans_2d", {"cluster_assignment", "sort", "sum"}}};
  for (int table : {1, 2}) {
    RunTable t;
    t.table = table;
    t.capture_hashes = {{"gbuffer", "fnv1a64:1"}};
    t.workload = {{"K", 1}};
    run.tables[table] = t;
    const std::string prefix = "table" + std::to_string(table) + "/";
    for (const auto& [g, phases] : generators) {
      std::vector<double> generator_total(kSamples, 0.0);
      for (const std::string view : {"camera_view", "light_view"}) {
        std::vector<double> view_total(kSamples, 0.0);
        double median = 0.05;
        for (const auto& phase : phases) {
          RunSeries s;
          s.name = prefix + g + "/" + view + "/" + phase;
          s.table = table, s.generator = g, s.view = view, s.phase = phase;
          for (int i = 0; i < kSamples; ++i) {
            double ms = median * noise(rng);
            if (g == "fis_modified" && phase == "filtered_sampling") ms += slow_ms;
            s.samples_ms.push_back(ms);
            view_total[i] += ms;
          }
          run.series.push_back(s);
          median *= 3.0;  // phases of different sizes
        }
        RunSeries vt;
        vt.name = prefix + g + "/" + view + "/total";
        vt.table = table, vt.generator = g, vt.view = view, vt.phase = "total";
        vt.samples_ms = view_total;
        run.series.push_back(vt);
        for (int i = 0; i < kSamples; ++i) generator_total[i] += view_total[i];
      }
      RunSeries gt;
      gt.name = prefix + g + "/total";
      gt.table = table, gt.generator = g, gt.phase = "total";
      gt.samples_ms = generator_total;
      run.series.push_back(gt);
    }
  }
  return run;
}

TEST(CompareDebugSlowVerdict, SlowedGeneratorAndOnlyItIsSlowerOnSyntheticSamples) {
  const BenchRun base = synthetic_run(1, 0.0);
  const BenchRun slow = synthetic_run(2, 1.0);  // a few times the slowed generator's total
  const RunComparison c = compare_runs(base, slow, CompareOptions{});
  EXPECT_EQ(c.rows.size(), 2u * 3u * 9u);
  EXPECT_EQ(rows_with(c, Verdict::kSlower), slowed_rows()) << comparison_markdown(base, slow, c, CompareOptions{});
  EXPECT_EQ(rows_with(c, Verdict::kSame).size(), c.rows.size() - slowed_rows().size());
  // The same noise without the slowdown: nothing is SLOWER.
  const RunComparison none = compare_runs(base, synthetic_run(3, 0.0), CompareOptions{});
  EXPECT_TRUE(rows_with(none, Verdict::kSlower).empty());
}

class CompareDebugSlowTest : public test::GpuTest {};

uint32_t dispatches(const nlohmann::ordered_json& doc, const std::string& g, const std::string& view) {
  return doc["generators"][g]["views"][view]["dispatch_calls"].get<uint32_t>();
}

TEST_F(CompareDebugSlowTest, SlowedGeneratorAndOnlyItIsSlower) {
  const test::TempDir root_temp("compare_slow");
  const std::filesystem::path& root = root_temp.path();
  TablesOptions o;
  o.captures_dir = root / "captures";
  o.record_sizes = RecordSizes{96, 64, 64};
  o.camera_vsgls = 48;
  o.light_vsgls = 24;
  o.generators = {"fis_tok15", "fis_modified", "kmeans_2d"};
  o.json_only = true;
  o.quick = true;
  o.timing.min_repetitions = 12;  // >= the verdict's 5 samples; 12 tolerates a few outliers
  o.timing.max_repetitions = 12;
  o.copy_bandwidth.bytes = 1u << 20;  // small: this test is about compare
  o.out_dir = root / "base";
  const TablesOutcome base = run_tables(device(), o);
  o.out_dir = root / "slow";
  o.altered_generators = {"fis_modified"};
  o.wrap_generator = debug_slowdown_of(o.altered_generators, 16);
  const TablesOutcome slow = run_tables(device(), o);
  EXPECT_EQ(slow.documents[0]["run"]["altered_generators"][0], "fis_modified");  // the run says so

  // Deterministic: the slowed recording holds one more dispatch per view, the others none.
  ASSERT_EQ(base.documents.size(), 2u);
  ASSERT_EQ(slow.documents.size(), 2u);
  for (std::size_t t = 0; t < 2; ++t)
    for (const std::string g : {"fis_tok15", "fis_modified", "kmeans_2d"})
      for (const std::string v : {"camera_view", "light_view"})
        EXPECT_EQ(dispatches(slow.documents[t], g, v), dispatches(base.documents[t], g, v) + (g == "fis_modified" ? 1u : 0u))
            << "table " << t + 1 << " " << g << " " << v;

  const BenchRun base_run = load_bench_run_path(root / "base");
  const BenchRun slow_run = load_bench_run_path(root / "slow");
  EXPECT_EQ(slow_run.altered_generators, std::vector<std::string>{"fis_modified"});
  CompareOptions options;
  options.verdict.min_change = 1.0;  // the slowed rows at least double
  const RunComparison c = compare_runs(base_run, slow_run, options);  // same captures and config: no refusal
  EXPECT_EQ(c.rows.size(), 2u * 3u * 9u);
  const std::set<std::string> slower = rows_with(c, Verdict::kSlower);
  for (const std::string& row : slowed_rows())
    EXPECT_TRUE(slower.contains(row)) << row << " is not SLOWER\n" << comparison_markdown(base_run, slow_run, c, options);
  // Reported, not judged: the margin the slowed rows had, and how far noise moved the others.
  double least_slowed = 1e30, most_other = -1e30;
  const std::set<std::string> slowed = slowed_rows();
  for (const auto& r : c.rows) {
    if (slowed.contains(r.name)) least_slowed = std::min(least_slowed, r.result.change);
    else most_other = std::max(most_other, r.result.change);
  }
  std::printf("slowed rows: median change >= %+.0f %%; other rows: <= %+.0f %%\n", 100 * least_slowed,
              100 * most_other);
}

}  // namespace
}  // namespace vsgl
