#pragma once
// A named scene as data (DESIGN.md §3.4): one JSON file per scene in harness/scene/presets/, naming
// the model file to load (found through the asset search path, asset_search.hpp), the camera, the
// spot light, the default sizes and the motion of a sequence (--frames). The paper's two scenes,
// sponza (Table 1) and conference-room (Table 2), are presets; a user adds a scene by adding a file.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "harness/scene/capture_recorder.hpp"
#include "harness/scene/gltf_scene.hpp"
#include "harness/scene/scene.hpp"

namespace vsgl {

struct ScenePreset {
  std::string name;          // the file's stem: `record --scene NAME`
  std::string description;   // one line, for listings
  uint32_t paper_table = 0;  // the paper table this scene reproduces (1, 2), 0 for none
  // Candidate model paths, relative to an asset directory, in order of preference (.gltf, .glb
  // or .obj); the first found is loaded.
  std::vector<std::string> model;
  std::string where_to_get;    // what a user who lacks the model should fetch, and from where
  GltfCameraChoice camera;     // eye, look-at and field of view (all given)
  GltfLightChoice light;       // position, direction, cone, intensity (all given)
  RecordSizes sizes;           // the default G-buffer and RSM sizes
  SceneMotion motion;          // how --frames moves the light and the camera
  std::filesystem::path file;  // where the preset was read from
};

// Reads and checks one preset file. Throws InputError naming the file and the key for a missing,
// mistyped or unknown key, a name that is not the file's stem, an empty model list, a model path
// that is absolute or climbs out of its asset directory (".."), a non-positive size, a field of
// view outside (0, 179) degrees, a zero direction, a cone outside (0, 90) degrees, or a negative
// intensity.
ScenePreset read_scene_preset(const std::filesystem::path& file);

// The presets in `dir` (every NAME.json), sorted by name; an empty list when `dir` does not exist.
std::vector<std::string> scene_preset_names(const std::filesystem::path& dir);

// The preset NAME from `dir`. Throws InputError when there is none, listing the presets there and
// the procedural scenes.
ScenePreset find_scene_preset(const std::filesystem::path& dir, const std::string& name);

}  // namespace vsgl
