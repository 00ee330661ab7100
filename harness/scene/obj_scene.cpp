#include "harness/scene/obj_scene.hpp"

// The OBJ import: the text pass (detail/obj_text: lines of bad indices and coordinates), then
// tinyobjloader with a material reader that keeps each .mtl's bytes (hashed, and scanned for the
// lines of its statements), then the materials and their textures, the triangles, and the
// pieces shared with the glTF importer (detail/model_import, detail/gltf_nodes): bounds, ground,
// notes, camera and light.
#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_map>

#include "harness/core/path_text.hpp"
#include "harness/core/error.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/scene/detail/gltf_accessors.hpp"
#include "harness/scene/detail/gltf_conversion.hpp"
#include "harness/scene/detail/gltf_nodes.hpp"
#include "harness/scene/detail/model_import.hpp"
#include "harness/scene/detail/obj_text.hpp"
#include "harness/scene/scene_textures.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;
using gltf::quote_name;
using gltf::Reporter;

// The .mtl files beside the .obj, as tinyobjloader asks for them; each one read is kept.
class MtlReader : public tinyobj::MaterialReader {
 public:
  explicit MtlReader(fs::path dir) : dir_(std::move(dir)) {}

  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* material_map, std::string* warn, std::string* err) override {
    // Nothing may throw through tinyobjloader: a name that is no regular file (a directory, found
    // by fuzz_obj: reading one threw std::ios_failure) or cannot be read counts as missing.
    const fs::path p = dir_ / name;
    std::error_code ec;
    std::ifstream in;
    if (fs::is_regular_file(p, ec)) in.open(p, std::ios::binary);
    std::string bytes;
    char chunk[1 << 14];
    while (in.is_open() && (in.read(chunk, sizeof chunk) || in.gcount() > 0)) bytes.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (!in.is_open() || in.bad()) {
      missing.push_back(name);
      return false;
    }
    Library lib{name, std::move(bytes), {}};
    std::istringstream text(lib.text);
    const std::size_t first = materials->size();
    tinyobj::LoadMtl(material_map, materials, &text, warn, err);
    lib.scan = obj::scan_mtl(lib.text);
    for (std::size_t i = first; i < materials->size(); ++i) library_of[i] = libraries.size();
    libraries.push_back(std::move(lib));
    return true;
  }

  struct Library {
    std::string name, text;
    obj::MtlText scan;
  };
  std::vector<Library> libraries;
  std::map<std::size_t, std::size_t> library_of;  // material -> libraries index
  std::vector<std::string> missing;

 private:
  fs::path dir_;
};

// Ks with its luminance clamped to [0,1]: scaled down when its luminance exceeds 1, then every
// channel clamped (a Phong Ks is not bounded by 1 the way F0 is).
glm::vec3 specular_f0(const tinyobj::real_t ks[3]) {
  glm::vec3 f(std::max(0.0f, static_cast<float>(ks[0])), std::max(0.0f, static_cast<float>(ks[1])),
              std::max(0.0f, static_cast<float>(ks[2])));
  if (!std::isfinite(f.x + f.y + f.z)) return glm::vec3(0.04f);
  const float lum = glm::dot(f, glm::vec3(0.2126f, 0.7152f, 0.0722f));
  if (lum > 1.0f) f /= lum;
  return glm::clamp(f, 0.0f, 1.0f);
}

// DESIGN.md §3: Blinn-Phong exponent -> Beckmann alpha^2 = 2 / (Ns + 2), used as the GGX alpha.
float ggx_alpha(float ns) {
  if (!std::isfinite(ns)) ns = 0.0f;
  return std::clamp(std::sqrt(2.0f / (std::max(ns, 0.0f) + 2.0f)), 1e-3f, 1.0f);
}

struct Surface {
  glm::vec3 diffuse{0.5f}, specular{0.04f};
  float roughness = ggx_alpha(1.0f);
};

class ObjConverter {
 public:
  ObjConverter(const fs::path& path, const Reporter& r, const MtlReader& mtl, gltf::Conversion& conv, gltf::Fnv1a& hash)
      : dir_(path.parent_path()), r_(r), mtl_(mtl), conv_(conv), hash_(hash) {}

  // Every material of the libraries, in order (Scene::materials[i] is material i).
  void convert_materials(const std::vector<tinyobj::material_t>& materials) {
    file_materials_ = materials.size();
    for (std::size_t i = 0; i < materials.size(); ++i) {
      const tinyobj::material_t& src = materials[i];
      const MtlReader::Library* lib = nullptr;
      const obj::MtlMaterialLines* lines = nullptr;
      if (const auto it = mtl_.library_of.find(i); it != mtl_.library_of.end()) {
        lib = &mtl_.libraries[it->second];
        if (const auto m = lib->scan.materials.find(src.name); m != lib->scan.materials.end()) lines = &m->second;
      }
      const auto where = [&](std::initializer_list<const char*> keywords) {
        std::string w = "material " + quote_name(src.name);
        if (lib == nullptr) return w;
        w += " of " + quote_name(lib->name);
        if (lines != nullptr)
          for (const char* k : keywords)
            if (const auto s = lines->statements.find(k); s != lines->statements.end())
              return w + " line " + std::to_string(s->second);
        return w;
      };
      Material mat;
      mat.name = escape_name(src.name);
      mat.model = MaterialModel::kVertexAlbedo;
      mat.roughness_factor = 1.0f;
      mat.double_sided = true;
      Surface s;
      s.diffuse = glm::clamp(glm::vec3(src.diffuse[0], src.diffuse[1], src.diffuse[2]), 0.0f, 1.0f);
      if (!std::isfinite(s.diffuse.x + s.diffuse.y + s.diffuse.z)) s.diffuse = glm::vec3(0.5f);
      const bool has_ks = lines != nullptr && lines->statements.count("Ks") > 0;
      s.specular = has_ks ? specular_f0(src.specular) : glm::vec3(0.04f);
      s.roughness = ggx_alpha(static_cast<float>(src.shininess));
      float d = static_cast<float>(src.dissolve);
      if (!std::isfinite(d)) d = 1.0f;
      d = std::clamp(d, 0.0f, 1.0f);
      const TextureImage* diffuse_map =
          src.diffuse_texname.empty() ? nullptr : &image(src.diffuse_texname, "map_Kd", where({"map_Kd"}));
      const TextureImage* alpha_map =
          src.alpha_texname.empty() ? nullptr : &image(src.alpha_texname, "map_d", where({"map_d"}));
      if (diffuse_map != nullptr || alpha_map != nullptr)
        mat.base_color_texture = base_texture(diffuse_map, alpha_map);
      mat.alpha_mask = d < 1.0f || alpha_map != nullptr;
      mat.alpha_cutoff = 0.5f;
      mat.base_color_factor = glm::vec4(1.0f, 1.0f, 1.0f, d);
      const std::string& bump = !src.normal_texname.empty() ? src.normal_texname : src.bump_texname;
      if (!bump.empty()) {
        const TextureImage& n = image(bump, src.normal_texname.empty() ? "map_bump" : "norm",
                                      where({"norm", "map_bump", "map_Bump", "bump"}));
        mat.normal_texture = add_texture(n, false);
      }
      if (!src.ambient_texname.empty()) conv_.unmapped.insert("map_Ka (ambient)");
      if (!src.specular_texname.empty()) conv_.unmapped.insert("map_Ks");
      if (!src.specular_highlight_texname.empty()) conv_.unmapped.insert("map_Ns");
      if (!src.displacement_texname.empty()) conv_.unmapped.insert("disp (displacement)");
      if (!src.reflection_texname.empty()) conv_.unmapped.insert("refl (reflection maps)");
      if (!src.emissive_texname.empty() || src.emission[0] > 0 || src.emission[1] > 0 || src.emission[2] > 0)
        conv_.unmapped.insert("Ke/map_Ke (emission)");
      if (src.illum > 2) conv_.unmapped.insert("illum models above 2 (reflection, refraction)");
      surfaces_.push_back(s);
      conv_.scene.materials.push_back(std::move(mat));
    }
  }

  // The grey material of faces without one (added once).
  uint32_t grey() {
    if (grey_ < 0) {
      grey_ = static_cast<int32_t>(conv_.scene.materials.size());
      Material mat;
      mat.name = "OBJ default (grey)";
      mat.model = MaterialModel::kVertexAlbedo;
      mat.double_sided = true;
      surfaces_.push_back(Surface{glm::vec3(0.5f), glm::vec3(0.04f), 0.5f});
      conv_.scene.materials.push_back(std::move(mat));
    }
    return static_cast<uint32_t>(grey_);
  }

  void convert_shapes(const tinyobj::attrib_t& a, const std::vector<tinyobj::shape_t>& shapes) {
    const std::size_t nv = a.vertices.size() / 3, nn = a.normals.size() / 3, nt = a.texcoords.size() / 2;
    SceneMesh& mesh = conv_.scene.mesh;
    std::unordered_map<uint64_t, uint32_t> shared;  // (position, texcoord, normal, material) -> vertex
    std::vector<bool> normal_mapped;
    for (const tinyobj::shape_t& shape : shapes) {
      const tinyobj::mesh_t& m = shape.mesh;
      std::size_t at = 0;
      for (std::size_t f = 0; f < m.num_face_vertices.size(); ++f) {
        const std::size_t fv = m.num_face_vertices[f];
        if (at + fv > m.indices.size()) r_.fail("tinyobjloader returned a face past its indices (shape " + quote_name(shape.name) + ")");
        const int mid = f < m.material_ids.size() ? m.material_ids[f] : -1;
        const uint32_t material = mid >= 0 && static_cast<std::size_t>(mid) < file_materials_ ? static_cast<uint32_t>(mid) : grey();
        if (material == static_cast<uint32_t>(grey_)) ++grey_faces_;
        const Surface s = surfaces_[material];
        const bool wants_tangents = conv_.scene.materials[material].normal_texture >= 0;
        for (std::size_t k = 2; k < fv; ++k) {  // fv is 3 after triangulation; a fan otherwise
          const tinyobj::index_t corner[3] = {m.indices[at], m.indices[at + k - 1], m.indices[at + k]};
          glm::vec3 p[3];
          for (int c = 0; c < 3; ++c) {
            const int v = corner[c].vertex_index;
            // The text pass refused these with their line; this guards what tinyobjloader may do
            // differently from it.
            if (v < 0 || static_cast<std::size_t>(v) >= nv ||
                (corner[c].normal_index >= 0 && static_cast<std::size_t>(corner[c].normal_index) >= nn) ||
                (corner[c].texcoord_index >= 0 && static_cast<std::size_t>(corner[c].texcoord_index) >= nt) ||
                corner[c].normal_index < -1 || corner[c].texcoord_index < -1)
              r_.fail("shape " + quote_name(shape.name) + " face " + std::to_string(f + 1) + ": an index is out of range");
            p[c] = glm::vec3(a.vertices[3 * v], a.vertices[3 * v + 1], a.vertices[3 * v + 2]);
            if (!std::isfinite(p[c].x + p[c].y + p[c].z))
              r_.fail("vertex position " + std::to_string(v + 1) + " is not finite");
          }
          glm::vec3 fn = glm::cross(p[1] - p[0], p[2] - p[0]);
          const float len = glm::length(fn);
          fn = len > 0.0f && std::isfinite(len) ? fn / len : glm::vec3(0.0f, 1.0f, 0.0f);
          for (int c = 0; c < 3; ++c) {
            SceneVertex vert{};
            vert.position = p[c];
            vert.diffuse = s.diffuse;
            vert.specular = s.specular;
            vert.roughness = s.roughness;
            vert.material = material;
            bool own_normal = false;
            if (corner[c].normal_index >= 0) {
              const auto ni = static_cast<std::size_t>(corner[c].normal_index);
              const glm::vec3 n(a.normals[3 * ni], a.normals[3 * ni + 1], a.normals[3 * ni + 2]);
              const float nl = glm::length(n);
              if (std::isfinite(nl) && nl > 1e-12f) {
                if (std::abs(nl - 1.0f) > 1e-3f) ++conv_.normals_normalized;
                vert.normal = n / nl;
                own_normal = true;
              } else {
                ++conv_.normals_replaced;
              }
            } else {
              ++flat_corners_;
            }
            if (!own_normal) vert.normal = fn;
            if (corner[c].texcoord_index >= 0) {
              const auto ti = static_cast<std::size_t>(corner[c].texcoord_index);
              vert.uv = glm::vec2(a.texcoords[2 * ti], 1.0f - a.texcoords[2 * ti + 1]);  // OBJ: v up
              if (!std::isfinite(vert.uv.x + vert.uv.y)) vert.uv = glm::vec2(0.0f);
            }
            if (mesh.vertices.size() >= std::numeric_limits<uint32_t>::max()) r_.fail("has more than 2^32 vertices");
            if (own_normal) {
              const uint64_t key = (static_cast<uint64_t>(corner[c].vertex_index) * 0x9E3779B97F4A7C15ull) ^
                                   (static_cast<uint64_t>(corner[c].texcoord_index + 1) * 0xC2B2AE3D27D4EB4Full) ^
                                   (static_cast<uint64_t>(corner[c].normal_index + 1) * 0x165667B19E3779F9ull) ^
                                   (static_cast<uint64_t>(material) * 0x27D4EB2F165667C5ull);
              const auto [it, added] = shared.try_emplace(key, static_cast<uint32_t>(mesh.vertices.size()));
              if (!added) {
                const SceneVertex& old = mesh.vertices[it->second];
                if (old.position == vert.position && old.normal == vert.normal && old.uv == vert.uv &&
                    old.material == vert.material) {
                  mesh.indices.push_back(it->second);
                  continue;
                }
              }
            }
            mesh.indices.push_back(static_cast<uint32_t>(mesh.vertices.size()));
            mesh.vertices.push_back(vert);
            normal_mapped.push_back(wants_tangents);
          }
        }
        at += fv;
      }
    }
    if (std::find(normal_mapped.begin(), normal_mapped.end(), true) != normal_mapped.end()) {
      compute_tangents(mesh.vertices, mesh.indices);
      conv_.tangents_computed += static_cast<uint64_t>(std::count(normal_mapped.begin(), normal_mapped.end(), true));
    }
  }

  uint64_t grey_faces() const { return grey_faces_; }
  uint64_t flat_corners() const { return flat_corners_; }

 private:
  // The texture file `name` (relative to the .obj's directory; '\' read as '/' when the name as
  // written does not exist), decoded once.
  const TextureImage& image(const std::string& name, const char* keyword, const std::string& where) {
    fs::path p = dir_ / name;
    if (!fs::exists(p)) {
      std::string slashed = name;
      std::replace(slashed.begin(), slashed.end(), '\\', '/');
      if (fs::exists(dir_ / slashed)) p = dir_ / slashed;
    }
    const std::string key = p.lexically_normal().string();
    if (const auto it = images_.find(key); it != images_.end()) return it->second;
    const std::string what = where + ": " + keyword + " " + quote_name(name);
    std::error_code ec;
    std::ifstream in;
    if (fs::is_regular_file(p, ec)) in.open(p, std::ios::binary);
    if (!in.is_open()) r_.fail(what + " is missing (looked for " + quote_name(path_text(p)) + ")");
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.empty() || bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
      r_.fail(what + " is empty or too large");
    tinygltf::Image img;
    std::string err, warn;
    if (!tinygltf::LoadImageData(&img, 0, &err, &warn, 0, 0, bytes.data(), static_cast<int>(bytes.size()), nullptr))
      r_.fail(what + " could not be decoded: " + printable_text(err));
    img.name = name;
    TextureImage t = gltf::rgba8_texture(img, true, what, quote_name(name), r_);
    hash_.add(t.rgba8.data(), t.rgba8.size());
    return images_.emplace(key, std::move(t)).first->second;
  }

  // map_Kd's RGB (white without one) with the cut-out alpha of map_d (opaque without one),
  // sampled at map_Kd's texels (nearest) when the sizes differ.
  int32_t base_texture(const TextureImage* diffuse, const TextureImage* alpha) {
    if (alpha == nullptr) return add_texture(*diffuse, true);
    TextureImage t;
    if (diffuse != nullptr) {
      t = *diffuse;
    } else {
      t.name = alpha->name;
      t.width = alpha->width;
      t.height = alpha->height;
      t.rgba8.assign(static_cast<std::size_t>(t.width) * t.height * 4, 255);
    }
    if (diffuse != nullptr) t.name += " + " + alpha->name;
    // The alpha channel of map_d when its image has one (not all 255), else its first channel.
    bool has_alpha = false;
    for (std::size_t i = 3; i < alpha->rgba8.size() && !has_alpha; i += 4) has_alpha = alpha->rgba8[i] != 255;
    for (uint32_t y = 0; y < t.height; ++y)
      for (uint32_t x = 0; x < t.width; ++x) {
        const uint32_t ax = static_cast<uint32_t>(uint64_t{x} * alpha->width / t.width);
        const uint32_t ay = static_cast<uint32_t>(uint64_t{y} * alpha->height / t.height);
        const std::size_t src = (static_cast<std::size_t>(ay) * alpha->width + ax) * 4;
        t.rgba8[(static_cast<std::size_t>(y) * t.width + x) * 4 + 3] = alpha->rgba8[src + (has_alpha ? 3 : 0)];
      }
    t.srgb = true;
    conv_.scene.textures.push_back(std::move(t));
    return static_cast<int32_t>(conv_.scene.textures.size() - 1);
  }

  int32_t add_texture(const TextureImage& img, bool srgb) {
    const std::string key = img.name + (srgb ? "|srgb" : "|linear");
    if (const auto it = texture_ids_.find(key); it != texture_ids_.end()) return it->second;
    TextureImage t = img;
    t.srgb = srgb;
    conv_.scene.textures.push_back(std::move(t));
    const auto id = static_cast<int32_t>(conv_.scene.textures.size() - 1);
    texture_ids_[key] = id;
    return id;
  }

  fs::path dir_;
  const Reporter& r_;
  const MtlReader& mtl_;
  gltf::Conversion& conv_;
  gltf::Fnv1a& hash_;
  std::vector<Surface> surfaces_;  // per scene material
  int32_t grey_ = -1;
  std::size_t file_materials_ = 0;
  uint64_t grey_faces_ = 0, flat_corners_ = 0;
  std::map<std::string, TextureImage> images_;
  std::map<std::string, int32_t> texture_ids_;
};

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '.')) s.pop_back();
  return s;
}

}  // namespace

GltfImport import_obj(const fs::path& path, const GltfCameraChoice& camera_choice, const GltfLightChoice& light_choice,
                      bool ground) {
  if (camera_choice.camera && (camera_choice.eye || camera_choice.look_at || camera_choice.fov_y_deg))
    throw UsageError("--camera picks a camera of the file; it cannot be combined with --eye/--look-at/--fov");
  GltfImport out;
  out.file = printable_text(path_text(path), std::string_view::npos);
  const Reporter r(out.file, "OBJ file");
  if (camera_choice.camera)
    r.fail("has no camera " + quote_name(*camera_choice.camera) + ": OBJ files have none (use --eye/--look-at/--fov)");
  const std::vector<unsigned char> bytes = gltf::read_bytes(path, r);
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  const obj::ObjText scanned = obj::scan_obj(text, r);
  if (scanned.faces == 0)
    r.fail("has no faces (" + std::to_string(scanned.positions) + " vertex positions" +
           (scanned.lines_points > 0 ? ", " + std::to_string(scanned.lines_points) + " line/point statements, which are not surfaces" : "") + ")");

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  MtlReader mtl(path.parent_path());
  std::istringstream in{std::string(text)};
  const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, &mtl, /*triangulate=*/true,
                                   /*default_vcols_fallback=*/false);
  if (!ok) r.fail("cannot be loaded: " + printable_text(trimmed(err.empty() ? warn : err)));

  gltf::Fnv1a hash;
  hash.add(bytes.data(), bytes.size());
  for (const MtlReader::Library& lib : mtl.libraries) hash.add(lib.text.data(), lib.text.size());
  gltf::Conversion conv;
  conv.scene.name = scene_name_from_file(path);
  ObjConverter converter(path, r, mtl, conv, hash);
  converter.convert_materials(materials);
  converter.convert_shapes(attrib, shapes);
  out.content_hash = hash.text();
  const SceneMesh& mesh = conv.scene.mesh;
  out.triangles = mesh.indices.size() / 3;
  if (out.triangles == 0) r.fail("has no faces with 3 or more corners after triangulation");

  for (const std::string& name : mtl.missing)
    out.notes.push_back("WARNING: material library " + quote_name(name) + " is missing (looked for it beside the file): its faces are grey (albedo 0.5)");
  if (converter.grey_faces() > 0)
    out.notes.push_back(std::to_string(converter.grey_faces()) + " faces have no material (no usemtl, or one the libraries lack): drawn grey (albedo 0.5)");
  if (converter.flat_corners() > 0)
    out.notes.push_back(std::to_string(converter.flat_corners()) + " face corners have no normal: the face's normal used (flat shading)");
  if (scanned.lines_points > 0)
    out.notes.push_back(std::to_string(scanned.lines_points) + " line/point statements skipped (no surface)");
  if (!attrib.colors.empty()) conv.unmapped.insert("vertex colours");

  gltf::SceneBounds bounds = gltf::triangle_bounds(mesh, r);
  out.bounds_lo = bounds.lo;
  out.bounds_hi = bounds.hi;
  if (ground) gltf::add_ground(conv.scene.mesh, bounds, out.notes);
  // An OBJ file has no cameras or lights: the glTF importer's choices over a model without any
  // place them from the command line or around the bounds.
  const tinygltf::Model none;
  const gltf::Importer imp(none, r);
  conv.scene.camera = gltf::choose_camera(imp, {}, camera_choice, bounds, out.camera_source);
  conv.scene.light = gltf::choose_light(imp, {}, light_choice, bounds, out.light_source);
  gltf::conversion_notes(conv, out.notes);

  out.motion = SceneMotion{0.02f * bounds.radius, 1.5f, 0.03f * bounds.radius};
  out.scene = std::move(conv.scene);
  return out;
}

}  // namespace vsgl
