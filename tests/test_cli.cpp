// The CLI as a user meets it: device listing, recording, and the exit codes of bad invocations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "gpu_test.hpp"
#include "harness/capture/capture.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/capture/visibility_geometry.hpp"
#include "harness/core/error.hpp"
#include "harness/scene/capture_recorder.hpp"
#include "harness/scene/scene.hpp"
#include "harness/scene/visibility_recording.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

using test::run_cli;

// The test device (lavapipe unless VSGL_TEST_DEVICE names another, by a substring of its name or
// by its index, as --device takes it) is listed, with timestamps, its limits and, for every
// generator and mip strategy, whether it runs there. Its type is Vulkan's: lavapipe and
// SwiftShader must say `cpu`; a GPU says what its driver reports.
TEST(Cli, DevicesListsTheTestDeviceWithTimestampsAndLimits) {
  const char* env = std::getenv("VSGL_TEST_DEVICE");
  const std::string wanted = env != nullptr ? env : "llvmpipe";
  const bool by_index = !wanted.empty() &&
                        std::all_of(wanted.begin(), wanted.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
  const auto lower = [](std::string s) {
    for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  const auto text = run_cli("devices");
  EXPECT_EQ(text.exit_code, 0) << text.output;
  EXPECT_NE(text.output.find("default device"), std::string::npos);

  const auto json = run_cli("devices --json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  const auto parsed = nlohmann::ordered_json::parse(json.output);
  bool found = false;
  for (const auto& d : parsed.at("devices")) {
    const std::string name = lower(d.at("name").get<std::string>());
    if (by_index ? d.at("index").get<int>() != std::stoi(wanted) : name.find(lower(wanted)) == std::string::npos)
      continue;
    found = true;
    EXPECT_NE(lower(text.output).find(name), std::string::npos) << text.output;
    const std::string type = d.at("type").get<std::string>();
    if (name.find("llvmpipe") != std::string::npos || name.find("swiftshader") != std::string::npos)
      EXPECT_EQ(type, "cpu");  // lavapipe and SwiftShader are both CPU devices
    else
      EXPECT_TRUE(type == "discrete" || type == "integrated" || type == "virtual" || type == "cpu" || type == "other")
          << type;
    EXPECT_TRUE(d.at("timestamps").get<bool>());
    EXPECT_GT(d.at("timestamp_valid_bits").get<int>(), 0);
    EXPECT_TRUE(d.at("usable").get<bool>());
    EXPECT_GE(d.at("limits").at("maxPerStageDescriptorStorageImages").get<int>(), 4);
    EXPECT_GT(d.at("limits").at("maxMemoryAllocationSize").get<uint64_t>(), 0u);
    const auto& support = d.at("support");
    for (const char* g : {"fis_tok15", "fis_modified", "kmeans_2d", "kmeans_3d"}) {
      ASSERT_TRUE(support.at("generators").contains(g)) << support.dump(2);
      EXPECT_TRUE(support.at("generators").at(g).at("runs").get<bool>()) << support.dump(2);
    }
    for (const char* m : {"single-pass", "blit", "per-level"})
      EXPECT_TRUE(support.at("mipmapping").at(m).at("runs").get<bool>()) << support.dump(2);
  }
  EXPECT_TRUE(found) << wanted << " names no device:\n" << json.output;
  EXPECT_GE(parsed.at("default").get<int>(), 0);
}

TEST(Cli, RecordWritesALoadableCaptureWithItsBrsmPdf) {
  const test::TempDir dir_temp("cli_record");
  const std::filesystem::path& dir = dir_temp.path();
  const std::string validate = test::test_validation() ? " --validate" : "";  // DESIGN.md §13.1: none under Wine
  const auto r = run_cli("record --scene tiny --gbuffer 96x64 --rsm 32" + validate + " --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  if (test::test_validation()) {
    EXPECT_NE(r.output.find("validation on"), std::string::npos) << r.output;
  }
  const Capture c = load_capture(dir);
  EXPECT_EQ(c.meta.scene, "tiny");
  EXPECT_EQ(c.gbuffer.width, 96u);
  EXPECT_EQ(c.rsm.width, 32u);
  EXPECT_TRUE(c.rsm.has_pdf);
  EXPECT_GT(c.meta.brsm_build_ms, 0.0);
  // The BRSM PDF is recorded data, built on the buffer pyramid wherever it binds (DESIGN.md §8).
  EXPECT_EQ(c.meta.brsm_pyramid, PyramidPath::kBuffer);
  EXPECT_NE(r.output.find("camera VSGLs on the buffer pyramid"), std::string::npos) << r.output;
  // One frame stores the visibility geometry (DESIGN.md §3, §8a) by default: every triangle of the
  // scene and 2^20 points on them, the same as the library draws from the same scene and seed.
  ASSERT_TRUE(c.meta.visibility_geometry) << r.output;
  const VisibilityGeometry g = load_visibility_geometry(dir, c.meta);
  const Scene tiny = make_scene("tiny");
  EXPECT_EQ(g.triangle_count(), tiny.mesh.indices.size() / 3);
  EXPECT_EQ(g.points.size(), kDefaultVisibilityPoints);
  const VisibilityGeometry want = scene_visibility_geometry(tiny, kDefaultVisibilityPoints, kVisibilityPointSeed);
  EXPECT_EQ(g.triangle_vertices, want.triangle_vertices);
  EXPECT_EQ(g.points.back().position, want.points.back().position);
  EXPECT_NE(r.output.find("visibility geometry: " + std::to_string(g.triangle_count()) + " triangles, 1048576 points"),
            std::string::npos)
      << r.output;
}

// --visibility-points sets the count, 0 stores none: such a capture is refused by what shades
// with visibility, naming the option.
TEST(Cli, RecordVisibilityPointsSetsOrDropsTheGeometry) {
  const test::TempDir dir_temp("cli_record_points");
  const std::filesystem::path& dir = dir_temp.path();
  auto r = run_cli("record --scene tiny --gbuffer 48x32 --rsm 16 --visibility-points 4096 --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  Capture c = load_capture(dir);
  ASSERT_TRUE(c.meta.visibility_geometry);
  EXPECT_EQ(load_visibility_geometry(dir, c.meta).points.size(), 4096u);
  r = run_cli("record --scene tiny --gbuffer 48x32 --rsm 16 --visibility-points 0 --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  c = load_capture(dir);
  EXPECT_FALSE(c.meta.visibility_geometry);
  EXPECT_FALSE(std::filesystem::exists(dir / kVisibilityGeometryFile));
  EXPECT_THROW(load_visibility_geometry(dir, c.meta), InputError);
}

TEST(Cli, RecordAnimatedSequenceWritesOneCapturePerFrame) {
  const test::TempDir dir_temp("cli_frames");
  const std::filesystem::path& dir = dir_temp.path();
  const auto r = run_cli("record --scene tiny --gbuffer 48x32 --rsm 16 --frames 3 --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Capture f0 = load_capture(dir / "frame_0000");
  const Capture f2 = load_capture(dir / "frame_0002");
  EXPECT_EQ(f2.meta.frame, 2u);
  EXPECT_EQ(f2.meta.frames, 3u);
  EXPECT_NE(f0.meta.light.position, f2.meta.light.position);
  EXPECT_FALSE(f0.meta.visibility_geometry);  // a sequence stores none unless asked
}

TEST(Cli, BadInvocationsExitWithTheDocumentedCodes) {
  auto r = run_cli("record --scene nowhere --out /tmp/vsgl_never_written");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("atrium"), std::string::npos) << "the message should list the scenes: " << r.output;
  EXPECT_FALSE(std::filesystem::exists("/tmp/vsgl_never_written"));
  r = run_cli("record --gbuffer 0x5");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  // One --out cannot hold two captures; the message says what to do instead (no phantom option).
  r = run_cli("record --scene tiny,atrium --out /tmp/vsgl_never_written");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("captures/NAME"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("--out-root"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists("/tmp/vsgl_never_written"));
  r = run_cli("record --rsm many");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = run_cli("frobnicate");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = run_cli("");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = run_cli("--help");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("exit codes"), std::string::npos);
}

}  // namespace
}  // namespace vsgl
