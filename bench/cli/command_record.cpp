// `vsgl-bench record`: rasterize a procedural scene or a user's glTF 2.0 file into a capture
// (DESIGN.md §3) and write it.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <algorithm>
#include <memory>

#include "bench/cli/option_types.hpp"
#include "harness/core/path_text.hpp"
#include "harness/scene/brsm_pdf.hpp"

#include "bench/cli/commands.hpp"
#include "bench/cli/gpu_session.hpp"
#include "harness/core/error.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/scene/capture_provisioning.hpp"
#include "harness/scene/named_scene.hpp"
#include "harness/scene/gltf_scene.hpp"
#include "harness/scene/model_scene.hpp"
#include "harness/scene/scene_preset.hpp"

namespace vsgl::cli {
namespace {

std::uintmax_t directory_bytes(const std::filesystem::path& dir) {
  std::uintmax_t total = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.is_regular_file()) total += e.file_size();
  return total;
}

// "X,Y,Z" (or, where `scalar_ok`, one number for all three).
CLI::Validator vec3_text(bool scalar_ok) {
  return CLI::Validator(
      [scalar_ok](std::string& text) -> std::string {
        const auto parts = split_list(text);
        const bool counted = parts.size() == 3 || (scalar_ok && parts.size() == 1);
        bool numbers = counted && std::count(text.begin(), text.end(), ',') + 1 == static_cast<long>(parts.size());
        for (const auto& p : parts) {
          std::size_t used = 0;
          float f = 0.0f;
          try {
            f = std::stof(p, &used);
          } catch (const std::exception&) {
            used = 0;
          }
          numbers = numbers && used == p.size() && std::isfinite(f);
        }
        if (!numbers) return std::string("takes X,Y,Z") + (scalar_ok ? " or one number" : "") + ", not '" + text + "'";
        return {};
      },
      scalar_ok ? "X,Y,Z|V" : "X,Y,Z");
}

glm::vec3 parse_vec3(const std::string& text) {
  const auto parts = split_list(text);
  if (parts.size() == 1) return glm::vec3(std::stof(parts[0]));
  return glm::vec3(std::stof(parts[0]), std::stof(parts[1]), std::stof(parts[2]));
}

CLI::Option* add_vec3_option(CLI::App& app, const std::string& name, std::optional<glm::vec3>& target,
                             const std::string& description, bool scalar_ok = false) {
  return app.add_option_function<std::string>(name, [&target](const std::string& t) { target = parse_vec3(t); },
                                              description)
      ->check(vec3_text(scalar_ok));
}

struct RecordOptions {
  std::optional<std::string> gltf, model;
  std::vector<std::string> scenes;
  std::vector<std::string> assets;
  std::optional<std::string> out;
  std::pair<uint32_t, uint32_t> gbuffer{1920, 1088};
  uint32_t rsm = 512;
  bool sizes_given = false;  // --gbuffer or --rsm: else a preset's own sizes
  uint32_t frames = 1;
  // Points of the visibility geometry; unset: kDefaultVisibilityPoints for one frame, none for a
  // sequence (its frames share the scene's triangles, and 28 MiB a frame adds up).
  std::optional<uint32_t> visibility_points;
  bool ground = false;
  GltfCameraChoice camera;
  GltfLightChoice light;
  DeviceOptions device;
};

void print_recorded(const std::string& name, const std::filesystem::path& dir, uint32_t f, uint32_t frames,
                    const RecordSizes& sizes, const RecordedCapture& r) {
  const std::optional<PyramidPath>& path = r.capture.meta.brsm_pyramid;
  std::printf(
      "recorded %s frame %u/%u -> %s  (G-buffer %ux%u, RSM %u^2; render + BRSM PDF %.0f ms, of which "
      "BRSM PDF %.1f ms GPU from %u camera VSGLs on the %s pyramid; write %.0f ms; %.1f MiB on disk)\n",
      name.c_str(), f + 1, frames, path_text(dir).c_str(), sizes.gbuffer_width, sizes.gbuffer_height, sizes.rsm_size,
      r.render_and_brsm_ms, r.brsm_gpu_ms, r.brsm_camera_vsgls, path ? pyramid_path_name(*path) : "unrecorded",
      r.write_ms, static_cast<double>(directory_bytes(dir)) / (1 << 20));
  if (const auto& g = r.capture.meta.visibility_geometry)
    std::printf("  visibility geometry: %llu triangles, %llu points (%s)\n",
                static_cast<unsigned long long>(g->triangles), static_cast<unsigned long long>(g->points),
                g->hash.c_str());
}

std::filesystem::path frame_dir(const std::filesystem::path& base, uint32_t f, uint32_t frames) {
  if (frames == 1) return base;
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04u", f);
  return base / name;
}

void print_import(const GltfImport& import, double import_ms) {
  std::printf("imported %s: %llu triangles, %zu materials, %zu textures in %.0f ms; content %s\n", import.file.c_str(),
              static_cast<unsigned long long>(import.triangles), import.scene.materials.size(),
              import.scene.textures.size(), import_ms, import.content_hash.c_str());
  std::printf("  camera: %s\n  light: %s\n", import.camera_source.c_str(), import.light_source.c_str());
  for (const std::string& note : import.notes) std::printf("  note: %s\n", note.c_str());
}

uint32_t visibility_points(const RecordOptions& o) {
  return o.visibility_points.value_or(o.frames == 1 ? kDefaultVisibilityPoints : 0u);
}

// A user's file (--model, --gltf): its frames recorded into OUT or captures/<its scene name>.
int record_model_file(RecordOptions& o, GpuSession& session, const std::string& file, bool any_format) {
  const RecordSizes sizes{o.gbuffer.first, o.gbuffer.second, o.rsm, visibility_points(o)};
  const auto t0 = std::chrono::steady_clock::now();
  const GltfImport import = any_format ? import_model(path_from_utf8(file), o.camera, o.light, o.ground)
                                       : import_gltf(path_from_utf8(file), o.camera, o.light, o.ground);
  print_import(import, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  std::string ext = path_from_utf8(file).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  // The file by its name in the directory it was given in (DESIGN.md §3.4): the content hash
  // identifies the model, and where it lay is the machine's, not the capture's.
  const std::string name = printable_text(path_from_utf8(file).filename().string(), std::string_view::npos);
  const SceneSource source{ext == ".obj" ? "obj" : "gltf",
                           name,
                           import.content_hash,
                           static_cast<uint32_t>(import.triangles),
                           import.camera_source,
                           import.light_source};
  const std::filesystem::path base =
      o.out ? path_from_utf8(*o.out) : std::filesystem::path("captures") / import.scene.name;
  for (uint32_t f = 0; f < o.frames; ++f) {
    const auto dir = frame_dir(base, f, o.frames);
    RecordedCapture r;
    try {
      r = record_capture(session.device(), gltf_frame(import, f, o.frames), sizes, f, o.frames, dir, source);
    } catch (const InputError& e) {
      const std::string what = e.what();
      if (what.find("BRSM PDF") == std::string::npos || o.ground) throw;
      // A lone convex model lights nothing of itself: say what helps.
      throw InputError(what +
                       " (a single convex object receives no indirect light from itself: add a floor with "
                       "--ground, or move the light with --light-pos/--light-dir)");
    }
    print_recorded(import.scene.name, dir, f, o.frames, sizes, r);
  }
  return session.finish(0);
}

int run_record(RecordOptions& o) {
  // Every named scene is resolved (presets read, models found) before the device is opened, so a
  // missing model is an input error that writes nothing.
  const SceneLibrary library = default_scene_library(paths_from_utf8(o.assets));
  const auto names = o.scenes.empty() ? std::vector<std::string>{"atrium"} : o.scenes;
  if (!o.gltf && !o.model)
    for (const auto& name : names)
      if (!is_named_scene(name, library)) (void)load_named_scene(name, library);  // throws listing the scenes
  GpuSession session = GpuSession::open(o.device);
  if (o.gltf) return record_model_file(o, session, *o.gltf, false);
  if (o.model) return record_model_file(o, session, *o.model, true);
  for (const auto& name : names) {
    const NamedScene scene = load_named_scene(name, library);
    if (scene.import) {
      std::printf("scene %s: %s\n", name.c_str(), scene.preset->description.c_str());
      print_import(*scene.import, scene.import_ms);
    }
    RecordSizes sizes =
        o.sizes_given || !scene.preset ? RecordSizes{o.gbuffer.first, o.gbuffer.second, o.rsm} : scene.default_sizes;
    sizes.visibility_points = visibility_points(o);
    const std::filesystem::path base = o.out ? path_from_utf8(*o.out) : std::filesystem::path("captures") / name;
    for (uint32_t f = 0; f < o.frames; ++f) {
      const auto dir = frame_dir(base, f, o.frames);
      // The one recording path, shared with `tables` (harness/scene/capture_provisioning.hpp).
      const RecordedCapture r = record_scene_capture(session.device(), scene, sizes, f, o.frames, dir);
      print_recorded(name, dir, f, o.frames, sizes, r);
    }
  }
  return session.finish(0);
}

}  // namespace

Command add_record_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "record",
      "rasterize a procedural scene or a glTF 2.0 file into a capture (real graphics pipeline, 5 render targets): "
      "G-buffer and RSM as OpenEXR + a JSON sidecar with the camera, the light and a hash of every channel; "
      "builds the BRSM PDF of the RSM from " + std::to_string(kBrsmCameraVsgls) + " camera-view VSGLs");
  auto o = std::make_shared<RecordOptions>();
  std::string presets;
  for (const auto& name : scene_preset_names(built_in_scene_presets())) presets += (presets.empty() ? "" : ", ") + name;
  auto* scene = add_list_option(*app, "--scene", o->scenes,
                                "scene(s): the paper's scenes as presets (" + presets +
                                    "; models found through --assets) or the procedural stand-ins atrium (Table 1), "
                                    "conference (Table 2), tiny (tests)",
                                CLI::Validator([](std::string&) { return std::string(); }, "NAME"))
                    ->default_str("atrium");
  auto* model = add_optional(*app, "--model", o->model,
                             "a scene file instead: glTF 2.0 (.gltf, .glb) or Wavefront OBJ + MTL (.obj) "
                             "(docs/scenes.md, \"Your own scenes\")")
                    ->check(input_file("--model"))
                    ->excludes(scene);
  auto* gltf = add_optional(*app, "--gltf", o->gltf,
                            "a glTF 2.0 file (.gltf or .glb) instead: its default scene, materials, textures and "
                            "normal maps (docs/scenes.md, \"Your own scenes\")")
                   ->check(input_file("--gltf"))
                   ->excludes(scene)
                   ->excludes(model);
  add_assets_option(*app, o->assets)->excludes(model)->excludes(gltf);
  add_optional(*app, "--out", o->out, "capture directory (one scene)")->default_str("captures/NAME; glTF: its scene name");
  CLI::Option* gbuffer = add_size_option(*app, "--gbuffer", o->gbuffer, "G-buffer size (a preset: its own)");
  CLI::Option* rsm =
      app->add_option("--rsm", o->rsm, "RSM size N x N (a preset: its own)")->check(at_least(1))->capture_default_str();
  app->add_option("--frames", o->frames, "animated sequence of F frames (moving light and camera) in DIR/frame_NNNN")
      ->check(at_least(1))
      ->capture_default_str();
  add_optional(*app, "--visibility-points", o->visibility_points,
               "points of the scene's surface stored with the capture for shading with visibility, beside its "
               "triangles (DESIGN.md §8a; 0: none, and such a capture shades with --visibility none only)")
      ->default_str(std::to_string(kDefaultVisibilityPoints) + " for one frame, 0 for --frames > 1");
  CLI::App* view = app->add_option_group("glTF view", "camera and light of a --gltf file");
  std::vector<CLI::Option*> gltf_only{
      add_optional(*view, "--camera", o->camera.camera, "the file's camera, by name or index")
          ->default_str("the file's first, else an automatic framing"),
      add_vec3_option(*view, "--eye", o->camera.eye, "a camera given here: its position"),
      add_vec3_option(*view, "--look-at", o->camera.look_at, "... the point it looks at"),
      add_optional(*view, "--fov", o->camera.fov_y_deg, "... its vertical field of view in degrees")
          ->check(CLI::Validator(
              [](std::string& t) {
                float f = -1.0f;
                if (!CLI::detail::lexical_cast(t, f)) f = -1.0f;
                return f > 0.0f && f < 179.0f ? std::string() : "must lie in (0, 179) degrees, not " + t;
              },
              "(0, 179)")),
      add_vec3_option(*view, "--light-pos", o->light.position,
                      "the spot light's position (replaces that of the file's first KHR_lights_punctual spot, else "
                      "of a spot placed above the bounds)"),
      add_vec3_option(*view, "--light-dir", o->light.direction, "... its direction"),
      add_optional(*view, "--cone", o->light.cone_half_angle_deg, "... its cone half-angle in degrees")
          ->check(positive_number()),
      add_vec3_option(*view, "--intensity", o->light.intensity, "... its intensity in W/sr (one value or R,G,B)",
                      /*scalar_ok=*/true)
          ->check(CLI::Validator([](std::string& t) {
                    for (const auto& p : split_list(t))
                      if (std::stof(p) < 0.0f) return std::string("must not be negative");
                    return std::string();
                  }, "")),
      view->add_flag("--ground", o->ground,
                     "add a grey floor under the model (a lone convex model has no indirect light: its BRSM PDF is "
                     "zero)"),
  };
  for (CLI::Option* option : gltf_only) option->excludes(scene);
  add_device_options(*app, o->device);
  return {app, [o, gbuffer, rsm, gltf_only] {
            if (o->scenes.size() > 1 && o->out)
              throw UsageError("--out names one capture directory, and several scenes were given: leave --out out "
                               "(each scene goes to captures/NAME) or record the scenes one at a time");
            o->sizes_given = gbuffer->count() > 0 || rsm->count() > 0;
            if (!o->gltf && !o->model)
              for (const CLI::Option* option : gltf_only)
                if (option->count() > 0)
                  throw UsageError(option->get_name() +
                                   " sets the view of a scene file: it needs --model or --gltf (a "
                                   "named scene's camera and light are its own)");
            return run_record(*o);
          }};
}

}  // namespace vsgl::cli
