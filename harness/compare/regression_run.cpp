#include "harness/compare/regression_run.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/path_text.hpp"
#include "harness/core/statistics.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/core/sorted_json.hpp"
#include "harness/formats/table_model.hpp"

namespace vsgl {
namespace {

using json = nlohmann::ordered_json;

std::string text_or(const json& obj, const std::string& key, const std::string& fallback) {
  const auto it = obj.find(key);
  return it != obj.end() && it->is_string() ? it->get<std::string>() : fallback;
}

RunSeries series_of(const TimingStatistics& stats, std::string name, int table, const std::string& generator,
                    const std::string& view, const std::string& phase) {
  RunSeries s;
  s.name = std::move(name);
  s.table = table, s.generator = generator, s.view = view, s.phase = phase;
  s.samples_ms = stats.samples_ms;
  s.median_ms = stats.median_ms;
  s.q1_ms = stats.q1_ms;
  s.q3_ms = stats.q3_ms;
  s.paper_ms = stats.paper_ms;
  return s;
}

// What identifies a run and must be in its file, beyond what the table model itself requires.
template <typename T>
const T& required(const JsonReader& r, const std::optional<T>& v, const std::string& pointer) {
  if (!v) r.fail(pointer, "missing field");
  return *v;
}

BenchRun parse_table_json(const json& doc, const JsonReader& r, CaptureTables capture_tables) {
  const TableModel m = table_model_from_json(doc, r.where());
  BenchRun run;
  run.format = "table";
  if (!m.table && capture_tables == CaptureTables::kRefuse)
    r.fail("/table", "is null: this is the table of a capture that is not one of the paper's (scene '" +
                         (m.scene ? printable_text(m.scene->name) : std::string("?")) +
                         "'); compare and export key runs by paper table (1, 2) and do not read it (dashboard "
                         "draws it)");
  if (!m.table && !m.scene) r.fail("/scene", "missing field: a table of no paper table is known by its scene");
  if (m.table && *m.table != 1 && *m.table != 2) r.fail("/table", "is " + std::to_string(*m.table) + ", not 1 or 2");
  const int table = m.table ? *m.table : 0;
  const DeviceRecord& device = required(r, m.device, "/device");
  run.device = device.name;
  run.device_type = device.type;
  const BuildRecord& build = required(r, m.build, "/build");
  run.git_commit = build.git_commit;
  run.git_dirty = build.git_dirty;
  const RunRecord& header_run = required(r, m.run, "/run");
  run.date = header_run.started_utc;
  run.quick = header_run.quick;
  run.altered_generators = header_run.altered_generators;

  RunTable t;
  t.table = table;
  if (!m.capture.fields.is_object()) r.fail("/capture", "missing field");
  t.capture_hashes = sorted_keys(required(r, m.capture.hashes, "/capture/hashes"));
  // The workload, not the protocol: repetitions, noise target and caps change how long a run
  // measures, not what it measures; the generator list decides which rows exist (compared row
  // by row); kmeans_sum and sampler are descriptions.
  if (!m.config.is_object()) r.fail("/config", "missing field");
  json workload = m.config;
  for (const char* key : {"timing", "generators", "kmeans_sum", "sampler"}) workload.erase(key);
  t.workload = sorted_keys(workload);
  t.scene = m.timed_scene();
  run.tables[table] = t;

  const std::string prefix = table != 0 ? "table" + std::to_string(table) + "/" : m.scene->name + "/";
  for (const GeneratorTiming& g : m.generators) {
    for (const auto& [view, v] : g.views) {
      for (const PhaseTiming& p : v.phases)
        run.series.push_back(series_of(p.stats, prefix + g.name + "/" + view + "/" + p.phase, table, g.name, view, p.phase));
      run.series.push_back(series_of(v.total, prefix + g.name + "/" + view + "/total", table, g.name, view, "total"));
    }
    run.series.push_back(series_of(g.total, prefix + g.name + "/total", table, g.name, "", "total"));
  }
  return run;
}

double to_ms(double value, const std::string& unit, const JsonReader& r, const std::string& pointer) {
  if (unit == "ns") return value * 1e-6;
  if (unit == "us") return value * 1e-3;
  if (unit == "ms") return value;
  if (unit == "s") return value * 1e3;
  r.fail(pointer, "unknown time unit " + quoted_text(unit));
}

json parse_embedded(const JsonReader& r, const json& context, const std::string& key) {
  const std::string text = r.string(context, "/context", key);
  try {
    return json::parse(text);
  } catch (const json::exception& e) {
    r.fail("/context/" + key, "is not JSON text: " + printable_text(e.what()));
  }
}

BenchRun parse_gbench_json(const json& doc, const JsonReader& r) {
  BenchRun run;
  run.format = "gbench";
  const json& context = r.object(doc, "", "context");
  run.device = r.string(context, "/context", "vsgl_device");
  run.device_type = text_or(context, "vsgl_device_type", "");
  run.git_commit = text_or(context, "vsgl_git_commit", "unknown");
  run.date = text_or(context, "date", "");
  const json workload = parse_embedded(r, context, "vsgl_config");

  const json& benchmarks = r.member(doc, "", "benchmarks");
  if (!benchmarks.is_array()) r.fail("/benchmarks", "is not an array");
  std::map<std::string, std::size_t> index;  // stable name -> series
  for (std::size_t i = 0; i < benchmarks.size(); ++i) {
    const json& b = benchmarks[i];
    const std::string bp = "/benchmarks/" + std::to_string(i);
    if (text_or(b, "run_type", "iteration") == "aggregate") continue;  // mean/median/stddev of the repetitions
    const std::string name = r.string(b, bp, "name");
    if (r.flag(b, bp, "error_occurred", false))
      r.fail(bp, "benchmark " + quoted_text(name) + " reported an error: " +
                     quoted_text(text_or(b, "error_message", "(no message)")));
    // "table1/fis_modified/light_view/filtered_sampling/iterations:30/manual_time": the first four
    // parts name it; the rest is Google Benchmark's decoration.
    std::vector<std::string> parts;
    std::stringstream ss(text_or(b, "run_name", name));
    for (std::string part; std::getline(ss, part, '/');) parts.push_back(part);
    if (parts.size() < 4 || parts[0].rfind("table", 0) != 0 || (parts[0] != "table1" && parts[0] != "table2"))
      r.fail(bp + "/name", quoted_text(name) + " is not a vsgl-gbench benchmark name (tableN/generator/view/phase/...)");
    const double ms = to_ms(r.time(b, bp, "real_time"), r.string(b, bp, "time_unit"), r, bp + "/time_unit");
    if (!std::isfinite(ms) || !(ms > 0)) r.fail(bp + "/real_time", "is not a positive time in ms (out of range)");
    const std::string stable = parts[0] + "/" + parts[1] + "/" + parts[2] + "/" + parts[3];
    auto [it, fresh] = index.try_emplace(stable, run.series.size());
    if (fresh) {
      RunSeries s;
      s.name = stable;
      s.table = parts[0] == "table1" ? 1 : 2;
      s.generator = parts[1], s.view = parts[2], s.phase = parts[3];
      run.series.push_back(std::move(s));
    }
    run.series[it->second].samples_ms.push_back(ms);
  }
  if (run.series.empty()) r.fail("/benchmarks", "holds no vsgl-gbench benchmark");
  for (RunSeries& s : run.series) {
    std::vector<double> sorted = s.samples_ms;
    std::sort(sorted.begin(), sorted.end());
    s.median_ms = quantile_sorted(sorted, 0.5);
    s.q1_ms = quantile_sorted(sorted, 0.25);
    s.q3_ms = quantile_sorted(sorted, 0.75);
    if (!run.tables.contains(s.table)) {
      RunTable t;
      t.table = s.table;
      t.capture_hashes =
          sorted_keys(parse_embedded(r, context, "vsgl_table" + std::to_string(s.table) + "_capture_hashes"));
      t.workload = sorted_keys(workload);
      const std::string scene_key = "vsgl_table" + std::to_string(s.table) + "_scene";
      if (context.contains(scene_key))
        t.scene = scene_identity_from_json(parse_embedded(r, context, scene_key), r.where(), "/context/" + scene_key);
      run.tables[s.table] = t;
    }
  }
  return run;
}

}  // namespace

bool is_table_file_name(const std::string& name) {
  if (name.size() < 11 || name.rfind("table", 0) != 0 || !name.ends_with(".json")) return false;
  return std::all_of(name.begin() + 5, name.end() - 5, [](char c) { return c >= '0' && c <= '9'; });
}

const RunSeries* BenchRun::find(const std::string& name) const {
  for (const RunSeries& s : series)
    if (s.name == name) return &s;
  return nullptr;
}

bool is_table_document(const nlohmann::ordered_json& doc) {
  return doc.is_object() && doc.contains("schema_version") && doc.contains("table") && doc.contains("generators") &&
         !doc.contains("kind");
}

BenchRun parse_bench_run(const nlohmann::ordered_json& doc, const std::string& what, CaptureTables capture_tables) {
  const JsonReader r(what, JsonPathStyle::kPointer);
  if (!doc.is_object()) r.fail("", "is not a JSON object (neither a table JSON nor Google Benchmark JSON)");
  BenchRun run;
  if (doc.contains("benchmarks") && doc.contains("context")) run = parse_gbench_json(doc, r);
  else if (doc.contains("schema_version") && doc.contains("generators")) run = parse_table_json(doc, r, capture_tables);
  else
    r.fail("", "neither a vsgl-bench table JSON (schema_version, generators) nor Google Benchmark JSON (context, "
               "benchmarks)");
  run.path = what;
  return run;
}

BenchRun load_bench_run(const std::filesystem::path& path, CaptureTables capture_tables) {
  return parse_bench_run(read_json_file(path, "the run"), path_text(path), capture_tables);
}

BenchRun merge_bench_runs(const std::vector<BenchRun>& runs) {
  if (runs.empty()) throw std::logic_error("nothing to merge");
  BenchRun merged = runs.front();
  std::set<std::string> names;
  for (const auto& s : merged.series) names.insert(s.name);
  for (std::size_t i = 1; i < runs.size(); ++i) {
    const BenchRun& r = runs[i];
    merged.path += " + " + r.path;
    if (r.format != merged.format) throw InputError(r.path + ": is " + r.format + " JSON, " + runs.front().path + " is " + merged.format + " JSON");
    for (const auto& [n, t] : r.tables)
      if (!merged.tables.emplace(n, t).second)
        throw InputError(r.path + ": table " + std::to_string(n) + " is also in " + runs.front().path);
    for (const auto& s : r.series) {
      if (!names.insert(s.name).second) throw InputError(r.path + ": " + quoted_text(s.name) + " appears twice");
      merged.series.push_back(s);
    }
    merged.date = std::min(merged.date, r.date);
    merged.quick = merged.quick || r.quick;
    for (const auto& g : r.altered_generators)
      if (std::find(merged.altered_generators.begin(), merged.altered_generators.end(), g) ==
          merged.altered_generators.end())
        merged.altered_generators.push_back(g);
  }
  return merged;
}

BenchRun load_bench_run_path(const std::filesystem::path& file_or_dir) {
  if (!std::filesystem::is_directory(file_or_dir)) return load_bench_run(file_or_dir);
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(file_or_dir)) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && is_table_file_name(name)) files.push_back(e.path());
  }
  if (files.empty()) throw InputError(path_text(file_or_dir) + ": a directory without tableN.json");
  std::sort(files.begin(), files.end());
  std::vector<BenchRun> runs;
  for (const auto& f : files) runs.push_back(load_bench_run(f));
  BenchRun merged = merge_bench_runs(runs);
  merged.path = file_or_dir.string();
  return merged;
}

}  // namespace vsgl
