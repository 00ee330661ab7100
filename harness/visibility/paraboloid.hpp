#pragma once
// C++ twin of kernels/include/paraboloid.glsl: the paraboloid (hemisphere) parameterization of an
// imperfect shadow map (DESIGN.md §8a.2), the same formulas in float32. A unit direction l in the
// frame (t, b, n) of a map's axis n, l.z >= 0, maps to p = l.xy / (1 + l.z) in the unit disk, and
// back by l = (2 p, 1 - |p|^2) / (1 + |p|^2).
#include <cstdint>

#include <glm/glm.hpp>

namespace vsgl {

struct ParaboloidFrame {
  glm::vec3 t{1.0f, 0.0f, 0.0f};
  glm::vec3 b{0.0f, 1.0f, 0.0f};
  glm::vec3 n{0.0f, 0.0f, 1.0f};
  // A world direction in the frame, and back.
  glm::vec3 local(glm::vec3 d) const { return {glm::dot(d, t), glm::dot(d, b), glm::dot(d, n)}; }
  glm::vec3 world(glm::vec3 l) const { return l.x * t + l.y * b + l.z * n; }
};

// The orthonormal frame about the unit axis n (Duff et al. 2017), as paraboloid_frame().
ParaboloidFrame paraboloid_frame(glm::vec3 n);
// The disk point of a direction in the frame (l.z >= 0).
glm::vec2 paraboloid_project(glm::vec3 l);
// The unit direction, in the frame, of a disk point (|p| <= 1).
glm::vec3 paraboloid_unproject(glm::vec2 p);
// The texel of a side x side map holding disk point p, clamped to the map.
glm::uvec2 paraboloid_texel(glm::vec2 p, uint32_t side);
// The centre of texel (i, j) of a side x side map, in the disk's coordinates.
glm::vec2 paraboloid_texel_centre(glm::uvec2 texel, uint32_t side);
// The angle one texel spans at p: 4 / (side (1 + |p|^2)).
float paraboloid_texel_angle(glm::vec2 p, uint32_t side);

}  // namespace vsgl
