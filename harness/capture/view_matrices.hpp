#pragma once
// View and projection matrices of the camera and the spot light, in Vulkan clip space
// (y down, depth in [0,1]), so that image row 0 is the top of the picture.
#include <glm/glm.hpp>

#include "harness/capture/capture.hpp"

namespace vsgl {

struct ViewMatrices {
  glm::mat4 view;
  glm::mat4 projection;
};

ViewMatrices camera_matrices(const CameraDesc& camera, float aspect);
// The RSM is square with a field of view of twice the cone half angle: the cone is inscribed.
ViewMatrices light_matrices(const SpotLightDesc& light);
// Area of one RSM texel on the light's image plane at unit distance (DESIGN.md §3: dOmega_j = area * cos^3).
float rsm_texel_area(const SpotLightDesc& light, uint32_t rsm_size);

}  // namespace vsgl
