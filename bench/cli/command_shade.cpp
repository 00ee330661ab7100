// `vsgl-bench shade`: the camera view of a capture lit by the N light-view VSGLs of each listed
// generator, without visibility (indirect light only, no occlusion, no direct spot light), written
// as OUT/shade_<scene>_<generator>.png, so a user can see what each generator produces (the 2016
// paper's Fig. 5). One exposure serves every picture of a run, so they compare directly.
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bench/cli/commands.hpp"
#include "bench/cli/gpu_session.hpp"
#include "harness/capture.hpp"
#include "harness/command_stream.hpp"
#include "harness/device_view.hpp"
#include "harness/error.hpp"
#include "harness/fis_generator.hpp"
#include "harness/png_image.hpp"
#include "harness/shading_pass.hpp"
#include "harness/vsgl_generator.hpp"

namespace vsgl::cli {
namespace {

constexpr uint32_t kLightViewVsgls = 1024;  // the paper's N for the light view (SPEC §2)

// The generators `shade` can run on the light view, by name. A new generator is one more row.
struct LightGenerator {
  std::string name;
  std::function<std::unique_ptr<VsglGenerator>(Device&, const DeviceView&, uint32_t vsgl_count)> make;
};

std::unique_ptr<VsglGenerator> make_fis(Device& device, const DeviceView& view, FisVariant variant, uint32_t count) {
  FisParams params;
  params.vsgl_count = count;
  return std::make_unique<FisGenerator>(device, view, variant, params);
}

const std::vector<LightGenerator>& light_generators() {
  static const std::vector<LightGenerator> table = {
      {"fis_tok15", [](Device& d, const DeviceView& v, uint32_t n) { return make_fis(d, v, FisVariant::kTok15, n); }},
      {"fis_modified",
       [](Device& d, const DeviceView& v, uint32_t n) { return make_fis(d, v, FisVariant::kModified, n); }},
  };
  return table;
}

const LightGenerator& find_generator(const std::string& name) {
  std::string known;
  for (const auto& g : light_generators()) {
    if (g.name == name) return g;
    known += (known.empty() ? "" : ", ") + g.name;
  }
  throw UsageError("--generators: unknown generator '" + name + "' (known: " + known + ")");
}

}  // namespace

int run_shade(Args& args) {
  const auto capture_arg = args.value("--capture");
  const auto names = args.list("--generators", "fis_tok15,fis_modified");
  const uint32_t stride = args.u32("--stride", 1, 1);
  const uint32_t vsgl_count = args.u32("--vsgls", kLightViewVsgls, 1);
  const std::filesystem::path out_dir = args.string("--out", ".");
  float exposure = args.positive_float("--exposure", 0.0f);  // 0: not given, expose automatically
  GpuSession session = GpuSession::open(args);
  args.finish();
  if (!capture_arg) throw UsageError("shade needs --capture DIR (a capture written by `vsgl-bench record`)");
  if (names.empty()) throw UsageError("--generators needs at least one generator name");
  std::vector<const LightGenerator*> generators;
  for (const auto& name : names) generators.push_back(&find_generator(name));

  const Capture capture = load_capture(*capture_arg);
  Device& device = session.device();
  const DeviceView camera = upload_view(device, capture, ViewKind::kCamera);
  const DeviceView light = upload_view(device, capture, ViewKind::kLight);

  // Everything is computed and checked before the first file is written (SPEC §12).
  std::vector<RadianceImage> images;
  for (const LightGenerator* g : generators) {
    auto generator = g->make(device, light, vsgl_count);
    run_untimed(device, *generator);
    images.push_back(shade_camera_view(device, camera, generator->vsgls(), generator->vsgl_count(), stride));
  }
  const bool auto_exposed = exposure == 0.0f;
  if (auto_exposed) exposure = auto_exposure(images.front());
  std::vector<Rgb8Image> pictures;
  for (const auto& image : images) pictures.push_back(tone_map(image, exposure));

  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw InputError(out_dir.string() + ": cannot create the output directory (" + ec.message() + ")");
  std::printf("shading %s (G-buffer %ux%u, stride %u -> %ux%u) with %u light-view VSGLs per generator; "
              "no visibility (indirect light only); exposure %g%s\n",
              capture_arg->c_str(), capture.gbuffer.width, capture.gbuffer.height, stride, images.front().width,
              images.front().height, vsgl_count, static_cast<double>(exposure),
              auto_exposed ? (" (auto: 99th-percentile luminance of " + generators.front()->name + " -> 0.8)").c_str()
                           : "");
  for (std::size_t i = 0; i < generators.size(); ++i) {
    const auto path = out_dir / ("shade_" + capture.meta.scene + "_" + generators[i]->name + ".png");
    write_png_atomic(path, pictures[i]);
    std::printf("wrote %s\n", path.string().c_str());
  }
  return session.finish(0);
}

}  // namespace vsgl::cli
