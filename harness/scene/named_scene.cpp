#include "harness/scene/named_scene.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "harness/capture/capture_files.hpp"
#include "harness/core/error.hpp"
#include "harness/core/platform_environment.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/scene/model_scene.hpp"

namespace vsgl {
namespace {

bool procedural(const std::string& name) {
  const auto names = scene_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string format_of(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".obj" ? "obj" : "gltf";
}

bool near(glm::vec3 a, glm::vec3 b) { return glm::length(a - b) <= 1e-5f * std::max(1.0f, glm::length(b)); }
bool near(float a, float b) { return std::abs(a - b) <= 1e-5f * std::max(1.0f, std::abs(b)); }

std::string size_text(uint32_t w, uint32_t h, uint32_t rsm) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "G-buffer %ux%u, RSM %u^2", w, h, rsm);
  return buf;
}

}  // namespace

Scene NamedScene::frame(uint32_t f, uint32_t frames) const {
  return import ? gltf_frame(*import, f, frames) : make_scene(name, f, frames);
}

SceneLibrary default_scene_library(const std::vector<std::filesystem::path>& assets) {
  const std::optional<std::string> env_assets = environment_variable("VSGL_ASSETS");
  return SceneLibrary{built_in_scene_presets(), make_asset_search(assets, env_assets ? env_assets->c_str() : nullptr)};
}

bool is_named_scene(const std::string& name, const SceneLibrary& library) {
  if (procedural(name)) return true;
  const auto presets = scene_preset_names(library.presets);
  return std::find(presets.begin(), presets.end(), name) != presets.end();
}

NamedScene load_named_scene(const std::string& name, const SceneLibrary& library) {
  NamedScene out;
  out.name = name;
  if (procedural(name)) return out;
  out.preset = find_scene_preset(library.presets, name);
  const FoundModel model = find_preset_model(*out.preset, library.assets);
  const auto t0 = std::chrono::steady_clock::now();
  out.import = import_model(model.file, out.preset->camera, out.preset->light);
  out.import_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  out.import->scene.name = name;  // captures and tables are named after the preset, not the file
  out.import->motion = out.preset->motion;
  out.default_sizes = out.preset->sizes;
  // The model as the preset names it, relative to its asset directory (DESIGN.md §3.4), so a
  // capture of it records the same file wherever the models lie; messages name the whole path.
  out.source = SceneSource{format_of(model.file),
                           printable_text(model.name, std::string_view::npos),
                           out.import->content_hash,
                           static_cast<uint32_t>(out.import->triangles),
                           "the scene preset " + name + ": " + out.import->camera_source,
                           "the scene preset " + name + ": " + out.import->light_source,
                           name,
                           out.preset->paper_table};
  return out;
}

std::string capture_staleness(const CaptureMeta& meta, uint32_t gbuffer_width, uint32_t gbuffer_height,
                              uint32_t rsm_size, const NamedScene& scene, const RecordSizes& sizes) {
  if (meta.scene != scene.name) return "it is of scene '" + meta.scene + "', not '" + scene.name + "'";
  if (gbuffer_width != sizes.gbuffer_width || gbuffer_height != sizes.gbuffer_height || rsm_size != sizes.rsm_size)
    return "it was recorded at " + size_text(gbuffer_width, gbuffer_height, rsm_size) + ", not " +
           size_text(sizes.gbuffer_width, sizes.gbuffer_height, sizes.rsm_size);
  if (meta.source.has_value() != scene.source.has_value())
    return meta.source ? "it was recorded from a model file, and the scene is procedural"
                       : "it is the procedural scene, and the scene now loads a model";
  if (scene.source && meta.source->content_hash != scene.source->content_hash)
    return "its model's content was " + meta.source->content_hash + ", and the model found now is " +
           scene.source->content_hash;
  if (meta.frame != 0 || meta.frames != 1) return "it is a frame of a sequence";
  if (std::string why = brsm_importance_mismatch(meta, /*rsm_has_pdf=*/true); !why.empty()) return why;
  const Scene now = scene.frame(0, 1);
  if (!near(meta.camera.position, now.camera.position) || !near(meta.camera.target, now.camera.target) ||
      !near(meta.camera.fov_y_deg, now.camera.fov_y_deg))
    return "its camera differs from the scene's";
  if (!near(meta.light.position, now.light.position) || !near(meta.light.direction, now.light.direction) ||
      !near(meta.light.cone_half_angle_deg, now.light.cone_half_angle_deg) ||
      !near(meta.light.intensity, now.light.intensity))
    return "its light differs from the scene's";
  return {};
}

}  // namespace vsgl
