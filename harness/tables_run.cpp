#include "harness/tables_run.hpp"

#include <chrono>
#include <ctime>
#include <fstream>
#include <map>
#include <memory>
#include <set>

#include "harness/atomic_file.hpp"
#include "harness/capture_provisioning.hpp"
#include "harness/printable_text.hpp"
#include "harness/command_stream.hpp"
#include "harness/device.hpp"
#include "harness/device_view.hpp"
#include "harness/error.hpp"
#include "harness/json_schema_subset.hpp"
#include "harness/regression_debug_slow.hpp"
#include "harness/run_provenance.hpp"
#include "harness/table_markdown.hpp"
#include "harness/table_report.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

void check_options(const TablesOptions& o) {
  if (o.out_dir.empty()) throw UsageError("tables needs an output directory");
  if (o.tables.empty()) throw UsageError("no table to produce");
  std::set<int> seen;
  for (int t : o.tables) {
    table_scene(t);
    if (!seen.insert(t).second) throw UsageError("table " + std::to_string(t) + " is asked for twice");
  }
  if (o.generators.empty()) throw UsageError("no generator to time");
  const auto known = generator_names();
  std::set<std::string> gens;
  for (const auto& g : o.generators) {
    if (std::find(known.begin(), known.end(), g) == known.end()) generator_sources(g);  // throws naming the known ones
    if (!gens.insert(g).second) throw UsageError("generator " + g + " is asked for twice");
  }
  for (const auto& g : o.debug_slow)
    if (!gens.contains(g)) throw UsageError("--debug-slow " + g + ": not one of the generators timed");
  if (o.camera_vsgls == 0 || o.light_vsgls == 0) throw InputError("N = 0: at least one VSGL is needed");
  o.timing.check();
}

nlohmann::json load_schema(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string() + ": cannot read the table schema (use --schema FILE)");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string() + ": not valid JSON: " + printable_text(e.what()));
  }
}

ojson config_json(const TablesOptions& o, const Capture& capture) {
  const TimingOptions& tm = o.timing;
  ojson views{{"camera_view", ojson{{"source", "gbuffer"},
                                     {"width", capture.gbuffer.width},
                                     {"height", capture.gbuffer.height},
                                     {"vsgl_count", o.camera_vsgls}}},
              {"light_view", ojson{{"source", "rsm"},
                                   {"width", capture.rsm.width},
                                   {"height", capture.rsm.height},
                                   {"vsgl_count", o.light_vsgls}}}};
  return ojson{
      {"views", views},
      {"K", o.generator.K},
      {"bisection_iterations", o.generator.bisection_iterations},
      {"kmeans_iterations", o.generator.kmeans_iterations},
      {"kmeans_sum", "kmeans_2d/kmeans_3d: one thread per cluster sums sequentially (the paper's); *_segsum: "
                     "parallel segmented reduction (extra, not in the paper)"},
      {"offset_bits", o.generator.offset_bits},
      {"sampler", "Fibonacci lattice + hierarchical sample warping (SPEC §5)"},
      {"generators", o.generators},
      {"timing", ojson{{"warmup", tm.warmup},
                       {"min_repetitions", tm.min_repetitions},
                       {"max_repetitions", tm.max_repetitions},
                       {"noise_target", tm.noise_target},
                       {"time_cap_s", tm.time_cap_s},
                       {"cold", tm.cold},
                       {"cold_bytes", tm.cold ? tm.cold_bytes : 0},
                       {"schedule", "each case recorded once and replayed; warm-up rounds discarded; round-robin "
                                    "over all (generator, view) cases with a rotating start; stop after "
                                    "min_repetitions once every case total has IQR/median <= noise_target, or at "
                                    "time_cap_s, or at max_repetitions"},
                       {"timestamps", "full barrier + timestamp + full barrier at every phase boundary"},
                       {"quantiles", "linear interpolation between order statistics (Hyndman-Fan type 7)"},
                       {"stdev", "sample standard deviation (n - 1)"}}}};
}

}  // namespace

std::string table_scene(int table) {
  if (table == 1) return "atrium";
  if (table == 2) return "conference";
  throw UsageError("there is no paper table " + std::to_string(table) + " with timings (tables are 1 and 2)");
}

TablesOutcome run_tables(Device& device, const TablesOptions& o, const std::function<void(const TablesEvent&)>& on_event) {
  check_options(o);
  require_timestamps(device.info());  // before minutes of recording
  const auto say = [&](int table, const std::string& msg) {
    if (on_event) on_event(TablesEvent{msg, nullptr, table});
  };

  ReportContext ctx;
  ctx.device = device.info();
  ctx.paper = load_paper_tables(o.paper_tables);
  ctx.paper_path = o.paper_tables.string();
  const nlohmann::json schema = load_schema(o.schema);
  ctx.build = build_json(o.source_dir);
  ctx.run = ojson{{"started_utc", utc_now()},
                  {"validation_layer", o.validation},
                  {"quick", o.quick},
                  {"protocol_compliant", o.timing.warmup >= 2 && o.timing.min_repetitions >= 10},
                  {"clocks_locked_claimed", o.clocks_locked},
                  {"clocks_note", "Vulkan cannot lock GPU clocks: lock them outside (e.g. `nvidia-smi -lgc <MHz>` on "
                                  "NVIDIA, `rocm-smi --setperfdeterminism <MHz>` on AMD) and pass --clocks-locked"}};
  if (!o.debug_slow.empty()) ctx.run["debug_slow"] = o.debug_slow;  // TEST-ONLY: these timings are inflated
  for (const auto& g : generator_names()) ctx.lines[g] = count_generator_lines(generator_sources(g), o.source_dir);
  for (const auto& g : o.generators) ctx.shaders[g] = static_cast<uint32_t>(generator_sources(g).kernels.size());

  std::vector<MeasuredTable> measured;
  std::vector<ojson> configs;
  for (int number : o.tables) {
    MeasuredTable t;
    t.number = number;
    t.scene = table_scene(number);
    t.generators = o.generators;
    const std::filesystem::path dir = o.captures_dir / t.scene;
    t.capture_dir = dir.string();
    if (!std::filesystem::exists(dir / "capture.json")) say(number, "recording the missing capture " + dir.string());
    ProvidedCapture provided = provide_capture(device, t.scene, o.record_sizes, dir);
    t.recorded_now = provided.recorded;
    const Capture& capture = provided.capture;
    t.capture = ojson{{"hashes", capture_hashes_json(capture)},
                      {"frame", capture.meta.frame},
                      {"recorded_on", capture.meta.device},
                      {"tool_version", capture.meta.tool_version},
                      {"brsm_build_ms", capture.meta.brsm_build_ms}};
    configs.push_back(config_json(o, capture));

    // Inputs uploaded, generators built and recorded before any timing (SPEC §9).
    const DeviceView camera = upload_view(device, capture, ViewKind::kCamera);
    const DeviceView light = upload_view(device, capture, ViewKind::kLight);
    std::vector<std::unique_ptr<VsglGenerator>> generators;
    TimingRunner runner(device, o.timing);
    for (const auto& g : o.generators)
      for (const DeviceView* view : {&camera, &light}) {
        GeneratorConfig cfg = o.generator;
        cfg.vsgl_count = view->kind == ViewKind::kCamera ? o.camera_vsgls : o.light_vsgls;
        generators.push_back(make_generator(g, device, *view, cfg));
        if (std::find(o.debug_slow.begin(), o.debug_slow.end(), g) != o.debug_slow.end()) {  // TEST-ONLY
          DebugSlowWork work = DebugSlowWork::for_device(device.info());
          work.iterations *= std::max(1u, o.debug_slow_factor);
          generators.back() = with_debug_slowdown(device, std::move(generators.back()), work);
        }
        runner.add(TimingCase{g, view_name(view->kind), generators.back().get()});
      }
    say(number, "timing table " + std::to_string(number) + " (" + t.scene + "): " + std::to_string(generators.size()) +
                    " cases");
    t.timing = runner.run([&](const TimingProgress& p) {
      if (on_event) on_event(TablesEvent{"", &p, number});
    });
    measured.push_back(std::move(t));
  }

  TablesOutcome out;
  std::filesystem::create_directories(o.out_dir);
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  for (std::size_t i = 0; i < measured.size(); ++i) {
    const MeasuredTable* other = nullptr;
    for (std::size_t j = 0; j < measured.size(); ++j)
      if (j != i) other = &measured[j];
    ReportContext table_ctx = ctx;
    table_ctx.config = configs[i];
    ojson doc;
    try {
      doc = table_json(measured[i], other, table_ctx);
      require_finite_numbers(doc);
    } catch (const std::invalid_argument& e) {
      throw DeviceError("table " + std::to_string(measured[i].number) + ": " + e.what());
    }
    const auto problems = validate_against_schema(nlohmann::json::parse(doc.dump()), schema);
    if (!problems.empty()) {
      std::string all;
      for (const auto& p : problems) all += "\n  " + p;
      throw std::logic_error("table " + std::to_string(measured[i].number) + " does not conform to " + o.schema.string() + ":" + all);
    }
    const std::string stem = "table" + std::to_string(measured[i].number);
    files.emplace_back(o.out_dir / (stem + ".json"), doc.dump(2) + "\n");
    out.markdown.push_back(table_markdown(doc));
    if (!o.json_only) files.emplace_back(o.out_dir / (stem + ".md"), out.markdown.back());
    out.documents.push_back(std::move(doc));
  }
  // Nothing is written until every table is complete and valid.
  for (const auto& [path, text] : files) {
    write_text_atomic(path, text);
    out.written.push_back(path);
  }
  return out;
}

}  // namespace vsgl
