#pragma once
// The scene model the recorder rasterizes (triangles, materials, textures, a camera and a spot
// light), and the procedural, deterministic scenes of DESIGN.md §3 built in it. No downloads, no
// randomness beyond fixed seeds.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "harness/capture/capture.hpp"

namespace vsgl {

// A vertex without a material (kNoMaterial) is drawn with its own constant albedos and
// roughness, exactly as the procedural scenes always were; a vertex with a material index takes
// its surface from Scene::materials (textures, normal map). A triangle's material is that of its
// first vertex.
inline constexpr uint32_t kNoMaterial = 0xFFFFFFFFu;

struct SceneVertex {
  glm::vec3 position;
  glm::vec3 normal;    // unit, outward (towards the side that is seen)
  glm::vec3 diffuse;   // diffuse albedo in [0,1]; with a metallic-roughness material: the vertex colour
  glm::vec3 specular;  // specular albedo in [0,1] (unused by metallic-roughness materials)
  float roughness;     // GGX alpha in (0,1] (unused by metallic-roughness materials)
  glm::vec2 uv{0.0f};  // texture coordinates (glTF TEXCOORD_0: origin top left, v down)
  // xyz: unit tangent along +u, w: handedness (bitangent = w * cross(normal, tangent)); only read
  // where the material has a normal map. compute_tangents() fills it when a file has none.
  glm::vec4 tangent{0.0f};
  uint32_t material = kNoMaterial;  // index into Scene::materials
};
static_assert(sizeof(SceneVertex) == 20 * sizeof(float));

struct SceneMesh {
  std::vector<SceneVertex> vertices;
  std::vector<uint32_t> indices;  // triangle list, counter-clockwise seen from the normal side
};

enum class TextureWrap : uint32_t { kRepeat, kClampToEdge, kMirroredRepeat };

// One texture as the scene provides it (decoded from a file, or generated procedurally): level 0
// only; the recorder builds the full mip chain (scene_textures.hpp) and samples it trilinearly.
// Exactly one of rgba8 / rgba32f holds width * height * 4 values, rows top to bottom.
struct TextureImage {
  std::string name;  // for debug names and messages
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba8;
  std::vector<float> rgba32f;
  bool srgb = false;  // rgba8 is sRGB-encoded colour (base colour maps); filtered in linear space
  TextureWrap wrap_u = TextureWrap::kRepeat;
  TextureWrap wrap_v = TextureWrap::kRepeat;
};

enum class MaterialModel : uint32_t {
  // DESIGN.md §3 / glTF 2.0: base = factor * texture * vertex colour; diffuse = base * (1 - metallic),
  // specular F0 = mix(0.04, base, metallic), GGX alpha = (roughness factor * texture G)^2;
  // metallic = factor * texture B.
  kMetallicRoughness = 1,
  // For procedural scenes: the vertex albedos and roughness modulated by the maps: diffuse =
  // vertex diffuse * base (factor * texture), specular = vertex specular, GGX alpha = vertex
  // roughness * (roughness factor * texture G)^2.
  kVertexAlbedo = 2,
};

// A material: factors, and optional textures (indices into Scene::textures, -1 for none).
struct Material {
  std::string name;
  MaterialModel model = MaterialModel::kMetallicRoughness;
  glm::vec4 base_color_factor{1.0f};  // linear rgb, alpha
  float metallic_factor = 1.0f;
  float roughness_factor = 1.0f;      // perceptual roughness; GGX alpha is its square
  float normal_scale = 1.0f;          // scales the normal map's x and y (glTF normalTexture.scale)
  bool alpha_mask = false;            // glTF alphaMode MASK: texels with alpha < cutoff are cut out
  float alpha_cutoff = 0.5f;
  bool double_sided = false;          // no back-face culling; the normal flips on the back side
  int32_t base_color_texture = -1;          // sRGB colour, alpha in A
  int32_t metallic_roughness_texture = -1;  // linear: G roughness, B metallic
  int32_t normal_texture = -1;              // linear: tangent-space normal in RGB
};

struct Scene {
  std::string name;
  SceneMesh mesh;
  CameraDesc camera;
  SpotLightDesc light;
  std::vector<Material> materials;    // indexed by SceneVertex::material
  std::vector<TextureImage> textures;  // indexed by Material::*_texture
};

// How a sequence (frames > 1) moves the light and the camera along smooth periodic paths of phase
// phi = 2*pi*frame/frames. Every offset is zero at phi = 0, so frame 0 is the static scene.
struct SceneMotion {
  float light_circle_m;  // the light's position runs on a horizontal circle of this radius
  float aim_wobble_deg;  // the spot axis precesses by up to about twice this angle
  float camera_dolly_m;  // the camera moves this far along its view direction and back
};

// Moves the scene's light and camera to frame `frame` of `frames` (the same arithmetic for
// every frame, frame 0 included). Throws InputError unless frame < frames.
void animate_scene(Scene& scene, const SceneMotion& motion, uint32_t frame, uint32_t frames);

// The light's `up` (the RSM image's orientation) for a unit spot axis: the component of a fixed
// hint orthogonal to the axis, so that it is a unit vector never parallel to the axis.
glm::vec3 spot_light_up(glm::vec3 direction);

// "atrium" (Table 1), "conference" (Table 2), "tiny" (tests). frame in [0, frames): with
// frames > 1 the light and the camera move along a short smooth path (temporal tests); frame 0
// of any sequence equals the static scene. Throws InputError for an unknown name.
Scene make_scene(const std::string& name, uint32_t frame = 0, uint32_t frames = 1);
std::vector<std::string> scene_names();

}  // namespace vsgl
