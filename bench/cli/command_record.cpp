// `vsgl-bench record`: rasterize a procedural scene into a capture (SPEC §3) and write it.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "bench/cli/commands.hpp"
#include "bench/cli/gpu_session.hpp"
#include "harness/brsm_pdf.hpp"
#include "harness/capture_recorder.hpp"
#include "harness/error.hpp"
#include "harness/scene.hpp"

namespace vsgl::cli {
namespace {

std::vector<std::string> split_commas(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

std::uintmax_t directory_bytes(const std::filesystem::path& dir) {
  std::uintmax_t total = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.is_regular_file()) total += e.file_size();
  return total;
}

}  // namespace

int run_record(Args& args) {
  const auto scenes = split_commas(args.string("--scene", "atrium"));
  const auto out_arg = args.value("--out");
  const auto gbuffer = args.size("--gbuffer", {1920, 1088});
  const uint32_t rsm = args.u32("--rsm", 512, 1);
  const uint32_t frames = args.u32("--frames", 1, 1);
  GpuSession session = GpuSession::open(args);
  args.finish();
  if (scenes.empty()) throw UsageError("--scene needs a scene name");
  if (scenes.size() > 1 && out_arg)
    throw UsageError("with several scenes, --out names a parent directory: use --out-root instead");

  CaptureRecorder recorder(session.device());
  const RecordSizes sizes{gbuffer.first, gbuffer.second, rsm};
  for (const auto& name : scenes) {
    const std::filesystem::path base = out_arg ? std::filesystem::path(*out_arg) : std::filesystem::path("captures") / name;
    for (uint32_t f = 0; f < frames; ++f) {
      char frame_dir[32];
      std::snprintf(frame_dir, sizeof frame_dir, "frame_%04u", f);
      const auto dir = frames == 1 ? base : base / frame_dir;
      const auto t0 = std::chrono::steady_clock::now();
      const Scene scene = make_scene(name, f, frames);
      Capture capture = recorder.record(scene, sizes, f, frames);
      const BrsmBuild brsm = build_brsm_pdf(session.device(), capture);  // SPEC §8: once per capture
      const auto t1 = std::chrono::steady_clock::now();
      write_capture(capture, dir);
      const auto t2 = std::chrono::steady_clock::now();
      const auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
      std::printf("recorded %s frame %u/%u -> %s  (G-buffer %ux%u, RSM %u^2; render + BRSM PDF %.0f ms, of which "
                  "BRSM PDF %.1f ms GPU from %u camera VSGLs; write %.0f ms; %.1f MiB on disk)\n",
                  name.c_str(), f + 1, frames, dir.string().c_str(), sizes.gbuffer_width, sizes.gbuffer_height,
                  sizes.rsm_size, ms(t0, t1), brsm.gpu_ms, brsm.camera_vsgls, ms(t1, t2),
                  static_cast<double>(directory_bytes(dir)) / (1 << 20));
    }
  }
  return session.finish(0);
}

}  // namespace vsgl::cli
