#pragma once
// A point on a scene's surface, as the imperfect shadow maps splat it (DESIGN.md §8a.2) and a
// capture stores it (§3, visibility geometry): drawn on one triangle of a soup, carrying that
// triangle's geometric normal and index.
#include <cstdint>

#include <glm/glm.hpp>

namespace vsgl {

struct SurfacePoint {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};  // the triangle's geometric normal, normalize(cross(b - a, c - a))
  uint32_t triangle = 0;   // index of the triangle in the soup
};

}  // namespace vsgl
