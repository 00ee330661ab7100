#include "harness/scene/gltf_scene.hpp"

// The import that chooses: loads the file through the checked image loader, hashes it, converts
// its materials (detail/gltf_materials) and the meshes of its node graph (detail/gltf_nodes),
// measures the bounds, adds the ground, then chooses the camera and the light.
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "harness/core/path_text.hpp"
#include "harness/core/error.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/scene/detail/gltf_accessors.hpp"
#include "harness/scene/detail/gltf_conversion.hpp"
#include "harness/scene/detail/gltf_materials.hpp"
#include "harness/scene/detail/gltf_nodes.hpp"
#include "harness/scene/detail/model_import.hpp"
#include "harness/scene/scene_geometry.hpp"

namespace vsgl {

std::string escape_name(const std::string& name) { return printable_text(name, 80); }

std::string scene_name_from_file(const std::filesystem::path& file) {
  std::string out;
  for (char c : file.stem().string()) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
    out += ok ? c : '_';
  }
  if (out.size() > 64) out.resize(64);
  if (out.empty() || out == "." || out == "..") out = "gltf";
  return out;
}

namespace {

using gltf::Reporter;

// The file parsed by tinygltf (buffers and images decoded), or an error with its message.
void load_model(tinygltf::Model& model, const std::vector<unsigned char>& bytes, const std::filesystem::path& path,
                const Reporter& r) {
  tinygltf::TinyGLTF loader;
  gltf::ImageLoadContext image_context{&model};
  loader.SetImageLoader(gltf::load_image_checked, &image_context);
  std::string err, warn;
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  const std::string base_dir = path.parent_path().string();
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                                       static_cast<unsigned int>(bytes.size()), base_dir)
                         : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                      static_cast<unsigned int>(bytes.size()), base_dir);
  if (!ok) {
    std::string problem = err.empty() ? warn : err;
    while (!problem.empty() && (problem.back() == '\n' || problem.back() == ' ')) problem.pop_back();
    r.fail("cannot be loaded: " + printable_text(problem));
  }
  // tinygltf reports unreadable external images as warnings and leaves them empty; they are
  // caught where a material uses them.
}

// Over the file, its buffers and its decoded images: what the capture was recorded from.
std::string content_hash(const std::vector<unsigned char>& bytes, const tinygltf::Model& model) {
  gltf::Fnv1a hash;
  hash.add(bytes.data(), bytes.size());
  for (const tinygltf::Buffer& b : model.buffers) hash.add(b.data.data(), b.data.size());
  for (const tinygltf::Image& img : model.images) hash.add(img.image.data(), img.image.size());
  return hash.text();
}

}  // namespace

GltfImport import_gltf(const std::filesystem::path& path, const GltfCameraChoice& camera_choice,
                       const GltfLightChoice& light_choice, bool ground) {
  if (camera_choice.camera && (camera_choice.eye || camera_choice.look_at || camera_choice.fov_y_deg))
    throw UsageError("--camera picks a camera of the file; it cannot be combined with --eye/--look-at/--fov");
  GltfImport out;
  // The path is the user's own: shown whole (escaped, never cut), so a message names the file
  // however deep it lies.
  out.file = printable_text(path_text(path), std::string_view::npos);
  const Reporter r(out.file);
  const std::vector<unsigned char> bytes = gltf::read_bytes(path, r);
  gltf::require_gltf2(bytes, r);
  tinygltf::Model model;
  load_model(model, bytes, path, r);
  out.content_hash = content_hash(bytes, model);

  const gltf::Importer imp(model, r);
  gltf::Conversion conv;
  conv.scene.name = scene_name_from_file(path);
  gltf::convert_materials(conv, imp);
  const gltf::NodeContents contents = gltf::convert_nodes(conv, imp, gltf::scene_nodes(model, r, out.notes));
  if (!model.animations.empty()) conv.unmapped.insert("animations (rest pose drawn)");
  const SceneMesh& mesh = conv.scene.mesh;
  out.triangles = mesh.indices.size() / 3;
  if (out.triangles == 0)
    r.fail("its default scene has no triangles" +
           (conv.skipped_non_triangle > 0
                ? " (" + std::to_string(conv.skipped_non_triangle) + " point/line primitives are not surfaces)"
                : std::string()));


  gltf::SceneBounds bounds = gltf::triangle_bounds(mesh, r);
  out.bounds_lo = bounds.lo;
  out.bounds_hi = bounds.hi;
  if (ground) gltf::add_ground(conv.scene.mesh, bounds, out.notes);
  conv.scene.camera = gltf::choose_camera(imp, contents.cameras, camera_choice, bounds, out.camera_source);
  conv.scene.light = gltf::choose_light(imp, contents.lights, light_choice, bounds, out.light_source);
  gltf::conversion_notes(conv, out.notes);

  out.motion = SceneMotion{0.02f * bounds.radius, 1.5f, 0.03f * bounds.radius};
  out.scene = std::move(conv.scene);
  return out;
}

Scene gltf_frame(const GltfImport& import, uint32_t frame, uint32_t frames) {
  Scene scene = import.scene;
  animate_scene(scene, import.motion, frame, frames);
  return scene;
}

}  // namespace vsgl
