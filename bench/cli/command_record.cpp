// `vsgl-bench record`: rasterize a procedural scene or a user's glTF 2.0 file into a capture
// (DESIGN.md §3) and write it.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "bench/cli/commands.hpp"
#include "bench/cli/gpu_session.hpp"
#include "harness/core/error.hpp"
#include "harness/scene/capture_provisioning.hpp"
#include "harness/scene/gltf_scene.hpp"

namespace vsgl::cli {
namespace {

std::uintmax_t directory_bytes(const std::filesystem::path& dir) {
  std::uintmax_t total = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.is_regular_file()) total += e.file_size();
  return total;
}

float parse_float(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  float f = 0.0f;
  try {
    f = std::stof(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(f)) throw UsageError(option + " takes numbers, not '" + text + "'");
  return f;
}

// "X,Y,Z" (or, where `scalar_ok`, one number for all three).
std::optional<glm::vec3> vec3_option(Args& args, const std::string& name, bool scalar_ok = false) {
  const auto v = args.value(name);
  if (!v) return std::nullopt;
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = v->find(',', start);
    parts.push_back(v->substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (parts.size() == 1 && scalar_ok) return glm::vec3(parse_float(name, parts[0]));
  if (parts.size() != 3) throw UsageError(name + " takes X,Y,Z" + (scalar_ok ? " or one number" : "") + ", not '" + *v + "'");
  return glm::vec3(parse_float(name, parts[0]), parse_float(name, parts[1]), parse_float(name, parts[2]));
}

std::optional<float> float_option(Args& args, const std::string& name) {
  const auto v = args.value(name);
  if (!v) return std::nullopt;
  return parse_float(name, *v);
}

void print_recorded(const std::string& name, const std::filesystem::path& dir, uint32_t f, uint32_t frames,
                    const RecordSizes& sizes, const RecordedCapture& r) {
  std::printf("recorded %s frame %u/%u -> %s  (G-buffer %ux%u, RSM %u^2; render + BRSM PDF %.0f ms, of which "
              "BRSM PDF %.1f ms GPU from %u camera VSGLs; write %.0f ms; %.1f MiB on disk)\n",
              name.c_str(), f + 1, frames, dir.string().c_str(), sizes.gbuffer_width, sizes.gbuffer_height,
              sizes.rsm_size, r.render_and_brsm_ms, r.brsm_gpu_ms, r.brsm_camera_vsgls, r.write_ms,
              static_cast<double>(directory_bytes(dir)) / (1 << 20));
}

std::filesystem::path frame_dir(const std::filesystem::path& base, uint32_t f, uint32_t frames) {
  if (frames == 1) return base;
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04u", f);
  return base / name;
}

}  // namespace

int run_record(Args& args) {
  const auto gltf = args.value("--gltf");
  const auto scene_list = args.list("--scene", "");
  const auto out_arg = args.value("--out");
  const auto gbuffer = args.size("--gbuffer", {1920, 1088});
  const uint32_t rsm = args.u32("--rsm", 512, 1);
  const uint32_t frames = args.u32("--frames", 1, 1);
  const bool ground = args.flag("--ground");
  GltfCameraChoice camera;
  GltfLightChoice light;
  camera.camera = args.value("--camera");
  camera.eye = vec3_option(args, "--eye");
  camera.look_at = vec3_option(args, "--look-at");
  camera.fov_y_deg = float_option(args, "--fov");
  light.position = vec3_option(args, "--light-pos");
  light.direction = vec3_option(args, "--light-dir");
  light.cone_half_angle_deg = float_option(args, "--cone");
  light.intensity = vec3_option(args, "--intensity", /*scalar_ok=*/true);
  if (camera.fov_y_deg && !(*camera.fov_y_deg > 0.0f && *camera.fov_y_deg < 179.0f))
    throw UsageError("--fov must lie in (0, 179) degrees");
  if (light.intensity && (light.intensity->r < 0.0f || light.intensity->g < 0.0f || light.intensity->b < 0.0f))
    throw UsageError("--intensity must not be negative");
  const bool view_options = camera.camera || camera.eye || camera.look_at || camera.fov_y_deg || light.position ||
                            light.direction || light.cone_half_angle_deg || light.intensity;
  if (gltf && !scene_list.empty()) throw UsageError("--gltf and --scene both name a scene: give one");
  if (!gltf && (view_options || ground))
    throw UsageError("--camera, --eye, --look-at, --fov, --ground and the --light options apply to --gltf files only");
  GpuSession session = GpuSession::open(args);
  args.finish();
  const RecordSizes sizes{gbuffer.first, gbuffer.second, rsm};

  if (gltf) {
    const auto t0 = std::chrono::steady_clock::now();
    const GltfImport import = import_gltf(*gltf, camera, light, ground);
    const double import_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::printf("imported %s: %llu triangles, %zu materials, %zu textures in %.0f ms; content %s\n", import.file.c_str(),
                static_cast<unsigned long long>(import.triangles), import.scene.materials.size(),
                import.scene.textures.size(), import_ms, import.content_hash.c_str());
    std::printf("  camera: %s\n  light: %s\n", import.camera_source.c_str(), import.light_source.c_str());
    for (const std::string& note : import.notes) std::printf("  note: %s\n", note.c_str());
    const SceneSource source{"gltf", import.file, import.content_hash, static_cast<uint32_t>(import.triangles),
                             import.camera_source, import.light_source};
    const std::filesystem::path base = out_arg ? std::filesystem::path(*out_arg)
                                               : std::filesystem::path("captures") / import.scene.name;
    for (uint32_t f = 0; f < frames; ++f) {
      const auto dir = frame_dir(base, f, frames);
      RecordedCapture r;
      try {
        r = record_capture(session.device(), gltf_frame(import, f, frames), sizes, f, frames, dir, source);
      } catch (const InputError& e) {
        const std::string what = e.what();
        if (what.find("BRSM PDF") == std::string::npos || ground) throw;
        // A lone convex model lights nothing of itself: say what helps.
        throw InputError(what + " (a single convex object receives no indirect light from itself: add a floor with "
                                "--ground, or move the light with --light-pos/--light-dir)");
      }
      print_recorded(import.scene.name, dir, f, frames, sizes, r);
    }
    return session.finish(0);
  }

  const auto scenes = scene_list.empty() ? std::vector<std::string>{"atrium"} : scene_list;
  if (scenes.size() > 1 && out_arg)
    throw UsageError("--out names one capture directory, and several scenes were given: leave --out out (each "
                     "scene goes to captures/NAME) or record the scenes one at a time");
  for (const auto& name : scenes) {
    const std::filesystem::path base = out_arg ? std::filesystem::path(*out_arg) : std::filesystem::path("captures") / name;
    for (uint32_t f = 0; f < frames; ++f) {
      const auto dir = frame_dir(base, f, frames);
      // The one recording path, shared with `tables` (harness/scene/capture_provisioning.hpp).
      const RecordedCapture r = record_scene_capture(session.device(), name, sizes, f, frames, dir);
      print_recorded(name, dir, f, frames, sizes, r);
    }
  }
  return session.finish(0);
}

}  // namespace vsgl::cli
