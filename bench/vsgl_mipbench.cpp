// vsgl-mipbench: the FIS texture path's three mipmapping strategies (DESIGN.md §6.1a) timed alone on
// both views of the paper's captures, as Google Benchmark results with manual time = the GPU
// timestamps around the `mipmapping` phase: single-pass (one dispatch to level 6, then one group
// finishes the small levels), blit (the vkCmdBlitImage chain) and per-level (one dispatch per level). This is
// the measurement behind each device kind's default strategy (fis_generator.cpp).
//
//   vsgl-mipbench [google benchmark flags] [--vsgl_captures=DIR] [--vsgl_device=D]
//                 [--vsgl_tables=1,2] [--vsgl_replays=N]   (replays per benchmark, default 30)
//
// Level 0 is built once (untimed) by a full run of the generator; each replay rebuilds levels
// 1..L from it, which leaves the pyramid as it was, so replays are alike.
#include <cstdio>
#include <benchmark/benchmark.h>

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
#include "bench/cli/gpu_session.hpp"
#include "harness/core/error.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/generators/fis/fis_generator.hpp"
#include "harness/scene/named_scene.hpp"
#include "harness/report/tables_run.hpp"
#include "harness/scene/capture_provisioning.hpp"
#include "harness/formats/run_header.hpp"
#include "harness/timing/timing_runner.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"

namespace {

using namespace vsgl;

// Only the mipmapping phase of a built FIS generator, as a one-phase generator for TimingRunner.
class MipmappingOnly : public VsglGenerator {
 public:
  explicit MipmappingOnly(std::unique_ptr<FisGenerator> fis) : fis_(std::move(fis)) {}
  std::string name() const override { return fis_->name(); }
  std::vector<std::string> phases() const override { return {"mipmapping"}; }
  void record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) override {
    boundary(stream.get());
    fis_->record_mipmapping(stream);
    boundary(stream.get());
  }
  const Buffer& vsgls() const override { return fis_->vsgls(); }
  uint32_t vsgl_count() const override { return fis_->vsgl_count(); }

 private:
  std::unique_ptr<FisGenerator> fis_;
};

struct TableState {
  Capture capture;
  std::unique_ptr<DeviceView> camera, light;
  std::vector<std::unique_ptr<VsglGenerator>> cases;
  std::unique_ptr<TimingRunner> runner;
};

int run(int argc, char** argv) {
  CLI::App app("vsgl-mipbench: the FIS texture path's mipmapping strategies timed alone, as Google Benchmark "
               "results (manual time = GPU timestamps); Google Benchmark's own --benchmark_* flags pass through",
               "vsgl-mipbench");
  app.footer(cli::exit_codes_help());
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.allow_extras();
  const cli::OptionNames names{.gbench = true};
  std::string captures = "captures";
  std::vector<std::string> table_names{"1", "2"};
  uint32_t replays = 30;
  cli::DeviceOptions device_options;
  app.add_option(names("captures"), captures, "capture root; missing captures are recorded first")
      ->type_name("DIR")
      ->capture_default_str();
  cli::add_list_option(app, names("tables"), table_names,
                       "which tables (1: sponza, else atrium; 2: conference-room, else conference)",
                       cli::one_of({"1", "2"}));
  std::vector<std::string> assets;
  cli::add_assets_option(app, assets, names);
  app.add_option(names("replays"), replays, "replays per benchmark")->check(cli::at_least(1))->capture_default_str();
  cli::add_device_options(app, device_options, names);
  if (const auto exit_code = cli::parse_command_line(app, argc, argv)) return *exit_code;
  // What CLI11 left is Google Benchmark's, or a mistake: both are checked before any device work.
  if (const auto exit_code = cli::initialize_benchmark(app, argv[0])) return *exit_code;
  std::vector<int> tables;
  for (const auto& t : table_names) tables.push_back(t == "1" ? 1 : 2);
  cli::GpuSession session = cli::GpuSession::open(device_options);
  Device& device = session.device();
  const DeviceInfo& info = device.info();
  require_timestamps(info);
  if (const std::string why = texture_path_unsupported_reason(info); !why.empty())
    throw DeviceError("the texture path cannot run on " + info.name + ": " + why);
  const BuildRecord build = this_build();
  benchmark::AddCustomContext("vsgl_device", info.name);
  benchmark::AddCustomContext("vsgl_device_type", device_type_name(info.type));
  benchmark::AddCustomContext("vsgl_driver", info.driver_name + " " + driver_version_string(info) + " " + info.driver_info);
  benchmark::AddCustomContext("vsgl_git_commit", build.git_commit);
  benchmark::AddCustomContext("vsgl_default_mipmapping", mip_strategy_name(default_mip_strategy(info)));

  const SceneLibrary library = default_scene_library(paths_from_utf8(assets));
  std::vector<std::unique_ptr<TableState>> states;
  for (int number : tables) {
    auto t = std::make_unique<TableState>();
    const TableScene scene = table_scene(number, library);
    const std::filesystem::path dir = path_from_utf8(captures) / scene.scene;
    const auto say = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    t->capture = provide_table_capture(device, scene, library, dir, RecordSizes{}, say).capture;
    benchmark::AddCustomContext("vsgl_table" + std::to_string(number) + "_capture", dir.string());
    benchmark::AddCustomContext("vsgl_table" + std::to_string(number) + "_capture_hashes",
                                capture_hashes_json(t->capture).dump());
    t->camera = std::make_unique<DeviceView>(upload_view(device, t->capture, ViewKind::kCamera));
    t->light = std::make_unique<DeviceView>(upload_view(device, t->capture, ViewKind::kLight));
    t->runner = std::make_unique<TimingRunner>(device, TimingOptions::defaults_for(info));
    for (MipStrategy m : {MipStrategy::kSinglePass, MipStrategy::kBlit, MipStrategy::kPerLevel})
      for (const DeviceView* view : {t->camera.get(), t->light.get()}) {
        FisParams p;
        p.vsgl_count = 1;  // filtered sampling is not timed here
        p.pyramid = PyramidPath::kTexture;
        p.mipmapping = m;
        auto fis = std::make_unique<FisGenerator>(device, *view, FisVariant::kModified, p);
        run_untimed(device, *fis);  // level 0
        t->cases.push_back(std::make_unique<MipmappingOnly>(std::move(fis)));
        const std::size_t index = t->cases.size() - 1;
        t->runner->add(TimingCase{"fis_mipmapping", view_name(view->kind), t->cases.back().get()});
        for (int w = 0; w < 2; ++w) t->runner->replay_once(index);  // warm-up: discarded
        TimingRunner* runner = t->runner.get();
        const std::string name =
            "table" + std::to_string(number) + "/" + mip_strategy_name(m) + "/" + view_name(view->kind) + "/mipmapping";
        benchmark::RegisterBenchmark(name.c_str(),
                                     [runner, index](benchmark::State& state) {
                                       for (auto _ : state) state.SetIterationTime(runner->replay_once(index)[0] * 1e-3);
                                     })
            ->UseManualTime()
            ->Iterations(replays)
            ->Unit(benchmark::kMicrosecond);
      }
    states.push_back(std::move(t));
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return session.finish(0);
}

}  // namespace

int main(int argc, char** argv) { return vsgl::cli::run_program("vsgl-mipbench", argc, argv, run); }
