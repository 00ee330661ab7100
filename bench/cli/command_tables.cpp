// `vsgl-bench tables`: the paper's Tables 1 and 2 (and the Table 3 analog) on this device
// (DESIGN.md §9, §10). The work is harness/report/tables_run.hpp; this file maps options and prints.

#include <cstdio>
#include <memory>
#include <optional>

#include "bench/cli/commands.hpp"
#include "bench/cli/tables_extension.hpp"
#include "bench/cli/option_types.hpp"
#include "bench/cli/generator_options.hpp"
#include "bench/cli/timed_generators.hpp"
#include "bench/cli/timing_flags.hpp"
#include "harness/core/path_text.hpp"
#include "bench/cli/gpu_session.hpp"
#include "bench/cli/progress_line.hpp"
#include "harness/core/error.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/core/platform_console.hpp"
#include "harness/timing/run_provenance.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/scene/named_scene.hpp"
#include "harness/report/tables_run.hpp"

namespace vsgl::cli {
namespace {

struct TablesCommandOptions {
  bool quick = false;
  std::optional<std::string> out;
  std::string captures = "captures";
  std::pair<uint32_t, uint32_t> gbuffer{1920, 1088};  // only for captures recorded now
  uint32_t rsm = 512;
  std::vector<std::string> tables{"1", "2"};
  std::vector<std::string> capture_dirs;
  std::vector<std::string> assets;
  GeneratorOptions gen;
  std::optional<uint32_t> warmup, repetitions, max_repetitions;
  std::optional<double> noise_target, time_cap;
  bool cold = false;
  uint32_t copy_mib = 256;
  bool json_only = false;
  bool clocks_locked = false;
  std::optional<std::string> paper, schema;
  bool no_progress = false;
  DeviceOptions device;
};

int run_tables_command(const TablesCommandOptions& c, const TablesExtension& extension) {
  TablesOptions o;
  const bool quick = c.quick;
  o.captures_dir = path_from_utf8(c.captures);
  o.scenes = default_scene_library(paths_from_utf8(c.assets));
  o.record_sizes = RecordSizes{c.gbuffer.first, c.gbuffer.second, c.rsm};
  for (const auto& d : c.capture_dirs) o.captures.push_back(path_from_utf8(d));
  o.tables.clear();
  if (o.captures.empty())
    for (const auto& t : c.tables) o.tables.push_back(std::stoi(t));
  o.timing.cold = c.cold;
  o.copy_bandwidth.bytes = uint64_t{c.copy_mib} << 20;
  o.json_only = c.json_only;
  o.clocks_locked = c.clocks_locked;
  if (c.paper) o.paper_tables = path_from_utf8(*c.paper);
  if (c.schema) o.schema = path_from_utf8(*c.schema);
  const bool progress_flag = !c.no_progress;
  const auto& out = c.out;
  GpuSession session = GpuSession::open(c.device);
  o.validation = session.context->instance().validation_enabled();

  // Defaults by device class (timing_runner.hpp), then the presets, then explicit options.
  const DeviceInfo& info = session.device().info();
  apply_timed_generators(c.gen, info, o);
  o.timing = [&] {
    TimingOptions t = TimingOptions::defaults_for(info);
    t.cold = o.timing.cold;
    return t;
  }();
  o.quick = quick;
  apply_timing_flags(c, o.timing);
  o.out_dir = out ? path_from_utf8(*out) : std::filesystem::path("results") / device_slug(info.name);
  if (extension.apply) extension.apply(o);

  std::fprintf(stderr,
               "timing: warm-up %u, >= %u repetitions, stop at IQR/median <= %.3g or %.0f s or %u repetitions%s\n"
               "clocks: Vulkan cannot lock GPU clocks; for stable numbers lock them first (e.g. `nvidia-smi -lgc "
               "<MHz>`) and pass --clocks-locked (%s)\n",
               o.timing.warmup, o.timing.min_repetitions, o.timing.noise_target, o.timing.time_cap_s,
               o.timing.max_repetitions, o.timing.cold ? ", cold caches" : "",
               o.clocks_locked ? "claimed locked" : "not claimed locked");
  ProgressLine line(progress_flag && vsgl::is_terminal(stderr));
  const TablesOutcome outcome = vsgl::run_tables(session.device(), o, [&](const TablesEvent& e) {
    if (e.progress == nullptr) line.message(e.message);
    else line.show("table " + std::to_string(e.table), *e.progress);
  });
  line.close();
  print_outcome(outcome.markdown, outcome.written);
  return session.finish(0);
}

}  // namespace

Command add_tables_command(CLI::App& parent, const TablesExtension& extension) {
  CLI::App* app = parent.add_subcommand(
      "tables",
      "the paper's Tables 1 and 2 (+ the Table 3 analog) on this device: every generator on both views (camera N = " +
          std::to_string(kPaperCameraVsgls) + ", light N = " + std::to_string(kPaperLightVsgls) +
          "), each recorded once with a timestamp at every phase boundary and replayed: discarded warm-ups, then "
          "interleaved repetitions until every total's IQR/median <= the noise target or a time cap. Writes "
          "OUT/tableN.json (schema results/schema/table.schema.json: the statistics and raw samples, the paper's "
          "value beside each, its ratios, the modified - Tok15 overhead paired by round with a 95 % Wilcoxon "
          "interval, the copy bandwidth measured in the same run, the Table 3 analog, the paper's claims checked) "
          "and OUT/tableN.md, each table as soon as it is measured. Table 1 runs on the paper's Crytek Sponza "
          "(scene sponza) and Table 2 on its conference room (conference-room) when their models are found "
          "(--assets), else on the procedural stand-ins atrium and conference, which the JSON names. On a CPU device "
          "the default generators are the paper's four");
  auto o = std::make_shared<TablesCommandOptions>();
  auto* tables =
      add_list_option(*app, "--tables", o->tables,
                      "which tables (1: sponza, else atrium; 2: conference-room, else conference)", one_of({"1", "2"}));
  CLI::Option* capture =
      app->add_option(
             "--capture", o->capture_dirs,
             "time this capture instead (repeatable): a glTF scene's capture gives OUT/<scene>.json + .md "
             "(\"table\": null, no paper columns); a capture of a paper scene (sponza, conference-room) or of its "
             "stand-in (atrium, conference) gives that paper table")
          ->allow_extra_args(false)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
          ->type_name("DIR")
          ->excludes(tables);
  add_assets_option(*app, o->assets)->excludes(capture);
  app->add_option("--captures", o->captures,
                  "capture root: Table N's capture is CAPTURES/<its scene>, recorded first when missing or stale "
                  "(another scene, size, model or view)")
      ->type_name("DIR")
      ->capture_default_str();
  add_size_option(*app, "--gbuffer", o->gbuffer, "G-buffer size of captures recorded because missing");
  app->add_option("--rsm", o->rsm, "RSM size N x N of captures recorded because missing")
      ->check(at_least(1))
      ->capture_default_str();
  add_optional(*app, "--out", o->out, "output directory")->type_name("DIR")->default_str("results/<device slug>");
  CLI::App* protocol = app->add_option_group("timing protocol", "warm-ups, repetitions and the stop rule");
  add_optional(*protocol, "--warmup", o->warmup, "discarded warm-up runs")->check(at_least(2))->default_str("2");
  add_optional(*protocol, "--repetitions", o->repetitions, "minimum repetitions")->check(at_least(2))->default_str("10");
  add_optional(*protocol, "--noise-target", o->noise_target, "stop once every total has IQR/median <= X")
      ->check(positive_number())
      ->default_str("0.02");
  add_optional(*protocol, "--time-cap", o->time_cap, "... or after S s of timing (0: no cap)")
      ->check(CLI::NonNegativeNumber)
      ->default_str("60; 20 on a CPU device such as lavapipe");
  add_optional(*protocol, "--max-repetitions", o->max_repetitions, "... or after M repetitions")
      ->check(at_least(2))
      ->default_str("1000");
  protocol->add_flag("--quick", o->quick, "3 repetitions, no noise target (CI smoke runs; marked in the JSON)");
  protocol->add_flag("--cold", o->cold, "overwrite a 256 MiB buffer before every sample (cold caches)");
  app->add_option("--copy-mib", o->copy_mib,
                  "MiB of the copy-bandwidth measurement's buffers (vkCmdCopyBuffer; less only if memory is short)")
      ->check(at_least(1))
      ->capture_default_str();
  CLI::App* generators = app->add_option_group("generators", "what is timed");
  add_generator_options(*generators, o->gen);
  app->add_flag("--json-only", o->json_only, "write no markdown file (the console still shows the tables)");
  app->add_flag("--clocks-locked", o->clocks_locked, "record that you locked the GPU clocks (Vulkan cannot)");
  add_optional(*app, "--paper", o->paper, "the paper's tables (default: the copy built into vsgl-bench)")
      ->check(input_file("--paper"))
      ->default_str("built-in results/paper/paper_tables.json");
  add_optional(*app, "--schema", o->schema, "the table JSON schema (default: the copy built into vsgl-bench)")
      ->check(input_file("--schema"))
      ->default_str("built-in results/schema/table.schema.json");
  app->add_flag("--no-progress", o->no_progress, "no progress line (it is off anyway when stderr is not a terminal)");
  add_device_options(*app, o->device);
  if (extension.add_options) extension.add_options(*app);
  return {app, [o, extension] { return run_tables_command(*o, extension); }};
}

}  // namespace vsgl::cli
