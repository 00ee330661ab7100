// `vsgl-bench record`: rasterize a procedural scene into a capture (SPEC §3) and write it.
#include <cstdio>
#include <filesystem>

#include "bench/cli/commands.hpp"
#include "bench/cli/gpu_session.hpp"
#include "harness/scene/capture_provisioning.hpp"
#include "harness/core/error.hpp"

namespace vsgl::cli {
namespace {

std::uintmax_t directory_bytes(const std::filesystem::path& dir) {
  std::uintmax_t total = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.is_regular_file()) total += e.file_size();
  return total;
}

}  // namespace

int run_record(Args& args) {
  const auto scenes = args.list("--scene", "atrium");
  const auto out_arg = args.value("--out");
  const auto gbuffer = args.size("--gbuffer", {1920, 1088});
  const uint32_t rsm = args.u32("--rsm", 512, 1);
  const uint32_t frames = args.u32("--frames", 1, 1);
  GpuSession session = GpuSession::open(args);
  args.finish();
  if (scenes.empty()) throw UsageError("--scene needs a scene name");
  if (scenes.size() > 1 && out_arg)
    throw UsageError("with several scenes, --out names a parent directory: use --out-root instead");

  const RecordSizes sizes{gbuffer.first, gbuffer.second, rsm};
  for (const auto& name : scenes) {
    const std::filesystem::path base = out_arg ? std::filesystem::path(*out_arg) : std::filesystem::path("captures") / name;
    for (uint32_t f = 0; f < frames; ++f) {
      char frame_dir[32];
      std::snprintf(frame_dir, sizeof frame_dir, "frame_%04u", f);
      const auto dir = frames == 1 ? base : base / frame_dir;
      // The one recording path, shared with `tables` (harness/scene/capture_provisioning.hpp).
      const RecordedCapture r = record_scene_capture(session.device(), name, sizes, f, frames, dir);
      std::printf("recorded %s frame %u/%u -> %s  (G-buffer %ux%u, RSM %u^2; render + BRSM PDF %.0f ms, of which "
                  "BRSM PDF %.1f ms GPU from %u camera VSGLs; write %.0f ms; %.1f MiB on disk)\n",
                  name.c_str(), f + 1, frames, dir.string().c_str(), sizes.gbuffer_width, sizes.gbuffer_height,
                  sizes.rsm_size, r.render_and_brsm_ms, r.brsm_gpu_ms, r.brsm_camera_vsgls, r.write_ms,
                  static_cast<double>(directory_bytes(dir)) / (1 << 20));
    }
  }
  return session.finish(0);
}

}  // namespace vsgl::cli
