// `vsgl-bench shade`: the camera view of a capture lit by the N light-view VSGLs of each listed
// generator (indirect light only, no direct spot light), with the visibility --visibility names
// (DESIGN.md §8: the VSGLs' imperfect shadow maps by default, as the paper shades; none; or exact,
// the control), written as OUT/shade_<scene>_<generator>.png, so a user can see what each
// generator produces (the 2016 paper's Fig. 5). One exposure serves every picture of a run, so
// they compare directly.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/cli/commands.hpp"
#include "bench/cli/generator_options.hpp"
#include "bench/cli/gpu_session.hpp"
#include "bench/cli/visibility_options.hpp"
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
  VisibilityOptions visibility;
  GeneratorConfig config;
  DeviceOptions device;
};

int run_shade(ShadeOptions& o) {
  const std::string* capture_arg = &o.capture;
  const auto& names = o.generators;
  const uint32_t stride = o.stride;
  const uint32_t vsgl_count = o.vsgls;
  const std::filesystem::path out_dir = path_from_utf8(o.out);
  float exposure = o.exposure;
  GeneratorConfig& config = o.config;
  const ShadingVisibilitySettings visibility = visibility_settings(o.visibility);
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
  add_visibility_options(*app, o->visibility, "the pictures");
  add_pyramid_option(*app, o->config.pyramid);
  add_mipmapping_option(*app, o->config.mipmapping, "FIS texture path's mip chain: single-pass, blit or per-level");
  app->add_option("--out", o->out, "output directory")->type_name("DIR")->capture_default_str();
  add_device_options(*app, o->device);
  return {app, [o] { return run_shade(*o); }};
}

}  // namespace vsgl::cli
