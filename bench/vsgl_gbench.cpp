// vsgl-gbench: the tables' measurements as Google Benchmark results for dashboards (SPEC §10):
// one benchmark per table/generator/view/phase (and per view total), each iteration a replay of the
// case's once-recorded command buffer, with UseManualTime fed by the GPU timestamps of that phase.
// Device, driver, git commit and every capture hash are in the JSON's "context".
//
//   vsgl-gbench [google benchmark flags] [--vsgl_captures=DIR] [--vsgl_device=D] [--vsgl_tables=1,2]
//               [--vsgl_generators=G,G] [--vsgl_camera_vsgls=N] [--vsgl_light_vsgls=N] [--vsgl_validate]
//               [--vsgl_iterations=N]   (replays per benchmark, default 30)
//   e.g. vsgl-gbench --benchmark_format=json --benchmark_out=gbench.json
//
// Differences from `vsgl-bench tables`: Google Benchmark chooses the iteration counts, and the
// cases run one after another rather than interleaved; every case is warmed up twice first.
#include <benchmark/benchmark.h>

#include <charconv>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/capture_provisioning.hpp"
#include "harness/device.hpp"
#include "harness/device_view.hpp"
#include "harness/error.hpp"
#include "harness/generator_registry.hpp"
#include "harness/run_provenance.hpp"
#include "harness/tables_run.hpp"
#include "harness/timing_runner.hpp"

namespace {

using namespace vsgl;

struct Options {
  std::string captures = "captures";
  std::string device;
  std::vector<int> tables{1, 2};
  std::vector<std::string> generators = generator_names();
  // Replays per benchmark. Fixed, because each iteration replays the whole case while reporting
  // one phase's manual time: letting Google Benchmark accumulate its min_time of a 20 us phase
  // would replay a millisecond-long k-means case tens of thousands of times.
  uint32_t iterations = 30;
  uint32_t camera_vsgls = 2048;
  uint32_t light_vsgls = 1024;
  bool validate = false;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

uint32_t parse_count(const std::string& flag, const std::string& v) {
  uint32_t n = 0;
  const auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
  if (ec != std::errc() || ptr != v.data() + v.size() || n == 0)
    throw UsageError(flag + " takes a positive whole number, not '" + v + "'");
  return n;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&](const std::string& flag) -> std::optional<std::string> {
      if (a.rfind(flag + "=", 0) == 0) return a.substr(flag.size() + 1);
      return std::nullopt;
    };
    if (auto v = value("--vsgl_captures")) o.captures = *v;
    else if (auto d = value("--vsgl_device")) o.device = *d;
    else if (auto t = value("--vsgl_tables")) {
      o.tables.clear();
      for (const auto& s : split(*t)) {
        if (s != "1" && s != "2") throw UsageError("--vsgl_tables takes 1, 2 or 1,2, not '" + *t + "'");
        o.tables.push_back(s == "1" ? 1 : 2);
      }
    } else if (auto g = value("--vsgl_generators")) o.generators = split(*g);
    else if (auto c = value("--vsgl_camera_vsgls")) o.camera_vsgls = parse_count("--vsgl_camera_vsgls", *c);
    else if (auto l = value("--vsgl_light_vsgls")) o.light_vsgls = parse_count("--vsgl_light_vsgls", *l);
    else if (auto n = value("--vsgl_iterations")) o.iterations = parse_count("--vsgl_iterations", *n);
    else if (a == "--vsgl_validate") o.validate = true;
    else throw UsageError("unknown argument '" + a + "'");
  }
  return o;
}

// Everything the registered benchmarks replay; alive until the end of main.
struct TableState {
  int number = 0;
  Capture capture;
  std::unique_ptr<DeviceView> camera, light;
  std::vector<std::unique_ptr<VsglGenerator>> generators;
  std::unique_ptr<TimingRunner> runner;
};

int run(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);  // removes the --benchmark_* flags
  const Options o = parse(argc, argv);
  GpuContextOptions ctx_options;
  ctx_options.device = o.device;
  ctx_options.instance.validation = o.validate;
  GpuContext ctx(ctx_options);
  Device& device = ctx.device();
  const DeviceInfo& info = device.info();
  require_timestamps(info);
  const nlohmann::json build = build_json(VSGL_SOURCE_DIR);
  benchmark::AddCustomContext("vsgl_device", info.name);
  benchmark::AddCustomContext("vsgl_device_type", device_type_name(info.type));
  benchmark::AddCustomContext("vsgl_driver", info.driver_name + " " + driver_version_string(info) + " " + info.driver_info);
  benchmark::AddCustomContext("vsgl_api_version", api_version_string(info.api_version));
  benchmark::AddCustomContext("vsgl_timestamp_period_ns", std::to_string(info.timestamp_period_ns));
  benchmark::AddCustomContext("vsgl_git_commit", build["git_commit"].get<std::string>());
  benchmark::AddCustomContext("vsgl_compiler", build["compiler"].get<std::string>());
  benchmark::AddCustomContext("vsgl_config", nlohmann::json{{"camera_vsgls", o.camera_vsgls},
                                                            {"light_vsgls", o.light_vsgls},
                                                            {"K", 1.0},
                                                            {"bisection_iterations", 12}}
                                                 .dump());

  std::vector<std::unique_ptr<TableState>> tables;
  for (int number : o.tables) {
    auto t = std::make_unique<TableState>();
    t->number = number;
    const std::string scene = table_scene(number);
    t->capture = provide_capture(device, scene, RecordSizes{}, std::filesystem::path(o.captures) / scene).capture;
    benchmark::AddCustomContext("vsgl_table" + std::to_string(number) + "_capture",
                                (std::filesystem::path(o.captures) / scene).string());
    benchmark::AddCustomContext("vsgl_table" + std::to_string(number) + "_capture_hashes",
                                capture_hashes_json(t->capture).dump());
    t->camera = std::make_unique<DeviceView>(upload_view(device, t->capture, ViewKind::kCamera));
    t->light = std::make_unique<DeviceView>(upload_view(device, t->capture, ViewKind::kLight));
    t->runner = std::make_unique<TimingRunner>(device, TimingOptions::defaults_for(info));
    for (const auto& g : o.generators)
      for (const DeviceView* view : {t->camera.get(), t->light.get()}) {
        GeneratorConfig cfg;
        cfg.vsgl_count = view->kind == ViewKind::kCamera ? o.camera_vsgls : o.light_vsgls;
        t->generators.push_back(make_generator(g, device, *view, cfg));
        const std::size_t index = t->generators.size() - 1;
        t->runner->add(TimingCase{g, view_name(view->kind), t->generators.back().get()});
        for (int w = 0; w < 2; ++w) t->runner->replay_once(index);  // warm-up: discarded
        TimingRunner* runner = t->runner.get();
        const auto phases = t->generators.back()->phases();
        const std::string prefix = "table" + std::to_string(number) + "/" + g + "/" + view_name(view->kind) + "/";
        for (std::size_t p = 0; p <= phases.size(); ++p) {
          const bool total = p == phases.size();
          benchmark::RegisterBenchmark((prefix + (total ? "total" : phases[p])).c_str(),
                                       [runner, index, p, total](benchmark::State& state) {
                                         for (auto _ : state) {
                                           const std::vector<double> ms = runner->replay_once(index);
                                           double seconds = 0;
                                           if (total)
                                             for (double m : ms) seconds += m * 1e-3;
                                           else
                                             seconds = ms[p] * 1e-3;
                                           state.SetIterationTime(seconds);
                                         }
                                       })
              ->UseManualTime()
              ->Iterations(o.iterations)
              ->Unit(benchmark::kMicrosecond);  // compare.py prints whole units: phases are tens of us
        }
      }
    tables.push_back(std::move(t));
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  const uint32_t errors = ctx.instance().validation_errors();
  if (errors > 0) {
    std::fprintf(stderr, "vsgl-gbench: the Khronos validation layer reported %u error(s)\n", errors);
    return static_cast<int>(ExitCode::kValidation);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const vsgl::UsageError& e) {
    std::fprintf(stderr, "vsgl-gbench: %s\n", e.what());
    return static_cast<int>(vsgl::ExitCode::kUsage);
  } catch (const vsgl::InputError& e) {
    std::fprintf(stderr, "vsgl-gbench: bad input: %s\n", e.what());
    return static_cast<int>(vsgl::ExitCode::kBadInput);
  } catch (const vsgl::DeviceError& e) {
    std::fprintf(stderr, "vsgl-gbench: device: %s\n", e.what());
    return static_cast<int>(vsgl::ExitCode::kDevice);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vsgl-gbench: error: %s\n", e.what());
    return static_cast<int>(vsgl::ExitCode::kFailure);
  }
}
