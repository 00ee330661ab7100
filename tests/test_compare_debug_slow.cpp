// End to end on the test device (lavapipe): two `tables` runs on tiny captures, the second with
// the TEST-ONLY --debug-slow fis_modified (harness/generators/testing/debug_slowdown.hpp); `compare` must
// call SLOWER exactly the rows that contain fis_modified's last phase (filtered sampling, its
// view totals, its total) and nothing else. The minimum relevant change is 100 % here: two runs
// on a shared, busy CPU drift by tens of percent (SAME/AMBIGUOUS at 2 % needs a quiet machine),
// while the extra work multiplies the slowed rows several times.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <set>

#include "gpu_test.hpp"
#include "harness/compare/regression_compare.hpp"
#include "harness/generators/testing/debug_slowdown.hpp"
#include "harness/report/tables_run.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

class CompareDebugSlowTest : public test::GpuTest {};

TEST_F(CompareDebugSlowTest, SlowedGeneratorAndOnlyItIsSlower) {
  const fs::path root = fs::temp_directory_path() / ("vsgl_compare_slow_" + std::to_string(::getpid()));
  fs::remove_all(root);
  TablesOptions o;
  o.captures_dir = root / "captures";
  o.record_sizes = RecordSizes{96, 64, 64};
  o.camera_vsgls = 48;
  o.light_vsgls = 24;
  o.generators = {"fis_tok15", "fis_modified", "kmeans_2d"};
  o.json_only = true;
  o.quick = true;
  o.timing.min_repetitions = 8;  // >= the verdict's 5 samples
  o.timing.max_repetitions = 8;
  o.copy_bandwidth.bytes = 1u << 20;  // small: this test is about compare
  o.out_dir = root / "base";
  run_tables(device(), o);
  o.out_dir = root / "slow";
  o.debug_slow = {"fis_modified"};
  o.wrap_generator = debug_slowdown_of(o.debug_slow);
  const TablesOutcome slow = run_tables(device(), o);
  EXPECT_EQ(slow.documents[0]["run"]["debug_slow"][0], "fis_modified");  // the run says so

  const BenchRun base_run = load_bench_run_path(root / "base");
  const BenchRun slow_run = load_bench_run_path(root / "slow");
  EXPECT_EQ(slow_run.debug_slow, std::vector<std::string>{"fis_modified"});
  CompareOptions options;
  options.verdict.min_change = 1.0;
  const RunComparison c = compare_runs(base_run, slow_run, options);  // same captures and config: no refusal
  std::set<std::string> slower;
  for (const auto& r : c.rows)
    if (r.result.verdict == Verdict::kSlower) slower.insert(r.name);
  std::set<std::string> expected;
  for (const std::string t : {"table1", "table2"}) {
    for (const std::string v : {"camera_view", "light_view"}) {
      expected.insert(t + "/fis_modified/" + v + "/filtered_sampling");
      expected.insert(t + "/fis_modified/" + v + "/total");
    }
    expected.insert(t + "/fis_modified/total");
  }
  EXPECT_EQ(slower, expected) << comparison_markdown(base_run, slow_run, c, options);
  EXPECT_EQ(c.rows.size(), 2u * 3u * 9u);
  fs::remove_all(root);
}

}  // namespace
}  // namespace vsgl
