#include "harness/scene/gltf_scene.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <tuple>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "harness/core/error.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/scene/scene_geometry.hpp"
#include "harness/scene/scene_textures.hpp"

namespace vsgl {
namespace {

// FNV-1a, 64 bit, over several byte ranges in turn.
struct Fnv1a {
  uint64_t h = 0xcbf29ce484222325ull;
  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
      h ^= p[i];
      h *= 0x100000001b3ull;
    }
  }
  std::string text() const {
    char buf[32];
    std::snprintf(buf, sizeof buf, "fnv1a64:%016llx", static_cast<unsigned long long>(h));
    return buf;
  }
};

std::string quote_name(const std::string& name) { return "'" + escape_name(name) + "'"; }

// Builds messages "glTF file F: <where>: <problem>" and throws them.
class Reporter {
 public:
  explicit Reporter(std::string file) : file_(std::move(file)) {}
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError("glTF file " + file_ + ": " + problem);
  }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

std::vector<unsigned char> read_bytes(const std::filesystem::path& path, const Reporter& r) {
  std::ifstream in(path, std::ios::binary);
  if (!in) r.fail("cannot be opened (missing or unreadable)");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) r.fail("could not be read");
  return bytes;
}

uint32_t le32(const std::vector<unsigned char>& b, std::size_t at) {
  return uint32_t{b[at]} | uint32_t{b[at + 1]} << 8 | uint32_t{b[at + 2]} << 16 | uint32_t{b[at + 3]} << 24;
}

// tinygltf reads many glTF 1.0 files without complaint and then finds nothing (or garbage) in
// them, so the version is checked first: from the binary header, else from asset.version.
void require_gltf2(const std::vector<unsigned char>& bytes, const Reporter& r) {
  std::string json_text;
  if (bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0) {
    if (bytes.size() < 20) r.fail("binary glTF header is truncated (" + std::to_string(bytes.size()) + " bytes)");
    const uint32_t version = le32(bytes, 4);
    if (version != 2)
      r.fail("binary glTF container version " + std::to_string(version) +
             (version == 1 ? " is glTF 1.0" : "") + "; only glTF 2.0 is supported");
    const uint32_t json_length = le32(bytes, 12);
    if (json_length > bytes.size() - 20) r.fail("binary glTF JSON chunk runs past the end of the file");
    json_text.assign(reinterpret_cast<const char*>(bytes.data()) + 20, json_length);
  } else {
    json_text.assign(bytes.begin(), bytes.end());
  }
  const nlohmann::json doc = nlohmann::json::parse(json_text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded()) r.fail("is not valid JSON (neither a .gltf nor a .glb file)");
  if (!doc.is_object()) r.fail("is not a glTF document (top level is not a JSON object)");
  const auto asset = doc.find("asset");
  if (asset == doc.end() || !asset->is_object() || !asset->contains("version") || !(*asset)["version"].is_string())
    r.fail("has no asset.version (glTF 1.0 files may omit it); only glTF 2.0 is supported");
  const std::string version = (*asset)["version"].get<std::string>();
  if (version.rfind("2.", 0) != 0)
    r.fail("is glTF " + escape_name(version) + "; only glTF 2.0 is supported (convert it, e.g. with gltf-pipeline)");
}

std::size_t component_bytes(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int type_components(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;
  }
}

double read_component(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, p, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0 : p[0];
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const auto v = static_cast<signed char>(p[0]);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_INT: {
      int32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    default: return 0.0;
  }
}

class Importer {
 public:
  Importer(const tinygltf::Model& model, Reporter reporter) : m_(model), r_(std::move(reporter)) {}

  // Accessor `index`, an error naming `what` when there is none.
  const tinygltf::Accessor& accessor(int index, const std::string& what) const {
    if (index < 0 || static_cast<std::size_t>(index) >= m_.accessors.size())
      r_.fail(what + ": accessor " + std::to_string(index) + " does not exist (" +
              std::to_string(m_.accessors.size()) + " accessors)");
    return m_.accessors[static_cast<std::size_t>(index)];
  }

  // The accessor's elements as doubles (count * components), every byte checked to lie inside
  // its buffer view and buffer. `what` names the accessor's use in messages.
  std::vector<double> read_accessor(int index, int want_components, const std::string& what) const {
    const tinygltf::Accessor& a = accessor(index, what);
    const std::string where = what + " (accessor " + std::to_string(index) + ")";
    if (a.sparse.isSparse) r_.fail(where + ": sparse accessors are not supported");
    const int comps = type_components(a.type);
    const std::size_t csize = component_bytes(a.componentType);
    if (comps == 0 || csize == 0) r_.fail(where + ": unsupported accessor type or component type");
    if (comps != want_components)
      r_.fail(where + ": has " + std::to_string(comps) + " components per element, expected " +
              std::to_string(want_components));
    const std::size_t count = a.count;
    std::vector<double> out(count * static_cast<std::size_t>(comps), 0.0);
    if (a.bufferView < 0) return out;  // glTF: an accessor without a buffer view is all zeros
    if (static_cast<std::size_t>(a.bufferView) >= m_.bufferViews.size())
      r_.fail(where + ": buffer view " + std::to_string(a.bufferView) + " does not exist");
    const tinygltf::BufferView& view = m_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= m_.buffers.size())
      r_.fail(where + ": buffer " + std::to_string(view.buffer) + " does not exist");
    const tinygltf::Buffer& buffer = m_.buffers[static_cast<std::size_t>(view.buffer)];
    const std::string buffer_name =
        "buffer " + std::to_string(view.buffer) + (buffer.uri.empty() || buffer.uri.rfind("data:", 0) == 0
                                                       ? std::string()
                                                       : " (" + quote_name(buffer.uri) + ")");
    if (buffer.data.empty()) r_.fail(where + ": " + buffer_name + " is missing or empty");
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
      r_.fail(where + ": buffer view " + std::to_string(a.bufferView) + " (bytes " + std::to_string(view.byteOffset) +
              " + " + std::to_string(view.byteLength) + ") runs past the end of " + buffer_name + " (" +
              std::to_string(buffer.data.size()) + " bytes): the buffer is short");
    const std::size_t element = csize * static_cast<std::size_t>(comps);
    const std::size_t stride = view.byteStride != 0 ? view.byteStride : element;
    if (count == 0) return out;
    const std::size_t needed = a.byteOffset + stride * (count - 1) + element;
    if (a.byteOffset > view.byteLength || needed > view.byteLength)
      r_.fail(where + ": " + std::to_string(count) + " elements need " + std::to_string(needed) +
              " bytes of buffer view " + std::to_string(a.bufferView) + ", which has " +
              std::to_string(view.byteLength));
    const unsigned char* base = buffer.data.data() + view.byteOffset + a.byteOffset;
    for (std::size_t i = 0; i < count; ++i)
      for (int c = 0; c < comps; ++c)
        out[i * static_cast<std::size_t>(comps) + static_cast<std::size_t>(c)] =
            read_component(base + i * stride + static_cast<std::size_t>(c) * csize, a.componentType, a.normalized);
    return out;
  }

  const tinygltf::Model& model() const { return m_; }
  const Reporter& reporter() const { return r_; }

 private:
  const tinygltf::Model& m_;
  Reporter r_;
};

glm::dmat4 node_local_matrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());
  glm::dmat4 t(1.0), rot(1.0), s(1.0);
  if (node.translation.size() == 3) t = glm::translate(glm::dmat4(1.0), glm::make_vec3(node.translation.data()));
  if (node.rotation.size() == 4) {
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);  // w, x, y, z
    rot = glm::mat4_cast(glm::normalize(q));
  }
  if (node.scale.size() == 3) s = glm::scale(glm::dmat4(1.0), glm::make_vec3(node.scale.data()));
  return t * rot * s;
}

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

int node_light(const tinygltf::Node& node) {
  const auto ext = node.extensions.find("KHR_lights_punctual");
  if (ext == node.extensions.end() || !ext->second.IsObject() || !ext->second.Has("light")) return -1;
  const tinygltf::Value& v = ext->second.Get("light");
  return v.IsInt() ? v.Get<int>() : (v.IsNumber() ? static_cast<int>(v.GetNumberAsDouble()) : -1);
}

TextureWrap wrap_of(int gl_wrap) {
  switch (gl_wrap) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::kClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::kMirroredRepeat;
    default: return TextureWrap::kRepeat;
  }
}

struct Conversion {
  Scene scene;
  std::vector<std::string> notes;
  std::map<std::tuple<int, bool>, int32_t> texture_ids;  // (glTF texture, sRGB) -> Scene::textures
  int32_t default_material = -1;
  uint64_t normals_normalized = 0, normals_replaced = 0, tangents_computed = 0;
  uint64_t skipped_non_triangle = 0;
  std::set<std::string> unmapped;
};

int32_t scene_texture(Conversion& conv, const Importer& imp, int texture, bool srgb, const std::string& what) {
  const tinygltf::Model& m = imp.model();
  const Reporter& r = imp.reporter();
  if (texture < 0) return -1;
  const auto key = std::make_tuple(texture, srgb);
  if (const auto it = conv.texture_ids.find(key); it != conv.texture_ids.end()) return it->second;
  if (static_cast<std::size_t>(texture) >= m.textures.size())
    r.fail(what + ": texture " + std::to_string(texture) + " does not exist (" + std::to_string(m.textures.size()) +
           " textures)");
  const tinygltf::Texture& t = m.textures[static_cast<std::size_t>(texture)];
  if (t.source < 0 || static_cast<std::size_t>(t.source) >= m.images.size())
    r.fail(what + ": texture " + std::to_string(texture) +
           " has no PNG/JPEG image source (KHR_texture_basisu, EXT_texture_webp and the like are not supported)");
  const tinygltf::Image& img = m.images[static_cast<std::size_t>(t.source)];
  const std::string image_name = "image " + std::to_string(t.source) +
                                 (img.uri.empty() || img.uri.rfind("data:", 0) == 0 ? "" : " (" + quote_name(img.uri) + ")");
  if (img.image.empty() || img.width <= 0 || img.height <= 0)
    r.fail(what + ": texture " + std::to_string(texture) + ": " + image_name +
           " is missing or could not be decoded");
  const int comps = img.component;
  const int bytes_per = img.bits == 16 ? 2 : 1;
  const std::size_t texels = static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height);
  if (comps < 1 || comps > 4 || (img.bits != 8 && img.bits != 16) ||
      img.image.size() != texels * static_cast<std::size_t>(comps * bytes_per))
    r.fail(what + ": " + image_name + " has an unsupported pixel layout (" + std::to_string(comps) + " channels of " +
           std::to_string(img.bits) + " bits)");
  TextureImage out;
  out.name = escape_name(img.name.empty() ? img.uri.rfind("data:", 0) == 0 ? "embedded" : img.uri : img.name);
  out.width = static_cast<uint32_t>(img.width);
  out.height = static_cast<uint32_t>(img.height);
  out.srgb = srgb;
  out.rgba8.resize(texels * 4);
  for (std::size_t i = 0; i < texels; ++i) {
    uint8_t v[4] = {0, 0, 0, 255};
    for (int c = 0; c < comps; ++c) {
      const std::size_t at = (i * static_cast<std::size_t>(comps) + static_cast<std::size_t>(c)) * static_cast<std::size_t>(bytes_per);
      v[c] = bytes_per == 2 ? img.image[at + 1] : img.image[at];  // 16-bit: little-endian, keep the high byte
    }
    if (comps == 1 || comps == 2) {  // grey (+ alpha)
      v[3] = comps == 2 ? v[1] : 255;
      v[1] = v[2] = v[0];
    }
    std::memcpy(&out.rgba8[i * 4], v, 4);
  }
  if (t.sampler >= 0 && static_cast<std::size_t>(t.sampler) < m.samplers.size()) {
    out.wrap_u = wrap_of(m.samplers[static_cast<std::size_t>(t.sampler)].wrapS);
    out.wrap_v = wrap_of(m.samplers[static_cast<std::size_t>(t.sampler)].wrapT);
  }
  const auto id = static_cast<int32_t>(conv.scene.textures.size());
  conv.scene.textures.push_back(std::move(out));
  conv.texture_ids[key] = id;
  return id;
}

void note_tex_coord(Conversion& conv, int tex_coord, const std::string& what) {
  if (tex_coord != 0) conv.unmapped.insert(what + " uses TEXCOORD_" + std::to_string(tex_coord) + " (TEXCOORD_0 used)");
}

void convert_materials(Conversion& conv, const Importer& imp) {
  const tinygltf::Model& m = imp.model();
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    const tinygltf::Material& src = m.materials[i];
    const std::string what = "material " + std::to_string(i) + " " + quote_name(src.name);
    Material mat;
    mat.name = escape_name(src.name);
    mat.model = MaterialModel::kMetallicRoughness;
    const auto& pbr = src.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() == 4)
      mat.base_color_factor = glm::vec4(glm::make_vec4(pbr.baseColorFactor.data()));
    mat.metallic_factor = static_cast<float>(pbr.metallicFactor);
    mat.roughness_factor = static_cast<float>(pbr.roughnessFactor);
    mat.base_color_texture = scene_texture(conv, imp, pbr.baseColorTexture.index, true, what + " base colour");
    note_tex_coord(conv, pbr.baseColorTexture.index >= 0 ? pbr.baseColorTexture.texCoord : 0, what + " base colour");
    mat.metallic_roughness_texture =
        scene_texture(conv, imp, pbr.metallicRoughnessTexture.index, false, what + " metallic-roughness");
    note_tex_coord(conv, pbr.metallicRoughnessTexture.index >= 0 ? pbr.metallicRoughnessTexture.texCoord : 0,
                   what + " metallic-roughness");
    mat.normal_texture = scene_texture(conv, imp, src.normalTexture.index, false, what + " normal map");
    note_tex_coord(conv, src.normalTexture.index >= 0 ? src.normalTexture.texCoord : 0, what + " normal map");
    mat.normal_scale = static_cast<float>(src.normalTexture.scale);
    mat.alpha_mask = src.alphaMode == "MASK";
    mat.alpha_cutoff = static_cast<float>(src.alphaCutoff);
    mat.double_sided = src.doubleSided;
    if (src.alphaMode == "BLEND") conv.unmapped.insert("alphaMode BLEND (drawn opaque)");
    if (src.emissiveTexture.index >= 0 ||
        (src.emissiveFactor.size() == 3 && (src.emissiveFactor[0] > 0 || src.emissiveFactor[1] > 0 || src.emissiveFactor[2] > 0)))
      conv.unmapped.insert("emissive");
    if (src.occlusionTexture.index >= 0) conv.unmapped.insert("occlusion textures");
    for (const auto& [name, value] : src.extensions) conv.unmapped.insert("material extension " + escape_name(name));
    conv.scene.materials.push_back(std::move(mat));
  }
}

uint32_t material_for(Conversion& conv, const tinygltf::Model& m, int material, const std::string& what,
                      const Reporter& r) {
  if (material >= 0) {
    if (static_cast<std::size_t>(material) >= m.materials.size())
      r.fail(what + ": material " + std::to_string(material) + " does not exist (" + std::to_string(m.materials.size()) +
             " materials)");
    return static_cast<uint32_t>(material);
  }
  if (conv.default_material < 0) {  // glTF's default material: white, metallic 1, roughness 1
    conv.default_material = static_cast<int32_t>(conv.scene.materials.size());
    Material def;
    def.name = "glTF default";
    conv.scene.materials.push_back(def);
  }
  return static_cast<uint32_t>(conv.default_material);
}

bool finite3(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void convert_primitive(Conversion& conv, const Importer& imp, const NodeInstance& inst, int mesh_index, std::size_t p) {
  const tinygltf::Model& m = imp.model();
  const Reporter& r = imp.reporter();
  const tinygltf::Mesh& mesh = m.meshes[static_cast<std::size_t>(mesh_index)];
  const tinygltf::Primitive& prim = mesh.primitives[p];
  const std::string what = "mesh " + std::to_string(mesh_index) + " " + quote_name(mesh.name) + " primitive " + std::to_string(p);
  const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    ++conv.skipped_non_triangle;  // points and lines have no surface to capture
    return;
  }
  // An attribute's accessor index, -1 when the primitive has no such attribute. An index outside
  // the accessors is an error here, before anything reads the accessor's type (found by fuzz_gltf:
  // an optional attribute's accessor type was read out of bounds).
  const auto attr = [&](const char* name) {
    const auto it = prim.attributes.find(name);
    if (it == prim.attributes.end()) return -1;
    imp.accessor(it->second, what + " " + name);
    return it->second;
  };
  const int pos_acc = attr("POSITION");
  if (pos_acc < 0) r.fail(what + " has no POSITION attribute");
  const std::vector<double> pos = imp.read_accessor(pos_acc, 3, what + " POSITION");
  const std::size_t n = pos.size() / 3;
  for (std::size_t i = 0; i < n; ++i)
    if (!finite3({pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]}))
      r.fail(what + " POSITION: vertex " + std::to_string(i) + " is not finite (" + std::to_string(pos[3 * i]) + ", " +
             std::to_string(pos[3 * i + 1]) + ", " + std::to_string(pos[3 * i + 2]) + ")");
  std::vector<uint32_t> source;  // vertex indices in primitive order
  if (prim.indices >= 0) {
    const std::vector<double> idx = imp.read_accessor(prim.indices, 1, what + " indices");
    const int ctype = m.accessors[static_cast<std::size_t>(prim.indices)].componentType;
    if (ctype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ctype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        ctype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      r.fail(what + " indices: component type " + std::to_string(ctype) + " is not an unsigned integer type");
    source.reserve(idx.size());
    for (std::size_t i = 0; i < idx.size(); ++i) {
      if (idx[i] >= static_cast<double>(n))
        r.fail(what + ": index " + std::to_string(i) + " is " + std::to_string(static_cast<uint64_t>(idx[i])) +
               ", out of range for its " + std::to_string(n) + " vertices");
      source.push_back(static_cast<uint32_t>(idx[i]));
    }
  } else {
    source.resize(n);
    for (std::size_t i = 0; i < n; ++i) source[i] = static_cast<uint32_t>(i);
  }
  std::vector<uint32_t> tris;
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (source.size() % 3 != 0)
      r.fail(what + ": " + std::to_string(source.size()) + (prim.indices >= 0 ? " indices" : " vertices") +
             " are not a whole number of triangles");
    tris = source;
  } else {
    for (std::size_t i = 2; i < source.size(); ++i) {
      if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        const bool even = i % 2 == 0;  // every other triangle of a strip is flipped to keep its winding
        tris.insert(tris.end(), {source[i - 2], even ? source[i - 1] : source[i], even ? source[i] : source[i - 1]});
      } else {
        tris.insert(tris.end(), {source[0], source[i - 1], source[i]});
      }
    }
  }
  if (tris.empty()) return;

  const auto optional_attr = [&](const char* name, int comps_a, int comps_b) -> std::pair<std::vector<double>, int> {
    const int acc = attr(name);
    if (acc < 0) return {{}, 0};
    const int comps = type_components(m.accessors[static_cast<std::size_t>(acc)].type);
    const int want = comps == comps_b ? comps_b : comps_a;
    std::vector<double> v = imp.read_accessor(acc, want, what + " " + name);
    if (v.size() / static_cast<std::size_t>(want) != n)
      r.fail(what + " " + std::string(name) + ": " + std::to_string(v.size() / static_cast<std::size_t>(want)) +
             " elements, but POSITION has " + std::to_string(n));
    return {std::move(v), want};
  };
  const auto [normals, nc] = optional_attr("NORMAL", 3, 3);
  const auto [uvs, uc] = optional_attr("TEXCOORD_0", 2, 2);
  const auto [tangents, tc] = optional_attr("TANGENT", 4, 4);
  const auto [colours, cc] = optional_attr("COLOR_0", 3, 4);
  (void)nc;
  (void)uc;
  (void)tc;

  const uint32_t material = material_for(conv, m, prim.material, what, r);
  const Material& mat = conv.scene.materials[material];
  const glm::dmat4& world = inst.world;
  const glm::dmat3 linear(world);
  const glm::dmat3 normal_matrix = glm::inverseTranspose(linear);
  const bool mirrored = glm::determinant(linear) < 0.0;

  std::vector<SceneVertex> verts(n);
  for (std::size_t i = 0; i < n; ++i) {
    SceneVertex& v = verts[i];
    const glm::dvec4 wp = world * glm::dvec4(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], 1.0);
    if (!finite3(glm::dvec3(wp)))
      r.fail(what + ": vertex " + std::to_string(i) + " is not finite after its node transform");
    v.position = glm::vec3(wp);
    v.normal = glm::vec3(0.0f);
    if (!normals.empty()) {
      const glm::dvec3 nn = normal_matrix * glm::dvec3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
      const double len = glm::length(nn);
      if (std::isfinite(len) && len > 1e-12) {
        const double raw = glm::length(glm::dvec3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]));
        if (std::abs(raw - 1.0) > 1e-3) ++conv.normals_normalized;
        v.normal = glm::vec3(nn / len);
      }
    }
    v.diffuse = glm::vec3(1.0f);  // vertex colour (metallic-roughness model)
    if (!colours.empty()) {
      const std::size_t k = static_cast<std::size_t>(cc) * i;
      v.diffuse = glm::clamp(glm::vec3(static_cast<float>(colours[k]), static_cast<float>(colours[k + 1]),
                                       static_cast<float>(colours[k + 2])),
                             0.0f, 1.0f);
    }
    v.specular = glm::vec3(0.04f);
    v.roughness = 1.0f;
    if (!uvs.empty()) v.uv = glm::vec2(static_cast<float>(uvs[2 * i]), static_cast<float>(uvs[2 * i + 1]));
    if (!tangents.empty()) {
      const glm::dvec3 t = linear * glm::dvec3(tangents[4 * i], tangents[4 * i + 1], tangents[4 * i + 2]);
      const double len = glm::length(t);
      const double w = tangents[4 * i + 3] < 0.0 ? -1.0 : 1.0;
      if (std::isfinite(len) && len > 1e-12) v.tangent = glm::vec4(glm::vec3(t / len), static_cast<float>(mirrored ? -w : w));
    }
    v.material = material;
  }
  if (mirrored)  // a mirroring transform turns counter-clockwise triangles clockwise
    for (std::size_t t = 0; t < tris.size(); t += 3) std::swap(tris[t + 1], tris[t + 2]);

  // Normals: missing ones give flat shading (glTF), bad ones (zero, non-finite) the
  // area-weighted normal of the vertex's triangles.
  if (normals.empty()) {
    std::vector<SceneVertex> flat;
    flat.reserve(tris.size());
    for (std::size_t t = 0; t < tris.size(); t += 3) {
      const glm::vec3 a = verts[tris[t]].position, b = verts[tris[t + 1]].position, c = verts[tris[t + 2]].position;
      glm::vec3 fn = glm::cross(b - a, c - a);
      const float len = glm::length(fn);
      fn = len > 0.0f ? fn / len : glm::vec3(0.0f, 1.0f, 0.0f);
      for (int k = 0; k < 3; ++k) {
        flat.push_back(verts[tris[t + static_cast<std::size_t>(k)]]);
        flat.back().normal = fn;
      }
    }
    verts = std::move(flat);
    for (std::size_t i = 0; i < tris.size(); ++i) tris[i] = static_cast<uint32_t>(i);
  } else {
    std::vector<glm::vec3> accumulated(n, glm::vec3(0.0f));
    bool any_bad = false;
    for (const SceneVertex& v : verts) any_bad = any_bad || v.normal == glm::vec3(0.0f);
    if (any_bad) {
      for (std::size_t t = 0; t < tris.size(); t += 3) {
        const glm::vec3 a = verts[tris[t]].position, b = verts[tris[t + 1]].position, c = verts[tris[t + 2]].position;
        const glm::vec3 fn = glm::cross(b - a, c - a);  // length = twice the area: area weighting
        for (int k = 0; k < 3; ++k) accumulated[tris[t + static_cast<std::size_t>(k)]] += fn;
      }
      for (std::size_t i = 0; i < n; ++i) {
        if (verts[i].normal != glm::vec3(0.0f)) continue;
        ++conv.normals_replaced;
        const float len = glm::length(accumulated[i]);
        verts[i].normal = len > 0.0f ? accumulated[i] / len : glm::vec3(0.0f, 1.0f, 0.0f);
      }
    }
  }
  if (mat.normal_texture >= 0 && tangents.empty()) {
    compute_tangents(verts, tris);
    conv.tangents_computed += verts.size();
  }

  SceneMesh& out = conv.scene.mesh;
  const auto base = static_cast<uint32_t>(out.vertices.size());
  if (out.vertices.size() + verts.size() > std::numeric_limits<uint32_t>::max())
    r.fail("has more than 2^32 vertices in its default scene");
  out.vertices.insert(out.vertices.end(), verts.begin(), verts.end());
  for (uint32_t i : tris) out.indices.push_back(base + i);
}

// Every node of the default scene (else of the first scene, else every root node) with its world
// matrix; a node reached twice on one path (a cycle) is an error.
std::vector<NodeInstance> scene_nodes(const tinygltf::Model& m, const Reporter& r, std::vector<std::string>& notes) {
  std::vector<int> roots;
  if (!m.scenes.empty()) {
    int s = m.defaultScene;
    if (s < 0 || static_cast<std::size_t>(s) >= m.scenes.size()) {
      if (m.scenes.size() > 1) notes.push_back("no default scene: scene 0 of " + std::to_string(m.scenes.size()) + " drawn");
      s = 0;
    }
    roots = m.scenes[static_cast<std::size_t>(s)].nodes;
  } else {
    std::vector<bool> child(m.nodes.size(), false);
    for (const tinygltf::Node& node : m.nodes)
      for (int c : node.children)
        if (c >= 0 && static_cast<std::size_t>(c) < m.nodes.size()) child[static_cast<std::size_t>(c)] = true;
    for (std::size_t i = 0; i < m.nodes.size(); ++i)
      if (!child[i]) roots.push_back(static_cast<int>(i));
  }
  std::vector<NodeInstance> out;
  std::vector<bool> on_path(m.nodes.size(), false);
  const std::function<void(int, const glm::dmat4&)> visit = [&](int index, const glm::dmat4& parent) {
    if (index < 0 || static_cast<std::size_t>(index) >= m.nodes.size())
      r.fail("node " + std::to_string(index) + " does not exist (" + std::to_string(m.nodes.size()) + " nodes)");
    if (on_path[static_cast<std::size_t>(index)]) r.fail("node " + std::to_string(index) + " is its own ancestor (a cycle)");
    if (out.size() > 10'000'000) r.fail("instantiates more than 10 million nodes");
    on_path[static_cast<std::size_t>(index)] = true;
    const tinygltf::Node& node = m.nodes[static_cast<std::size_t>(index)];
    const glm::dmat4 world = parent * node_local_matrix(node);
    out.push_back({index, world});
    for (int c : node.children) visit(c, world);
    on_path[static_cast<std::size_t>(index)] = false;
  };
  for (int root : roots) visit(root, glm::dmat4(1.0));
  return out;
}

CameraDesc framing_camera(glm::vec3 lo, glm::vec3 hi, float fov_y_deg) {
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
  // From the front (+z) and somewhat above: the usual glTF orientation (y up, facing +z).
  const glm::vec3 dir = glm::normalize(glm::vec3(0.35f, 0.45f, 1.0f));
  const float distance = radius / std::sin(glm::radians(0.5f * fov_y_deg)) * 1.05f;
  CameraDesc c;
  c.position = centre + dir * distance;
  c.target = centre;
  c.up = glm::vec3(0.0f, 1.0f, 0.0f);
  c.fov_y_deg = fov_y_deg;
  c.near_plane = std::max(0.5f * (distance - radius), 1e-3f * (distance + radius));
  c.far_plane = 1.5f * (distance + radius);
  return c;
}

float far_for(glm::vec3 eye, glm::vec3 lo, glm::vec3 hi) {
  float far = 0.0f;
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
    far = std::max(far, glm::length(corner - eye));
  }
  return far * 1.05f + 1e-3f;
}

std::string vec_text(glm::vec3 v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", static_cast<double>(v.x), static_cast<double>(v.y),
                static_cast<double>(v.z));
  return buf;
}

}  // namespace

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

// tinygltf 2.7 (Debian 12) hands an image's bufferView to the decoder as
// &buffer.data[byteOffset] with byteLength bytes, without checking that the view lies inside its
// buffer: a file whose view runs past the buffer made stb_image read past the heap block (found
// by fuzz_gltf). This loader checks the view against the model being filled (its buffers and
// views are parsed before the images) and only then lets tinygltf's own decoder run.
struct ImageLoadContext {
  const tinygltf::Model* model = nullptr;
};

bool load_image_checked(tinygltf::Image* image, const int image_idx, std::string* err, std::string* warn,
                        int req_width, int req_height, const unsigned char* bytes, int size, void* user_data) {
  const auto* ctx = static_cast<const ImageLoadContext*>(user_data);
  if (image->bufferView >= 0) {
    const tinygltf::Model& m = *ctx->model;
    // The loader found both indices valid before calling; the range is what it does not check.
    const tinygltf::BufferView& view = m.bufferViews[static_cast<std::size_t>(image->bufferView)];
    const tinygltf::Buffer& buffer = m.buffers[static_cast<std::size_t>(view.buffer)];
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset) {
      if (err != nullptr) {
        *err += "image " + std::to_string(image_idx) + ": bufferView " + std::to_string(image->bufferView) +
                " (offset " + std::to_string(view.byteOffset) + ", " + std::to_string(view.byteLength) +
                " bytes) runs past the end of buffer " + std::to_string(view.buffer) + " (" +
                std::to_string(buffer.data.size()) + " bytes)";
      }
      return false;
    }
  }
  return tinygltf::LoadImageData(image, image_idx, err, warn, req_width, req_height, bytes, size, nullptr);
}

}  // namespace

GltfImport import_gltf(const std::filesystem::path& path, const GltfCameraChoice& camera_choice,
                       const GltfLightChoice& light_choice, bool ground) {
  if (camera_choice.camera && (camera_choice.eye || camera_choice.look_at || camera_choice.fov_y_deg))
    throw UsageError("--camera picks a camera of the file; it cannot be combined with --eye/--look-at/--fov");
  GltfImport out;
  // The path is the user's own: shown whole (escaped, never cut), so a message names the file
  // however deep it lies.
  out.file = printable_text(path.string(), std::string_view::npos);
  const Reporter r(out.file);
  const std::vector<unsigned char> bytes = read_bytes(path, r);
  require_gltf2(bytes, r);

  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  ImageLoadContext image_context{&model};
  loader.SetImageLoader(load_image_checked, &image_context);
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

  Fnv1a hash;
  hash.add(bytes.data(), bytes.size());
  for (const tinygltf::Buffer& b : model.buffers) hash.add(b.data.data(), b.data.size());
  for (const tinygltf::Image& img : model.images) hash.add(img.image.data(), img.image.size());
  out.content_hash = hash.text();

  const Importer imp(model, r);
  Conversion conv;
  conv.scene.name = scene_name_from_file(path);
  convert_materials(conv, imp);
  const std::vector<NodeInstance> nodes = scene_nodes(model, r, out.notes);
  std::vector<CameraInstance> cameras;
  std::vector<LightInstance> lights;
  for (const NodeInstance& inst : nodes) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(inst.node)];
    if (node.mesh >= 0) {
      if (static_cast<std::size_t>(node.mesh) >= model.meshes.size())
        r.fail("node " + std::to_string(inst.node) + " refers to mesh " + std::to_string(node.mesh) + " of " +
               std::to_string(model.meshes.size()));
      const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(node.mesh)];
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        if (!mesh.primitives[p].targets.empty()) conv.unmapped.insert("morph targets (rest pose drawn)");
        convert_primitive(conv, imp, inst, node.mesh, p);
      }
    }
    if (node.skin >= 0) conv.unmapped.insert("skins (rest pose drawn)");
    if (node.camera >= 0 && static_cast<std::size_t>(node.camera) < model.cameras.size())
      cameras.push_back({node.camera, inst.node, inst.world});
    const int light = node_light(node);
    if (light >= 0 && static_cast<std::size_t>(light) < model.lights.size()) lights.push_back({light, inst.node, inst.world});
  }
  if (!model.animations.empty()) conv.unmapped.insert("animations (rest pose drawn)");
  const SceneMesh& mesh = conv.scene.mesh;
  out.triangles = mesh.indices.size() / 3;
  if (out.triangles == 0)
    r.fail("its default scene has no triangles" +
           (conv.skipped_non_triangle > 0
                ? " (" + std::to_string(conv.skipped_non_triangle) + " point/line primitives are not surfaces)"
                : std::string()));

  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (uint32_t i : mesh.indices) {
    lo = glm::min(lo, mesh.vertices[i].position);
    hi = glm::max(hi, mesh.vertices[i].position);
  }
  out.bounds_lo = lo;
  out.bounds_hi = hi;
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
  if (!std::isfinite(radius)) r.fail("its bounds are not finite");
  // The ground: a grey floor just under the bounds, 6 radii wide (kNoMaterial: constant albedos).
  // Camera framing and the automatic light use the file's bounds; the far planes include it.
  glm::vec3 far_lo = lo, far_hi = hi;
  if (ground) {
    const float y = lo.y - 1e-3f * radius;
    const glm::vec3 g_lo(centre.x - 3.0f * radius, y, centre.z - 3.0f * radius);
    const glm::vec3 g_hi(centre.x + 3.0f * radius, y, centre.z + 3.0f * radius);
    const SurfaceMaterial grey{glm::vec3(0.5f), glm::vec3(0.04f), 0.5f, kNoMaterial};
    const std::size_t before = conv.scene.mesh.indices.size();
    add_axis_rect(conv.scene.mesh, g_lo, g_hi, {0.0f, 1.0f, 0.0f}, grey, radius);
    char where[64];
    std::snprintf(where, sizeof where, "%.4g", static_cast<double>(y));
    out.notes.push_back("--ground: a grey floor of " + std::to_string((conv.scene.mesh.indices.size() - before) / 3) +
                        " triangles added at y = " + where);
    far_lo = glm::min(far_lo, g_lo);
    far_hi = glm::max(far_hi, g_hi);
  }

  // The camera.
  CameraDesc cam;
  const auto camera_from = [&](const CameraInstance& c) {
    const tinygltf::Camera& src = model.cameras[static_cast<std::size_t>(c.camera)];
    const std::string label = "camera " + std::to_string(c.camera) + " " + quote_name(src.name);
    if (src.type != "perspective")
      r.fail(label + " is " + escape_name(src.type) + "; only perspective cameras are supported (use --eye/--look-at)");
    const glm::dmat3 linear(c.world);
    CameraDesc d;
    d.position = glm::vec3(c.world[3]);
    const glm::vec3 forward = glm::normalize(glm::vec3(linear * glm::dvec3(0.0, 0.0, -1.0)));
    d.up = glm::normalize(glm::vec3(linear * glm::dvec3(0.0, 1.0, 0.0)));
    if (!finite3(glm::dvec3(forward)) || !finite3(glm::dvec3(d.up))) r.fail(label + " has a degenerate node transform");
    d.target = d.position + forward * std::max(glm::length(centre - d.position), 1e-3f);
    d.fov_y_deg = static_cast<float>(src.perspective.yfov * 180.0 / std::numbers::pi);
    if (!(d.fov_y_deg > 0.1f && d.fov_y_deg < 179.0f)) r.fail(label + " has a field of view of " + std::to_string(d.fov_y_deg) + " degrees");
    d.near_plane = static_cast<float>(src.perspective.znear > 0.0 ? src.perspective.znear : 1e-3 * static_cast<double>(radius));
    // The file's far plane (infinite when absent), cut to the farthest corner of the bounds: a
    // far plane a million times the near one would waste the depth buffer's precision.
    d.far_plane = far_for(d.position, far_lo, far_hi);
    if (src.perspective.zfar > src.perspective.znear) d.far_plane = std::min(d.far_plane, static_cast<float>(src.perspective.zfar));
    if (!(d.far_plane > d.near_plane)) r.fail(label + " sees nothing of the scene: its near plane lies beyond the bounds");
    out.camera_source = "the file's " + label + " on node " + std::to_string(c.node) +
                        " (aspect ratio from the G-buffer size)";
    return d;
  };
  if (camera_choice.camera) {
    const std::string& want = *camera_choice.camera;
    const CameraInstance* found = nullptr;
    const bool numeric = !want.empty() && std::all_of(want.begin(), want.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
    for (const CameraInstance& c : cameras) {
      const tinygltf::Camera& src = model.cameras[static_cast<std::size_t>(c.camera)];
      const bool match = numeric ? std::to_string(c.camera) == want
                                 : src.name == want || model.nodes[static_cast<std::size_t>(c.node)].name == want;
      if (match) {
        found = &c;
        break;
      }
    }
    if (found == nullptr) {
      std::string list;
      for (const CameraInstance& c : cameras)
        list += (list.empty() ? "" : ", ") + std::to_string(c.camera) + " " +
                quote_name(model.cameras[static_cast<std::size_t>(c.camera)].name);
      r.fail("has no camera " + quote_name(want) + " in its default scene (cameras: " + (list.empty() ? "none" : list) + ")");
    }
    cam = camera_from(*found);
  } else if (camera_choice.eye || camera_choice.look_at || camera_choice.fov_y_deg) {
    cam = framing_camera(lo, hi, camera_choice.fov_y_deg.value_or(50.0f));
    if (camera_choice.eye) cam.position = *camera_choice.eye;
    if (camera_choice.look_at) cam.target = *camera_choice.look_at;
    if (glm::length(cam.target - cam.position) < 1e-6f) throw UsageError("--eye and --look-at are the same point");
    const glm::vec3 fwd = glm::normalize(cam.target - cam.position);
    if (std::abs(fwd.y) > 0.999f) cam.up = glm::vec3(0.0f, 0.0f, -1.0f);
    const float far = far_for(cam.position, far_lo, far_hi);
    cam.far_plane = far;
    cam.near_plane = std::max(1e-4f * far, 1e-3f * radius);
    out.camera_source = "the command line: eye " + vec_text(cam.position) + ", look-at " + vec_text(cam.target) +
                        ", fov " + std::to_string(static_cast<int>(std::lround(cam.fov_y_deg))) + " degrees";
  } else if (!cameras.empty()) {
    cam = camera_from(cameras.front());
  } else {
    cam = framing_camera(lo, hi, 50.0f);
    out.camera_source = "automatic framing of the bounds " + vec_text(lo) + " - " + vec_text(hi) + " (no camera in the file)";
  }
  conv.scene.camera = cam;

  // The spot light.
  SpotLightDesc light;
  const LightInstance* file_spot = nullptr;
  std::size_t other_lights = 0;
  for (const LightInstance& l : lights) {
    if (model.lights[static_cast<std::size_t>(l.light)].type == "spot") {
      if (file_spot == nullptr) file_spot = &l;
    } else {
      ++other_lights;
    }
  }
  if (file_spot != nullptr) {
    const tinygltf::Light& src = model.lights[static_cast<std::size_t>(file_spot->light)];
    const glm::dmat3 linear(file_spot->world);
    light.position = glm::vec3(file_spot->world[3]);
    light.direction = glm::normalize(glm::vec3(linear * glm::dvec3(0.0, 0.0, -1.0)));
    light.cone_half_angle_deg = static_cast<float>(src.spot.outerConeAngle * 180.0 / std::numbers::pi);
    glm::vec3 colour(1.0f);
    if (src.color.size() == 3) colour = glm::vec3(glm::make_vec3(src.color.data()));
    light.intensity = colour * static_cast<float>(src.intensity);  // candela read as W/sr
    out.light_source = "the file's spot light " + std::to_string(file_spot->light) + " " + quote_name(src.name) +
                       " on node " + std::to_string(file_spot->node);
  } else {
    // Above the centre, at twice the bounds' radius, aimed straight down; the cone covers the
    // bounds, and the intensity gives an irradiance of pi W/m^2 at the centre.
    const float height = 2.0f * radius;
    light.position = centre + glm::vec3(0.0f, height, 0.0f);
    light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    light.cone_half_angle_deg = 30.0f;
    light.intensity = glm::vec3(std::numbers::pi_v<float> * height * height);
    out.light_source = "an automatic spot above the centre of the bounds" +
                       std::string(other_lights > 0 ? " (the file's point/directional lights are not spots)" : " (no spot light in the file)");
  }
  if (light_choice.position || light_choice.direction || light_choice.cone_half_angle_deg || light_choice.intensity) {
    if (light_choice.position) light.position = *light_choice.position;
    if (light_choice.direction) {
      if (!(glm::length(*light_choice.direction) > 1e-6f)) throw UsageError("--light-dir must not be zero");
      light.direction = glm::normalize(*light_choice.direction);
    }
    if (light_choice.cone_half_angle_deg) light.cone_half_angle_deg = *light_choice.cone_half_angle_deg;
    if (light_choice.intensity) light.intensity = *light_choice.intensity;
    out.light_source += ", with --light-pos/--light-dir/--cone/--intensity applied";
  }
  if (!(light.cone_half_angle_deg > 0.5f && light.cone_half_angle_deg <= 85.0f))
    r.fail("the spot light's cone half angle is " + std::to_string(light.cone_half_angle_deg) +
           " degrees; it must lie in (0.5, 85] (the RSM is a perspective view of twice that angle)");
  light.up = spot_light_up(light.direction);
  light.far_plane = far_for(light.position, far_lo, far_hi);
  light.near_plane = std::max(1e-4f * light.far_plane, 1e-3f * radius);
  out.light_source += ": position " + vec_text(light.position) + ", direction " + vec_text(light.direction) +
                      ", cone " + std::to_string(static_cast<int>(std::lround(light.cone_half_angle_deg))) +
                      " degrees, intensity " + vec_text(light.intensity) + " W/sr";
  conv.scene.light = light;

  if (conv.skipped_non_triangle > 0)
    out.notes.push_back(std::to_string(conv.skipped_non_triangle) + " point/line primitives skipped (no surface)");
  if (conv.normals_normalized > 0)
    out.notes.push_back(std::to_string(conv.normals_normalized) + " normals were not unit length and were normalized");
  if (conv.normals_replaced > 0)
    out.notes.push_back(std::to_string(conv.normals_replaced) +
                        " normals were zero or not finite and were replaced by the surface's normal");
  if (conv.tangents_computed > 0)
    out.notes.push_back("tangents computed for " + std::to_string(conv.tangents_computed) + " normal-mapped vertices");
  for (const std::string& u : conv.unmapped) out.notes.push_back("not mapped: " + u);

  out.motion = SceneMotion{0.02f * radius, 1.5f, 0.03f * radius};
  out.scene = std::move(conv.scene);
  return out;
}

Scene gltf_frame(const GltfImport& import, uint32_t frame, uint32_t frames) {
  Scene scene = import.scene;
  animate_scene(scene, import.motion, frame, frames);
  return scene;
}

}  // namespace vsgl
