// The capture's projection (capture/view_matrices.cpp) is glm's, flipped for Vulkan, with a tangent
// that is the same on every C library (core/portable_float.hpp, DESIGN.md §13.1): captures recorded
// on Windows and on Linux then hash alike.
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "harness/capture/view_matrices.hpp"
#include "harness/core/portable_float.hpp"

namespace vsgl {
namespace {

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Every entry but the tangent's is glm::perspective's own float arithmetic; the tangent is the
// portable one, so the matrix equals glm's built from that tangent.
TEST(ViewMatrices, CameraProjectionIsGlmsWithThePortableTangent) {
  CameraDesc camera;
  camera.position = {0.0f, 1.0f, 5.0f};
  camera.target = {0.0f, 1.0f, 0.0f};
  camera.up = {0.0f, 1.0f, 0.0f};
  camera.near_plane = 0.05f;
  camera.far_plane = 80.0f;
  for (float fov_deg : {30.0f, 45.0f, 54.4f, 60.0f, 75.0f}) {
    camera.fov_y_deg = fov_deg;
    const float aspect = 1920.0f / 1088.0f;
    const glm::mat4 p = camera_matrices(camera, aspect).projection;
    const float t = portable::tan(glm::radians(fov_deg) / 2.0f);
    EXPECT_TRUE(same_bits(p[1][1], -(1.0f / t))) << fov_deg;
    EXPECT_TRUE(same_bits(p[0][0], 1.0f / (aspect * t))) << fov_deg;
    const glm::mat4 g = glm::perspective(glm::radians(fov_deg), aspect, camera.near_plane, camera.far_plane);
    EXPECT_TRUE(same_bits(p[2][2], g[2][2]) && same_bits(p[3][2], g[3][2]) && p[2][3] == -1.0f) << fov_deg;
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) {
        const bool set = (c == r && c < 3) || (c == 2 && r == 3) || (c == 3 && r == 2);
        if (!set) {
          EXPECT_EQ(p[c][r], 0.0f) << fov_deg << " [" << c << "][" << r << "]";
        }
      }
    }
  }
}

TEST(ViewMatrices, RsmTexelAreaUsesThePortableTangent) {
  SpotLightDesc light;
  light.cone_half_angle_deg = 40.0f;
  const float side = 2.0f * portable::tan(glm::radians(40.0f)) / 512.0f;
  EXPECT_TRUE(same_bits(rsm_texel_area(light, 512), side * side));
}

}  // namespace
}  // namespace vsgl
