// `vsgl-bench sweep` through the command line: a tiny end-to-end sweep on the `tiny` procedural
// scene (recorded into the capture cache first), and bad axes refused with exit 2 before anything
// runs or is written. Nothing here looks at the measured speeds.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "cli_runner.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

const fs::path kSchema = fs::path(VSGL_SOURCE_DIR) / "results/schema/sweep.schema.json";

std::string tiny_sweep_args(const fs::path& root) {
  return "sweep --scene tiny --gbuffer 96x64 --rsm 64 --captures " + (root / "captures").string() + " --out " +
         (root / "out").string() + " --generators fis_modified --quick --no-progress --time-budget 40";
}

TEST(SweepCli, TinySweepOverTwoAxesWritesValidJsonFitsAndPlots) {
  const test::TempDir temp("sweep_cli");
  const fs::path& root = temp.path();
  const auto r = test::run_cli(tiny_sweep_args(root) + " --axis vsgls=8,16 --axis K=1,2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(root / "captures/tiny-g96x64-r64/capture.json")) << r.output;  // recorded into the cache
  const nlohmann::ordered_json doc = test::read_json(root / "out/sweep.json");
  const auto problems = validate_against_schema(doc, test::read_json(kSchema));
  EXPECT_TRUE(problems.empty()) << problems.front();
  EXPECT_EQ(doc["scene"]["name"], "tiny");
  EXPECT_EQ(doc["generators"], nlohmann::ordered_json::array({"fis_modified"}));
  EXPECT_EQ(doc["time_budget_s"], 40.0);
  // The product: (8, 1), (8, 2), (16, 1), (16, 2), each with both views' cases and its own cap.
  ASSERT_EQ(doc["points"].size(), 4u);
  std::set<std::pair<std::string, std::string>> seen;
  for (const auto& p : doc["points"]) {
    seen.emplace(p["values"]["vsgls"].get<std::string>(), p["values"]["K"].get<std::string>());
    EXPECT_EQ(p["cases"].size(), 2u);
    EXPECT_EQ(p["timing"]["time_cap_s"], 10.0);
    EXPECT_EQ(p["timing"]["repetitions"], 3);
    EXPECT_EQ(p["config"]["views"]["camera_view"]["vsgl_count"], p["config"]["views"]["light_view"]["vsgl_count"]);
    for (const auto& c : p["cases"])
      for (const auto& ph : c["phases"]) EXPECT_EQ(ph["samples_ms"].size(), 3u);
  }
  EXPECT_EQ(seen, (std::set<std::pair<std::string, std::string>>{{"8", "1"}, {"8", "2"}, {"16", "1"}, {"16", "2"}}));
  EXPECT_EQ(doc["points"][3]["config"]["views"]["camera_view"]["vsgl_count"], 16);
  EXPECT_EQ(doc["points"][3]["config"]["K"], 2.0);
  // A fit per axis, slice, view and phase (3 phases + total): vsgls at K=1, 2; K at N=8, 16.
  EXPECT_EQ(doc["fits"].size(), 2u * 2u * 2u * 4u);
  std::set<std::string> phases;
  for (const auto& f : doc["fits"]) {
    phases.insert(f["phase"].get<std::string>());
    EXPECT_TRUE(f["growth"].is_object()) << f.dump();
    EXPECT_NE(f["growth"]["text"].get<std::string>().find("cost \u221d "), std::string::npos);
  }
  EXPECT_EQ(phases, (std::set<std::string>{"additional", "mipmapping", "filtered_sampling", "total"}));
  for (const char* axis : {"vsgls", "K"})
    for (const char* phase : {"additional", "mipmapping", "filtered_sampling", "total"})
      EXPECT_TRUE(fs::exists(root / "out" / (std::string("sweep_") + axis + "_" + phase + ".svg"))) << axis << phase;
  const std::string md = test::read_text(root / "out/sweep.md");
  EXPECT_NE(md.find("## Axis vsgls"), std::string::npos) << md;
  EXPECT_NE(md.find("## Axis K"), std::string::npos) << md;
  EXPECT_NE(r.output.find("wrote "), std::string::npos) << r.output;
}

TEST(SweepUsage, BadAxesExitTwoAndWriteNothing) {
  const test::TempDir temp("sweep_usage");
  const fs::path& root = temp.path();
  const std::pair<const char*, const char*> cases[] = {
      {"--axis vsgls=256:16384:x1", "needs F > 1"},
      {"--axis lights=1,2", "unknown parameter"},
      {"--axis K=1", "only one value"},
      {"--axis K=1,2 --axis K=3,4", "both set K"},
      {"--axis vsgls=8,16 --axis light-vsgls=8,16", "both set N"},
      {"", "--axis is required"},
  };
  for (const auto& [axes, why] : cases) {
    const auto r = test::run_cli_without_vulkan(tiny_sweep_args(root) + " " + axes);
    EXPECT_EQ(r.exit_code, 2) << axes << "\n" << r.output;
    EXPECT_NE(r.output.find(why), std::string::npos) << axes << "\n" << r.output;
  }
  // Inputs: one of --capture and --scene; the size axes need a scene to record.
  const std::string out = " --out " + (root / "out").string() + " --captures " + (root / "captures").string();
  auto r = test::run_cli_without_vulkan("sweep --axis K=1,2" + out);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--capture DIR or --scene NAME"), std::string::npos) << r.output;
  r = test::run_cli_without_vulkan("sweep --capture " + root.string() + " --axis rsm=32,64" + out);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("needs --scene NAME"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(root / "out"));
  EXPECT_FALSE(fs::exists(root / "captures"));
}

}  // namespace
}  // namespace vsgl
