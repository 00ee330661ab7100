// `vsgl-bench sweep`: the tables' timing protocol at every point of one or more parameter axes, the
// cost growth per generator, view and phase, and log-log plots (DESIGN.md §10.1). The work is
// harness/sweep/sweep_run.hpp; this file maps options and prints.

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>

#include "bench/cli/commands.hpp"
#include "bench/cli/generator_options.hpp"
#include "bench/cli/timed_generators.hpp"
#include "bench/cli/timing_flags.hpp"
#include "bench/cli/gpu_session.hpp"
#include "bench/cli/progress_line.hpp"
#include "bench/cli/option_types.hpp"
#include "harness/core/error.hpp"
#include "harness/core/path_text.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/core/platform_console.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/scene/named_scene.hpp"
#include "harness/sweep/sweep_run.hpp"
#include "harness/timing/run_provenance.hpp"

namespace vsgl::cli {
namespace {

struct SweepCommandOptions {
  std::vector<std::string> axes;
  std::optional<std::string> capture;
  std::optional<std::string> scene;
  std::vector<std::string> assets;
  std::string captures = "captures/sweep";
  std::pair<uint32_t, uint32_t> gbuffer{1920, 1088};
  uint32_t rsm = 512;
  std::optional<std::string> out;
  GeneratorOptions gen;
  std::optional<uint32_t> warmup, repetitions, max_repetitions;
  std::optional<double> noise_target, time_cap, time_budget;
  std::optional<uint32_t> blocks;
  std::optional<uint64_t> order_seed;
  bool quick = false;
  bool clocks_locked = false;
  std::optional<std::string> schema;
  bool no_progress = false;
  DeviceOptions device;
};

int run_sweep_command(const SweepCommandOptions& c) {
  SweepOptions o;
  // Everything the command line alone decides is checked before Vulkan is touched (exit 2).
  for (const auto& spec : c.axes) o.axes.push_back(parse_axis_spec(spec));
  check_axes(o.axes);
  if (c.capture.has_value() == c.scene.has_value())
    throw UsageError("sweep needs exactly one input: --capture DIR or --scene NAME");
  for (const SweepAxis& a : o.axes)
    if (c.capture && (a.parameter == SweepParameter::kGbuffer || a.parameter == SweepParameter::kRsm))
      throw UsageError("--axis " + a.spec +
                       " records the capture again at each size, which needs --scene NAME, not "
                       "--capture");
  if (c.capture) o.capture = path_from_utf8(*c.capture);
  if (c.scene) o.scene = *c.scene;
  o.scenes = default_scene_library(paths_from_utf8(c.assets));
  o.captures_dir = path_from_utf8(c.captures);
  o.record_sizes = RecordSizes{c.gbuffer.first, c.gbuffer.second, c.rsm};
  o.time_budget_s = c.time_budget;
  const bool pdf_axis = std::any_of(o.axes.begin(), o.axes.end(),
                                    [](const SweepAxis& a) { return a.parameter == SweepParameter::kPdfSharpness; });
  o.blocks = c.blocks.value_or(pdf_axis ? kPdfSweepBlocks : 1);
  o.order_seed = c.order_seed.value_or(kSweepOrderSeed);
  if (o.blocks > kMaxSweepBlocks)
    throw UsageError("--blocks must be 1 to " + std::to_string(kMaxSweepBlocks) + " (got " + std::to_string(o.blocks) +
                     ")");
  if (c.schema) o.schema = path_from_utf8(*c.schema);
  TablesOptions& t = o.tables;
  t.clocks_locked = c.clocks_locked;

  GpuSession session = GpuSession::open(c.device);
  t.validation = session.context->instance().validation_enabled();
  const DeviceInfo& info = session.device().info();
  apply_timed_generators(c.gen, info, t);
  t.timing = TimingOptions::defaults_for(info);
  t.quick = c.quick;
  apply_timing_flags(c, t.timing);
  o.out_dir = c.out ? path_from_utf8(*c.out) : std::filesystem::path("results") / device_slug(info.name) / "sweep";

  ProgressLine line(!c.no_progress && vsgl::is_terminal(stderr));
  const SweepOutcome outcome = run_sweep(session.device(), o, [&](const SweepEvent& e) {
    if (e.progress == nullptr) line.message(e.message);
    else line.show("point " + std::to_string(e.point + 1) + "/" + std::to_string(e.points), *e.progress);
  });
  line.close();
  print_outcome({outcome.markdown}, outcome.written);
  return session.finish(0);
}

}  // namespace

Command add_sweep_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "sweep",
      "the tables' protocol at every point of one or more parameter axes (--axis, repeatable: two axes give their "
      "product): every generator on both views, recorded once per point and replayed with discarded warm-ups and "
      "interleaved repetitions. Per generator, view and phase, the cost growth along each axis is fitted on log-log "
      "axes (cost ∝ x^slope with a 95 % bootstrap interval over the rounds) and judged against what the algorithm "
      "predicts (e.g. filtered_sampling linear in N). Writes OUT/sweep.json (schema results/schema/sweep.schema.json: "
      "every point's statistics and raw samples, every fit), OUT/sweep.md (a table per axis) and "
      "OUT/sweep_<axis>_<phase>.svg (log-log, median and IQR band per generator and view); until the last point, "
      "OUT/sweep.json is rewritten after each point with the points so far and \"complete\": false");
  auto o = std::make_shared<SweepCommandOptions>();
  app->add_option("--axis", o->axes,
                  "NAME=VALUES: NAME one of vsgls (N on both views), camera-vsgls, light-vsgls, K, kmeans-iterations, "
                  "gbuffer (WxH, recorded at each size), rsm (side, recorded at each size), pdf-sharpness (gamma: both "
                  "views' PDFs raised to it, 0 = uniform); VALUES a:b:xF (geometric), a:b:+D (arithmetic) or "
                  "v1,v2,... (a list); e.g. vsgls=256:16384:x2, K=1,2,4, gbuffer=480x272:1920x1088:x2")
      ->required()
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->type_name("NAME=VALUES")
      ->check(usage_checked([](const std::string& t) { (void)parse_axis_spec(t); }, ""));
  CLI::Option* capture =
      add_optional(*app, "--capture", o->capture, "time this capture (not with the gbuffer and rsm axes)")
          ->type_name("DIR");
  CLI::Option* scene =
      add_optional(*app, "--scene", o->scene,
                   "or record this named scene (a preset such as sponza, or atrium, conference, tiny) into --captures")
          ->type_name("NAME")
          ->excludes(capture);
  add_assets_option(*app, o->assets)->excludes(capture);
  app->add_option("--captures", o->captures,
                  "capture cache of --scene: CAPTURES/<scene>-g<W>x<H>-r<R>, recorded when missing or stale")
      ->type_name("DIR")
      ->capture_default_str();
  add_size_option(*app, "--gbuffer", o->gbuffer, "G-buffer size of the --scene capture (the gbuffer axis sets its own)")
      ->excludes(capture);
  app->add_option("--rsm", o->rsm, "RSM size N x N of the --scene capture (the rsm axis sets its own)")
      ->check(at_least(1))
      ->capture_default_str()
      ->excludes(capture);
  add_optional(*app, "--out", o->out, "output directory")->type_name("DIR")->default_str("results/<device slug>/sweep");
  CLI::App* protocol = app->add_option_group("timing protocol", "warm-ups, repetitions and the stop rule, per point");
  add_optional(*protocol, "--warmup", o->warmup, "discarded warm-up runs")->check(at_least(2))->default_str("2");
  add_optional(*protocol, "--repetitions", o->repetitions, "minimum repetitions")
      ->check(at_least(2))
      ->default_str("10");
  add_optional(*protocol, "--noise-target", o->noise_target, "stop once every total has IQR/median <= X")
      ->check(positive_number())
      ->default_str("0.02");
  CLI::Option* budget = add_optional(*protocol, "--time-budget", o->time_budget,
                                     "S s of timing for the whole sweep, split evenly over the points' visits as each "
                                     "visit's time cap (recorded in the JSON with every point's stop rule)")
                            ->check(positive_number());
  add_optional(*protocol, "--time-cap", o->time_cap, "... or after S s of timing per point and visit (0: no cap)")
      ->check(CLI::NonNegativeNumber)
      ->default_str("60; 20 on a CPU device such as lavapipe")
      ->excludes(budget);
  add_optional(*protocol, "--max-repetitions", o->max_repetitions, "... or after M repetitions")
      ->check(at_least(2))
      ->default_str("1000");
  add_optional(*protocol, "--blocks", o->blocks,
               "B repeated blocks: each visits every point once, in an order drawn afresh per block from "
               "--order-seed (recorded in the JSON), timing it with the protocol above (its own warm-up and "
               "repetitions; the caps and the budget's share are per visit), and a point's rounds are pooled over "
               "its visits, so drift falls on every point alike; 1: each point once, in axis order")
      ->check(at_least(1))
      ->default_str(std::to_string(kPdfSweepBlocks) + " with a pdf-sharpness axis, else 1");
  add_optional(*protocol, "--order-seed", o->order_seed, "seed of the blocks' visit order")
      ->default_str(std::to_string(kSweepOrderSeed));
  protocol->add_flag("--quick", o->quick,
                     "3 repetitions per point, no noise target (CI smoke runs; marked in the JSON)");
  CLI::App* generators = app->add_option_group("generators", "what is timed (an axis overrides its parameter)");
  add_generator_options(*generators, o->gen);
  app->add_flag("--clocks-locked", o->clocks_locked, "record that you locked the GPU clocks (Vulkan cannot)");
  add_optional(*app, "--schema", o->schema, "the sweep JSON schema (default: the copy built into vsgl-bench)")
      ->check(input_file("--schema"))
      ->default_str("built-in results/schema/sweep.schema.json");
  app->add_flag("--no-progress", o->no_progress, "no progress line (it is off anyway when stderr is not a terminal)");
  add_device_options(*app, o->device);
  (void)scene;
  return {app, [o] { return run_sweep_command(*o); }};
}

}  // namespace vsgl::cli
