#include "harness/capture/view_matrices.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace vsgl {
namespace {
glm::mat4 vulkan_perspective(float fov_y_rad, float aspect, float near_plane, float far_plane) {
  glm::mat4 p = glm::perspective(fov_y_rad, aspect, near_plane, far_plane);  // depth [0,1] (GLM_FORCE_DEPTH_ZERO_TO_ONE)
  p[1][1] *= -1.0f;  // Vulkan's framebuffer y points down
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
  const float side = 2.0f * std::tan(glm::radians(l.cone_half_angle_deg)) / static_cast<float>(rsm_size);
  return side * side;
}

}  // namespace vsgl
