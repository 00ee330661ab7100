#include "harness/visibility/paraboloid.hpp"

#include <algorithm>
#include <cmath>

namespace vsgl {

ParaboloidFrame paraboloid_frame(glm::vec3 n) {
  const float s = n.z >= 0.0f ? 1.0f : -1.0f;
  const float a = -1.0f / (s + n.z);
  const float c = n.x * n.y * a;
  return {glm::vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x), glm::vec3(c, s + n.y * n.y * a, -n.y), n};
}

glm::vec2 paraboloid_project(glm::vec3 l) { return glm::vec2(l) / (1.0f + l.z); }

glm::vec3 paraboloid_unproject(glm::vec2 p) {
  const float r2 = glm::dot(p, p);
  return glm::vec3(2.0f * p, 1.0f - r2) / (1.0f + r2);
}

glm::uvec2 paraboloid_texel(glm::vec2 p, uint32_t side) {
  const glm::vec2 u = (p * 0.5f + 0.5f) * static_cast<float>(side);
  const int top = static_cast<int>(side) - 1;
  return {static_cast<uint32_t>(std::clamp(static_cast<int>(std::floor(u.x)), 0, top)),
          static_cast<uint32_t>(std::clamp(static_cast<int>(std::floor(u.y)), 0, top))};
}

glm::vec2 paraboloid_texel_centre(glm::uvec2 texel, uint32_t side) {
  return (glm::vec2(texel) + 0.5f) * (2.0f / static_cast<float>(side)) - 1.0f;
}

float paraboloid_texel_angle(glm::vec2 p, uint32_t side) {
  return 4.0f / (static_cast<float>(side) * (1.0f + glm::dot(p, p)));
}

}  // namespace vsgl
