#include "harness/report/run_context.hpp"

#include <ctime>

#include "harness/core/embedded_files.hpp"
#include "harness/core/text_format.hpp"
#include "harness/core/generator_ids.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/generators/fis/fis_generator.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/vk/device_info.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

}  // namespace

RunRecord run_record(const TablesOptions& o) {
  RunRecord run;
  run.started_utc = utc_now_text();
  run.validation_layer = o.validation;
  run.quick = o.quick;
  run.protocol_compliant = o.timing.warmup >= 2 && o.timing.min_repetitions >= 10;
  run.clocks_locked_claimed = o.clocks_locked;
  run.clocks_note =
      "Vulkan cannot lock GPU clocks: lock them outside (e.g. `nvidia-smi -lgc <MHz>` on NVIDIA, `rocm-smi "
      "--setperfdeterminism <MHz>` on AMD) and pass --clocks-locked";
  run.altered_generators = o.altered_generators;  // not a measurement
  return run;
}

RunContext make_run_context(const DeviceInfo& device, const TablesOptions& o) {
  RunContext out;
  ReportContext& ctx = out.report;
  ctx.device = device;
  ctx.paper = paper_tables_or_built_in(o.paper_tables);
  ctx.paper_path = file_or_built_in_name(o.paper_tables, kPaperTablesFile);
  out.schema = json_file_or_built_in(o.schema, kTableSchemaFile, "the table schema", " (use --schema FILE)");
  ctx.build = this_build();
  ctx.run = run_record(o);
  // Table 3 counts the sources of the path this run takes (FIS: pyramid path and mip strategy).
  const GeneratorConfig resolved = resolve_fis_config(device, o.generator);
  const SourceTree sources = o.source_dir ? checkout_source_tree(*o.source_dir) : built_in_source_tree();
  for (const auto& g : generator_names()) ctx.lines[g] = count_generator_lines(generator_sources(g, resolved), sources);
  for (const auto& g : o.generators)
    ctx.shaders[g] = static_cast<uint32_t>(generator_sources(g, resolved).kernels.size());
  return out;
}

namespace {

// DESIGN.md §6.1a: the FIS pyramid as this run builds it, and why its mip strategy is the one used.
ojson pyramid_json(const TablesOptions& o, const DeviceInfo& device) {
  std::string fallback;
  const PyramidPath path = effective_pyramid_path(device, o.generator.pyramid, &fallback);
  std::string mip_fallback;
  const MipStrategy strategy = path == PyramidPath::kTexture
                                   ? effective_mip_strategy(device, o.generator.mipmapping, &mip_fallback)
                                   : o.generator.mipmapping.value_or(default_mip_strategy(device));
  ojson j{{"path", pyramid_path_name(path)}, {"requested_path", pyramid_path_name(o.generator.pyramid)}};
  if (!fallback.empty()) j["fallback_reason"] = fallback;
  if (path == PyramidPath::kTexture) {
    j["image_format"] = kPyramidImageFormat;
    j["sampler"] = kPyramidSampler;
    j["lookups"] = "hierarchical warping: texelFetch; every trilinear lookup (moments, PDF, each bisection step): one "
                   "textureLod";
    j["mipmapping"] = mip_strategy_name(strategy);
    j["mipmapping_reason"] = o.generator.mipmapping ? std::string("chosen with --mipmapping")
                                                    : default_mip_strategy_reason(device);
    j["mipmapping_default_measured"] = !o.generator.mipmapping && device.type == VK_PHYSICAL_DEVICE_TYPE_CPU;
    if (!mip_fallback.empty()) {
      j["mipmapping_fallback_reason"] = mip_fallback;  // the device's limits refused the strategy asked for
      j["mipmapping_default_measured"] = false;
    }
  } else {
    j["image_format"] = "storage buffer of vec4 (RGBA32F), software trilinear filter";
    j["mipmapping"] = "per-level";
    j["mipmapping_reason"] = "the buffer path builds its chain with one dispatch per level";
  }
  j["sub_texel_precision_bits"] = device.sub_texel_precision_bits;
  j["mipmap_precision_bits"] = device.mipmap_precision_bits;
  return j;
}

}  // namespace

nlohmann::ordered_json config_json(const TablesOptions& o, const Capture& capture, const DeviceInfo& device) {
  const TimingOptions& tm = o.timing;
  ojson views{{"camera_view", ojson{{"source", "gbuffer"},
                                     {"width", capture.gbuffer.width},
                                     {"height", capture.gbuffer.height},
                                     {"vsgl_count", o.camera_vsgls}}},
              {"light_view", ojson{{"source", "rsm"},
                                   {"width", capture.rsm.width},
                                   {"height", capture.rsm.height},
                                   {"vsgl_count", o.light_vsgls}}}};
  const std::string kmeans_sum = std::string(kKmeans2d) + "/" + std::string(kKmeans3d) +
                                 ": one thread per cluster sums sequentially (the paper's); *_segsum: "
                                 "parallel segmented reduction (extra, not in the paper)";
  return ojson{
      {"views", views},
      {"K", o.generator.K},
      {"bisection_iterations", o.generator.bisection_iterations},
      {"kmeans_iterations", o.generator.kmeans_iterations},
      {"kmeans_sum", kmeans_sum},
      {"offset_bits", o.generator.offset_bits},
      {"sampler", "Fibonacci lattice + hierarchical sample warping (DESIGN.md §5)"},
      {"pyramid", pyramid_json(o, device)},
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

}  // namespace vsgl
