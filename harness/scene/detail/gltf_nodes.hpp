#pragma once
// glTF import, part 3 of 4: the node graph of the default scene (world matrices, cycles refused),
// the triangle meshes its nodes instance (converted into Conversion::scene.mesh), and the
// camera and the spot light, from the file, the command line or placed around the bounds.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "harness/scene/detail/gltf_accessors.hpp"
#include "harness/scene/detail/gltf_conversion.hpp"
#include "harness/scene/gltf_scene.hpp"

namespace vsgl::gltf {

struct NodeInstance {
  int node;
  glm::dmat4 world;
};

struct CameraInstance {
  int camera;  // index into model.cameras
  int node;
  glm::dmat4 world;
};

struct LightInstance {
  int light;  // index into model.lights
  int node;
  glm::dmat4 world;
};

// Every node of the default scene (else of the first scene, else every root node) with its world
// matrix; a node reached twice on one path (a cycle) is an error.
std::vector<NodeInstance> scene_nodes(const tinygltf::Model& m, const Reporter& r, std::vector<std::string>& notes);

// The cameras and lights the nodes carry, in node order.
struct NodeContents {
  std::vector<CameraInstance> cameras;
  std::vector<LightInstance> lights;
};

// Converts every mesh the nodes instance into conv.scene.mesh (world space, mirrored windings
// flipped, normals and tangents repaired) and collects their cameras and lights.
NodeContents convert_nodes(Conversion& conv, const Importer& imp, const std::vector<NodeInstance>& nodes);

// The converted geometry's extent, which the camera and light are placed and clipped by.
struct SceneBounds {
  glm::vec3 lo{0.0f}, hi{0.0f};  // the file's triangles
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
  glm::vec3 far_lo{0.0f}, far_hi{0.0f};  // with --ground: what the far planes must include
};

// The camera: --camera, else --eye/--look-at/--fov, else the file's first camera, else an
// automatic framing of the bounds. `source` says which, in words.
CameraDesc choose_camera(const Importer& imp, const std::vector<CameraInstance>& cameras,
                         const GltfCameraChoice& choice, const SceneBounds& b, std::string& source);

// The spot light: the file's first spot, else one above the centre of the bounds, with the
// command line's values applied. `source` says which, in words.
SpotLightDesc choose_light(const Importer& imp, const std::vector<LightInstance>& lights, const GltfLightChoice& choice,
                           const SceneBounds& b, std::string& source);

}  // namespace vsgl::gltf
