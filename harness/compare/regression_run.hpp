#pragma once
// One benchmark run as `vsgl-bench compare`, `export` and `dashboard` see it: the
// timing series of a table JSON (DESIGN.md §10, results/schema/table.schema.json) or of the project's
// Google Benchmark JSON (bench/vsgl_gbench.cpp), each under a stable name, with what must match
// for two runs to be comparable (capture hashes, workload config) and what labels a run (device,
// commit, date).
//
// Stable names: "table1/fis_modified/light_view/filtered_sampling" (a phase),
// "table1/fis_modified/light_view/total" (a view), "table1/fis_modified/total" (a generator, table
// JSON only: the camera view plus the light view per repetition).
//
// Samples: a table JSON holds every timed replay (samples_ms). A Google Benchmark JSON holds one
// entry per benchmark and repetition, each the mean of that repetition's iterations; the samples
// of a benchmark are its repetitions ("iteration" entries; "aggregate" entries are skipped), so
// a run for `compare` must be made with --benchmark_repetitions=R (R >= the verdict's
// min_samples, 5 by default). Without repetitions every row has one sample and compares as
// AMBIGUOUS ("too few samples").
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/scene_identity.hpp"

namespace vsgl {

struct RunSeries {
  std::string name;       // stable name, see above
  int table = 0;          // 1 or 2; 0: a capture that is not a paper table's (CaptureTables::kRead)
  std::string generator;
  std::string view;       // "camera_view" | "light_view" | "" for a generator total
  std::string phase;      // a phase name, or "total"
  std::vector<double> samples_ms;
  double median_ms = 0;   // from the file when it has them (table JSON), else from the samples
  double q1_ms = 0;
  double q3_ms = 0;
  std::optional<double> paper_ms;  // the paper's value beside it (table JSON)

  bool is_total() const { return phase == "total"; }
};

// What has to be equal for the timings of one paper table in two runs to be comparable.
struct RunTable {
  int table = 0;  // 0: a capture that is not a paper table's, known by its scene
  // Keys sorted (core/sorted_json.hpp), so that equal objects compare equal whatever their order.
  nlohmann::ordered_json capture_hashes;  // {"gbuffer": {...}, "rsm": {...}}
  nlohmann::ordered_json workload;        // the config minus the timing protocol and the descriptions
  // Which scene was timed: a paper scene and its stand-in are different inputs of one table, never
  // compared, exported or charted as one series. None: a Google Benchmark file that predates it.
  std::optional<SceneIdentity> scene;
};

struct BenchRun {
  std::string path;          // where it was read from (messages)
  std::string format;        // "table" | "gbench"
  std::string device;        // device name
  std::string device_type;   // "discrete", "cpu", ... ("" when unknown)
  std::string git_commit;    // "unknown" when the build did not know
  bool git_dirty = false;
  std::string date;          // ISO 8601 UTC start of the run
  bool quick = false;        // a --quick run (table JSON)
  // Generators whose timings were altered on purpose (run.altered_generators, tables_run.hpp
  // TablesOptions): every report of the run says so.
  std::vector<std::string> altered_generators;
  std::map<int, RunTable> tables;
  std::vector<RunSeries> series;  // in the file's order

  const RunSeries* find(const std::string& name) const;
};

// The table JSON of a capture that is not one of the paper's ("table": null: OUT/<scene>.json of
// `tables --capture DIR`). `compare` and `export` key runs by paper table and refuse it; the
// dashboard reads it as table 0, its series named "<scene>/generator/view/phase".
enum class CaptureTables { kRefuse, kRead };

// Reads a table JSON or a Google Benchmark JSON. Throws InputError naming the file and the
// problem: unreadable, not JSON (also a truncated file), neither format, a missing or mistyped
// field (with its JSON pointer), a non-positive or non-finite time, a benchmark that reported an
// error, a capture's table under CaptureTables::kRefuse.
BenchRun load_bench_run(const std::filesystem::path& path, CaptureTables capture_tables = CaptureTables::kRefuse);

// The same from a parsed document; `what` names it in messages.
BenchRun parse_bench_run(const nlohmann::ordered_json& doc, const std::string& what,
                         CaptureTables capture_tables = CaptureTables::kRefuse);

// Whether a parsed document is a table JSON (results/schema/table.schema.json), by its content
// (schema_version, table, generators, and no sweep's kind), whatever its file is named.
bool is_table_document(const nlohmann::ordered_json& doc);

// Several runs in one (e.g. table1.json + table2.json of one `tables` run). Throws InputError
// when two of them hold the same table or a series of the same name.
BenchRun merge_bench_runs(const std::vector<BenchRun>& runs);

// "table1.json", "table2.json", ...: the file names of a `tables` run (not table.schema.json).
bool is_table_file_name(const std::string& name);

// A file, or a directory: then every tableN.json in it (the output of one `tables` run), merged.
// Throws InputError for a directory without one.
BenchRun load_bench_run_path(const std::filesystem::path& file_or_dir);

}  // namespace vsgl
