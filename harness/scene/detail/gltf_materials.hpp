#pragma once
// glTF import, part 2 of 4: metallic-roughness materials and their textures (base colour in sRGB,
// metallic-roughness, normal map), decoded to RGBA8 with the file's wrap modes; what a material
// uses that is not mapped goes to Conversion::unmapped.
#include <cstdint>
#include <string>

#include "harness/scene/detail/gltf_accessors.hpp"
#include "harness/scene/detail/gltf_conversion.hpp"

namespace vsgl::gltf {

// Every material of the file, in order (Scene::materials[i] is the file's material i).
void convert_materials(Conversion& conv, const Importer& imp);

// The scene material of a primitive's `material`; -1 is glTF's default material, added once.
uint32_t material_for(Conversion& conv, const tinygltf::Model& m, int material, const std::string& what,
                      const Reporter& r);

}  // namespace vsgl::gltf
