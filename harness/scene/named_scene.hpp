#pragma once
// A scene chosen by name (`record --scene NAME`, the tables' inputs): one of the procedural scenes
// (scene.hpp), or a scene preset (scene_preset.hpp) whose model is found through the asset search
// path (asset_search.hpp) and imported. Either way it yields the frames to record and, for a
// preset, the SceneSource its captures' sidecars name.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "harness/capture/capture.hpp"
#include "harness/scene/asset_search.hpp"
#include "harness/scene/capture_recorder.hpp"
#include "harness/scene/gltf_scene.hpp"
#include "harness/scene/scene_preset.hpp"

namespace vsgl {

// Where named scenes come from: the presets (none by default) and where their models are looked for.
struct SceneLibrary {
  std::vector<ScenePresetFile> presets;
  AssetSearch assets;
};

// What the programs use (DESIGN.md §3.4): the presets built in, the models found through
// --assets (`assets`), VSGL_ASSETS and assets/ in the current directory.
SceneLibrary default_scene_library(const std::vector<std::filesystem::path>& assets);

struct NamedScene {
  std::string name;
  std::optional<ScenePreset> preset;  // none: a procedural scene
  std::optional<GltfImport> import;   // the preset's model, imported with its camera and light
  std::optional<SceneSource> source;  // what the sidecar says of the preset's model
  RecordSizes default_sizes;          // the preset's; the recorder's defaults for procedural scenes
  double import_ms = 0;

  // Frame `frame` of `frames`, the camera and light moving with the preset's (or the procedural
  // scene's) motion; frame 0 is the scene as declared.
  Scene frame(uint32_t frame, uint32_t frames) const;
};

// True when `name` is a procedural scene or a preset of the library (nothing is loaded).
bool is_named_scene(const std::string& name, const SceneLibrary& library);

// Loads the scene: a procedural scene at once, a preset by reading it, finding its model and
// importing it. Throws InputError for an unknown name (listing the scenes), a bad preset, a
// missing model (listing every place looked, find_preset_model) or a bad model file.
NamedScene load_named_scene(const std::string& name, const SceneLibrary& library);

// Why a capture on disk is not one of `scene` at `sizes` (another scene, size, model content,
// camera or light), in words; empty when it is.
std::string capture_staleness(const CaptureMeta& meta, uint32_t gbuffer_width, uint32_t gbuffer_height,
                              uint32_t rsm_size, const NamedScene& scene, const RecordSizes& sizes);

}  // namespace vsgl
