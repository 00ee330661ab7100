#pragma once
// The geometry that occludes (DESIGN.md §8a): a plain list of triangles, three corners each, in
// world space. Not indexed: a scene's meshes become one soup by writing out each index triple, and
// the BVH reorders triangles freely, so shared corners would buy nothing but an indirection on the
// GPU. Degenerate triangles are allowed (they never occlude).
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vsgl {

struct TriangleSoup {
  std::vector<glm::vec3> vertices;  // 3 per triangle: triangle k is vertices[3k], [3k + 1], [3k + 2]

  std::size_t triangle_count() const { return vertices.size() / 3; }
};

// Throws InputError when the vertex count is not a multiple of 3 or a coordinate is not finite
// (a NaN or infinity would make every box test and the node array meaningless).
void require_valid_soup(const TriangleSoup& soup);

// 64-bit FNV-1a of the vertices' little-endian float bytes, as "fnv1a64:<16 hex>", like the
// capture's channel hashes (capture/capture.hpp): identifies the occluders exactly.
std::string soup_content_hash(const TriangleSoup& soup);

}  // namespace vsgl
