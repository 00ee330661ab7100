#pragma once
// What the glTF and the OBJ importers share once a file's triangles are in a Conversion: the
// bounds the camera and light are placed by, the --ground floor, the notes on what was repaired,
// and a decoded image (tinygltf's image loader: PNG, JPEG, ...) as a TextureImage.
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "harness/scene/detail/gltf_accessors.hpp"
#include "harness/scene/detail/gltf_conversion.hpp"
#include "harness/scene/detail/gltf_nodes.hpp"
#include "harness/scene/scene.hpp"

namespace vsgl::gltf {

// The extent of the mesh's triangles; an error when it is not finite.
SceneBounds triangle_bounds(const SceneMesh& mesh, const Reporter& r);

// The ground: a grey floor just under the bounds, 6 radii wide (kNoMaterial: constant albedos).
// Camera framing and the automatic light use the file's bounds; the far planes include it.
void add_ground(SceneMesh& mesh, SceneBounds& b, std::vector<std::string>& notes);

// What the conversion repaired or skipped, then what the file has that is not mapped.
void conversion_notes(const Conversion& conv, std::vector<std::string>& notes);

// A decoded image (1-4 channels of 8 or 16 bits) as RGBA8, grey spread to RGB; `what` and
// `image_name` name it in the error for an empty image or an unsupported layout.
TextureImage rgba8_texture(const tinygltf::Image& img, bool srgb, const std::string& what,
                           const std::string& image_name, const Reporter& r);

}  // namespace vsgl::gltf
