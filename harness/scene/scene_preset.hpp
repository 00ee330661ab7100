#pragma once
// A named scene as data (DESIGN.md §3.4): one JSON file per scene in harness/scene/presets/, naming
// the model file to load (found through the asset search path, asset_search.hpp), the camera, the
// spot light, the default sizes and the motion of a sequence (--frames). The paper's scenes are
// presets: sponza (Table 1), conference-room (Table 2) and sibenik (Fig. 5 only, no table); the
// files are built into the program (core/embedded_files.hpp), so a scene is added by adding a file
// there and rebuilding.
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
  uint32_t paper_table = 0;  // the paper table this scene reproduces (1, 2), 0 for none (sibenik)
  // Candidate model paths, relative to an asset directory, in order of preference (.gltf, .glb
  // or .obj); the first found is loaded.
  std::vector<std::string> model;
  std::string where_to_get;    // what a user who lacks the model should fetch, and from where
  GltfCameraChoice camera;     // eye, look-at and field of view (all given)
  GltfLightChoice light;       // position, direction, cone, intensity (all given)
  RecordSizes sizes;           // the default G-buffer and RSM sizes
  SceneMotion motion;          // how --frames moves the light and the camera
  std::string origin;          // where the preset was read from: a file, or "... (built in)"
};

// A preset file before it is parsed: its name (the file's stem), where it came from and its text.
struct ScenePresetFile {
  std::string name;
  std::string origin;  // a path, or "harness/scene/presets/NAME.json (built in)"
  std::string text;
};

// Checks and reads one preset. Throws InputError naming its origin and the key for text that is
// not JSON, a missing, mistyped or unknown key, a name that is not the file's stem, an empty model
// list, a model path that is absolute or climbs out of its asset directory (".."), a non-positive
// size, a field of view outside (0, 179) degrees, a zero direction, a cone outside (0, 90) degrees,
// or a negative intensity.
ScenePreset parse_scene_preset(const ScenePresetFile& file);
// The same for a file on disk (InputError also when it cannot be read).
ScenePreset read_scene_preset(const std::filesystem::path& file);

// The presets built into the program (harness/scene/presets/*.json), sorted by name.
std::vector<ScenePresetFile> built_in_scene_presets();
// The presets in `dir` (every NAME.json), sorted by name; none when `dir` does not exist.
std::vector<ScenePresetFile> scene_preset_files(const std::filesystem::path& dir);

std::vector<std::string> scene_preset_names(const std::vector<ScenePresetFile>& presets);

// The preset NAME of `presets`, parsed. Throws InputError when there is none, listing the presets
// and the procedural scenes.
ScenePreset find_scene_preset(const std::vector<ScenePresetFile>& presets, const std::string& name);

}  // namespace vsgl
