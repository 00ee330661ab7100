#include "harness/capture/view_matrices.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include "harness/core/portable_float.hpp"

namespace vsgl {
namespace {
// glm::perspective's right-handed, depth [0,1] matrix (GLM_FORCE_DEPTH_ZERO_TO_ONE), the same float
// operations, but with a tangent that is the same on every C library (core/portable_float.hpp).
glm::mat4 vulkan_perspective(float fov_y_rad, float aspect, float near_plane, float far_plane) {
  const float tan_half_fov = portable::tan(fov_y_rad / 2.0f);
  glm::mat4 p(0.0f);
  p[0][0] = 1.0f / (aspect * tan_half_fov);
  p[1][1] = -(1.0f / tan_half_fov);  // Vulkan's framebuffer y points down
  p[2][2] = far_plane / (near_plane - far_plane);
  p[2][3] = -1.0f;
  p[3][2] = -(far_plane * near_plane) / (far_plane - near_plane);
  return p;
}
}  // namespace

ViewMatrices camera_matrices(const CameraDesc& c, float aspect) {
  return {glm::lookAt(c.position, c.target, c.up),
          vulkan_perspective(glm::radians(c.fov_y_deg), aspect, c.near_plane, c.far_plane)};
}

ViewMatrices light_matrices(const SpotLightDesc& l) {
  return {glm::lookAt(l.position, l.position + l.direction, l.up),
          vulkan_perspective(glm::radians(2.0f * l.cone_half_angle_deg), 1.0f, l.near_plane, l.far_plane)};
}

float rsm_texel_area(const SpotLightDesc& l, uint32_t rsm_size) {
  const float side = 2.0f * portable::tan(glm::radians(l.cone_half_angle_deg)) / static_cast<float>(rsm_size);
  return side * side;
}

}  // namespace vsgl
