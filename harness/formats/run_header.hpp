#pragma once
// What every output document says of the run besides its numbers (DESIGN.md §9): the device it ran
// on, the build that ran and how the run was made. One typed header, built once from the device
// the run used (vk/device_info.hpp, device_record) and the build (this_build below), and
// written and read here alone; each document carries the parts it has, in its own place:
//   table:   device, build, run (and the driver, API version and timestamps beside them, from the device)
//   sweep:   device, build, run
//   verify:  device;  devices: one device per entry
//   quality: the device's name and driver (its driver name and info), build
// The device and build objects keep the sorted key order they were always written in
// (core/sorted_json.hpp); the run object keeps its own.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/core/device_limits.hpp"

namespace vsgl {

class JsonReader;  // core/json_reader.hpp

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

// The build that ran (core/build_info.hpp): fixed at build time, never asked of git at run time.
struct BuildRecord {
  std::string vsgl_bench_version;
  std::string git_commit;  // the full commit id, or "unknown"
  bool git_dirty = false;
  std::string compiler;  // "GCC 12.2.0"
  bool assertions = false;
};

// How the run was made (`tables` and `sweep`).
struct RunRecord {
  std::string started_utc;  // "2026-12-02T15:42:10Z"
  bool validation_layer = false;
  bool quick = false;
  bool protocol_compliant = false;  // DESIGN.md §9's warm-up and repetitions
  bool clocks_locked_claimed = false;
  std::optional<std::string> clocks_note;
  std::vector<std::string> altered_generators;  // timings altered on purpose (the test build): not a measurement; written only when any
};

// This program's build: the commit and its dirty state as the build found them
// (core/build_info.hpp), the compiler, the version, whether assertions are on.
BuildRecord this_build();

nlohmann::ordered_json to_json(const DeviceRecord& device);
nlohmann::ordered_json to_json(const BuildRecord& build);
nlohmann::ordered_json to_json(const RunRecord& run);

// Readers of what to_json writes, the object at `path` in the reader's document. Every member is
// required (a device's limits excepted, a run's clocks note and altered generators too) and an
// unknown one refused: InputError naming its place.
DeviceRecord device_record_from_json(const JsonReader& reader, const nlohmann::ordered_json& device,
                                     const std::string& path);
BuildRecord build_record_from_json(const JsonReader& reader, const nlohmann::ordered_json& build,
                                   const std::string& path);
RunRecord run_record_from_json(const JsonReader& reader, const nlohmann::ordered_json& run, const std::string& path);

}  // namespace vsgl
