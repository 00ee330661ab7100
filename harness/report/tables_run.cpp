#include "harness/report/tables_run.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "harness/core/path_text.hpp"
#include "harness/capture/capture_sidecar.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/core/error.hpp"
#include "harness/core/embedded_files.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/report/run_context.hpp"
#include "harness/report/table_json.hpp"
#include "harness/report/table_markdown.hpp"
#include "harness/report/table_timing.hpp"
#include "harness/scene/capture_provisioning.hpp"
#include "harness/vk/device.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

// "table1", "table22": the names compare/dashboard read as paper tables.
bool is_reserved_stem(const std::string& stem) {
  return stem.size() > 5 && stem.rfind("table", 0) == 0 &&
         std::all_of(stem.begin() + 5, stem.end(), [](char c) { return c >= '0' && c <= '9'; });
}

void check_options(const TablesOptions& o) {
  if (o.out_dir.empty()) throw UsageError("tables needs an output directory");
  if (o.tables.empty() && o.captures.empty()) throw UsageError("no table to produce");
  std::set<int> seen;
  for (int t : o.tables) {
    if (t != 1 && t != 2) table_scene(t);  // throws naming the tables
    if (!seen.insert(t).second) throw UsageError("table " + std::to_string(t) + " is asked for twice");
  }
  if (o.generators.empty()) throw UsageError("no generator to time");
  const auto known = generator_names();
  std::set<std::string> gens;
  for (const auto& g : o.generators) {
    if (std::find(known.begin(), known.end(), g) == known.end()) generator_sources(g);  // throws naming the known ones
    if (!gens.insert(g).second) throw UsageError("generator " + g + " is asked for twice");
  }
  for (const auto& g : o.altered_generators)
    if (!gens.contains(g)) throw UsageError("altered generator " + g + ": not one of the generators timed");
  if (!o.altered_generators.empty() && !o.wrap_generator)
    throw std::logic_error("altered_generators names generators but no wrapper alters them");
  if (o.camera_vsgls == 0 || o.light_vsgls == 0) throw InputError("N = 0: at least one VSGL is needed");
  o.timing.check();
  o.copy_bandwidth.check();
}

// The other paper table measured so far, for table i's Table 1 -> 2 change; nullptr when none.
const MeasuredTable* other_paper_table(const std::vector<TableMeasurement>& measured, std::size_t i) {
  const MeasuredTable* other = nullptr;
  for (std::size_t j = 0; j < measured.size(); ++j)
    if (j != i && measured[i].table.number != 0 && measured[j].table.number != 0 &&
        measured[j].table.number != measured[i].table.number)
      other = &measured[j].table;
  return other;
}

// Writes one table's JSON and markdown atomically, each complete and schema-valid first, and keeps
// them as documents[index] and markdown[index] of `out`.
void write_table(const TableMeasurement& m, const MeasuredTable* other, const RunContext& run, const TablesOptions& o,
                 TablesOutcome& out, std::size_t index) {
  const std::string stem = table_file_stem(m.table.number, m.table.scene);
  ReportContext table_ctx = run.report;
  table_ctx.config = m.config;
  ojson doc;
  try {
    doc = table_json(m.table, other, table_ctx);
    require_finite_numbers(doc);
  } catch (const std::invalid_argument& e) {
    throw DeviceError("table " + stem + ": " + e.what());
  }
  require_conforming(doc, run.schema, "table " + stem, file_or_built_in_name(o.schema, kTableSchemaFile));
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  files.emplace_back(o.out_dir / (stem + ".json"), doc.dump(2) + "\n");
  out.markdown[index] = table_markdown(doc);
  if (!o.json_only) files.emplace_back(o.out_dir / (stem + ".md"), out.markdown[index]);
  out.documents[index] = std::move(doc);
  std::filesystem::create_directories(o.out_dir);
  for (const auto& [path, text] : files) {
    write_text_atomic(path, text);
    if (std::find(out.written.begin(), out.written.end(), path) == out.written.end()) out.written.push_back(path);
  }
}

}  // namespace

int paper_table_of(const CaptureMeta& meta) {
  // A preset of the paper's scenes says which table it reproduces; a file given directly is never a
  // paper table, whatever its name.
  if (meta.source) return static_cast<int>(meta.source->paper_table);
  if (meta.scene == "atrium") return 1;
  if (meta.scene == "conference") return 2;
  return 0;
}

std::string table_file_stem(int paper_table, const std::string& scene) {
  return paper_table != 0 ? "table" + std::to_string(paper_table) : scene;
}

std::vector<TableInput> table_inputs(const TablesOptions& o) {
  std::vector<TableInput> out;
  if (o.captures.empty()) {
    for (int t : o.tables) {
      TableScene scene = table_scene(t, o.scenes);
      const std::filesystem::path dir = o.captures_dir / scene.scene;
      out.push_back(TableInput{dir, t, true, std::move(scene)});
    }
    return out;
  }
  std::map<std::string, std::filesystem::path> stems;  // output stem -> the capture that takes it
  for (const auto& dir : o.captures) {
    const CaptureMeta meta = read_sidecar(dir / kSidecarName).meta;
    const int table = paper_table_of(meta);
    const std::string stem = table_file_stem(table, meta.scene);
    if (table == 0 && is_reserved_stem(stem))
      throw UsageError("capture " + path_text(dir) + ": its scene is named '" + stem +
                       "', which is the name of a paper table's output; rename the file it was recorded from");
    const auto [it, fresh] = stems.emplace(stem, dir);
    if (!fresh)
      throw UsageError("captures " + path_text(it->second) + " and " + path_text(dir) + " are both of scene '" +
                       meta.scene + "': their results would both be named " + stem + " (" + stem + ".json, " + stem +
                       "/... benchmarks); time them in separate runs");
    out.push_back(TableInput{dir, table, false});
  }
  return out;
}

TableScene table_scene(int table, const SceneLibrary& library) {
  if (table != 1 && table != 2)
    throw UsageError("there is no paper table " + std::to_string(table) + " with timings (tables are 1 and 2)");
  const std::string stand_in = table == 1 ? "atrium" : "conference";
  for (const ScenePresetFile& file : library.presets) {
    const ScenePreset preset = parse_scene_preset(file);
    const std::string& name = preset.name;
    if (preset.paper_table != static_cast<uint32_t>(table)) continue;
    try {
      find_preset_model(preset, library.assets);
    } catch (const InputError&) {
      return TableScene{stand_in, false,
                        "table " + std::to_string(table) + ": the paper's scene " + name +
                            " is not here (its model is looked for under each --assets DIR, then VSGL_ASSETS, then "
                            "assets/ in the current directory; where to get it: " +
                            kPaperScenesSection + "), so the procedural stand-in " + stand_in + " is timed"};
    }
    return TableScene{name, true, {}};
  }
  return TableScene{stand_in, false,
                    "table " + std::to_string(table) + ": no scene preset reproduces it, so the procedural stand-in " +
                        stand_in + " is used"};
}

ProvidedCapture provide_table_capture(Device& device, const TableScene& scene, const SceneLibrary& library,
                                      const std::filesystem::path& dir, const RecordSizes& sizes,
                                      const std::function<void(const std::string&)>& say) {
  if (!scene.note.empty()) say(scene.note);
  ProvidedCapture provided = provide_capture(device, load_named_scene(scene.scene, library), sizes, dir);
  if (!provided.stale_because.empty())
    say("re-recorded the stale capture " + path_text(dir) + ": " + provided.stale_because);
  else if (provided.recorded) say("recorded the missing capture " + path_text(dir));
  return provided;
}

TablesOutcome run_tables(Device& device, const TablesOptions& o, const std::function<void(const TablesEvent&)>& on_event) {
  check_options(o);
  require_timestamps(device.info());  // before minutes of recording
  // 1. Everything that is not a measurement, checked before any timing.
  const RunContext run = make_run_context(device.info(), o);
  // 2. Each table: its capture, its generators, their interleaved timing; then its files, at once,
  // so a run cut short keeps the tables it finished (DESIGN.md §10). A paper table is written
  // without the Table 1 -> 2 change until the other paper table is measured; then the new one is
  // written and the earlier one rewritten with it, so a complete run ends with the same files as
  // when everything was written at the end.
  std::vector<TableInput> inputs = table_inputs(o);
  // Said once, before minutes of recording and timing: what is timed is not the paper's scene.
  for (TableInput& input : inputs) {
    if (input.scene.note.empty()) continue;
    if (on_event) on_event(TablesEvent{"warning: " + input.scene.note, nullptr, input.paper_table});
    input.scene.note.clear();
  }
  std::vector<TableMeasurement> measured;
  measured.reserve(inputs.size());
  std::vector<const MeasuredTable*> written_with;  // the `other` of each table's files on disk
  TablesOutcome out;
  for (const TableInput& input : inputs) {
    measured.push_back(measure_table(device, o, input, on_event));
    const std::size_t latest = measured.size() - 1;
    written_with.push_back(nullptr);
    out.documents.emplace_back();
    out.markdown.emplace_back();
    // The new table first, then those whose change it completes.
    std::vector<std::size_t> order{latest};
    for (std::size_t i = 0; i < latest; ++i) order.push_back(i);
    for (std::size_t i : order) {
      const MeasuredTable* other = other_paper_table(measured, i);
      if (i != latest && other == written_with[i]) continue;
      write_table(measured[i], other, run, o, out, i);
      written_with[i] = other;
    }
  }
  return out;
}

}  // namespace vsgl
