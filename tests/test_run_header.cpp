// The device and run header every document shares (harness/formats/run_header.hpp), against the
// committed results: every JSON document under results/ (tables, sweeps, quality reports, verify
// and devices documents, Google Benchmark runs, the paper's tables) reads through its model, and
// each device, build and run object in them reads into the header and writes back as the same
// bytes; a table states its driver, API version and timestamps as its device does; the reader
// names what is missing, mistyped or unknown.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "harness/compare/regression_run.hpp"
#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/formats/devices_model.hpp"
#include "harness/formats/frame_model.hpp"
#include "harness/formats/quality_model.hpp"
#include "harness/formats/run_header.hpp"
#include "harness/formats/sweep_model.hpp"
#include "harness/formats/table_model.hpp"
#include "harness/formats/verify_model.hpp"
#include "harness/report/paper_tables.hpp"
#include "input_error.hpp"
#include "synthetic_header.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;
using test::kSource;

// Every JSON file under results/ but the schemas (read by the schema tests).
std::vector<fs::path> committed_json_documents() {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(kSource / "results"))
    if (e.is_regular_file() && e.path().extension() == ".json" &&
        e.path().parent_path() != kSource / "results" / "schema")
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

bool name_starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// Reads `file` through the model of its kind; the kind's name, or "" for a file no model reads.
std::string read_through_model(const fs::path& file) {
  const std::string name = file.filename().string();
  if (name == "devices.json") return (void)read_devices_file(file), "devices";
  if (name_starts_with(name, "verify_")) return (void)read_verify_file(file), "verify";
  if (name == "sweep.json") return (void)read_sweep_file(file), "sweep";
  if (name == "quality.json")
    return (void)quality_model_from_json(read_json_file(file, "the quality report"), file.string()), "quality";
  if (name == "frame.json")
    return (void)frame_model_from_json(read_json_file(file, "the frame table"), file.string()), "frame";
  if (name == "paper_tables.json") return (void)load_paper_tables(file), "paper";
  if (name_starts_with(name, "table") || name == "gbench.json") return (void)load_bench_run(file), "run";
  return "";
}

TEST(CommittedResults, EveryDocumentReadsThroughItsModel) {
  std::vector<std::string> kinds;
  for (const fs::path& f : committed_json_documents()) {
    SCOPED_TRACE(f.string());
    std::string kind;
    EXPECT_NO_THROW(kind = read_through_model(f));
    EXPECT_FALSE(kind.empty()) << "no model reads this document";
    kinds.push_back(kind);
  }
  for (const char* kind : {"devices", "verify", "sweep", "quality", "frame", "paper", "run"})
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), kind), kinds.end()) << "no committed " << kind << " document";
}

TEST(RunHeader, EveryCommittedDeviceBuildAndRunReadsAndWritesBackTheSame) {
  std::size_t devices = 0, builds = 0, runs = 0;
  for (const fs::path& f : committed_json_documents()) {
    SCOPED_TRACE(f.string());
    const ojson doc = read_json_file(f, "the document");
    const JsonReader r(f.string(), JsonPathStyle::kPointer);
    std::vector<std::pair<std::string, const ojson*>> device_objects;
    if (doc.contains("device") && doc["device"].contains("index"))
      device_objects.emplace_back("/device", &doc["device"]);
    if (doc.contains("devices"))
      for (std::size_t i = 0; i < doc["devices"].size(); ++i) {
        ojson entry = doc["devices"][i];
        entry.erase("support");  // the devices document's own, beside the device
        EXPECT_EQ(to_json(device_record_from_json(r, entry, "/devices")).dump(), entry.dump());
        ++devices;
      }
    for (const auto& [path, object] : device_objects) {
      EXPECT_EQ(to_json(device_record_from_json(r, *object, path)).dump(), object->dump());
      ++devices;
    }
    if (doc.contains("build")) {
      EXPECT_EQ(to_json(build_record_from_json(r, doc["build"], "/build")).dump(), doc["build"].dump());
      ++builds;
    }
    if (doc.contains("run") && doc["run"].is_object()) {
      EXPECT_EQ(to_json(run_record_from_json(r, doc["run"], "/run")).dump(), doc["run"].dump());
      ++runs;
    }
  }
  // The tables and verify documents of three devices, the sweeps and the H100's devices.json.
  EXPECT_GE(devices, 20u);
  EXPECT_GE(builds, 20u);
  EXPECT_GE(runs, 15u);
}

TEST(RunHeader, ATableStatesItsDriverApiAndTimestampsAsItsDeviceDoes) {
  for (const fs::path& f : committed_json_documents()) {
    if (!name_starts_with(f.filename().string(), "table")) continue;
    SCOPED_TRACE(f.string());
    const TableModel m = table_model_from_json(read_json_file(f, "the table"), f.string());
    ASSERT_TRUE(m.device && m.driver && m.api_version && m.timestamp_period_ns && m.timestamp_valid_bits);
    EXPECT_EQ(m.driver->name, m.device->driver_name);
    EXPECT_EQ(m.driver->info, m.device->driver_info);
    EXPECT_EQ(m.driver->version, m.device->driver_version);
    EXPECT_EQ(*m.api_version, m.device->api_version);
    EXPECT_EQ(*m.timestamp_period_ns, m.device->timestamp_period_ns);
    EXPECT_EQ(*m.timestamp_valid_bits, m.device->timestamp_valid_bits);
  }
}

// The device and build objects keep the sorted key order every file has; the run its own.
TEST(RunHeader, WritesTheKeyOrderOfTheCommittedFiles) {
  DeviceRecord device = test::synthetic_device();
  device.limits = DeviceLimits{};
  const ojson d = to_json(device);
  std::vector<std::string> keys;
  for (auto it = d.begin(); it != d.end(); ++it) keys.push_back(it.key());
  EXPECT_TRUE(std::is_sorted(keys.begin(), keys.end()));
  EXPECT_EQ(keys.size(), 21u);
  const ojson& limits = d["limits"];
  std::vector<std::string> limit_keys;
  for (auto it = limits.begin(); it != limits.end(); ++it) limit_keys.push_back(it.key());
  EXPECT_TRUE(std::is_sorted(limit_keys.begin(), limit_keys.end()));
  EXPECT_EQ(
      to_json(test::synthetic_build("c")).dump(),
      R"({"assertions":false,"compiler":"test","git_commit":"c","git_dirty":false,"vsgl_bench_version":"0.1.0"})");
  RunRecord run = test::synthetic_run("t", false);
  run.altered_generators = {"fis_modified"};
  EXPECT_EQ(to_json(run).dump(),
            R"({"started_utc":"t","validation_layer":false,"quick":false,"protocol_compliant":false,)"
            R"("clocks_locked_claimed":false,"altered_generators":["fis_modified"]})");
}

TEST(RunHeader, TheReaderNamesWhatIsMissingMistypedOrUnknown) {
  const JsonReader r("h.json", JsonPathStyle::kPointer);
  const ojson device = to_json(test::synthetic_device());
  ojson bad = device;
  bad.erase("queue_family");
  EXPECT_NE(test::input_error([&] {
              device_record_from_json(r, bad, "/device");
            }).find("h.json: /device/queue_family: missing field"),
            std::string::npos);
  bad = device;
  bad["queue_family"] = -2;
  EXPECT_NE(test::input_error([&] {
              device_record_from_json(r, bad, "/device");
            }).find("/device/queue_family: has type number, expected an index or -1"),
            std::string::npos);
  bad = device;
  bad["colour"] = "red";
  EXPECT_NE(
      test::input_error([&] { device_record_from_json(r, bad, "/device"); }).find("/device/colour: is not a known key"),
      std::string::npos);
  ojson build = to_json(test::synthetic_build());
  build["git_dirty"] = "no";
  EXPECT_NE(test::input_error([&] {
              build_record_from_json(r, build, "/build");
            }).find("/build/git_dirty: has type string, expected a boolean"),
            std::string::npos);
  ojson run = to_json(test::synthetic_run());
  run["altered_generators"] = ojson::array({1});
  EXPECT_NE(test::input_error([&] {
              run_record_from_json(r, run, "/run");
            }).find("/run/altered_generators/0: has type number, expected a generator name"),
            std::string::npos);
  EXPECT_NE(test::input_error([&] {
              run_record_from_json(r, ojson::array(), "/run");
            }).find("/run: has type array, expected an object"),
            std::string::npos);
}

}  // namespace
}  // namespace vsgl
