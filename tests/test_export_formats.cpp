// `vsgl-bench export`: the committed H100 run as github-action-benchmark customSmallerIsBetter and
// as Bencher Metric Format, checked against the documented shapes (export_formats.hpp) and, field
// by field, against the run's own medians and quartiles; bad formats and inputs are refused.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "cli_runner.hpp"
#include "harness/core/error.hpp"
#include "harness/compare/export_formats.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

const fs::path kRun = fs::path(VSGL_SOURCE_DIR) / "results/nvidia-h100-80gb-hbm3";

using test::read_json;

TEST(ExportFormats, GithubActionBenchmarkHasOneEntryPerSeries) {
  const BenchRun run = load_bench_run_path(kRun);
  const nlohmann::ordered_json out = export_run(run, ExportFormat::kGithubActionBenchmark);
  const auto problems = validate_against_schema(out, export_schema(ExportFormat::kGithubActionBenchmark));
  EXPECT_TRUE(problems.empty()) << problems.front();
  ASSERT_TRUE(out.is_array());
  ASSERT_EQ(out.size(), run.series.size());
  const nlohmann::ordered_json table1 = read_json(kRun / "table1.json");
  bool found = false;
  for (const auto& e : out) {
    EXPECT_EQ(e.at("unit"), "ms");
    EXPECT_TRUE(e.at("range").get<std::string>().starts_with("± "));
    // The H100 run is schema 1: its scene, named under /capture, is the stand-in.
    if (e.at("name") == "table1/fis_modified/light_view/filtered_sampling [atrium, stand-in]") {
      found = true;
      const auto& stats = table1["generators"]["fis_modified"]["views"]["light_view"]["phases"]["filtered_sampling"];
      EXPECT_DOUBLE_EQ(e.at("value").get<double>(), stats["median_ms"].get<double>());
      EXPECT_NE(e.at("extra").get<std::string>().find("NVIDIA H100"), std::string::npos);
    }
  }
  EXPECT_TRUE(found);
}

TEST(ExportFormats, BencherMetricFormatKeysByStableName) {
  const BenchRun run = load_bench_run(kRun / "table2.json");
  const nlohmann::ordered_json out = export_run(run, ExportFormat::kBencherMetricFormat);
  const auto problems = validate_against_schema(out, export_schema(ExportFormat::kBencherMetricFormat));
  EXPECT_TRUE(problems.empty()) << problems.front();
  EXPECT_EQ(out.size(), run.series.size());
  const nlohmann::ordered_json table2 = read_json(kRun / "table2.json");
  const auto& total = table2["generators"]["kmeans_3d"]["total"];
  const auto& m = out.at("table2/kmeans_3d/total [conference, stand-in]").at("latency");
  EXPECT_DOUBLE_EQ(m.at("value").get<double>(), total["median_ms"].get<double>() * 1e6);  // ns
  EXPECT_DOUBLE_EQ(m.at("lower_value").get<double>(), total["q1_ms"].get<double>() * 1e6);
  EXPECT_DOUBLE_EQ(m.at("upper_value").get<double>(), total["q3_ms"].get<double>() * 1e6);
  for (const auto& [name, measures] : out.items()) {
    const auto& l = measures.at("latency");
    EXPECT_LE(l.at("lower_value").get<double>(), l.at("value").get<double>()) << name;
    EXPECT_LE(l.at("value").get<double>(), l.at("upper_value").get<double>()) << name;
  }
}

TEST(ExportFormats, TheSchemasRejectOtherShapes) {
  const auto gab = export_schema(ExportFormat::kGithubActionBenchmark);
  EXPECT_FALSE(validate_against_schema(nlohmann::ordered_json::parse(R"([{"name": "x", "value": 1}])"), gab)
                   .empty());  // no unit
  EXPECT_FALSE(validate_against_schema(nlohmann::ordered_json::parse(R"({"name": "x"})"), gab).empty());
  const auto bmf = export_schema(ExportFormat::kBencherMetricFormat);
  EXPECT_FALSE(
      validate_against_schema(nlohmann::ordered_json::parse(R"({"x": {"latency": {"value": "1"}}})"), bmf).empty());
  EXPECT_TRUE(
      validate_against_schema(nlohmann::ordered_json::parse(R"({"x": {"latency": {"value": 1}}})"), bmf).empty());
}

TEST(ExportCli, WritesBothFormatsAndRefusesBadOnes) {
  const test::TempDir dir_temp("export");
  const std::filesystem::path& dir = dir_temp.path();
  const auto gab = run_cli("export --format gab " + kRun.string() + " --out " + (dir / "gab.json").string());
  EXPECT_EQ(gab.exit_code, 0) << gab.output;
  EXPECT_EQ(read_json(dir / "gab.json").size(), 108u);  // 2 tables x 6 generators x 9 rows
  const auto gbench = run_cli("export --format bmf " + (kRun / "gbench.json").string() + " --out " + (dir / "bmf.json").string());
  EXPECT_EQ(gbench.exit_code, 0) << gbench.output;
  EXPECT_TRUE(read_json(dir / "bmf.json").contains("table1/fis_modified/light_view/filtered_sampling"));
  const auto bad_format = run_cli("export --format csv " + kRun.string() + " --out " + (dir / "x").string());
  EXPECT_EQ(bad_format.exit_code, 2);
  EXPECT_NE(bad_format.output.find("--format: takes gab"), std::string::npos) << bad_format.output;
  std::ofstream(dir / "broken.json") << "{\"schema_version\": 1, \"gener";
  const auto broken = run_cli("export --format gab " + (dir / "broken.json").string() + " --out " + (dir / "y").string());
  EXPECT_NE(broken.exit_code, 0);
  EXPECT_NE(broken.output.find("not valid JSON"), std::string::npos) << broken.output;
  EXPECT_FALSE(fs::exists(dir / "y"));
}

}  // namespace
}  // namespace vsgl
