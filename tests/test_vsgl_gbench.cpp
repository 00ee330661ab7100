// vsgl-gbench registers one benchmark per phase of every case of a capture and one per case total,
// named CAPTURE/GENERATOR/VIEW/PHASE with the descriptor's phases, each replayed --vsgl_replays
// times, and names the device, build and capture in the JSON's context.
//
// vsgl-gbench declares vsgl-bench's options (--vsgl_name=V is `tables --name V`) with the same
// code, passes --benchmark_* to Google Benchmark, and exits with vsgl-bench's codes: 2 for a bad
// command line (decided before any Vulkan instance exists), 4 for a device problem.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "cli_runner.hpp"
#include "harness/generators/generator_registry.hpp"
#include "test_support.hpp"

#ifdef VSGL_GBENCH_EXE
namespace vsgl {
namespace {

test::CliResult run_gbench(const std::string& arguments) { return test::run_program(VSGL_GBENCH_EXE, arguments); }
test::CliResult run_gbench_without_vulkan(const std::string& arguments) {
  return test::run_program(VSGL_GBENCH_EXE, arguments, test::kNoVulkanDriver);
}

TEST(GbenchCli, UnknownOptionsAndBadValuesAreUsageErrors) {
  const auto unknown = run_gbench("--vsgl_no_such_option=1");
  EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("--vsgl_no_such_option"), std::string::npos) << unknown.output;
  // Messages name the program that printed them.
  EXPECT_EQ(unknown.output.rfind("vsgl-gbench: ", 0), 0u) << unknown.output;
  const auto foreign = run_gbench("--not_ours");
  EXPECT_EQ(foreign.exit_code, 2) << foreign.output;
  EXPECT_NE(foreign.output.find("--vsgl_"), std::string::npos) << foreign.output;
  const auto zero = run_gbench("--vsgl_camera_vsgls=0");
  EXPECT_EQ(zero.exit_code, 2) << zero.output;
  EXPECT_NE(zero.output.find("--vsgl_camera_vsgls"), std::string::npos) << zero.output;
  const auto table = run_gbench("--vsgl_tables=3");
  EXPECT_EQ(table.exit_code, 2) << table.output;
  const auto k = run_gbench("--vsgl_K=-1");
  EXPECT_EQ(k.exit_code, 2) << k.output;
  const auto both = run_gbench("--vsgl_capture=a --vsgl_tables=1");
  EXPECT_EQ(both.exit_code, 2) << both.output;
}

TEST(GbenchUsage, BadCommandLinesExitTwoWithoutVulkanAndGoodOnesReachTheDevice) {
  for (const char* bad : {"--vsgl_camera_vsgls=0", "--vsgl_pyramid=cardboard", "--benchmark_no_such_flag=1",
                          "--vsgl_replays=0", "stray"}) {
    SCOPED_TRACE(bad);
    const auto r = run_gbench_without_vulkan(bad);
    EXPECT_EQ(r.exit_code, 2) << r.output;
  }
  // Accepted (Google Benchmark's flags pass through): the run goes on to the device, which is not there.
  const auto good = run_gbench_without_vulkan(
      "--benchmark_format=json --benchmark_repetitions=5 --vsgl_K=2 --vsgl_iterations=6 --vsgl_camera_vsgls=64 "
      "--vsgl_light_vsgls=32 --vsgl_kmeans_iterations=2 --vsgl_pyramid=buffer --vsgl_mipmapping=blit "
      "--vsgl_generators=fis_tok15 --vsgl_capture=a --vsgl_capture=b --vsgl_replays=3 --vsgl_validate");
  EXPECT_EQ(good.exit_code, 4) << good.output;
}

TEST(GbenchUsage, HelpListsTheToolsOwnOptions) {
  const auto r = run_gbench_without_vulkan("--help");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("--vsgl_camera_vsgls"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--benchmark_"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("exit codes"), std::string::npos) << r.output;
}

TEST(GbenchCli, UnknownDeviceIsADeviceError) {
  const auto r = run_gbench("--vsgl_device=no-such-gpu-anywhere");
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("no-such-gpu-anywhere"), std::string::npos) << r.output;
}

TEST(GbenchCli, TimesEveryPhaseOfEveryCaseOfACaptureUnderItsName) {
  const test::TempDir dir("gbench_capture");
  const auto recorded =
      test::run_cli("record --scene tiny --gbuffer 48x32 --rsm 16 --out " + (dir.path() / "tiny").string());
  ASSERT_EQ(recorded.exit_code, 0) << recorded.output;
  const std::filesystem::path out = dir.path() / "gbench.json";
  const auto r = run_gbench("--vsgl_capture=" + (dir.path() / "tiny").string() +
                            " --vsgl_generators=fis_modified,kmeans_3d --vsgl_camera_vsgls=64 --vsgl_light_vsgls=32"
                            " --vsgl_replays=3 --benchmark_format=json --benchmark_out=" +
                            out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::ordered_json doc = test::read_json(out);

  std::multiset<std::string> expected, named;
  for (const char* g : {"fis_modified", "kmeans_3d"})
    for (const char* view : {"camera_view", "light_view"}) {
      std::vector<std::string> phases = generator_descriptor(g).phases;
      phases.push_back("total");
      for (const std::string& phase : phases)
        expected.insert("tiny/" + std::string(g) + "/" + view + "/" + phase + "/iterations:3/manual_time");
    }
  for (const auto& b : doc.at("benchmarks")) {
    named.insert(b.at("name").get<std::string>());
    EXPECT_EQ(b.at("iterations"), 3) << b.at("name");
    EXPECT_GT(b.at("real_time").get<double>(), 0.0) << b.at("name");
  }
  EXPECT_EQ(named, expected);

  const nlohmann::ordered_json& context = doc.at("context");
  for (const char* key : {"vsgl_device", "vsgl_driver", "vsgl_git_commit", "vsgl_config", "vsgl_tiny_capture",
                          "vsgl_tiny_capture_hashes", "vsgl_tiny_scene"})
    EXPECT_TRUE(context.contains(key)) << key;
  EXPECT_EQ(nlohmann::ordered_json::parse(context.at("vsgl_config").get<std::string>()).at("replays"), 3);
}

}  // namespace
}  // namespace vsgl
#endif
