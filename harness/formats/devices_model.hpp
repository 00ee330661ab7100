#pragma once
// The devices document (`vsgl-bench devices --json`, results/schema/devices.schema.json, DESIGN.md
// §10) as one typed model, and the device object every other document carries as it is written
// there (the verify document's `device`; a table's and a sweep's, passed on whole).
//
// The device object is written by the vk layer (vk/device_info.hpp, to_json) and the support by
// the generators layer (generators/device_support.hpp), neither of which sees this layer: a
// command reads them into the model with device_from_json and support_from_json, and the model
// writes the file. Files written before the limits and the support existed have neither; they are
// absent in the model then and not written back, so every committed file round-trips unchanged.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "harness/core/device_limits.hpp"

namespace vsgl {

inline constexpr const char* kDevicesSchemaFile = "results/schema/devices.schema.json";

// One physical device as a run saw it.
struct DeviceRecord {
  uint32_t index = 0;
  std::string name;
  std::string type;  // "discrete", "integrated", "virtual", "cpu", "other"
  uint32_t vendor_id = 0;
  uint32_t device_id = 0;
  std::string api_version;     // "1.3.230"
  std::string driver_version;  // as the vendor numbers it
  std::string driver_name;
  std::string driver_info;
  int64_t queue_family = -1;  // the compute family chosen; -1: none
  bool graphics = false;
  bool timestamps = false;
  uint32_t timestamp_valid_bits = 0;
  double timestamp_period_ns = 0;
  bool pipeline_statistics = false;
  uint32_t subgroup_size = 0;
  uint32_t max_compute_shared_memory = 0;
  uint64_t device_local_bytes = 0;
  std::optional<DeviceLimits> limits;  // absent in older files
  bool usable = false;
  std::string unusable_reason;  // empty when usable
};

// Whether something runs on the device, and why not.
struct SupportVerdict {
  bool runs = false;
  std::string reason;  // empty when it runs
};

// A generator's verdict, and for FIS the path and mip strategy a default run takes there, each
// with why it is not the one asked for when it falls back.
struct GeneratorSupport {
  SupportVerdict verdict;
  std::optional<std::string> pyramid, pyramid_fallback_reason;
  std::optional<std::string> mipmapping, mipmapping_fallback_reason;
};

// Keyed by generator id and by mip strategy name, in the file's (sorted) order; both empty for an
// unusable device.
struct DeviceSupport {
  std::map<std::string, GeneratorSupport> generators;
  std::map<std::string, SupportVerdict> mipmapping;
};

struct DeviceEntry {
  DeviceRecord device;
  std::optional<DeviceSupport> support;  // absent in older files
};

struct DevicesDocument {
  int64_t default_index = -1;  // the device a run uses by default; -1: none is usable
  std::vector<DeviceEntry> devices;
};

nlohmann::json to_json(const DeviceRecord& device);
nlohmann::json to_json(const DeviceSupport& support);
nlohmann::json to_json(const DevicesDocument& doc);

// Readers: every failure an InputError "<where>: <JSON pointer>: <problem>"; `pointer` is where
// the object sits in its document ("" for a document, "/device" in the verify one).
DeviceRecord device_from_json(const nlohmann::json& device, const std::string& where, const std::string& pointer);
DeviceSupport support_from_json(const nlohmann::json& support, const std::string& where, const std::string& pointer);
DevicesDocument devices_from_json(const nlohmann::json& doc, const std::string& where);
DevicesDocument read_devices_file(const std::filesystem::path& path);

// The file's text as `devices --json` prints it (2-space indent, a final newline), once the
// document conforms to the built-in devices schema (std::logic_error otherwise: a bug).
std::string devices_file_text(const DevicesDocument& doc);

}  // namespace vsgl
