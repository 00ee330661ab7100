#pragma once
// The table JSON of SPEC §10 (results/schema/table.schema.json): one file per paper table, with
// per generator, view and phase the statistics of SPEC §9 and the paper's value beside each, the
// ratios the paper argues with, the Table 3 analog, and the paper's claims checked on this run.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/device_info.hpp"
#include "harness/paper_tables.hpp"
#include "harness/source_lines.hpp"
#include "harness/timing_runner.hpp"

namespace vsgl {

inline constexpr int kTableSchemaVersion = 1;

// One measured paper table (1: atrium, 2: conference).
struct MeasuredTable {
  int number = 1;
  std::string scene;
  std::string capture_dir;
  bool recorded_now = false;
  nlohmann::ordered_json capture;  // {"hashes": ..., sizes, ...}
  std::vector<std::string> generators;  // in column order
  TimingResult timing;
};

// Everything of a run that is not a measurement.
struct ReportContext {
  DeviceInfo device;
  nlohmann::json paper;             // results/paper/paper_tables.json
  std::string paper_path;
  nlohmann::ordered_json config;    // views, N, K, iterations, timing options
  nlohmann::ordered_json build;     // build_json()
  nlohmann::ordered_json run;       // started, validation, quick, ...
  std::map<std::string, GeneratorLines> lines;   // per generator
  std::map<std::string, uint32_t> shaders;       // per generator: kernels (pipelines) it dispatches
};

// load_paper_tables (the paper's numbers, validated) is in harness/paper_tables.hpp.

// The table document. `other` is the other paper table of the same run (for the Table 1 ->
// Table 2 change), or nullptr. Throws std::invalid_argument when a statistic cannot be computed.
nlohmann::ordered_json table_json(const MeasuredTable& table, const MeasuredTable* other, const ReportContext& ctx);

// The paper's column name of a generator ("[Tok15]", "Ours (modified FIS)", ...).
std::string generator_label(const std::string& generator);

}  // namespace vsgl
