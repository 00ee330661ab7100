// The devices document (harness/formats/devices_model.hpp): every committed results/**/devices.json
// reads into the model and is written back byte for byte (the H100's, from before the limits and
// the support were recorded, included); bad fields are named by file and JSON pointer;
// `vsgl-bench devices --json` prints exactly the model's text; and the device object is described
// alike by the devices and the verify schemas.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "harness/core/generator_ids.hpp"
#include "harness/core/error.hpp"
#include "harness/core/sorted_json.hpp"
#include "harness/formats/devices_model.hpp"
#include "harness/generators/device_support.hpp"
#include "harness/vk/device_info.hpp"
#include "harness/vk/instance.hpp"
#include "input_error.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;
using test::kSource;

std::vector<fs::path> committed_devices_files() {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(kSource / "results"))
    if (e.is_regular_file() && e.path().filename() == "devices.json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(DevicesModel, CommittedFilesRoundTripByteForByte) {
  const auto files = committed_devices_files();
  ASSERT_GE(files.size(), 1u);  // the H100's
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    const DevicesDocument doc = read_devices_file(f);
    ASSERT_FALSE(doc.devices.empty());
    EXPECT_EQ(devices_file_text(doc), test::read_text(f));
  }
  const DevicesDocument h100 = read_devices_file(kSource / "results/nvidia-h100-80gb-hbm3/devices.json");
  EXPECT_EQ(h100.default_index, 0);
  EXPECT_FALSE(h100.devices[0].device.limits.has_value());
  EXPECT_FALSE(h100.devices[0].support.has_value());
  EXPECT_EQ(h100.devices[0].device.type, "discrete");
}

// A document as `devices --json` writes it today: limits and support on every device. Counts are
// unsigned, as a parsed file and vk/device_info.hpp's to_json hold them.
json current_document() {
  json support{{"generators",
                {{std::string(kFisTok15),
                  {{"runs", true}, {"reason", ""}, {"pyramid", "texture"}, {"mipmapping", "single-pass"}}},
                 {std::string(kKmeans2d), {{"runs", false}, {"reason", "needs more shared memory"}}}}},
               {"mipmapping", {{"blit", {{"runs", true}, {"reason", ""}}}}}};
  json limits = json::object();
  // clang-format off
  for (const char* k : {"maxPerStageDescriptorStorageImages", "maxPerStageDescriptorSampledImages",
                        "maxPerStageDescriptorSamplers", "maxPerStageDescriptorStorageBuffers",
                        "maxPerStageDescriptorUniformBuffers", "maxPerStageResources", "maxDescriptorSetStorageImages",
                        "maxDescriptorSetSampledImages", "maxDescriptorSetSamplers", "maxDescriptorSetStorageBuffers",
                        "maxDescriptorSetUniformBuffers", "maxBoundDescriptorSets", "maxPushConstantsSize",
                        "maxComputeSharedMemorySize", "maxComputeWorkGroupInvocations", "maxImageDimension2D",
                        "maxImageArrayLayers", "maxStorageBufferRange", "maxMemoryAllocationSize", "subgroupSize"})
    limits[k] = 8u;
  // clang-format on
  limits["maxComputeWorkGroupSize"] = {1024u, 1024u, 64u};
  limits["maxComputeWorkGroupCount"] = {65535u, 65535u, 65535u};
  limits["rgba32f_optimal_tiling"] = {{"sampled_image", true},
                                      {"sampled_image_filter_linear", true},
                                      {"storage_image", true},
                                      {"blit_src", true},
                                      {"blit_dst", false}};
  json doc = test::read_json(kSource / "results/nvidia-h100-80gb-hbm3/devices.json");
  doc["devices"][0]["limits"] = limits;
  doc["devices"][0]["support"] = support;
  json unusable = doc["devices"][0];
  unusable["index"] = 1u;
  unusable["usable"] = false;
  unusable["unusable_reason"] = "has no compute queue";
  unusable["queue_family"] = -1;
  unusable["support"] = {{"generators", json::object()}, {"mipmapping", json::object()}};
  doc["devices"].push_back(unusable);
  return doc;
}

TEST(DevicesModel, LimitsSupportAndUnusableDevicesRoundTrip) {
  const json doc = current_document();
  const DevicesDocument m = devices_from_json(doc, "d.json");
  ASSERT_EQ(m.devices.size(), 2u);
  ASSERT_TRUE(m.devices[0].device.limits && m.devices[0].support);
  EXPECT_EQ(m.devices[0].device.limits->workgroup_size[2], 64u);
  EXPECT_FALSE(m.devices[0].device.limits->rgba32f_optimal_tiling.blit_dst);
  const GeneratorSupport& fis = m.devices[0].support->generators.at(std::string(kFisTok15));
  EXPECT_TRUE(fis.verdict.runs);
  EXPECT_EQ(fis.mipmapping.value_or(""), "single-pass");
  EXPECT_FALSE(fis.pyramid_fallback_reason.has_value());
  EXPECT_FALSE(m.devices[0].support->generators.at(std::string(kKmeans2d)).verdict.runs);
  EXPECT_EQ(m.devices[1].device.queue_family, -1);
  EXPECT_TRUE(m.devices[1].support->generators.empty());
  EXPECT_EQ(devices_file_text(m), sorted_keys(doc).dump(2) + "\n");  // as the document is written
}

TEST(DevicesModel, BadFieldsAreNamedByFileAndPointer) {
  const json base = current_document();
  const auto message = [](const json& d) { return test::input_error([&] { devices_from_json(d, "d.json"); }); };
  json bad = base;
  bad["default"] = -2;
  EXPECT_NE(message(bad).find("d.json: /default: has type number, expected an index or -1"), std::string::npos)
      << message(bad);
  bad = base;
  bad["devices"][1].erase("name");
  EXPECT_NE(message(bad).find("d.json: /devices/1/name: missing field"), std::string::npos) << message(bad);
  bad = base;
  bad["devices"][0]["support"]["generators"][std::string(kKmeans2d)].erase("reason");
  EXPECT_NE(message(bad).find("/devices/0/support/generators/" + std::string(kKmeans2d) + "/reason: missing field"),
            std::string::npos)
      << message(bad);
  bad = base;
  bad["devices"][0]["support"]["mipmapping"]["blit"]["why"] = "";
  EXPECT_NE(message(bad).find("/devices/0/support/mipmapping/blit/why: is not a known key"), std::string::npos)
      << message(bad);
  bad = base;
  bad["devices"][0]["limits"]["rgba32f_optimal_tiling"].erase("blit_dst");
  EXPECT_NE(message(bad).find("/devices/0/limits/rgba32f_optimal_tiling/blit_dst: missing field"), std::string::npos)
      << message(bad);
  bad = base;
  bad["devices"][0]["timestamp_period_ns"] = "1";
  EXPECT_NE(message(bad).find("/devices/0/timestamp_period_ns: has type string"), std::string::npos) << message(bad);
  bad = base;
  bad["devices"][0]["device_local_bytes"] = -5;
  EXPECT_NE(message(bad).find("/devices/0/device_local_bytes: has type number, expected a non-negative integer"),
            std::string::npos)
      << message(bad);
  bad = base;
  bad["devices"] = json::object();
  EXPECT_NE(message(bad).find("d.json: /devices: has type object, expected an array"), std::string::npos)
      << message(bad);
}

// The device object of the verify document is a devices entry without its support: the two
// schemas say so alike (JSON Schema's subset here has no cross-file $ref to share it).
TEST(DevicesModel, TheVerifySchemaDescribesTheDeviceAsTheDevicesSchemaDoes) {
  const json devices = test::read_json(kSource / "results/schema/devices.schema.json");
  const json verify = test::read_json(kSource / "results/schema/verify.schema.json");
  json entry = devices["$defs"]["device_entry"];
  entry["properties"].erase("support");
  EXPECT_EQ(verify["$defs"]["device"], entry);
  for (const char* def : {"limits", "count", "count3"}) EXPECT_EQ(verify["$defs"][def], devices["$defs"][def]) << def;
}

// What `devices --json` prints is the model's text of it, every device with its limits and support.
TEST(DevicesCli, JsonIsTheDevicesDocument) {
  const auto r = test::run_cli("devices --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const DevicesDocument doc = devices_from_json(json::parse(r.output), "devices --json");
  EXPECT_EQ(devices_file_text(doc), r.output);
  ASSERT_FALSE(doc.devices.empty());
  EXPECT_GE(doc.default_index, 0);
  for (const DeviceEntry& e : doc.devices) {
    EXPECT_TRUE(e.device.limits.has_value()) << e.device.name;
    ASSERT_TRUE(e.support.has_value()) << e.device.name;
    if (e.device.usable) {
      EXPECT_TRUE(e.support->generators.count(std::string(kFisModified))) << e.device.name;
    }
  }
}

// `devices --json` is each device's record, built from what the vk layer enumerated
// (vk/device_info.hpp, device_record) with the generators layer's support, under the default
// index; the record says what the device info says.
TEST(DevicesCli, JsonIsEachDevicesRecordAndSupport) {
  Instance instance;
  const std::vector<DeviceInfo> devices = enumerate_devices(instance.get());
  int64_t default_index = -1;
  try {
    default_index = select_device(devices, "").index;
  } catch (const DeviceError&) {
    // no device is usable: the default stays -1, as the command writes it
  }
  DevicesDocument expected{default_index, {}};
  for (const DeviceInfo& d : devices) {
    const DeviceRecord record = device_record(d);
    EXPECT_EQ(record.index, d.index);
    EXPECT_EQ(record.name, d.name);
    EXPECT_EQ(record.type, device_type_name(d.type));
    EXPECT_EQ(record.api_version, api_version_string(d.api_version));
    EXPECT_EQ(record.driver_version, driver_version_string(d));
    EXPECT_EQ(record.queue_family, d.compute_queue_family == UINT32_MAX ? -1 : int64_t{d.compute_queue_family});
    EXPECT_EQ(record.timestamps, d.timestamps());
    EXPECT_EQ(record.timestamp_period_ns, double{d.timestamp_period_ns});
    EXPECT_EQ(record.max_compute_shared_memory, d.max_shared_memory);
    ASSERT_TRUE(record.limits.has_value());
    EXPECT_EQ(record.limits->workgroup_size, d.limits.workgroup_size);
    EXPECT_EQ(record.usable, d.usable());
    expected.devices.push_back({record, device_support(d)});
  }
  const auto r = test::run_cli("devices --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output, devices_file_text(expected));
}

}  // namespace
}  // namespace vsgl
