// `vsgl-bench shade`: the camera view of a capture lit by the N light-view VSGLs of each listed
// generator (indirect light only, no direct spot light), with the visibility --visibility names
// (DESIGN.md §8: the VSGLs' imperfect shadow maps by default, as the paper shades; none; or exact,
// the control), written as OUT/shade_<scene>_<generator>.png, so a user can see what each
// generator produces (the 2016 paper's Fig. 5). One exposure serves every picture of a run, so
// they compare directly.
#include <bit>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/cli/commands.hpp"
#include "bench/cli/generator_options.hpp"
#include "bench/cli/gpu_session.hpp"
#include "harness/capture/capture.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/core/path_text.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/core/error.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/quality/png_image.hpp"
#include "harness/quality/shading_pass.hpp"
#include "harness/quality/shading_visibility.hpp"
#include "harness/generators/vsgl_generator.hpp"

namespace vsgl::cli {
namespace {

// Every registered generator can light the view (generators/generator_registry.hpp).
const GeneratorDescriptor& find_generator(const std::string& name) {
  try {
    return generator_descriptor(name);
  } catch (const InputError& e) {
    throw UsageError(std::string("--generators: ") + e.what());
  }
}


struct ShadeOptions {
  std::string capture;
  std::vector<std::string> generators = generator_names(GeneratorFamily::kFis);
  uint32_t stride = 1;
  uint32_t vsgls = kPaperLightVsgls;
  std::string out = ".";
  float exposure = 0.0f;  // 0: not given, expose automatically
  std::string visibility = "ism";
  IsmSettings ism;
  std::vector<const CLI::Option*> ism_options;  // the --ism-* options, refused unless --visibility ism
  GeneratorConfig config;
  DeviceOptions device;
};

// A number read by CLI11's own parser (the option's type), checked by `ok`; `rule` says what it must be.
template <class T, class Ok>
CLI::Validator checked_number(Ok ok, const std::string& rule) {
  return CLI::Validator(
      [ok, rule](std::string& text) -> std::string {
        T v{};
        if (!CLI::detail::lexical_cast(text, v) || !ok(v)) return "must be " + rule + ", not '" + text + "'";
        return {};
      },
      rule);
}

ShadingVisibilitySettings visibility_settings(const ShadeOptions& o) {
  ShadingVisibilitySettings s;
  s.mode = parse_shading_visibility(o.visibility);
  s.ism = o.ism;
  if (s.mode != ShadingVisibility::kIsm)
    for (const CLI::Option* option : o.ism_options)
      if (option->count() > 0)
        throw UsageError(option->get_name() + " sets the imperfect shadow maps, which only --visibility ism uses");
  return s;
}

int run_shade(ShadeOptions& o) {
  const std::string* capture_arg = &o.capture;
  const auto& names = o.generators;
  const uint32_t stride = o.stride;
  const uint32_t vsgl_count = o.vsgls;
  const std::filesystem::path out_dir = path_from_utf8(o.out);
  float exposure = o.exposure;
  GeneratorConfig& config = o.config;
  const ShadingVisibilitySettings visibility = visibility_settings(o);
  std::vector<const GeneratorDescriptor*> generators;
  for (const auto& name : names) generators.push_back(&find_generator(name));
  GpuSession session = GpuSession::open(o.device);

  const std::filesystem::path capture_dir = path_from_utf8(*capture_arg);
  const Capture capture = load_capture(capture_dir);
  // A capture without the visibility geometry is refused here, naming --visibility-points of
  // `record` and --visibility none, before anything runs.
  std::optional<VisibilityGeometry> geometry;
  if (visibility.mode != ShadingVisibility::kNone) geometry = load_visibility_geometry(capture_dir, capture.meta);
  Device& device = session.device();
  // The BVH (exact) is built and checked against the device's limits, and the maps' settings and
  // sizes (ism) checked, before any generator runs.
  VisibleShading shading(device, visibility, geometry ? &*geometry : nullptr);
  shading.require_maps_fit(vsgl_count);
  const DeviceView camera = upload_view(device, capture, ViewKind::kCamera);
  const DeviceView light = upload_view(device, capture, ViewKind::kLight);

  // Everything is computed and checked before the first file is written (DESIGN.md §12).
  std::vector<RadianceImage> images;
  for (const GeneratorDescriptor* g : generators) {
    config.vsgl_count = vsgl_count;
    auto generator = g->make(device, light, config);
    run_untimed(device, *generator);
    images.push_back(shading.shade(camera, generator->vsgls(), generator->vsgl_count(), stride));
  }
  const bool auto_exposed = exposure == 0.0f;
  if (auto_exposed) exposure = auto_exposure(images.front());
  std::vector<Rgb8Image> pictures;
  for (const auto& image : images) pictures.push_back(tone_map(image, exposure));

  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw InputError(path_text(out_dir) + ": cannot create the output directory (" + ec.message() + ")");
  std::printf(
      "shading %s (G-buffer %ux%u, stride %u -> %ux%u) with %u light-view VSGLs per generator; "
      "%s; %s; exposure %g%s\n",
      capture_arg->c_str(), capture.gbuffer.width, capture.gbuffer.height, stride, images.front().width,
      images.front().height, vsgl_count, shading_visibility_text(visibility).c_str(), shading_model_text().c_str(),
      static_cast<double>(exposure),
      auto_exposed ? (" (auto: 99th-percentile luminance of " + generators.front()->name + " -> 0.8)").c_str() : "");
  for (std::size_t i = 0; i < generators.size(); ++i) {
    const auto path = out_dir / ("shade_" + capture.meta.scene + "_" + generators[i]->name + ".png");
    write_png_atomic(path, pictures[i]);
    std::printf("wrote %s\n", path_text(path).c_str());
  }
  return session.finish(0);
}

}  // namespace

Command add_shade_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "shade",
      "the camera view lit by each generator's light-view VSGLs (indirect light only) with the visibility "
      "--visibility names, as OUT/shade_<scene>_<generator>.png, like the paper's Fig. 5");
  auto o = std::make_shared<ShadeOptions>();
  app->add_option("--capture", o->capture, "capture directory (written by `vsgl-bench record`)")
      ->required()
      ->type_name("DIR");
  add_generators_option(*app, o->generators, joined_names(o->generators));
  app->add_option("--vsgls", o->vsgls, "light-view VSGLs per generator")->check(at_least(1))->capture_default_str();
  app->add_option("--stride", o->stride, "shade every K-th G-buffer pixel (K > 1: a quick preview)")
      ->check(at_least(1))
      ->capture_default_str();
  app->add_option("--exposure", o->exposure, "linear scale before the sRGB curve")
      ->check(positive_number())
      ->default_str("auto: 99th-percentile luminance -> 0.8");
  app->add_option("--visibility", o->visibility,
                  "what each VSGL's light passes (DESIGN.md §8.1): ism (its imperfect shadow map, as the "
                  "paper shades), exact (the segment to its mean through a BVH of the scene: the control) "
                  "or none; ism and exact need the visibility geometry `record` stores (--visibility-points)")
      ->check(one_of({"none", "ism", "exact"}))
      ->capture_default_str();
  o->ism_options = {
      app->add_option("--ism-side", o->ism.side, "texels per side of each imperfect shadow map (--visibility ism)")
          ->check(
              checked_number<uint32_t>([](uint32_t v) { return v >= 2 && v <= kIsmMaxSide && std::has_single_bit(v); },
                                       "a power of two in [2, " + std::to_string(kIsmMaxSide) + "]"))
          ->capture_default_str(),
      app->add_option("--ism-points-per-map", o->ism.points_per_map,
                      "points of the capture's sampling each map splats, at most the points it holds")
          ->check(at_least(1))
          ->capture_default_str(),
      app->add_option("--ism-bias", o->ism.depth_bias,
                      "relative depth bias: a map texel occludes where its depth is below (1 - bias) x the receiver's "
                      "distance")
          ->check(checked_number<float>([](float v) { return v >= 0.0f && v < 1.0f; }, "a number in [0, 1)"))
          ->capture_default_str(),
      app->add_option("--ism-normal-offset", o->ism.normal_offset,
                      "texel widths (at the receiver's distance) the receiver moves along its normal before the lookup")
          ->check(checked_number<float>([](float v) { return std::isfinite(v) && v >= 0.0f; }, "a finite number >= 0"))
          ->capture_default_str(),
      app->add_option("--ism-pcf-radius", o->ism.pcf_radius, "the lookup averages (2R + 1)^2 taps")
          ->check(checked_number<uint32_t>([](uint32_t v) { return v <= kIsmMaxPcfRadius; },
                                           "a whole number in [0, " + std::to_string(kIsmMaxPcfRadius) + "]"))
          ->capture_default_str(),
  };
  add_pyramid_option(*app, o->config.pyramid);
  add_mipmapping_option(*app, o->config.mipmapping, "FIS texture path's mip chain: single-pass, blit or per-level");
  app->add_option("--out", o->out, "output directory")->type_name("DIR")->capture_default_str();
  add_device_options(*app, o->device);
  return {app, [o] { return run_shade(*o); }};
}

}  // namespace vsgl::cli
