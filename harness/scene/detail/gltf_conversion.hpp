#pragma once
// glTF import: the scene being filled while a file is converted, shared by its parts
// (gltf_materials, gltf_nodes, gltf_scene.cpp), and what they count for the notes.
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "harness/scene/scene.hpp"

namespace vsgl::gltf {

struct Conversion {
  Scene scene;
  std::vector<std::string> notes;
  std::map<std::tuple<int, bool>, int32_t> texture_ids;  // (glTF texture, sRGB) -> Scene::textures
  int32_t default_material = -1;
  uint64_t normals_normalized = 0, normals_replaced = 0, tangents_computed = 0;
  uint64_t skipped_non_triangle = 0;
  std::set<std::string> unmapped;
};

}  // namespace vsgl::gltf
