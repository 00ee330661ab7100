// `vsgl-bench verify` (SPEC §11): every FIS check passes on a small capture and on the full-size
// atrium capture, and bad invocations fail with clear messages and the documented exit codes.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_runner.hpp"
#include "gpu_test.hpp"
#include "harness/scene/brsm_pdf.hpp"
#include "harness/scene/capture_recorder.hpp"
#include "harness/verify/fis_verification.hpp"
#include "harness/verify/kmeans_verification.hpp"
#include "harness/scene/scene.hpp"

namespace vsgl {
namespace {

class VerifyTest : public test::GpuTest {
 protected:
  Capture record(const std::string& scene, const RecordSizes& sizes) {
    CaptureRecorder recorder(device());
    Capture c = recorder.record(make_scene(scene), sizes, 0, 1);
    build_brsm_pdf(device(), c, 512);
    return c;
  }
  static void expect_all_pass(const std::vector<CheckResult>& results, std::size_t expected_checks) {
    EXPECT_EQ(results.size(), expected_checks);
    for (const auto& r : results) EXPECT_TRUE(r.passed()) << format_check(r);
  }
};

// Per view and pyramid path: 2 generators x 6 checks + one histogram; the texture path adds the
// pyramid check of its two other mipmapping strategies.
constexpr std::size_t kChecksPerPath = 2 * 6 + 1;
constexpr std::size_t kChecks = 2 * (kChecksPerPath + (kChecksPerPath + 2));

TEST_F(VerifyTest, EveryCheckPassesOnASmallCapture) {
  const Capture c = record("tiny", {96, 64, 64});
  VerifyConfig config;
  config.camera_vsgls = 256;
  config.light_vsgls = 128;
  config.histogram_samples = 2048;
  expect_all_pass(verify_fis(device(), c, config), kChecks);
}

// 2 views x 2 generators x 5 checks.
constexpr std::size_t kKmeansChecks = 2 * 2 * 5;

TEST_F(VerifyTest, EveryKmeansCheckPassesOnASmallCapture) {
  const Capture c = record("tiny", {96, 64, 64});
  VerifyConfig config;
  config.camera_vsgls = 256;
  config.light_vsgls = 128;
  expect_all_pass(verify_kmeans(device(), c, config, 1), kKmeansChecks);
}

// The full-size FIS checks take the timed default, the texture path (the buffer path's passes are
// checked on the small capture; `vsgl-bench verify` checks both at full size).
TEST_F(VerifyTest, EveryCheckPassesOnTheFullSizeAtrium) {
  const Capture c = record("atrium", {1920, 1088, 512});
  VerifyConfig texture_only;
  texture_only.pyramids = {PyramidPath::kTexture};
  expect_all_pass(verify_fis(device(), c, texture_only), 2 * (kChecksPerPath + 2));
  expect_all_pass(verify_kmeans(device(), c, VerifyConfig{}), kKmeansChecks);
}

TEST(VerifyCli, MissingCaptureIsBadInputNamingThePath) {
  const auto r = test::run_cli("verify --capture /nonexistent/vsgl-capture");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("/nonexistent/vsgl-capture"), std::string::npos) << r.output;
}

TEST(VerifyCli, BadOptionsAreUsageErrors) {
  auto r = test::run_cli("verify");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--capture"), std::string::npos) << r.output;
  r = test::run_cli("verify --capture x --camera-vsgls 0");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = test::run_cli("verify --capture x --K -1");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = test::run_cli("verify --capture x --pyramid cardboard");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("texture or buffer"), std::string::npos) << r.output;
  r = test::run_cli("verify --capture x --mipmapping magic");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("single-pass, blit or per-level"), std::string::npos) << r.output;
  r = test::run_cli("verify --capture x --frobnicate");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--frobnicate"), std::string::npos) << r.output;
}

TEST(VerifyCli, UnknownDeviceIsADeviceError) {
  const auto r = test::run_cli("verify --capture x --device no-such-gpu-anywhere");
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("no-such-gpu-anywhere"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace vsgl
