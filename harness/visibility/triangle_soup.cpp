#include "harness/visibility/triangle_soup.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "harness/core/content_hash.hpp"
#include "harness/core/error.hpp"

namespace vsgl {

void require_valid_soup(const TriangleSoup& soup) {
  if (soup.vertices.size() % 3 != 0)
    throw InputError("triangle soup: " + std::to_string(soup.vertices.size()) +
                     " vertices, not a whole number of triangles (3 corners each)");
  for (std::size_t i = 0; i < soup.vertices.size(); ++i) {
    const glm::vec3& v = soup.vertices[i];
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw InputError("triangle soup: vertex " + std::to_string(i) + " of triangle " + std::to_string(i / 3) +
                       " has a coordinate that is not finite");
  }
}

std::string soup_content_hash(const TriangleSoup& soup) {
  // Over the little-endian bytes of the floats, x y z per vertex (glm::vec3 holds exactly those).
  static_assert(std::endian::native == std::endian::little);
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
  return fnv1a64_text(
      std::string_view(reinterpret_cast<const char*>(soup.vertices.data()), soup.vertices.size() * sizeof(glm::vec3)));
}

}  // namespace vsgl
