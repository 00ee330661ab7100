#pragma once
// `vsgl-bench tables` as a library function (the CLI and the tests call it): provide the captures
// (record the paper's scenes when missing, else load and validate them), time every generator on
// both views of each table with the protocol of timing_runner.hpp, and write OUT/tableN.json
// (validated against results/schema/table.schema.json) and OUT/tableN.md, atomically.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/capture_recorder.hpp"
#include "harness/generator_registry.hpp"
#include "harness/timing_runner.hpp"

namespace vsgl {

class Device;

struct TablesOptions {
  std::filesystem::path captures_dir = "captures";  // Table 1: DIR/atrium, Table 2: DIR/conference
  std::filesystem::path out_dir;                     // required
  std::vector<int> tables{1, 2};
  std::vector<std::string> generators = generator_names();
  uint32_t camera_vsgls = 2048;  // N on the G-buffer (the paper's)
  uint32_t light_vsgls = 1024;   // N on the RSM (the paper's)
  GeneratorConfig generator;     // K, iterations (vsgl_count is set per view)
  TimingOptions timing;
  RecordSizes record_sizes;      // for captures recorded because they were missing
  std::filesystem::path source_dir = VSGL_SOURCE_DIR;  // lines of code, git commit
  std::filesystem::path paper_tables = std::filesystem::path(VSGL_SOURCE_DIR) / "results/paper/paper_tables.json";
  std::filesystem::path schema = std::filesystem::path(VSGL_SOURCE_DIR) / "results/schema/table.schema.json";
  bool json_only = false;       // no markdown file
  bool quick = false;           // recorded in the JSON: a CI preset, not the SPEC §9 protocol
  bool validation = false;      // recorded in the JSON
  bool clocks_locked = false;   // the user claims locked clocks (recorded, not checked)
  // TEST-ONLY (harness/regression_debug_slow.hpp): generators whose last phase gets extra work, so
  // that `compare` can be tested; recorded in the JSON as run.debug_slow.
  std::vector<std::string> debug_slow;
  uint32_t debug_slow_factor = 1;  // TEST-ONLY: multiplies DebugSlowWork::for_device's iterations
};

// Scene and capture sub-directory of a paper table; throws UsageError for a table other than 1, 2.
std::string table_scene(int table);

struct TablesEvent {
  std::string message;      // a line for the log ("recording captures/atrium ...")
  const TimingProgress* progress = nullptr;  // non-null during timing
  int table = 0;
};

struct TablesOutcome {
  std::vector<nlohmann::ordered_json> documents;  // one per table, in the order asked
  std::vector<std::string> markdown;
  std::vector<std::filesystem::path> written;
};

// Throws UsageError for bad options, InputError for bad captures / paper file / schema,
// DeviceError for a device without timestamps or a zero interval.
TablesOutcome run_tables(Device& device, const TablesOptions& options,
                         const std::function<void(const TablesEvent&)>& on_event = {});

}  // namespace vsgl
