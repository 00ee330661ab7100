// vsgl-gbench: the tables' measurements as Google Benchmark results for dashboards (DESIGN.md §10):
// one benchmark per table/generator/view/phase (and per view total), each iteration a replay of the
// case's once-recorded command buffer, with UseManualTime fed by the GPU timestamps of that phase.
// Device, driver, git commit and every capture hash are in the JSON's "context".
//
//   vsgl-gbench [google benchmark flags] [--vsgl_captures=DIR] [--vsgl_device=D] [--vsgl_tables=1,2]
//               [--vsgl_capture=DIR ...]   (time these captures instead: benchmarks <scene>/..., or
//                                           tableN/... for a capture of a paper table's scene)
//               [--vsgl_generators=G,G] [--vsgl_camera_vsgls=N] [--vsgl_light_vsgls=N] [--vsgl_K=K]
//               [--vsgl_iterations=I] [--vsgl_kmeans_iterations=I] [--vsgl_validate]
//               [--vsgl_pyramid=texture|buffer] [--vsgl_mipmapping=single-pass|blit|per-level]
//               [--vsgl_replays=N]   (replays per benchmark, default 30)
//   e.g. vsgl-gbench --benchmark_format=json --benchmark_out=gbench.json
//
// Every --vsgl_name option is `vsgl-bench tables --name` (underscores for dashes), declared by the
// same code (bench/cli/), so the two front ends cannot drift; `vsgl-gbench --help` lists them;
// exit codes are vsgl-bench's.
//
// Differences from `vsgl-bench tables`: Google Benchmark chooses the iteration counts, and the
// cases run one after another rather than interleaved; every case is warmed up twice first.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <deque>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

#include "bench/benchmark_arguments.hpp"
#include "bench/cli/command_line.hpp"
#include "bench/cli/exit_codes.hpp"
#include "bench/cli/option_types.hpp"
#include "bench/cli/program_main.hpp"
#include "bench/cli/generator_options.hpp"
#include "bench/cli/gpu_session.hpp"
#include "bench/cli/timed_generators.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/core/sorted_json.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/generators/fis/fis_generator.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/report/capture_cases.hpp"
#include "harness/report/capture_scene_identity.hpp"
#include "harness/report/table_timing.hpp"
#include "harness/report/tables_run.hpp"
#include "harness/scene/named_scene.hpp"
#include "harness/formats/run_header.hpp"
#include "harness/timing/timing_runner.hpp"
#include "harness/vk/device.hpp"

namespace {

using namespace vsgl;

struct Options {
  std::string captures = "captures";
  std::vector<int> tables;                // filled from --vsgl_tables unless captures are given
  std::vector<std::string> capture_dirs;  // --vsgl_capture: instead of the paper's tables
  std::vector<std::string> assets;
  cli::GeneratorOptions generator;
  // Replays per benchmark. Fixed, because each iteration replays the whole case while reporting
  // one phase's manual time: letting Google Benchmark accumulate its min_time of a 20 us phase
  // would replay a millisecond-long k-means case tens of thousands of times.
  uint32_t replays = 30;
};

// The tool's own options (each `vsgl-bench tables --name` as --vsgl_name, declared by the same
// functions); every --benchmark_* argument is left for Google Benchmark.
void add_options(CLI::App& app, Options& o, std::vector<std::string>& tables, cli::DeviceOptions& device) {
  const cli::OptionNames names{.gbench = true};
  app.add_option(names("captures"), o.captures, "capture root; missing captures are recorded first")
      ->type_name("DIR")
      ->capture_default_str();
  auto* table_option = cli::add_list_option(app, names("tables"), tables,
                                            "which tables (1: sponza, else atrium; 2: conference-room, else "
                                            "conference)",
                                            cli::one_of({"1", "2"}));
  cli::add_assets_option(app, o.assets, names);
  app.add_option(names("capture"), o.capture_dirs,
                 "time this capture instead (repeatable): benchmarks <scene>/..., or tableN/... for a capture of a "
                 "paper table's scene")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->type_name("DIR")
      ->excludes(table_option);
  cli::add_generator_options(app, o.generator, names);
  app.add_option(names("replays"), o.replays, "replays per benchmark")->check(cli::at_least(1))->capture_default_str();
  cli::add_device_options(app, device, names);
}

// The run as vsgl-bench tables would make it: the same inputs (table_inputs), generators, N and
// config. Unlike `tables` on a CPU device, every generator by default (a dashboard wants them all).
TablesOptions timed_options(const Options& o, const DeviceInfo& info) {
  TablesOptions t;
  t.captures_dir = path_from_utf8(o.captures);
  t.scenes = default_scene_library(paths_from_utf8(o.assets));
  t.tables = o.tables;
  t.captures = paths_from_utf8(o.capture_dirs);
  cli::apply_generator_options(o.generator, t);
  t.timing = TimingOptions::defaults_for(info);
  return t;
}

// The JSON's "context" for the whole run: device, driver, build and the generator config.
void add_run_context(const DeviceInfo& info, const Options& o) {
  const BuildRecord build = this_build();
  benchmark::AddCustomContext("vsgl_device", info.name);
  benchmark::AddCustomContext("vsgl_device_type", device_type_name(info.type));
  benchmark::AddCustomContext("vsgl_driver",
                              info.driver_name + " " + driver_version_string(info) + " " + info.driver_info);
  benchmark::AddCustomContext("vsgl_api_version", api_version_string(info.api_version));
  benchmark::AddCustomContext("vsgl_timestamp_period_ns", std::to_string(info.timestamp_period_ns));
  benchmark::AddCustomContext("vsgl_git_commit", build.git_commit);
  benchmark::AddCustomContext("vsgl_compiler", build.compiler);
  const GeneratorConfig resolved = resolve_fis_config(info, o.generator.config);
  benchmark::AddCustomContext(
      "vsgl_config",
      sorted_keys(nlohmann::ordered_json{{"camera_vsgls", o.generator.camera_vsgls},
                                         {"light_vsgls", o.generator.light_vsgls},
                                         {"K", o.generator.config.K},
                                         {"bisection_iterations", o.generator.config.bisection_iterations},
                                         {"kmeans_iterations", o.generator.config.kmeans_iterations},
                                         {"pyramid", pyramid_path_name(resolved.pyramid)},
                                         {"mipmapping", mip_strategy_name(*resolved.mipmapping)},
                                         {"replays", o.replays}})
          .dump());
}

// Everything one input's benchmarks replay; alive until the end of main.
struct TimedInput {
  std::string stem;  // "tableN", or the scene of another capture: the benchmarks' first name part
  Capture capture;
  std::unique_ptr<CaptureCases> cases;
};

// The JSON's "context" for one input: where its capture is, its hashes, scene and source.
void add_input_context(const TimedInput& t, const std::filesystem::path& dir) {
  benchmark::AddCustomContext("vsgl_" + t.stem + "_capture", dir.string());
  benchmark::AddCustomContext("vsgl_" + t.stem + "_capture_hashes", capture_hashes_json(t.capture).dump());
  benchmark::AddCustomContext("vsgl_" + t.stem + "_scene", to_json(capture_scene_identity(t.capture.meta)).dump());
  if (t.capture.meta.source)
    benchmark::AddCustomContext("vsgl_" + t.stem + "_source",
                                t.capture.meta.source->file + " " + t.capture.meta.source->content_hash);
}

// One benchmark per phase of each case and one for its total, named STEM/GENERATOR/VIEW/PHASE;
// each iteration replays the whole case and reports the phase's GPU time as its manual time.
void register_benchmarks(TimedInput& t, uint32_t replays) {
  TimingRunner* runner = &t.cases->runner();
  const std::vector<TimingCase>& cases = t.cases->cases();
  for (std::size_t index = 0; index < cases.size(); ++index) {
    for (int w = 0; w < 2; ++w) runner->replay_once(index);  // warm-up: discarded
    const std::vector<std::string> phases = cases[index].source->phases();
    const std::string prefix = t.stem + "/" + cases[index].generator + "/" + cases[index].view + "/";
    for (std::size_t p = 0; p <= phases.size(); ++p) {
      const bool total = p == phases.size();
      benchmark::RegisterBenchmark((prefix + (total ? "total" : phases[p])).c_str(),
                                   [runner, index, p, total](benchmark::State& state) {
                                     for (auto _ : state) {
                                       const std::vector<double> ms = runner->replay_once(index);
                                       double seconds = 0;
                                       if (total)
                                         for (double m : ms) seconds += m * 1e-3;
                                       else seconds = ms[p] * 1e-3;
                                       state.SetIterationTime(seconds);
                                     }
                                   })
          ->UseManualTime()
          ->Iterations(replays)
          ->Unit(benchmark::kMicrosecond);  // compare.py prints whole units: phases are tens of us
    }
  }
}

int run(int argc, char** argv) {
  CLI::App app("vsgl-gbench: the tables' measurements as Google Benchmark results (manual time = GPU "
               "timestamps), for dashboards; Google Benchmark's own flags (--benchmark_format=json, "
               "--benchmark_out=FILE, --benchmark_repetitions=R, ...) pass through",
               "vsgl-gbench");
  app.footer(cli::exit_codes_help());
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.allow_extras();
  Options o;
  std::vector<std::string> table_names{"1", "2"};
  cli::DeviceOptions device_options;
  add_options(app, o, table_names, device_options);
  if (const auto exit_code = cli::parse_command_line(app, argc, argv)) return *exit_code;
  // What CLI11 left is Google Benchmark's, or a mistake: both are checked before any device work.
  if (const auto exit_code = cli::initialize_benchmark(app, argv[0])) return *exit_code;
  if (o.capture_dirs.empty())
    for (const auto& t : table_names) o.tables.push_back(t == "1" ? 1 : 2);
  cli::GpuSession session = cli::GpuSession::open(device_options);
  Device& device = session.device();
  require_timestamps(device.info());
  add_run_context(device.info(), o);

  // The inputs: the paper's tables (recorded when missing), or the captures given (loaded).
  const TablesOptions timed = timed_options(o, device.info());
  const auto say = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
  std::deque<TimedInput> inputs;  // a deque: the registered benchmarks point into its elements
  for (const TableInput& input : table_inputs(timed)) {
    TimedInput& t = inputs.emplace_back();
    t.capture = provide_input_capture(device, timed, input, say).capture;
    t.stem = table_file_stem(input.paper_table, t.capture.meta.scene);
    add_input_context(t, input.capture_dir);
    t.cases = std::make_unique<CaptureCases>(device, timed, t.capture);
    register_benchmarks(t, o.replays);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return session.finish(0);
}

}  // namespace

int main(int argc, char** argv) { return vsgl::cli::run_program("vsgl-gbench", argc, argv, run); }
