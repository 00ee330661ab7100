#pragma once
// The procedural, deterministic scenes of SPEC §3: triangles with per-vertex materials, a camera
// and a spot light per frame. No downloads, no randomness beyond fixed seeds.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "harness/capture/capture.hpp"

namespace vsgl {

struct SceneVertex {
  glm::vec3 position;
  glm::vec3 normal;    // unit, outward (towards the side that is seen)
  glm::vec3 diffuse;   // diffuse albedo in [0,1]
  glm::vec3 specular;  // specular albedo in [0,1]
  float roughness;     // GGX alpha in (0,1]
};
static_assert(sizeof(SceneVertex) == 13 * sizeof(float));

struct SceneMesh {
  std::vector<SceneVertex> vertices;
  std::vector<uint32_t> indices;  // triangle list, counter-clockwise seen from the normal side
};

struct Scene {
  std::string name;
  SceneMesh mesh;
  CameraDesc camera;
  SpotLightDesc light;
};

// "atrium" (Table 1), "conference" (Table 2), "tiny" (tests). frame in [0, frames): with
// frames > 1 the light and the camera move along a short smooth path (temporal tests); frame 0
// of any sequence equals the static scene. Throws InputError for an unknown name.
Scene make_scene(const std::string& name, uint32_t frame = 0, uint32_t frames = 1);
std::vector<std::string> scene_names();

}  // namespace vsgl
