// The verify document (harness/formats/verify_model.hpp) against the committed results: every
// results/**/verify_*.json reads into the model and is written back byte for byte, the files from
// before measurements existed (no `kind`) included; bad fields are named by file and JSON
// pointer; and `vsgl-bench verify --json` writes exactly the model's text of what it ran.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "harness/formats/verify_model.hpp"
#include "input_error.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;
using test::kSource;

std::vector<fs::path> committed_verify_files() {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(kSource / "results")) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && name.rfind("verify_", 0) == 0 && e.path().extension() == ".json")
      files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(VerifyModel, CommittedFilesRoundTripByteForByte) {
  const auto files = committed_verify_files();
  ASSERT_GE(files.size(), 6u);  // lavapipe, SwiftShader and the H100, two scenes each
  int without_kind = 0, with_measurements = 0, devices_with_limits = 0;
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    const VerifyDocument doc = read_verify_file(f);
    ASSERT_FALSE(doc.checks.empty());
    EXPECT_EQ(verify_file_text(doc), test::read_text(f));
    const bool kinds = std::all_of(doc.checks.begin(), doc.checks.end(), [](const VerifyCheck& c) { return c.kind; });
    EXPECT_TRUE(kinds ||
                std::none_of(doc.checks.begin(), doc.checks.end(), [](const VerifyCheck& c) { return c.kind; }));
    without_kind += kinds ? 0 : 1;
    with_measurements +=
        std::any_of(doc.checks.begin(), doc.checks.end(), [](const VerifyCheck& c) { return c.is_measurement(); });
    // The H100's files have neither the device's limits nor kinds, lavapipe's stand-ins kinds
    // without limits, the others both; the model keeps each as it was.
    if (!kinds) {
      EXPECT_FALSE(doc.device.limits.has_value());
    }
    devices_with_limits += doc.device.limits ? 1 : 0;
  }
  EXPECT_EQ(without_kind, 2);  // the H100's, written before measurements existed
  EXPECT_GE(with_measurements, 4);
  EXPECT_GE(devices_with_limits, 4);  // lavapipe's and SwiftShader's, two scenes each
}

TEST(VerifyModel, KindsDecideTheToleranceOrExpectation) {
  const json base = test::read_json(kSource / "results/lavapipe/verify_sponza.json");
  const VerifyDocument doc = verify_from_json(base, "v.json");
  for (const VerifyCheck& c : doc.checks) {
    ASSERT_TRUE(c.kind.has_value());
    EXPECT_EQ(c.is_measurement(), c.expected.has_value());
    EXPECT_NE(c.is_measurement(), c.tolerance.has_value());
  }
  const json old = test::read_json(kSource / "results/nvidia-h100-80gb-hbm3/verify_atrium.json");
  for (const VerifyCheck& c : verify_from_json(old, "o.json").checks) {
    EXPECT_FALSE(c.kind.has_value());
    EXPECT_FALSE(c.is_measurement());
    EXPECT_TRUE(c.tolerance.has_value());
  }
}

TEST(VerifyModel, BadFieldsAreNamedByFileAndPointer) {
  const json base = test::read_json(kSource / "results/lavapipe/verify_sponza.json");
  const auto message = [](const json& d) { return test::input_error([&] { verify_from_json(d, "v.json"); }); };
  std::size_t measurement = 0;
  while (base["checks"][measurement]["kind"] != "measurement") ++measurement;
  const std::string m = "/checks/" + std::to_string(measurement);

  json bad = base;
  bad["checks"][0].erase("tolerance");
  EXPECT_NE(message(bad).find("v.json: /checks/0/tolerance: missing field"), std::string::npos) << message(bad);
  bad = base;
  bad["checks"][measurement]["tolerance"] = 1.0;
  EXPECT_NE(message(bad).find("v.json: " + m + "/tolerance: is not a field of a measurement"), std::string::npos)
      << message(bad);
  bad = base;
  bad["checks"][measurement].erase("expected");
  EXPECT_NE(message(bad).find(m + "/expected: missing field"), std::string::npos) << message(bad);
  bad = base;
  bad["checks"][1]["kind"] = "guess";
  EXPECT_NE(message(bad).find("/checks/1/kind: is neither"), std::string::npos) << message(bad);
  bad = base;
  bad["checks"][2]["colour"] = "red";
  EXPECT_NE(message(bad).find("/checks/2/colour: is not a known key"), std::string::npos) << message(bad);
  bad = base;
  bad["checks"][2]["passed"] = "yes";
  EXPECT_NE(message(bad).find("/checks/2/passed: has type string"), std::string::npos) << message(bad);
  bad = base;
  bad["device"]["limits"]["maxBoundDescriptorSets"] = -1;
  EXPECT_NE(message(bad).find("/device/limits/maxBoundDescriptorSets"), std::string::npos) << message(bad);
  bad = base;
  bad["device"]["limits"]["maxComputeWorkGroupSize"] = json::array({1, 2});
  EXPECT_NE(message(bad).find("/device/limits/maxComputeWorkGroupSize: has 2 elements"), std::string::npos)
      << message(bad);
  bad = base;
  bad["device"]["limits"]["maxWhatever"] = 1;
  EXPECT_NE(message(bad).find("/device/limits/maxWhatever: is not a known limit"), std::string::npos) << message(bad);
  bad = base;
  bad["device"].erase("queue_family");
  EXPECT_NE(message(bad).find("/device/queue_family: missing field"), std::string::npos) << message(bad);
  bad = base;
  bad.erase("scene");
  EXPECT_NE(message(bad).find("v.json: /scene: missing field"), std::string::npos) << message(bad);
}

// A GPU that returns NaN fails its check; the error is written as null (JSON has no NaN), which
// the schema allows and the reader takes back as NaN.
TEST(VerifyModel, ANonFiniteErrorIsWrittenAsNullAndReadBackAsNaN) {
  VerifyDocument doc = read_verify_file(kSource / "results/lavapipe/verify_sponza.json");
  doc.checks[0].measured = std::numeric_limits<double>::quiet_NaN();
  doc.checks[0].passed = false;
  const std::string text = verify_file_text(doc);
  const json written = json::parse(text);
  EXPECT_TRUE(written["checks"][0]["measured"].is_null());
  const VerifyDocument back = verify_from_json(written, "w.json");
  EXPECT_TRUE(std::isnan(back.checks[0].measured));
  EXPECT_FALSE(back.checks[0].passed);
  EXPECT_EQ(verify_file_text(back), text);
}

// What the writer refuses to write: a document its own schema rejects is a bug, not a file.
TEST(VerifyModel, TheWriterRefusesADocumentItsSchemaRejects) {
  VerifyDocument doc = read_verify_file(kSource / "results/lavapipe/verify_sponza.json");
  doc.checks[0].view = "side_view";
  EXPECT_THROW(verify_file_text(doc), std::logic_error);
}

// The command writes the model's text of what it ran: read back and written again it is the same
// bytes, with as many checks as it printed.
TEST(VerifyCli, JsonIsTheVerifyDocumentOfTheChecksPrinted) {
  const test::TempDir dir("verify_model_cli");
  const auto record =
      test::run_cli("record --scene tiny --gbuffer 96x64 --rsm 32 --out " + (dir.path() / "cap").string());
  ASSERT_EQ(record.exit_code, 0) << record.output;
  const fs::path out = dir.path() / "verify_tiny.json";
  const auto verify = test::run_cli("verify --capture " + (dir.path() / "cap").string() + " --camera-vsgls 64 " +
                                    "--light-vsgls 32 --json " + out.string());
  ASSERT_EQ(verify.exit_code, 0) << verify.output;
  const VerifyDocument doc = read_verify_file(out);
  EXPECT_EQ(verify_file_text(doc), test::read_text(out));
  EXPECT_EQ(doc.scene, "tiny");
  EXPECT_EQ(doc.capture, (dir.path() / "cap").string());
  EXPECT_TRUE(doc.device.limits.has_value());
  std::smatch counted;
  ASSERT_TRUE(std::regex_search(verify.output, counted, std::regex("([0-9]+) checks, 0 failed"))) << verify.output;
  EXPECT_EQ(std::to_string(doc.checks.size()), counted[1].str());
  for (const VerifyCheck& c : doc.checks) {
    EXPECT_TRUE(c.kind.has_value()) << c.check;
    EXPECT_TRUE(c.passed) << c.generator << " " << c.check;
  }
}

}  // namespace
}  // namespace vsgl
