#pragma once
// A user's glTF 2.0 file (.gltf with external or embedded buffers, or .glb) as a Scene (DESIGN.md §3),
// imported with Debian's tinygltf: every triangle mesh of the default scene with its node
// transforms, metallic-roughness materials with their base-colour, metallic-roughness and
// normal textures, alpha-mask cut-outs, double-sided materials; the camera and the spot light
// from the file, from the command line, or placed automatically around the scene's bounds.
// Not mapped: emissive, occlusion, transmission, clearcoat, sheen and the other material
// extensions, KHR_texture_transform, texture coordinates other than TEXCOORD_0, skins, morph
// targets and animations (the rest pose is drawn), point and directional lights.
//
// A malformed file is an InputError naming the file and the problem: not glTF 2.0, unreadable or
// missing buffers and images, accessors out of their buffers, indices out of range, non-finite
// positions, a primitive whose vertex count is not a whole number of triangles, node cycles, no
// triangles at all. File-derived names in messages are escaped (escape_name).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "harness/scene/scene.hpp"

namespace vsgl {

// How the camera is chosen; the default is the file's first camera, else automatic framing.
struct GltfCameraChoice {
  std::optional<std::string> camera;  // --camera NAME|INDEX: a camera of the file
  std::optional<glm::vec3> eye;       // --eye/--look-at/--fov: a camera given here
  std::optional<glm::vec3> look_at;
  std::optional<float> fov_y_deg;
};

// How the spot light is chosen; the default is the file's first KHR_lights_punctual spot, else an
// automatic spot above the centre of the bounds. Given values replace those of that light.
struct GltfLightChoice {
  std::optional<glm::vec3> position;   // --light-pos
  std::optional<glm::vec3> direction;  // --light-dir
  std::optional<float> cone_half_angle_deg;  // --cone
  std::optional<glm::vec3> intensity;  // --intensity (W/sr)
};

struct GltfImport {
  Scene scene;                 // frame 0; gltf_frame() animates it
  SceneMotion motion;          // scaled to the scene's bounds
  std::string file;            // the file's name as given (escaped)
  std::string content_hash;    // "fnv1a64:<16 hex>" over the file, its buffers and its decoded images
  uint64_t triangles = 0;
  glm::vec3 bounds_lo{0.0f}, bounds_hi{0.0f};
  std::string camera_source;   // which camera was used, in words
  std::string light_source;    // which light was used, in words
  std::vector<std::string> notes;  // what the file has that is not mapped or was repaired
};

// Loads and converts the file. With `ground` (--ground) a grey floor is added under the bounds:
// a single convex object receives no indirect light from itself (its BRSM PDF is zero), so a
// lone model needs something to bounce light onto. Throws InputError (bad file, bad choice) or
// UsageError (a choice that contradicts itself, e.g. --camera with --eye).
GltfImport import_gltf(const std::filesystem::path& file, const GltfCameraChoice& camera = {},
                       const GltfLightChoice& light = {}, bool ground = false);

// Frame `frame` of `frames` of the imported scene (camera and light moving as for the procedural
// scenes); frame 0 is the imported scene itself.
Scene gltf_frame(const GltfImport& import, uint32_t frame, uint32_t frames);

// A name from a file as it may appear in a message: printable ASCII as is, every other byte as
// \xNN, at most 80 bytes (then "...").
// core/printable_text, cut at 80 bytes: names are shown in one-line messages.
std::string escape_name(const std::string& name);

// A scene name usable as a file name (tables writes OUT/<scene>.json): letters, digits, '-', '_'
// and '.' kept, everything else '_', never empty, never "." or "..".
std::string scene_name_from_file(const std::filesystem::path& file);

}  // namespace vsgl
