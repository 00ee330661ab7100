#pragma once
// A user's scene file by its extension (case-insensitive): .gltf / .glb -> import_gltf,
// .obj -> import_obj; anything else is an InputError naming the file and the supported extensions.
#include <filesystem>

#include "harness/scene/gltf_scene.hpp"

namespace vsgl {

GltfImport import_model(const std::filesystem::path& file, const GltfCameraChoice& camera = {},
                        const GltfLightChoice& light = {}, bool ground = false);

}  // namespace vsgl
