// `vsgl-bench tables`: the paper's Tables 1 and 2 (and the Table 3 analog) on this device
// (DESIGN.md §9, §10). The work is harness/report/tables_run.hpp; this file maps options and prints.
#include <unistd.h>

#include <cstdio>
#include <sstream>

#include "bench/cli/commands.hpp"
#include "bench/cli/generator_options.hpp"
#include "harness/generators/testing/debug_slowdown.hpp"
#include "bench/cli/gpu_session.hpp"
#include "harness/core/error.hpp"
#include "harness/timing/run_provenance.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/report/tables_run.hpp"

namespace vsgl::cli {
namespace {

std::vector<int> parse_tables(const std::string& s) {
  std::vector<int> out;
  for (const auto& item : Args(std::vector<std::string>{"--tables", s}).list("--tables", "")) {
    if (item == "1") out.push_back(1);
    else if (item == "2") out.push_back(2);
    else throw UsageError("--tables takes 1, 2 or 1,2, not '" + s + "'");
  }
  if (out.empty()) throw UsageError("--tables needs at least one table");
  return out;
}

// Options whose defaults depend on the device are read as text first and parsed afterwards.
uint32_t parse_u32(const std::string& name, const std::string& v, uint32_t min) {
  Args a(std::vector<std::string>{name, v});
  return a.u32(name, 0, min);
}
double parse_positive(const std::string& name, const std::string& v) {
  Args a(std::vector<std::string>{name, v});
  return static_cast<double>(a.positive_float(name, 1.0f));
}

}  // namespace

int run_tables(Args& args) {
  TablesOptions o;
  const bool quick = args.flag("--quick");
  const auto out = args.value("--out");
  o.captures_dir = args.string("--captures", "captures");
  const auto gbuffer = args.size("--gbuffer", {1920, 1088});  // only for captures recorded now
  o.record_sizes = RecordSizes{gbuffer.first, gbuffer.second, args.u32("--rsm", 512, 1)};
  const auto tables_arg = args.value("--tables");
  for (const auto& c : args.values("--capture")) o.captures.emplace_back(c);
  if (!o.captures.empty() && tables_arg)
    throw UsageError("--capture times the given captures; --tables picks the paper's: give one of them");
  o.tables = o.captures.empty() ? parse_tables(tables_arg.value_or("1,2")) : std::vector<int>{};
  const GeneratorOptions gen = read_generator_options(args);
  if (!gen.generators.empty()) o.generators = gen.generators;
  o.camera_vsgls = gen.camera_vsgls;
  o.light_vsgls = gen.light_vsgls;
  o.generator = gen.config;
  const auto warmup = args.value("--warmup");
  const auto reps = args.value("--repetitions");
  const auto max_reps = args.value("--max-repetitions");
  const auto noise = args.value("--noise-target");
  const auto cap = args.value("--time-cap");
  o.timing.cold = args.flag("--cold");
  o.copy_bandwidth.bytes = uint64_t{args.u32("--copy-mib", 256, 1)} << 20;
  o.json_only = args.flag("--json-only");
  o.clocks_locked = args.flag("--clocks-locked");
  o.debug_slow = args.list("--debug-slow", "");  // TEST-ONLY (harness/generators/testing/debug_slowdown.hpp)
  if (!o.debug_slow.empty()) o.wrap_generator = debug_slowdown_of(o.debug_slow);
  if (const auto p = args.value("--paper")) o.paper_tables = *p;
  if (const auto s = args.value("--schema")) o.schema = *s;
  const bool progress_flag = !args.flag("--no-progress");
  GpuSession session = GpuSession::open(args);
  o.validation = session.context->instance().validation_enabled();
  args.finish();

  // Defaults by device class (timing_runner.hpp), then the presets, then explicit options.
  const DeviceInfo& info = session.device().info();
  // On a CPU device (lavapipe) a k-means replay of both views takes seconds, so the full
  // protocol (2 warm-ups + 10 rounds) of all six generators would take ~20 minutes: there the
  // default is the paper's four; the segmented-sum extras are one --generators away.
  if (gen.generators.empty() && info.type == VK_PHYSICAL_DEVICE_TYPE_CPU) {
    std::vector<std::string> paper;
    for (const auto& g : o.generators)
      if (generator_in_paper(g)) paper.push_back(g);
    o.generators = paper;
    std::fprintf(stderr, "CPU device: timing the paper's four generators (add the extras with --generators)\n");
  }
  o.timing = [&] {
    TimingOptions t = TimingOptions::defaults_for(info);
    t.cold = o.timing.cold;
    return t;
  }();
  if (quick) {  // CI / tests: the protocol's shape, not its statistics
    o.quick = true;
    o.timing.min_repetitions = 3;
    o.timing.max_repetitions = 3;
  }
  if (warmup) o.timing.warmup = parse_u32("--warmup", *warmup, 2);
  if (reps) {
    o.timing.min_repetitions = parse_u32("--repetitions", *reps, 2);
    o.timing.max_repetitions = std::max(o.timing.max_repetitions, o.timing.min_repetitions);
  }
  if (max_reps) o.timing.max_repetitions = parse_u32("--max-repetitions", *max_reps, 2);
  if (noise) o.timing.noise_target = parse_positive("--noise-target", *noise);
  if (cap) o.timing.time_cap_s = *cap == "0" ? 0.0 : parse_positive("--time-cap", *cap);
  o.out_dir = out ? std::filesystem::path(*out) : std::filesystem::path("results") / device_slug(info.name);

  std::fprintf(stderr,
               "timing: warm-up %u, >= %u repetitions, stop at IQR/median <= %.3g or %.0f s or %u repetitions%s\n"
               "clocks: Vulkan cannot lock GPU clocks; for stable numbers lock them first (e.g. `nvidia-smi -lgc "
               "<MHz>`) and pass --clocks-locked (%s)\n",
               o.timing.warmup, o.timing.min_repetitions, o.timing.noise_target, o.timing.time_cap_s,
               o.timing.max_repetitions, o.timing.cold ? ", cold caches" : "",
               o.clocks_locked ? "claimed locked" : "not claimed locked");
  const bool tty = progress_flag && isatty(fileno(stderr)) != 0;
  bool line_open = false;
  const TablesOutcome outcome = vsgl::run_tables(session.device(), o, [&](const TablesEvent& e) {
    if (e.progress == nullptr) {
      if (line_open) std::fputc('\n', stderr);
      line_open = false;
      std::fprintf(stderr, "%s\n", e.message.c_str());
      return;
    }
    if (!tty) return;  // the progress line is for people watching a terminal
    const TimingProgress& p = *e.progress;
    if (p.rounds == 0)
      std::fprintf(stderr, "\r  table %d: warm-up %u/%u        ", e.table, p.warmup_done, p.warmup_total);
    else
      std::fprintf(stderr, "\r  table %d: repetition %u (min %u), worst IQR/median %.3f (target %.3f), %.1f s / %.0f s   ",
                   e.table, p.rounds, p.min_rounds, p.worst_noise < 0 ? 0.0 : p.worst_noise, p.noise_target,
                   p.elapsed_s, p.cap_s);
    std::fflush(stderr);
    line_open = true;
  });
  if (line_open) std::fputc('\n', stderr);
  for (const auto& md : outcome.markdown) std::printf("%s\n", md.c_str());
  std::fflush(stdout);
  for (const auto& path : outcome.written) std::fprintf(stderr, "wrote %s\n", path.string().c_str());
  return session.finish(0);
}

}  // namespace vsgl::cli
