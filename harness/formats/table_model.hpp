#pragma once
// The table JSON of DESIGN.md §10 (results/schema/table.schema.json) as one typed model: the
// writer (report/table_json.cpp) fills it, the markdown (report/table_markdown.cpp) renders it,
// and `compare`, `export` and `dashboard` (compare/regression_run.cpp) read a file into it.
//
// What is required: a writer always fills every field. The model itself requires only the
// timings (per generator, view and phase the samples, median and quartiles); every other field is
// optional here, absent in the model when absent in the file, and written back only when
// present, so a file round-trips unchanged. A reader that needs more says so (compare needs the
// table number, device, build, run and capture hashes). The device, build and run are the header
// every document shares (formats/run_header.hpp), read whole when present. Objects the harness
// writes from elsewhere and only passes on (config, capture, a claim's measurements) are kept
// whole as JSON, with the few fields a reader needs parsed out beside them.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/claim.hpp"
#include "harness/formats/run_header.hpp"
#include "harness/formats/scene_identity.hpp"
#include "harness/formats/timing_statistics.hpp"

namespace vsgl {

inline constexpr int kTableSchemaVersion = 3;  // 3: `scene` is an object (SceneIdentity)

struct PhaseTiming {
  std::string phase;  // "additional", "mipmapping", "filtered_sampling", "cluster_assignment", ...
  TimingStatistics stats;  // StatisticsLayout::kTable, with the paper's number
};

struct ViewTiming {
  std::vector<PhaseTiming> phases;  // in the generator's order
  TimingStatistics total;
  std::optional<uint32_t> dispatch_calls;
};

struct GeneratorTiming {
  std::string name;                  // the generator id (core/generator_ids.hpp)
  std::optional<std::string> label;  // the paper's column name
  std::optional<bool> in_paper;
  std::map<std::string, ViewTiming> views;  // "camera_view", "light_view"
  TimingStatistics total;                   // per round: camera view + light view
};

struct MeasuredVsPaper {
  double measured = 0;
  std::optional<double> paper;
};

// One per-round difference fis_modified - fis_tok15 (µs), DESIGN.md §9.
struct PairedDifference {
  uint64_t rounds = 0;
  double median_us = 0;
  double hodges_lehmann_us = 0;
  double ci_low_us = 0;
  double ci_high_us = 0;
  double confidence = 0;
  bool reaches_nominal = false;
  std::string critical_value;  // "exact" | "normal"
  std::optional<double> paper_us;
};

struct PairedViewDifference {
  PairedDifference total;
  PairedDifference filtered_sampling;
};

struct PairedOverhead {
  std::string estimator;
  std::string interval;
  double nominal_confidence = 0;
  std::map<std::string, PairedViewDifference> views;  // "camera_view", "light_view"
  PairedDifference total;
};

// Keyed rows in the order written ("camera_view", "light_view", "total"; or generator names).
using KeyedRatios = std::vector<std::pair<std::string, MeasuredVsPaper>>;

struct TableRatios {
  std::optional<KeyedRatios> modified_minus_tok15_us;  // difference of the medians
  std::optional<PairedOverhead> paired_modified_minus_tok15;
  std::optional<KeyedRatios> kmeans_over_modified;
  std::optional<KeyedRatios> table1_to_table2;
};

struct CopyBandwidthResult {
  std::string method;
  uint64_t requested_bytes = 0;
  uint64_t buffer_bytes = 0;
  std::string reduced_because;  // empty: the buffers are the size asked for
  uint64_t bytes_per_copy = 0;
  uint64_t warmup_copies = 0;
  std::vector<double> samples_ms;
  double median_ms = 0;
  double bytes_per_s = 0;
};

struct PassTraffic {
  uint64_t min_bytes_read = 0;
  uint64_t min_bytes_written = 0;
  uint64_t min_bytes = 0;
  double median_ms = 0;
  double achieved_bytes_per_s = 0;
  double fraction_of_copy = 0;
  std::optional<uint64_t> level_by_level_bytes;  // mipmapping only
  std::optional<double> level_by_level_fraction_of_copy;
};

struct GeneratorTraffic {
  std::string generator;
  std::map<std::string, std::map<std::string, PassTraffic>> views;  // view -> pass -> traffic
};

struct TableBandwidth {
  CopyBandwidthResult copy;
  std::string model;  // how the least traffic is counted
  std::vector<GeneratorTraffic> passes;  // FIS generators, in column order
};

struct SourceFileLines {
  std::string path;
  uint64_t lines = 0;
  std::optional<std::string> kind;  // "host" | "shader" (absent in older files)
};

// The dispatches of one view's recording that a repeated block (k-means' Lloyd iterations)
// recorded: iterations * per_iteration + outside = the view's dispatch calls.
struct IterationDispatches {
  uint32_t iterations = 0;
  uint32_t per_iteration = 0;
  uint32_t outside = 0;
};

struct Table3Row {
  std::string generator;
  MeasuredVsPaper shaders;
  uint32_t dispatch_camera_view = 0;
  uint32_t dispatch_light_view = 0;
  std::optional<double> dispatch_paper;
  std::map<std::string, IterationDispatches> dispatch_iterations;  // per view; empty: none (FIS, older files)
  uint64_t lines_of_code = 0;
  std::optional<double> lines_of_code_paper;
  std::optional<uint64_t> shader_lines, host_lines;  // absent in older files
  std::vector<SourceFileLines> files;
};

// The lines in which two generators' counted sources differ (DESIGN.md §10).
struct Table3Difference {
  std::string from, to;  // generator ids: kFisTok15, kFisModified (core/generator_ids.hpp)
  uint64_t removed = 0, added = 0, differing = 0;
  int64_t net = 0;  // lines_of_code(to) - lines_of_code(from)
  std::optional<double> paper;
};

// How Table 3 was counted, and the FIS variants' difference (absent in older files).
struct Table3Counting {
  std::string rule;
  std::string difference_rule;
  std::optional<Table3Difference> difference;
};

struct DriverSummary {
  std::string name, info, version;
};

struct PaperSource {
  std::string source, file, gpu;
};

struct TimingStop {
  uint64_t repetitions = 0;
  double timed_seconds = 0;
  std::string stop_reason;
  double worst_relative_iqr = 0;
};

struct CaptureSummary {
  nlohmann::ordered_json fields = nlohmann::ordered_json::object();  // scene, dir, recorded_now, hashes, ...
  std::optional<nlohmann::ordered_json> hashes;  // {"gbuffer": {...}, "rsm": {...}}; compare needs them
  std::optional<std::string> scene;
  struct Source {
    std::string format, file, content_hash;
    uint64_t triangles = 0;
  };
  std::optional<Source> source;  // a glTF scene's
};

struct TableModel {
  int schema_version = kTableSchemaVersion;
  std::optional<int> table;  // 1, 2; none: a user's capture (no paper numbers)
  std::optional<std::string> title, unit;
  std::optional<SceneIdentity> scene;  // a writer always sets it; schema 1-2 files: name_only
  // None: the file has none (a test's synthetic table); compare requires them.
  std::optional<DeviceRecord> device;
  std::optional<DriverSummary> driver;
  std::optional<std::string> api_version;
  std::optional<double> timestamp_period_ns;
  std::optional<uint64_t> timestamp_valid_bits;
  std::optional<BuildRecord> build;
  std::optional<RunRecord> run;
  nlohmann::ordered_json config = nlohmann::ordered_json::object();  // views, N, K, timing options
  CaptureSummary capture;
  std::optional<PaperSource> paper;
  std::optional<TimingStop> timing;
  std::vector<GeneratorTiming> generators;  // in column order
  std::optional<TableRatios> ratios;
  std::optional<TableBandwidth> bandwidth;
  std::optional<std::vector<Table3Row>> table3;
  std::optional<Table3Counting> table3_counting;
  std::optional<std::vector<Claim>> claims;  // ClaimLayout::kTable (report/table_claims.hpp)

  // The scene the run timed: `scene`, else (schema 1) the capture's scene name, its kind inferred
  // as for a schema 2 name. Not written back: only `scene` is.
  std::optional<SceneIdentity> timed_scene() const;
  const GeneratorTiming* find_generator(const std::string& name) const;
  // config.views.<view>.vsgl_count; throws InputError when absent.
  int vsgl_count(const std::string& view) const;
};

// The document, keys in the order of the schema. Throws std::invalid_argument for a model that
// cannot be written (a required view missing).
nlohmann::ordered_json to_json(const TableModel& model);

// Reads a table document; `what` names it in messages. Throws InputError naming the JSON pointer
// of whatever is missing or mistyped, and a time that is not positive. A table that is null (a
// user's capture) is read; callers that need a paper table say so.
TableModel table_model_from_json(const nlohmann::ordered_json& doc, const std::string& what);
// The capture object alone (its hashes, scene and glTF source parsed out), as at /capture.
CaptureSummary capture_summary_from_json(const nlohmann::ordered_json& capture, const std::string& what);

}  // namespace vsgl
