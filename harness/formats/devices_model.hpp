#pragma once
// The devices document (`vsgl-bench devices --json`, results/schema/devices.schema.json, DESIGN.md
// §10) as one typed model: each device as every document records it (formats/run_header.hpp,
// built by the vk layer's device_record) with what runs on it (built by the generators layer's
// device_support). Files written before the limits and the support existed have neither; they are
// absent in the model then and not written back, so every committed file round-trips unchanged.
// The document's keys are sorted, as they always were (core/sorted_json.hpp).
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/run_header.hpp"

namespace vsgl {

inline constexpr const char* kDevicesSchemaFile = "results/schema/devices.schema.json";

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

nlohmann::ordered_json to_json(const DeviceSupport& support);
nlohmann::ordered_json to_json(const DevicesDocument& doc);

// Readers: every failure an InputError "<where>: <JSON pointer>: <problem>"; `pointer` is where
// the object sits in its document ("" for a document).
DeviceSupport support_from_json(const nlohmann::ordered_json& support, const std::string& where,
                                const std::string& pointer);
DevicesDocument devices_from_json(const nlohmann::ordered_json& doc, const std::string& where);
DevicesDocument read_devices_file(const std::filesystem::path& path);

// The file's text as `devices --json` prints it (2-space indent, a final newline), once the
// document conforms to the built-in devices schema (std::logic_error otherwise: a bug).
std::string devices_file_text(const DevicesDocument& doc);

}  // namespace vsgl
