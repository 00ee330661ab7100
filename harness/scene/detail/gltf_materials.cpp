#include "harness/scene/detail/gltf_materials.hpp"

#include <cstring>
#include <tuple>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "harness/scene/detail/model_import.hpp"

namespace vsgl::gltf {
namespace {

TextureWrap wrap_of(int gl_wrap) {
  switch (gl_wrap) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::kClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::kMirroredRepeat;
    default: return TextureWrap::kRepeat;
  }
}

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
  TextureImage out = rgba8_texture(img, srgb, what + ": texture " + std::to_string(texture), image_name, r);
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

}  // namespace

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

}  // namespace vsgl::gltf
