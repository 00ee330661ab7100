// The paraboloid parameterization of the imperfect shadow maps (harness/visibility/paraboloid.hpp,
// the CPU twin of kernels/include/paraboloid.glsl; DESIGN.md §8a.2): the frame is orthonormal, the
// projection and its inverse round-trip, the axis is the disk's centre and the horizon its rim, and
// the texel angle the lookup's bias is scaled by is the angle a texel spans.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "harness/visibility/paraboloid.hpp"

namespace vsgl {
namespace {

std::vector<glm::vec3> paraboloid_test_axes() {
  std::vector<glm::vec3> axes = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, {0, 1e-7f, -1}};
  std::mt19937 rng(5);
  std::normal_distribution<float> g;
  for (int i = 0; i < 200; ++i) axes.push_back(glm::normalize(glm::vec3(g(rng), g(rng), g(rng))));
  return axes;
}

TEST(IsmParaboloid, TheFrameIsOrthonormalAndRightHanded) {
  for (const glm::vec3 n : paraboloid_test_axes()) {
    const ParaboloidFrame f = paraboloid_frame(n);
    EXPECT_NEAR(glm::length(f.t), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(f.b), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(f.t, f.b), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(f.t, n), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(f.b, n), 0.0f, 1e-6f);
    EXPECT_LT(glm::length(glm::cross(f.t, f.b) - n), 1e-6f);
  }
}

TEST(IsmParaboloid, ProjectionAndInverseRoundTrip) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (const glm::vec3 n : paraboloid_test_axes()) {
    const ParaboloidFrame f = paraboloid_frame(n);
    for (int i = 0; i < 50; ++i) {
      // A world direction in the hemisphere about n, to the disk and back.
      glm::vec3 d = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
      if (glm::dot(d, n) < 0.0f) d = -d;
      const glm::vec2 p = paraboloid_project(f.local(d));
      EXPECT_LE(glm::length(p), 1.0f + 1e-6f);
      EXPECT_LT(glm::length(f.world(paraboloid_unproject(p)) - d), 2e-6f);
      // A disk point to its direction and back.
      glm::vec2 q(u(rng), u(rng));
      if (glm::length(q) > 1.0f) q /= 1.0001f * glm::length(q);
      const glm::vec3 l = paraboloid_unproject(q);
      EXPECT_NEAR(glm::length(l), 1.0f, 1e-6f);
      EXPECT_GE(l.z, 0.0f);
      EXPECT_LT(glm::length(paraboloid_project(l) - q), 1e-6f);
    }
  }
}

TEST(IsmParaboloid, TheAxisIsTheCentreAndTheHorizonTheRim) {
  EXPECT_EQ(paraboloid_project({0, 0, 1}), glm::vec2(0.0f));
  EXPECT_EQ(paraboloid_unproject(glm::vec2(0.0f)), glm::vec3(0, 0, 1));
  for (float a = 0.0f; a < 6.3f; a += 0.1f) {
    const glm::vec3 horizon(std::cos(a), std::sin(a), 0.0f);
    EXPECT_NEAR(glm::length(paraboloid_project(horizon)), 1.0f, 1e-6f);
  }
  // 60 degrees from the axis: r = tan(30 degrees).
  EXPECT_NEAR(glm::length(paraboloid_project({std::sqrt(3.0f) / 2.0f, 0.0f, 0.5f})), std::tan(0.5236f), 1e-4f);
}

TEST(IsmParaboloid, TexelsAndTheirCentresAgree) {
  for (uint32_t side : {2u, 64u, 256u})
    for (uint32_t y = 0; y < side; y += 1 + side / 16)
      for (uint32_t x = 0; x < side; x += 1 + side / 16) {
        const glm::uvec2 t(x, y);
        EXPECT_EQ(paraboloid_texel(paraboloid_texel_centre(t, side), side), t);
      }
  // Points on or past the map's edge stay on the map.
  EXPECT_EQ(paraboloid_texel({1.0f, -1.0f}, 64), glm::uvec2(63, 0));
  EXPECT_EQ(paraboloid_texel({1.5f, -1.5f}, 64), glm::uvec2(63, 0));
}

// The angle between the directions of two neighbouring texel centres is the texel angle at their
// midpoint, to the second order of a texel (1 % at 64^2): 4/side at the axis, 2/side at the rim.
TEST(IsmParaboloid, TheTexelAngleIsTheAngleBetweenNeighbouringTexels) {
  const uint32_t side = 64;
  const float step = 2.0f / static_cast<float>(side);
  for (float r = 0.0f; r < 0.95f; r += 0.05f)
    for (float a : {0.0f, 0.7f, 2.0f}) {
      const glm::vec2 dir(std::cos(a), std::sin(a));
      const glm::vec2 across(-dir.y, dir.x);
      for (const glm::vec2 along : {dir, across}) {
        const glm::vec2 p = r * dir;
        const float angle = std::acos(std::clamp(
            glm::dot(paraboloid_unproject(p - 0.5f * step * along), paraboloid_unproject(p + 0.5f * step * along)),
            -1.0f, 1.0f));
        EXPECT_NEAR(angle / paraboloid_texel_angle(p, side), 1.0f, 0.01f) << "r " << r << " angle " << a;
      }
    }
  EXPECT_FLOAT_EQ(paraboloid_texel_angle({0, 0}, side), 4.0f / 64.0f);
  EXPECT_FLOAT_EQ(paraboloid_texel_angle({1, 0}, side), 2.0f / 64.0f);
}

}  // namespace
}  // namespace vsgl
