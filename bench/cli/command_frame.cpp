// `vsgl-bench frame`: the paper's frame timed phase by phase on this device, per generator (DESIGN.md
// §9.2). The work is harness/quality/frame_run.hpp; this file maps options and prints.
#include <bit>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/cli/commands.hpp"
#include "bench/cli/generator_options.hpp"
#include "bench/cli/gpu_session.hpp"
#include "bench/cli/progress_line.hpp"
#include "bench/cli/option_types.hpp"
#include "bench/cli/timing_flags.hpp"
#include "harness/core/path_text.hpp"
#include "harness/core/platform_console.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/quality/frame_run.hpp"
#include "harness/vk/device_info.hpp"

namespace vsgl::cli {
namespace {

struct FrameCommandOptions {
  std::string capture;
  std::string out = ".";
  std::vector<std::string> generators;  // empty: the paper's four
  uint32_t vsgls = kPaperLightVsgls;
  uint32_t stride = 1;
  IsmSettings ism;
  GeneratorConfig config;
  bool quick = false;
  std::optional<uint32_t> warmup, repetitions, max_repetitions;
  std::optional<double> noise_target, time_cap;
  bool json_only = false;
  bool clocks_locked = false;
  std::optional<std::string> schema;
  bool no_progress = false;
  DeviceOptions device;
};

std::vector<std::string> paper_generators() {
  std::vector<std::string> out;
  for (const auto& g : generator_names())
    if (generator_in_paper(g)) out.push_back(g);
  return out;
}

int run_frame_command(const FrameCommandOptions& c) {
  FrameOptions o;
  o.capture_dir = path_from_utf8(c.capture);
  o.out_dir = path_from_utf8(c.out);
  o.generators = c.generators.empty() ? paper_generators() : c.generators;
  o.light_vsgls = c.vsgls;
  o.stride = c.stride;
  o.ism = c.ism;
  o.generator = c.config;
  o.quick = c.quick;
  o.json_only = c.json_only;
  o.clocks_locked = c.clocks_locked;
  if (c.schema) o.schema = path_from_utf8(*c.schema);
  GpuSession session = GpuSession::open(c.device);
  o.validation = session.context->instance().validation_enabled();
  const DeviceInfo& info = session.device().info();
  o.timing = TimingOptions::defaults_for(info);
  apply_timing_flags(c, o.timing);
  std::fprintf(stderr,
               "frame: %zu generator(s), N = %u, ISM %ux%u, stride %u; warm-up %u, >= %u rounds, stop at "
               "IQR/median <= %.3g or %.0f s or %u rounds\n",
               o.generators.size(), o.light_vsgls, o.ism.side, o.ism.side, o.stride, o.timing.warmup,
               o.timing.min_repetitions, o.timing.noise_target, o.timing.time_cap_s, o.timing.max_repetitions);
  ProgressLine line(!c.no_progress && vsgl::is_terminal(stderr));
  const FrameOutcome outcome = run_frame(session.device(), o, [&](const TimingProgress& p) { line.show("frame", p); });
  line.close();
  print_outcome({outcome.markdown}, outcome.written);
  return session.finish(0);
}

}  // namespace

Command add_frame_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "frame",
      "the paper's frame timed phase by phase on this device, per generator (DESIGN.md §9.2): rsm_replay (the "
      "recorded RSM copied into the buffer the generators read: a replay, not the paper's RSM rendering), pdf (the "
      "BRSM PDF), vsgl_generation (N light-view VSGLs), ism (their imperfect shadow maps, splat + pull-push) and "
      "shading (the camera view, visibility ism), each between Vulkan timestamps in one command buffer per frame, "
      "replayed with the timing protocol of `tables`. Writes OUT/frame.json (schema "
      "results/schema/frame.schema.json) and OUT/frame.md");
  auto o = std::make_shared<FrameCommandOptions>();
  app->add_option("--capture", o->capture,
                  "capture directory with its visibility geometry (`vsgl-bench record`, --visibility-points > 0)")
      ->required()
      ->type_name("DIR");
  add_generators_option(*app, o->generators, "the paper's four");
  app->add_option("--vsgls", o->vsgls, "light-view VSGLs per generator (the paper's N)")
      ->check(at_least(1))
      ->capture_default_str();
  app->add_option("--ism-side", o->ism.side, "texels per side of each imperfect shadow map (the paper's 64)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            uint32_t v = 0;
            if (!CLI::detail::lexical_cast(text, v) || v < 2 || v > kIsmMaxSide || !std::has_single_bit(v))
              return "must be a power of two in [2, " + std::to_string(kIsmMaxSide) + "], not '" + text + "'";
            return {};
          },
          "a power of two"))
      ->capture_default_str();
  app->add_option("--ism-points-per-map", o->ism.points_per_map,
                  "points of the capture's sampling each map splats, at most the points it holds")
      ->check(at_least(1))
      ->capture_default_str();
  app->add_option("--stride", o->stride,
                  "shade every K-th G-buffer pixel per axis (K > 1 for a slow CPU driver: recorded, and the output "
                  "says the size is not the paper's)")
      ->check(at_least(1))
      ->capture_default_str();
  app->add_option("--out", o->out, "output directory")->type_name("DIR")->capture_default_str();
  CLI::App* protocol =
      app->add_option_group("timing protocol", "warm-ups, repetitions and the stop rule (as `tables`)");
  add_optional(*protocol, "--warmup", o->warmup, "discarded warm-up frames")->check(at_least(2))->default_str("2");
  add_optional(*protocol, "--repetitions", o->repetitions, "minimum rounds")->check(at_least(2))->default_str("10");
  add_optional(*protocol, "--noise-target", o->noise_target, "stop once every frame has IQR/median <= X")
      ->check(positive_number())
      ->default_str("0.02");
  add_optional(*protocol, "--time-cap", o->time_cap, "... or after S s of timing (0: no cap)")
      ->check(CLI::NonNegativeNumber)
      ->default_str("60; 20 on a CPU device such as lavapipe");
  add_optional(*protocol, "--max-repetitions", o->max_repetitions, "... or after M rounds")
      ->check(at_least(2))
      ->default_str("1000");
  protocol->add_flag("--quick", o->quick, "3 rounds, no noise target (CI smoke runs; marked in the JSON)");
  add_pyramid_option(*app, o->config.pyramid);
  add_mipmapping_option(*app, o->config.mipmapping, "FIS texture path's mip chain: single-pass, blit or per-level");
  app->add_flag("--json-only", o->json_only, "write no markdown file (the console still shows the table)");
  app->add_flag("--clocks-locked", o->clocks_locked, "record that you locked the GPU clocks (Vulkan cannot)");
  add_optional(*app, "--schema", o->schema, "the frame JSON schema (default: the copy built into vsgl-bench)")
      ->check(input_file("--schema"))
      ->default_str("built-in results/schema/frame.schema.json");
  app->add_flag("--no-progress", o->no_progress, "no progress line (it is off anyway when stderr is not a terminal)");
  add_device_options(*app, o->device);
  return {app, [o] { return run_frame_command(*o); }};
}

}  // namespace vsgl::cli
